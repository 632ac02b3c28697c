// Runs dealt to the free rank (assessment/ida.h: deal_runs, run_ida_tasks),
// on a stand-in run (a row computed at once after a sleep) instead of a
// model, so that the test is about the dealing alone:
//  - every task of a list comes back once, with its own row, on one rank
//    or several; the journal resumes it: a second call runs nothing and
//    gives the same rows; a journal of other runs is refused;
//  - on two ranks (mpi/dealing-2), two long runs (0.6 s) among short ones
//    (0.02 s) placed where a static split (every other task to each rank)
//    gives both to rank 0: dealt one by one to the free rank, the list
//    takes about one long run (~0.7 s by the dealer's order: the worker's
//    first four tasks, rank 0 the long fifth), a static split 1.24 s. The
//    check is where the two long runs went (one to each rank), not the
//    wall time, which a loaded machine stretches;
//  - on two ranks, rank 0's runs twenty times as long as the worker's (0.2 s,
//    0.01 s): the worker goes on with the runs dealt to it while rank 0 is
//    in a run, and rank 0 reads every row that came in during its run
//    right after it and deals again, so the worker runs the four runs dealt
//    ahead per run of rank 0 (20 and 5 of the 25): at least three times as
//    many is checked. A worker that waited for rank 0 to take each row (a
//    blocking send: rank 0 takes rows between its own runs) ran about as
//    many as rank 0; a rank 0 that saw the rows only after its next run
//    (MPI_Iprobe's first answer after a run), half as many again (17, 8).
#include <poundfe/assessment/ida.h>
#include <poundfe/base/exceptions.h>

#include "test_utilities.h"

#include <boost/test/unit_test.hpp>

#include <deal.II/base/mpi.h>

#include <chrono>
#include <filesystem>
#include <set>
#include <thread>

#include <unistd.h>

using namespace poundfe;
using poundfe_test::MpiFixture;
BOOST_GLOBAL_FIXTURE(MpiFixture);

namespace
{
  /// A scratch journal the ranks agree on (rank 0's process id), empty.
  std::string
  dealing_journal(const std::string &name)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    const long     id   = dealii::Utilities::MPI::broadcast(comm, long(getpid()), 0);
    const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("poundfe_dealing_" + std::to_string(id));
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::filesystem::create_directories(folder);
        std::filesystem::remove(folder / name);
        std::filesystem::remove(folder / (name + ".inputs"));
      }
    MPI_Barrier(comm);
    return (folder / name).string();
  }

  const std::vector<std::string> dealing_names{"record", "intensity", "collapsed", "demand"};

  /// The stand-in run: a row that names its task, after `seconds`.
  std::vector<double>
  stand_in_row(const IdaTask &task, const double seconds)
  {
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    return {double(task.record), task.intensity, 0.0, 10 * task.record + task.intensity};
  }

  /// Removes the scratch folder of `file` once every rank is past it.
  void
  remove_dealing_journal(const std::string &file)
  {
    MPI_Barrier(MPI_COMM_WORLD);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::remove_all(std::filesystem::path(file).parent_path());
  }

  std::set<std::vector<double>>
  as_set(const std::vector<std::vector<double>> &rows)
  {
    return {rows.begin(), rows.end()};
  }
} // namespace

BOOST_AUTO_TEST_SUITE(dealing)

