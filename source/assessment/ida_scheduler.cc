// Runs dealt one by one to the free rank (ida.h, deal_runs): the hunt and
// fill of an IDA (run_ida) and a list of runs (run_ida_tasks: msa's stripes
// and cloud).
//
// A record's hunt is a chain: its next intensity needs its last result. The
// records' chains are independent, so rank 0 keeps every record's search
// and deals (record, next intensity) of a record with no run under way to
// whichever rank is free; no rank waits at a collective step between runs.
// A list of runs (every record at every stripe) is the same with chains of
// one run each: rank 0 deals them in the list's order. What is dealt is
// decided by a DealtRuns (HuntFillRuns, ListedRuns); the dealer below
// knows only tasks and rows.
// Rank 0 computes too: between its own runs it reads the rows that came
// back, journals them and deals again. A worker keeps up to `queue_depth`
// runs dealt (one running, the others waiting), so it goes on while rank 0
// is in the middle of a run and reads its message only after; for the same
// reason every message is sent without waiting for its receiver
// (PendingSends): a worker that waited for rank 0 to take each row stood
// still, after each of its runs, until rank 0's run under way ended; and a
// probe that finds nothing is asked again once (message_waiting), since
// Open MPI's first answer after a run is no.
//   Messages: rank 0 -> worker: a task (record, intensity) or stop (no
//   more tasks); worker -> rank 0: a row (ida_row) per run, then done (1
//   when it stopped on its own signal). Rank 0 sends stop once: when every
//   record is done and nothing is under way, or at an interruption (its
//   own signal or a worker's done with 1); a worker then drops the runs it
//   had not started. Rank 0 receives until every worker is done.
// Rank 0 writes each row to the journal as it comes; the journal is synced
// every half second on a thread of its own and at the end (append_file.h):
// a row is a few ms of computing, and a sync per row made rank 0 wait on
// the disk longer than it computed; a sync in its loop still cost ~3 % of
// its time under disk load. What a crash can lose is only rows that a
// resume runs again: a killed process none (written rows are in the page
// cache), a machine going down the rows since the last sync.
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
    constexpr unsigned int queue_depth  = 4; // runs dealt to a worker at a time

    /// Whether a message from `source` has arrived (its envelope in
    /// `status`). Open MPI's MPI_Iprobe answers no on a call that first had
    /// to progress the transport, and matches what that call took in only
    /// on the next: a miss is asked again once, or the rows that came in
    /// during rank 0's run were read only after its next one.
    bool
    message_waiting(const int source, const MPI_Comm comm, MPI_Status &status)
    {
      int waiting = 0;
      for (unsigned int attempt = 0; attempt < 2 && !waiting; ++attempt)
        MPI_Iprobe(source, MPI_ANY_TAG, comm, &waiting, &status);
      return waiting != 0;
    }

    /// Messages sent without waiting for their receiver: each buffer kept
    /// until its send completes. A blocking MPI_Send, even of a short row,
    /// can return only once the receiver has taken the message (Open MPI's
    /// shared memory), and rank 0 takes rows between its own runs: a worker
    /// that sent its rows so waited for rank 0's run to end after each of
    /// its own.
    class PendingSends
    {
    public:
      void
      send(std::vector<double> data, const int destination, const int tag, const MPI_Comm comm)
      {
        pending.push_back({std::move(data), MPI_REQUEST_NULL});
        MPI_Isend(pending.back().data.data(), pending.back().data.size(), MPI_DOUBLE,
                  destination, tag, comm, &pending.back().request);
        release_completed();
      }

      /// Frees the buffers of the sends completed, oldest first.
      void
      release_completed()
      {
        int completed = 1;
        while (!pending.empty() &&
               (MPI_Test(&pending.front().request, &completed, MPI_STATUS_IGNORE), completed))
          pending.pop_front();
      }

      void
      wait_all()
      {
        for (Pending &p : pending)
          MPI_Wait(&p.request, MPI_STATUS_IGNORE);
        pending.clear();
      }

      PendingSends() = default;
      PendingSends(const PendingSends &) = delete;
      PendingSends &operator=(const PendingSends &) = delete;

      /// Left by an exception with sends in flight (the normal paths end in
      /// wait_all): MPI may still read a buffer, and its receiver may never
      /// take the message. Open MPI does not cancel a send (MPI_Cancel then
      /// MPI_Wait blocks until the receiver takes it, forever if it never
      /// does), so each request is freed, which returns at once and lets the
      /// send complete or not, and its buffer is kept alive, leaked on
      /// purpose: a few rows, once, on the way to an error exit.
      ~PendingSends()
      {
        int finalized = 0;
        MPI_Finalized(&finalized);
        if (finalized)
          return;
        static std::deque<std::vector<double>> *const in_flight = new std::deque<std::vector<double>>;
        for (Pending &p : pending)
          {
            int completed = 0;
            MPI_Test(&p.request, &completed, MPI_STATUS_IGNORE);
            if (!completed)
              {
                MPI_Request_free(&p.request);
                in_flight->push_back(std::move(p.data)); // a moved vector keeps its buffer
              }
          }
      }

    private:
      struct Pending
      {
        std::vector<double> data;
        MPI_Request         request;
      };
      std::deque<Pending> pending; // a deque: an element stays where it is
    };

    /// A short sleep while polling: a blocking MPI wait would spin on a core
    /// that the other rank needs.
    void
    ida_pause()
    {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }

    /// The hunt and fill of every record (the searches, a run under way).
    class HuntFillRuns : public DealtRuns
    {
    public:
      HuntFillRuns(const unsigned int n_records, const HuntFill::Settings &settings)
        : searches(n_records, HuntFill(settings))
        , busy(n_records, 0)
      {}

      bool
      holds(const std::vector<double> &row) const override
      {
        return row[0] >= 0 && row[0] < searches.size();
      }

      /// The free record with the fewest runs (the lowest number among equals).
      std::optional<IdaTask>
      next() override
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
      take(const std::vector<double> &row) override
      {
        const unsigned int r = static_cast<unsigned int>(row[0]);
        searches.at(r).record(row[1], row[2] != 0);
        busy[r] = 0;
      }

      bool
      finished() const override
      {
        for (unsigned int r = 0; r < searches.size(); ++r)
          if (busy[r] || searches[r].next())
            return false;
        return true;
      }

    private:
      std::vector<HuntFill> searches;
      std::vector<char>     busy; // a run of the record is under way
    };

    /// A list of independent runs, dealt in its order; a row is matched to
    /// its task by (record, intensity), under way first (a list may hold
    /// a task twice).
    class ListedRuns : public DealtRuns
    {
    public:
      explicit ListedRuns(const std::vector<IdaTask> &tasks)
        : tasks(tasks)
        , state(tasks.size(), todo)
      {}

      bool
      holds(const std::vector<double> &row) const override
      {
        return std::any_of(tasks.begin(), tasks.end(), [&](const IdaTask &t) {
          return row[0] == t.record && row[1] == t.intensity;
        });
      }

      std::optional<IdaTask>
      next() override
      {
        while (cursor < tasks.size() && state[cursor] != todo)
          ++cursor;
        if (cursor == tasks.size())
          return {};
        state[cursor] = under_way;
        ++n_under_way;
        return tasks[cursor];
      }

      void
      take(const std::vector<double> &row) override
      {
        for (const char from : {under_way, todo})
          for (std::size_t i = 0; i < tasks.size(); ++i)
            if (state[i] == from && row[0] == tasks[i].record && row[1] == tasks[i].intensity)
              {
                n_under_way -= from == under_way ? 1 : 0;
                state[i] = done;
                return;
              }
        Assert(false, dealii::ExcMessage("a row of no task"));
      }

      bool
      finished() const override
      {
        return n_under_way == 0 &&
               std::find(state.begin(), state.end(), todo) == state.end();
      }

    private:
      static constexpr char          todo = 0, under_way = 1, done = 2;
      const std::vector<IdaTask>    &tasks;
      std::vector<char>              state;
      std::size_t                    cursor      = 0; // no task before it is to do
      unsigned int                   n_under_way = 0;
    };

    /// Rank 0: what is under way where, the journal.
    class RunDealer
    {
    public:
      RunDealer(const IdaRun &run, DealtRuns &runs, const std::size_t width,
                std::map<std::uint64_t, RealizationRow> journaled, const std::string &file,
                const MPI_Comm comm, Progress *const progress, const unsigned long offset)
        : run_row(run)
        , runs(runs)
        , comm(comm)
        , n_workers(dealii::Utilities::MPI::n_mpi_processes(comm) - 1)
        , outstanding(n_workers + 1, 0)
        , done(n_workers + 1, 0)
        , row(width)
        , progress(progress && progress->active() ? progress : nullptr)
        , offset(offset)
      {
        resume(std::move(journaled), file);
      }

      /// Deals and runs until every run is done or the run is stopped;
      /// returns every row (journaled ones first) in the order taken.
      std::vector<std::vector<double>> run();
      unsigned long                    n_run_now = 0;

    private:
      const IdaRun                    &run_row;
      DealtRuns                       &runs;
      const MPI_Comm                   comm;
      const unsigned int               n_workers;
      std::vector<unsigned int>        outstanding; // runs dealt to each worker
      std::vector<char>                done;
      std::vector<double>              row; // a receive buffer
      Progress *const                  progress;
      const unsigned long              offset;
      std::unique_ptr<AppendFile>      journal;
      std::uint64_t                    next_id = 0;
      std::vector<std::vector<double>> rows;
      unsigned int                     n_done = 0; // workers done
      bool                             stop   = false;
      PendingSends                     sends; // tasks and stops

      void resume(std::map<std::uint64_t, RealizationRow> journaled, const std::string &file);
      void take(std::vector<double> row, bool fresh);
      void deal();
      void poll();
      void stop_all();
    };

    void
    RunDealer::resume(std::map<std::uint64_t, RealizationRow> journaled, const std::string &file)
    {
      for (auto &[id, earlier] : journaled)
        {
          take(std::move(earlier.responses), false);
          next_id = id + 1;
        }
      if (!file.empty()) // "": the journal in memory, its rows those returned
        journal = std::make_unique<AppendFile>(file);
    }

    void
    RunDealer::take(std::vector<double> taken, const bool fresh)
    {
      runs.take(taken);
      if (fresh)
        {
          // synced in groups: a sync can outlast the run (append_file.h)
          if (journal)
            journal->append_grouped(realization_line({next_id, true, taken}, 0));
          ++next_id;
          ++n_run_now;
        }
      rows.push_back(std::move(taken));
      if (progress)
        progress->update(offset + rows.size());
    }

    void
    RunDealer::deal()
    {
      for (unsigned int w = 1; w <= n_workers; ++w)
        while (!done[w] && outstanding[w] < queue_depth)
          {
            const std::optional<IdaTask> task = runs.next();
            if (!task)
              return;
            sends.send({double(task->record), task->intensity}, w, ida_task_tag, comm);
            ++outstanding[w];
          }
    }

    void
    RunDealer::poll()
    {
      MPI_Status status;
      while (message_waiting(MPI_ANY_SOURCE, comm, status))
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
    RunDealer::stop_all()
    {
      if (stop)
        return;
      stop = true;
      for (unsigned int w = 1; w <= n_workers; ++w)
        {
          sends.send({}, w, ida_stop_tag, comm);
        }
    }

    std::vector<std::vector<double>>
    RunDealer::run()
    {
      while (!stop || n_done < n_workers)
        {
          if (interruption_requested())
            stop_all();
          poll();
          if (!stop)
            deal();
          if (!stop && runs.finished())
            stop_all();
          if (stop)
            {
              if (n_done < n_workers)
                ida_pause();
              continue;
            }
          if (const std::optional<IdaTask> task = runs.next())
            take(run_row(*task), true);
          else
            ida_pause();
        }
      sends.wait_all();
      if (journal)
        journal->sync();
      return std::move(rows);
    }

    /// A worker: runs what rank 0 deals, in order, until it says stop.
    void
    run_dealt_worker(const IdaRun &run, const MPI_Comm comm)
    {
      std::deque<IdaTask> queue;
      PendingSends        rows;
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
          MPI_Status status;
          while (!stopped && message_waiting(0, comm, status))
            receive(status);
          if (stopped || interruption_requested())
            break;
          if (queue.empty())
            {
              ida_pause();
              continue;
            }
          std::vector<double> row = run(queue.front());
          queue.pop_front();
          rows.send(std::move(row), 0, ida_row_tag, comm);
        }
      double flag = stopped ? 0 : 1;
      MPI_Send(&flag, 1, MPI_DOUBLE, 0, ida_done_tag, comm);
      while (!stopped) // tasks dealt meanwhile are dropped
        {
          MPI_Status status;
          MPI_Probe(0, MPI_ANY_TAG, comm, &status);
          receive(status);
        }
      rows.wait_all();
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

    /// The text realizations.csv would hold after a fresh run of `rows`
    /// (the order taken): a journal kept in memory.
    std::string
    journal_text(const std::vector<std::string> &names, const std::vector<std::vector<double>> &rows)
    {
      MonteCarloTable table;
      table.columns = names;
      for (std::size_t i = 0; i < rows.size(); ++i)
        {
          table.realizations.push_back(i);
          table.completed.push_back(true);
          table.responses.push_back(rows[i]);
        }
      return realizations_text(table);
    }
  } // namespace

  DealtRows
  deal_runs(const IdaRun &run, DealtRuns *const runs, const std::vector<std::string> &names,
            const std::string &file, const MPI_Comm comm, Progress *const progress,
            const unsigned long offset)
  {
    const bool rank0 = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    Assert(!rank0 || runs, dealii::ExcMessage("rank 0 deals"));
    std::map<std::uint64_t, RealizationRow> journaled; // none in memory
    if (!file.empty())
      journaled = open_realization_table(file, names, 0, comm);
    bool foreign = false; // a row of none of these runs
    for (const auto &[id, row] : journaled)
      foreign = foreign || (runs && !runs->holds(row.responses));
    if (dealii::Utilities::MPI::broadcast(comm, foreign, 0))
      throw InputError(file, 0, "record",
                       "this journal holds other runs (another suite, intensity measure or "
                       "stripes): remove the output directory's journal/ to start again");
    DealtRows           dealt;
    std::vector<double> flat;
    if (rank0)
      {
        RunDealer dealer(run, *runs, names.size(), std::move(journaled), file, comm, progress,
                         offset);
        const std::vector<std::vector<double>> rows = dealer.run();
        for (const std::vector<double> &row : rows)
          flat.insert(flat.end(), row.begin(), row.end());
        if (file.empty())
          dealt.journal = journal_text(names, rows);
        dealt.n_run_now   = dealer.n_run_now;
        dealt.interrupted = !runs->finished();
      }
    else
      run_dealt_worker(run, comm);
    dealt.n_run_now   = dealii::Utilities::MPI::broadcast(comm, dealt.n_run_now, 0);
    dealt.interrupted = dealii::Utilities::MPI::broadcast(comm, dealt.interrupted, 0);
    flat              = dealii::Utilities::MPI::broadcast(comm, flat, 0);
    for (std::size_t i = 0; i < flat.size(); i += names.size())
      dealt.rows.emplace_back(flat.begin() + i, flat.begin() + i + names.size());
    return dealt;
  }

  std::vector<std::vector<double>>
  run_ida_tasks(const IdaRun &run, const std::vector<std::string> &names,
                const std::vector<IdaTask> &tasks, const std::string &file, const MPI_Comm comm,
                Progress *const progress, const unsigned long offset, IdaResult &result)
  {
    ListedRuns listed(tasks);
    const bool rank0 = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    DealtRows  dealt = deal_runs(run, rank0 ? &listed : nullptr, names, file, comm, progress, offset);
    if (file.empty())
      result.journals.emplace_back("realizations.csv", std::move(dealt.journal));
    result.n_run_now += dealt.n_run_now;
    result.interrupted = result.interrupted || dealt.interrupted;
    return std::move(dealt.rows);
  }

  std::vector<std::vector<double>>
  run_ida_tasks(IdaRunner &runner, const std::vector<IdaTask> &tasks, const std::string &file,
                const MPI_Comm comm, Progress *const progress, const unsigned long offset,
                IdaResult &result)
  {
    return run_ida_tasks([&](const IdaTask &task) { return ida_row(runner, task); },
                         ida_row_names(runner), tasks, file, comm, progress, offset, result);
  }

  IdaResult
  run_ida(IdaRunner &runner, const std::string &journal, const MPI_Comm comm,
          Progress *const progress)
  {
    const auto         start     = std::chrono::steady_clock::now();
    const unsigned int n_records = runner.suite().records.size();
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0 && !journal.empty())
      create_directories(journal);
    IdaResult result;
    result.records.resize(n_records);
    HuntFillRuns    hunts(n_records, runner.search());
    const DealtRows dealt =
      deal_runs([&](const IdaTask &task) { return ida_row(runner, task); },
                dealii::Utilities::MPI::this_mpi_process(comm) == 0 ? &hunts : nullptr,
                ida_row_names(runner), journal.empty() ? "" : journal + "/realizations.csv", comm,
                progress);
    result.n_run_now = dealt.n_run_now;
    if (journal.empty()) // "": in memory
      result.journals.emplace_back("realizations.csv", dealt.journal);
    std::vector<HuntFill> searches(n_records, HuntFill(runner.search()));
    for (const std::vector<double> &row : dealt.rows)
      take_ida_row(row, searches, result);
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
