// Hunt and fill over the ranks, dealt run by run (ida.h, run_ida).
//
// A record's hunt is a chain: its next intensity needs its last result. The
// records' chains are independent, so rank 0 keeps every record's search
// and deals (record, next intensity) of a record with no run under way to
// whichever rank is free; no rank waits at a collective step between runs.
// Rank 0 computes too: between its own runs it reads the rows that came
// back, journals them and deals again. A worker keeps up to `queue_depth`
// runs dealt (one running, the others waiting), so it goes on while rank 0
// is in the middle of a run and reads its message only after.
//   Messages: rank 0 -> worker: a task (record, intensity) or stop (no
//   more tasks); worker -> rank 0: a row (ida_row) per run, then done (1
//   when it stopped on its own signal). Rank 0 sends stop once: when every
//   record is done and nothing is under way, or at an interruption (its
//   own signal or a worker's done with 1); a worker then drops the runs it
//   had not started. Rank 0 receives until every worker is done.
// Rank 0 writes each row to the journal as it comes and syncs the journal
// every half second and at the end (append_file.h): a row is a few ms of
// computing, and a sync per row made rank 0 wait on the disk longer than it
// computed.
// The record dealt is the free one with the fewest runs (the lowest number
// among equals), so the records advance together and the last rounds, in
// which few chains remain, are short; the order changes which rank runs
// what, never a record's intensities.
#include <poundfe/assessment/ida.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/progress.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/reliability/montecarlo.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <deque>
#include <map>
#include <optional>
#include <thread>

namespace poundfe
{
  namespace
  {
    constexpr int          ida_task_tag = 21, ida_row_tag = 22, ida_done_tag = 23, ida_stop_tag = 24;
    constexpr unsigned int queue_depth  = 3; // runs dealt to a worker at a time

    /// A short sleep while polling: a blocking MPI wait would spin on a core
    /// that the other rank needs.
    void
    ida_pause()
    {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }

    /// Rank 0: the searches, what is under way where, the journal.
    class IdaDealer
    {
    public:
      IdaDealer(IdaRunner &runner, std::map<std::uint64_t, RealizationRow> journaled,
                const std::string &file, const MPI_Comm comm, Progress *const progress)
        : runner(runner)
        , comm(comm)
        , n_workers(dealii::Utilities::MPI::n_mpi_processes(comm) - 1)
        , searches(runner.suite().records.size(), HuntFill(runner.search()))
        , busy(searches.size(), 0)
        , outstanding(n_workers + 1, 0)
        , done(n_workers + 1, 0)
        , row(ida_row_names(runner).size())
        , progress(progress && progress->active() ? progress : nullptr)
      {
        resume(std::move(journaled), file);
      }

      /// Deals and runs until every record is done or the run is stopped;
      /// returns every row (journaled ones first) in the order taken.
      std::vector<std::vector<double>> run();
      unsigned long                    n_run_now = 0;

    private:
      IdaRunner                       &runner;
      const MPI_Comm                   comm;
      const unsigned int               n_workers;
      std::vector<HuntFill>            searches;
      std::vector<char>                busy; // a run of the record is under way
      std::vector<unsigned int>        outstanding; // runs dealt to each worker
      std::vector<char>                done;
      std::vector<double>              row; // a receive buffer
      Progress *const                  progress;
      std::unique_ptr<AppendFile>      journal;
      std::uint64_t                    next_id = 0;
      std::vector<std::vector<double>> rows;
      std::chrono::steady_clock::time_point synced = std::chrono::steady_clock::now();
      unsigned int                     n_done = 0; // workers done
      bool                             stop   = false;
      std::deque<std::array<double, 2>> sent; // the tasks' buffers until Waitall
      std::vector<MPI_Request>         requests;

      void resume(std::map<std::uint64_t, RealizationRow> journaled, const std::string &file);
      std::optional<IdaTask> pick();
      void take(std::vector<double> row, bool fresh);
      void deal();
      void poll();
      void stop_all();
      bool finished() const;
    };

    void
    IdaDealer::resume(std::map<std::uint64_t, RealizationRow> journaled, const std::string &file)
    {
      for (auto &[id, earlier] : journaled)
        {
          take(std::move(earlier.responses), false);
          next_id = id + 1;
        }
      journal = std::make_unique<AppendFile>(file);
    }

