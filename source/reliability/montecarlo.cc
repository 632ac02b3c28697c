#include <poundfe/reliability/montecarlo.h>
#include <poundfe/base/input_text.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/reliability/statistics.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/progress.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/atomic_file.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace poundfe
{
  namespace
  {
    std::string
    header_of(const std::vector<std::string> &names)
    {
      std::string header = "realization,seed,completed";
      for (const std::string &n : names)
        header += "," + n;
      return header;
    }

  } // namespace

  std::string
  realization_line(const RealizationRow &row, const std::uint64_t seed)
  {
    std::string line = std::to_string(row.realization) + "," + std::to_string(seed) + "," +
                       (row.completed ? "1" : "0");
    for (const double x : row.responses)
      {
        line += ',';
        append_number(line, x);
      }
    return line + "\n";
  }

  namespace
  {
    /// The comma-separated numbers of a table's row `line` into `fields`;
    /// false when a field is not a number (a row cut by a kill).
    bool
    read_numbers(const std::string &line, std::vector<double> &fields)
    {
      const char *p    = line.c_str();
      bool        good = true;
      while (*p && good)
        {
          char        *next = nullptr;
          const double x    = std::strtod(p, &next);
          good              = next != p && (*next == ',' || *next == '\0');
          fields.push_back(x);
          p = *next == ',' ? next + 1 : next;
        }
      return good;
    }

    /// The complete rows of an existing realizations.csv; sets `damaged` when a
    /// line (a partial last line of a killed run) had to be dropped.
    std::map<std::uint64_t, RealizationRow>
    read_rows(const std::string &file, const std::string &header, const std::uint64_t seed,
              const unsigned int n_responses, bool &damaged)
    {
      // bounded as any input: a FIFO or /dev/zero in its place is refused
      const std::string text = read_input_text(file, "table of realizations");
      std::map<std::uint64_t, RealizationRow> rows;
      damaged = false;
      std::size_t start = 0;
      bool        first = true;
      while (start < text.size())
        {
          const std::size_t end = text.find('\n', start);
          if (end == std::string::npos) // no newline: cut by a kill
            {
              damaged = true;
              break;
            }
          const std::string line = text.substr(start, end - start);
          start                  = end + 1;
          if (first)
            {
              first = false;
              if (line != header)
                throw InputError(file, 1, "",
                                 "holds realizations of a different model or version (its "
                                 "columns differ); remove it or choose another output directory");
              continue;
            }
          std::vector<double> fields;
          const bool          good = read_numbers(line, fields);
          if (!good || fields.size() != n_responses + 3)
            {
              damaged = true;
              continue;
            }
          if (static_cast<std::uint64_t>(fields[1]) != seed)
            throw InputError(file, 0, "Ground motion/Stochastic/Seed",
                             "holds realizations of seed " +
                               std::to_string(static_cast<std::uint64_t>(fields[1])) +
                               ", the input asks for seed " + std::to_string(seed) +
                               "; remove it or choose another output directory");
          RealizationRow row;
          row.realization = static_cast<std::uint64_t>(fields[0]);
          row.completed   = fields[2] != 0;
          row.responses.assign(fields.begin() + 3, fields.end());
          if (!rows.count(row.realization))
            rows.emplace(row.realization, std::move(row));
          else
            damaged = true;
        }
      if (first) // empty file: only the header was being written
        damaged = true;
      return rows;
    }

  } // namespace

  std::map<std::uint64_t, RealizationRow>
  open_realization_table(const std::string &file, const std::vector<std::string> &names,
                         const std::uint64_t seed, const MPI_Comm comm)
  {
    const std::string                       header = header_of(names);
    std::map<std::uint64_t, RealizationRow> rows;
    std::string error, error_parameter, error_file = file;
    int         error_line = 0;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          // its record first: an earlier run's rows must be of this model
          const bool earlier_run = std::filesystem::exists(file);
          resume_file(file);
          if (earlier_run)
            {
              bool damaged = false;
              rows = read_rows(file, header, seed, names.size(), damaged);
              if (damaged) // keep only the complete rows, atomically
                {
                  std::string text = header + "\n";
                  for (const auto &[r, row] : rows)
                    text += realization_line(row, seed);
                  write_file_atomically(file, text);
                }
            }
          else
            write_file_atomically(file, header + "\n");
        }
      catch (const InputError &e)
        {
          error           = e.problem();
          error_parameter = e.parameter();
          error_file      = e.file(); // the table or its record
          error_line      = e.line();
        }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(dealii::Utilities::MPI::broadcast(comm, error_file, 0),
                       dealii::Utilities::MPI::broadcast(comm, error_line, 0),
                       dealii::Utilities::MPI::broadcast(comm, error_parameter, 0), error);
    return rows;
  }

  std::vector<double>
  MonteCarloTable::completed_values(const unsigned int c) const
  {
    std::vector<double> values;
    for (std::size_t i = 0; i < responses.size(); ++i)
      if (completed[i])
        values.push_back(responses[i][c]);
    return values;
  }

  MonteCarloTable
  run_monte_carlo(RealizationRunner &runner, const unsigned long n, const double amplitude_factor,
                  const std::string &file, const MPI_Comm comm, const std::string &label,
                  Progress *const progress, const unsigned long progress_offset)
  {
    const RealizationJob job{runner.response_names(), runner.stochastic_load().seed(),
                             [&](const std::uint64_t r, std::vector<double> &row) {
                               return runner.run(r, row, amplitude_factor);
                             }};
    return run_realizations(job, n, file, comm, label, progress, progress_offset);
  }

  namespace
  {
    /// The run of one call of run_realizations, in phases: read what an
    /// earlier run left (resume), run this rank's share, let rank 0 gather
    /// the workers' rows until every worker is done (finish), then the table.
    ///   Stopping early (SIGINT or SIGTERM on any rank): no rank starts
    ///   another realization, and every finished one is written. Rank 0 sends
    ///   each worker exactly one stop message: when it stops, or else in
    ///   answer to the worker's done message, which the worker waits for; a
    ///   worker that stops on its own signal says so in its done message, and
    ///   rank 0 then stops the others. Rank 0 receives until every worker is done.
    class RealizationScheduler
    {
    public:
      RealizationScheduler(const RealizationJob &job, const unsigned long n,
                           const std::string &file, const MPI_Comm comm,
                           const std::string &label, Progress *const progress,
                           const unsigned long progress_offset)
        : job(job)
        , n(n)
        , file(file)
        , comm(comm)
        , label(label)
        , progress(progress)
        , progress_offset(progress_offset)
        , rank(dealii::Utilities::MPI::this_mpi_process(comm))
        , n_ranks(dealii::Utilities::MPI::n_mpi_processes(comm))
        , pcout(std::cout, rank == 0)
        , header(header_of(job.names))
        , message(job.names.size() + 2)
        , stop_sent(n_ranks, 0)
      {}

      /// Rank 0 reads what an earlier run left and decides what is missing;
      /// every rank learns the verdict and the missing realizations.
      void resume();
      /// This rank's share of the missing realizations (every n_ranks-th).
      void run_share();
      /// Workers say they are done; rank 0 gathers rows until all are.
      void finish();
      /// The realizations of 0..n-1 done (rank 0; empty elsewhere), with
      /// the wall time since `start`.
      MonteCarloTable table(std::chrono::steady_clock::time_point start);

    private:
      static constexpr int row_tag = 1, done_tag = 2, stop_tag = 3;

      const RealizationJob      &job;
      const unsigned long        n;
      const std::string         &file;
      const MPI_Comm             comm;
      const std::string         &label;
      Progress *const            progress;
      const unsigned long        progress_offset;
      const unsigned int         rank, n_ranks;
      dealii::ConditionalOStream pcout;
      const std::string          header;

      std::map<std::uint64_t, RealizationRow> rows; // rank 0
      std::vector<unsigned long>   todo;
      std::unique_ptr<AppendFile>  out; // rank 0
      unsigned long                n_done        = 0;
      bool                         show_progress = false;
      std::vector<double>          message;

      bool                     stop = false; // rank 0: no new realization anywhere
      std::vector<char>        stop_sent;
      std::vector<MPI_Request> stop_requests;
      unsigned int             n_finished = 0; // workers done
      unsigned long            n_run      = 0; // by this rank
      bool                     released   = false; // a worker: has its stop message
      std::size_t              next       = 0;     // this rank's next index into todo

      void store(RealizationRow row);
      void send_stop(unsigned int worker);
      void stop_all();
      void receive(const MPI_Status &status);
      /// Whether this rank starts no more realizations.
      bool stopping();
    };

    void
    RealizationScheduler::resume()
    {
      if (!file.empty()) // none: results in memory, nothing to resume
        rows = open_realization_table(file, job.names, job.seed, comm);
      if (rank == 0)
        for (unsigned long r = 0; r < n; ++r)
          if (!rows.count(r))
            todo.push_back(r);
      todo = dealii::Utilities::MPI::broadcast(comm, todo, 0);
      if (rows.size() > 0 && !todo.empty())
        pcout << label << "resuming: " << (n - todo.size()) << " of " << n
              << " realizations are in " << file << "\n";
      if (rank == 0 && !file.empty())
        out = std::make_unique<AppendFile>(file);
      n_done        = n - todo.size();
      show_progress = rank == 0 && progress != nullptr && progress->active();
      if (show_progress)
        progress->update(progress_offset + n_done);
    }

    void
    RealizationScheduler::store(RealizationRow row)
    {
      if (out) // synced in groups, and at the end (finish)
        out->append_grouped(realization_line(row, job.seed));
      rows.emplace(row.realization, std::move(row));
      ++n_done;
      const unsigned long step = std::max(1UL, n / 10);
      if (show_progress)
        progress->update(progress_offset + n_done);
      else if (job.report_lines && (n_done % step == 0 || n_done == n))
        pcout << label << n_done << " / " << n << " realizations" << std::endl;
    }

    void
    RealizationScheduler::send_stop(const unsigned int worker)
    {
      if (stop_sent[worker])
        return;
      stop_sent[worker] = 1;
      stop_requests.emplace_back();
      MPI_Isend(nullptr, 0, MPI_DOUBLE, worker, stop_tag, comm, &stop_requests.back());
    }

    void
    RealizationScheduler::stop_all()
    {
      stop = true;
      for (unsigned int worker = 1; worker < n_ranks; ++worker)
        send_stop(worker);
    }

    void
    RealizationScheduler::receive(const MPI_Status &status)
    {
      MPI_Recv(message.data(), message.size(), MPI_DOUBLE, status.MPI_SOURCE, status.MPI_TAG,
               comm, MPI_STATUS_IGNORE);
      if (status.MPI_TAG == done_tag)
        {
          ++n_finished;
          if (message[0] != 0 && !stop) // it stopped with realizations left
            stop_all();
          send_stop(status.MPI_SOURCE);
          return;
        }
      RealizationRow row;
      row.realization = static_cast<std::uint64_t>(message[0]);
      row.completed   = message[1] != 0;
      row.responses.assign(message.begin() + 2, message.end());
      store(std::move(row));
    }

    bool
    RealizationScheduler::stopping()
    {
      if (rank == 0)
        {
          if (interruption_requested() && !stop)
            stop_all();
          return stop;
        }
      int stopped = 0;
      MPI_Iprobe(0, stop_tag, comm, &stopped, MPI_STATUS_IGNORE);
      if (stopped)
        {
          MPI_Recv(nullptr, 0, MPI_DOUBLE, 0, stop_tag, comm, MPI_STATUS_IGNORE);
          released = true;
        }
      return released || interruption_requested();
    }

    void
    RealizationScheduler::run_share()
    {
      for (next = rank; next < todo.size(); next += n_ranks)
        {
          if (stopping())
            break;
          RealizationRow row;
          row.realization = todo[next];
          row.completed   = job.run(row.realization, row.responses);
          ++n_run;
          if (rank == 0)
            {
              store(std::move(row));
              int        waiting = 0;
              MPI_Status status;
              // write what the workers finished meanwhile
              while (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm, &waiting, &status), waiting)
                receive(status);
            }
          else
            {
              message[0] = row.realization;
              message[1] = row.completed;
              std::copy(row.responses.begin(), row.responses.end(), message.begin() + 2);
              MPI_Send(message.data(), message.size(), MPI_DOUBLE, 0, row_tag, comm);
            }
        }
    }

    void
    RealizationScheduler::finish()
    {
      if (rank != 0)
        {
          message[0] = next < todo.size();
          MPI_Send(message.data(), message.size(), MPI_DOUBLE, 0, done_tag, comm);
          if (!released)
            MPI_Recv(nullptr, 0, MPI_DOUBLE, 0, stop_tag, comm, MPI_STATUS_IGNORE);
          return;
        }
      // polled rather than a blocking probe, to see a signal that comes meanwhile
      while (n_finished + 1 < n_ranks)
        {
          if (interruption_requested() && !stop)
            stop_all();
          int        waiting = 0;
          MPI_Status status;
          MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm, &waiting, &status);
          if (waiting)
            receive(status);
          else
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
      MPI_Waitall(stop_requests.size(), stop_requests.data(), MPI_STATUSES_IGNORE);
      if (out) // the rows since the last grouped sync
        out->sync();
    }

    MonteCarloTable
    RealizationScheduler::table(const std::chrono::steady_clock::time_point start)
    {
      MonteCarloTable table;
      table.n_run_now   = dealii::Utilities::MPI::sum(n_run, comm);
      table.interrupted = dealii::Utilities::MPI::broadcast(comm, rank == 0 && n_done < n, 0);
      table.wall_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (rank != 0)
        return table;
      table.columns = job.names;
      table.seed    = job.seed;
      for (auto &[r, row] : rows)
        if (r < n)
          {
            table.realizations.push_back(r);
            table.completed.push_back(row.completed);
            table.responses.push_back(std::move(row.responses));
          }
      return table;
    }
  } // namespace

  std::string
  realizations_text(const MonteCarloTable &table)
  {
    std::string text = header_of(table.columns) + "\n";
    for (std::size_t i = 0; i < table.realizations.size(); ++i)
      text += realization_line({table.realizations[i], table.completed[i], table.responses[i]},
                               table.seed);
    return text;
  }

  MonteCarloTable
  run_realizations(const RealizationJob &job, const unsigned long n, const std::string &file,
                   const MPI_Comm comm, const std::string &label, Progress *const progress,
                   const unsigned long progress_offset)
  {
    const auto           start = std::chrono::steady_clock::now();
    RealizationScheduler scheduler(job, n, file, comm, label, progress, progress_offset);
    scheduler.resume();
    scheduler.run_share();
    scheduler.finish();
    return scheduler.table(start);
  }

  Exceedances
  count_exceedances(const MonteCarloTable &table, const RealizationRunner &runner,
                    const std::vector<double> &drift_limits)
  {
    Exceedances         e;
    const auto          drift = table.completed_values(runner.column("max_drift_ratio"));
    const unsigned long n     = drift.size();
    if (runner.has_gaps())
      {
        const auto pounded = table.completed_values(runner.column("pounded"));
        e.pounding = estimate_probability(std::count(pounded.begin(), pounded.end(), 1.0), n);
      }
    for (const double limit : drift_limits)
      e.drift.push_back(estimate_probability(
        std::count_if(drift.begin(), drift.end(), [limit](double x) { return x > limit; }), n));
    for (const unsigned int c : runner.damage_state_columns())
      {
        const auto states = table.completed_values(c);
        auto      &p      = e.damage.emplace_back();
        for (unsigned int l = 0; l < n_section_limits; ++l) // state l + 1 or worse
          p[l] = estimate_probability(
            std::count_if(states.begin(), states.end(), [l](double x) { return x >= l + 1; }), n);
      }
    return e;
  }

  void
  write_probability(JsonWriter &json, const ProbabilityEstimate &p)
  {
    json.value("probability", p.probability)
      .value("coefficient_of_variation", undefined_if_infinite(p.coefficient_of_variation))
      .value("failures", p.n_failures)
      .value("realizations", p.n);
  }

  void
  write_damage_probabilities(JsonWriter &json, const RealizationRunner &runner,
                             const Exceedances &e)
  {
    if (e.damage.empty())
      return;
    json.begin_array("storey_damage_states");
    for (std::size_t k = 0; k < e.damage.size(); ++k)
      {
        json.begin_object().value("column",
                                  runner.response_names()[runner.damage_state_columns()[k]]);
        for (unsigned int l = 0; l < n_section_limits; ++l)
          {
            json.begin_object(damage_state_name(l));
            write_probability(json, e.damage[k][l]);
            json.end_object();
          }
        json.end_object();
      }
    json.end_array();
  }

  std::string
  fragility_level_folder(const double level)
  {
    return "pga_" + rounded(level, 6) + "g";
  }

  FragilityLevels
  run_fragility_levels(RealizationRunner &runner, const FragilityParameters &parameters,
                       const std::vector<double> &drift_limits, const double reference_pga,
                       const std::string &directory, const MPI_Comm comm, Progress &progress)
  {
    const unsigned int         rank      = dealii::Utilities::MPI::this_mpi_process(comm);
    const std::vector<double> &levels    = parameters.pga_levels;
    const unsigned long        per_level = parameters.realizations_per_level;
    FragilityLevels            result;
    for (std::size_t j = 0; j < levels.size() && !result.interrupted; ++j)
      {
        const bool        in_memory       = directory.empty();
        const std::string level_directory = directory + "/" + fragility_level_folder(levels[j]);
        if (rank == 0 && !in_memory)
          create_directories(level_directory);
        MonteCarloTable table =
          run_monte_carlo(runner, per_level, levels[j] / reference_pga,
                          in_memory ? "" : level_directory + "/realizations.csv", comm,
                          "PGA " + rounded(levels[j]) + " g: ", &progress, j * per_level);
        result.interrupted = table.interrupted; // the same on every rank
        if (rank == 0 && !result.interrupted)
          {
            result.levels.push_back(levels[j]);
            result.counts.push_back(count_exceedances(table, runner, drift_limits));
          }
        if (rank == 0 && result.interrupted)
          result.interrupted_level = levels[j];
        if (rank == 0 && in_memory) // the interrupted level's too, last
          result.tables.push_back(std::move(table));
      }
    return result;
  }

  std::vector<FragilityCurve>
  fit_fragility_curves(const FragilityLevels &levels, const std::vector<double> &drift_limits,
                       const bool has_gaps)
  {
    std::vector<FragilityCurve> curves;
    if (has_gaps)
      {
        curves.push_back({"pounding", {}, {}});
        for (const Exceedances &e : levels.counts)
          curves.back().observed.push_back(e.pounding);
      }
    for (std::size_t i = 0; i < drift_limits.size(); ++i)
      {
        curves.push_back({"drift_" + rounded(drift_limits[i], 6), {}, {}});
        for (const Exceedances &e : levels.counts)
          curves.back().observed.push_back(e.drift[i]);
      }
    for (FragilityCurve &curve : curves)
      {
        std::vector<unsigned long> failures, trials;
        for (const ProbabilityEstimate &p : curve.observed)
          failures.push_back(p.n_failures), trials.push_back(p.n);
        curve.fit = fit_lognormal_fragility(levels.levels, failures, trials);
      }
    return curves;
  }
} // namespace poundfe