BOOST_AUTO_TEST_CASE(every_task_once_and_resumed)
{
  std::vector<IdaTask> tasks;
  for (const double x : {0.1, 0.3, 0.7})
    for (unsigned int r = 0; r < 5; ++r)
      tasks.push_back({r, x});
  const std::string file = dealing_journal("listed.csv");
  const IdaRun      run  = [](const IdaTask &t) { return stand_in_row(t, 0.001); };
  IdaResult         first;
  const auto rows = run_ida_tasks(run, dealing_names, tasks, file, MPI_COMM_WORLD, nullptr, 0, first);
  BOOST_TEST(rows.size() == tasks.size());
  BOOST_TEST(first.n_run_now == tasks.size());
  BOOST_TEST(!first.interrupted);
  std::set<std::vector<double>> expected;
  for (const IdaTask &t : tasks)
    expected.insert(stand_in_row(t, 0));
  BOOST_TEST((as_set(rows) == expected));

  IdaResult  again;
  const auto resumed =
    run_ida_tasks(run, dealing_names, tasks, file, MPI_COMM_WORLD, nullptr, 0, again);
  BOOST_TEST(again.n_run_now == 0u);
  BOOST_TEST((as_set(resumed) == expected));

  std::vector<IdaTask> other{{0, 0.2}};
  IdaResult            refused;
  BOOST_CHECK_THROW(
    run_ida_tasks(run, dealing_names, other, file, MPI_COMM_WORLD, nullptr, 0, refused),
    InputError);
  remove_dealing_journal(file);
}

BOOST_AUTO_TEST_CASE(long_runs_go_to_the_free_rank)
{
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) != 2)
    {
      BOOST_TEST_MESSAGE("the dealing of long runs is checked on two ranks (mpi/dealing-2)");
      return;
    }
  std::vector<IdaTask> tasks;
  for (unsigned int r = 0; r < 8; ++r)
    tasks.push_back({r, 1.0});
  // Which rank ran each long run: the test's verdict, not the wall time,
  // which a loaded machine stretches.
  int       ran_long[2] = {-1, -1};
  const int rank        = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const IdaRun run      = [&ran_long, rank](const IdaTask &t) {
    if (t.record == 0 || t.record == 4)
      ran_long[t.record == 0 ? 0 : 1] = rank;
    return stand_in_row(t, t.record == 0 || t.record == 4 ? 0.6 : 0.02);
  };
  const std::string file = dealing_journal("long.csv");
  MPI_Barrier(MPI_COMM_WORLD);
  const auto start = std::chrono::steady_clock::now();
  IdaResult  result;
  const auto rows = run_ida_tasks(run, dealing_names, tasks, file, MPI_COMM_WORLD, nullptr, 0, result);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  BOOST_TEST(rows.size() == tasks.size());
  BOOST_TEST_MESSAGE("8 runs, two of 0.6 s, on two ranks: " << seconds << " s");
  int where[2] = {-1, -1};
  MPI_Allreduce(ran_long, where, 2, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  BOOST_TEST(where[0] >= 0);
  BOOST_TEST(where[1] >= 0);
  BOOST_TEST(where[0] != where[1]); // a static split gives both to rank 0
  remove_dealing_journal(file);
}

BOOST_AUTO_TEST_CASE(a_worker_does_not_wait_for_rank_0)
{
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) != 2)
    {
      BOOST_TEST_MESSAGE("a worker's waiting is checked on two ranks (mpi/dealing-2)");
      return;
    }
  std::vector<IdaTask> tasks;
  for (unsigned int r = 0; r < 25; ++r)
    tasks.push_back({r, 1.0});
  const unsigned int rank   = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  unsigned int       n_runs = 0; // on this rank
  const IdaRun       run    = [&n_runs, rank](const IdaTask &t) {
    ++n_runs;
    return stand_in_row(t, rank == 0 ? 0.2 : 0.01);
  };
  const std::string file = dealing_journal("waiting.csv");
  IdaResult         result;
  const auto rows = run_ida_tasks(run, dealing_names, tasks, file, MPI_COMM_WORLD, nullptr, 0, result);
  BOOST_TEST(rows.size() == tasks.size());
  const unsigned int on_rank_0 = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, n_runs, 0);
  const unsigned int on_worker = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, n_runs, 1);
  BOOST_TEST_MESSAGE("runs of 0.2 s on rank 0: " << on_rank_0 << ", of 0.01 s on the worker: "
                                                 << on_worker);
  BOOST_TEST(on_rank_0 + on_worker == tasks.size());
  BOOST_TEST(on_worker >= 3 * on_rank_0);
  remove_dealing_journal(file);
}

BOOST_AUTO_TEST_SUITE_END()