    std::optional<IdaTask>
    IdaDealer::pick()
    {
      std::optional<IdaTask> task;
      for (unsigned int r = 0; r < searches.size(); ++r)
        if (!busy[r] && (!task || searches[r].n_runs() < searches[task->record].n_runs()))
          if (const std::optional<double> x = searches[r].next())
            task = IdaTask{r, *x};
      if (task)
        busy[task->record] = 1;
      return task;
    }

    void
    IdaDealer::take(std::vector<double> taken, const bool fresh)
    {
      const unsigned int r = static_cast<unsigned int>(taken[0]);
      searches.at(r).record(taken[1], taken[2] != 0);
      busy[r] = 0;
      if (fresh)
        {
          journal->append(realization_line({next_id++, true, taken}, 0), false);
          // synced in groups: a sync can outlast the run (append_file.h)
          const auto now = std::chrono::steady_clock::now();
          if (now - synced > std::chrono::milliseconds(500))
            journal->sync(), synced = now;
          ++n_run_now;
        }
      rows.push_back(std::move(taken));
      if (progress)
        progress->update(rows.size());
    }

    void
    IdaDealer::deal()
    {
      for (unsigned int w = 1; w <= n_workers; ++w)
        while (!done[w] && outstanding[w] < queue_depth)
          {
            const std::optional<IdaTask> task = pick();
            if (!task)
              return;
            sent.push_back({{double(task->record), task->intensity}});
            requests.emplace_back();
            MPI_Isend(sent.back().data(), 2, MPI_DOUBLE, w, ida_task_tag, comm, &requests.back());
            ++outstanding[w];
          }
    }

    void
    IdaDealer::poll()
    {
      int        waiting = 0;
      MPI_Status status;
      while (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm, &waiting, &status), waiting)
        {
          const int w = status.MPI_SOURCE;
          if (status.MPI_TAG == ida_row_tag)
            {
              MPI_Recv(row.data(), row.size(), MPI_DOUBLE, w, ida_row_tag, comm, MPI_STATUS_IGNORE);
              --outstanding[w];
              take(row, true);
              continue;
            }
          double flag = 0;
          MPI_Recv(&flag, 1, MPI_DOUBLE, w, ida_done_tag, comm, MPI_STATUS_IGNORE);
          done[w] = 1;
          ++n_done;
          if (flag != 0) // the worker stopped on its own signal
            stop_all();
        }
    }

    void
    IdaDealer::stop_all()
    {
      if (stop)
        return;
      stop = true;
      for (unsigned int w = 1; w <= n_workers; ++w)
        {
          requests.emplace_back();
          MPI_Isend(nullptr, 0, MPI_DOUBLE, w, ida_stop_tag, comm, &requests.back());
        }
    }

    bool
    IdaDealer::finished() const
    {
      for (unsigned int r = 0; r < searches.size(); ++r)
        if (busy[r] || searches[r].next())
          return false;
      return true;
    }

    std::vector<std::vector<double>>
    IdaDealer::run()
    {
      while (!stop || n_done < n_workers)
        {
          if (interruption_requested())
            stop_all();
          poll();
          if (!stop)
            deal();
          if (!stop && finished())
            stop_all();
          if (stop)
            {
              if (n_done < n_workers)
                ida_pause();
              continue;
            }
          if (const std::optional<IdaTask> task = pick())
            take(ida_row(runner, *task), true);
          else
            ida_pause();
        }
      MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
      journal->sync();
      return std::move(rows);
    }

    /// A worker: runs what rank 0 deals, in order, until it says stop.
    void
    run_ida_worker(IdaRunner &runner, const MPI_Comm comm)
    {
      std::deque<IdaTask> queue;
      bool                stopped = false;
      auto                receive = [&](const MPI_Status &status) {
        std::array<double, 2> task{};
        MPI_Recv(task.data(), status.MPI_TAG == ida_task_tag ? 2 : 0, MPI_DOUBLE, 0,
                 status.MPI_TAG, comm, MPI_STATUS_IGNORE);
        if (status.MPI_TAG == ida_task_tag)
          queue.push_back({static_cast<unsigned int>(task[0]), task[1]});
        else
          stopped = true;
      };
      while (true)
        {
          int        waiting = 0;
          MPI_Status status;
          while (!stopped && (MPI_Iprobe(0, MPI_ANY_TAG, comm, &waiting, &status), waiting))
            receive(status);
          if (stopped || interruption_requested())
            break;
          if (queue.empty())
            {
              ida_pause();
              continue;
            }
          const std::vector<double> row = ida_row(runner, queue.front());
          queue.pop_front();
          MPI_Send(row.data(), row.size(), MPI_DOUBLE, 0, ida_row_tag, comm);
        }
      double flag = stopped ? 0 : 1;
      MPI_Send(&flag, 1, MPI_DOUBLE, 0, ida_done_tag, comm);
      while (!stopped) // tasks dealt meanwhile are dropped
        {
          MPI_Status status;
          MPI_Probe(0, MPI_ANY_TAG, comm, &status);
          receive(status);
        }
    }

    /// A row into its record's search and points.
    void
    take_ida_row(const std::vector<double> &row, std::vector<HuntFill> &searches,
                 IdaResult &result)
    {
      const unsigned int r = static_cast<unsigned int>(row[0]);
      IdaPoint           point;
      point.intensity = row[1];
      point.collapsed = row[2] != 0;
      point.demands.assign(row.begin() + 3, row.end());
      searches.at(r).record(point.intensity, point.collapsed);
      result.records[r].points.push_back(std::move(point));
      ++result.n_runs;
    }

    /// Every rank: the rows of rank 0, flat, in the order taken.
    std::vector<double>
    dealt_rows(IdaRunner &runner, const std::string &file, const MPI_Comm comm,
               Progress *const progress, unsigned long &n_run_now)
    {
      const bool rank0 = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      std::map<std::uint64_t, RealizationRow> journaled =
        open_realization_table(file, ida_row_names(runner), 0, comm);
      bool foreign = false; // a record beyond the suite's
      for (const auto &[id, row] : journaled)
        foreign = foreign || !(row.responses[0] >= 0 &&
                               row.responses[0] < runner.suite().records.size());
      if (dealii::Utilities::MPI::broadcast(comm, foreign, 0))
        throw InputError(file, 0, "record",
                         "this journal holds other runs (another suite): remove the output "
                         "directory's journal/ to start again");
      std::vector<double> flat;
      if (rank0)
        {
          IdaDealer dealer(runner, std::move(journaled), file, comm, progress);
          for (const std::vector<double> &row : dealer.run())
            flat.insert(flat.end(), row.begin(), row.end());
          n_run_now = dealer.n_run_now;
        }
      else
        run_ida_worker(runner, comm);
      n_run_now = dealii::Utilities::MPI::broadcast(comm, n_run_now, 0);
      return dealii::Utilities::MPI::broadcast(comm, flat, 0);
    }
  } // namespace

  IdaResult
  run_ida(IdaRunner &runner, const std::string &journal, const MPI_Comm comm,
          Progress *const progress)
  {
    const auto         start     = std::chrono::steady_clock::now();
    const unsigned int n_records = runner.suite().records.size();
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      create_directories(journal);
    IdaResult result;
    result.records.resize(n_records);
    const std::vector<double> flat = dealt_rows(runner, journal + "/realizations.csv", comm,
                                                progress, result.n_run_now);
    std::vector<HuntFill> searches(n_records, HuntFill(runner.search()));
    const std::size_t     width = ida_row_names(runner).size();
    for (std::size_t i = 0; i < flat.size(); i += width)
      take_ida_row(std::vector<double>(flat.begin() + i, flat.begin() + i + width), searches,
                   result);
    for (unsigned int r = 0; r < n_records; ++r)
      {
        IdaRecordResult &record = result.records[r];
        std::sort(record.points.begin(), record.points.end(),
                  [](const IdaPoint &a, const IdaPoint &b) { return a.intensity < b.intensity; });
        for (IdaPoint &point : record.points)
          point.scale_factor = point.intensity / runner.base_intensities()[r];
        record.collapse_intensity = searches[r].collapse_intensity();
        record.highest_survived   = searches[r].highest_survived();
        record.done               = !searches[r].next();
        result.interrupted        = result.interrupted || !record.done;
      }
    result.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
} // namespace poundfe
