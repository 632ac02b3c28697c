#include <poundfe/reliability/montecarlo.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/reliability/statistics.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/progress.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/drift_limits.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/plots.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

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
    constexpr int row_tag = 1, done_tag = 2, stop_tag = 3;

    std::string
    header_of(const std::vector<std::string> &names)
    {
      std::string header = "realization,seed,completed";
      for (const std::string &n : names)
        header += "," + n;
      return header;
    }

    struct Row
    {
      std::uint64_t       realization = 0;
      bool                completed   = false;
      std::vector<double> responses;
    };

    std::string
    format_row(const Row &row, const std::uint64_t seed)
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

    /// The complete rows of an existing realizations.csv; sets `damaged` when a
    /// line (a partial last line of a killed run) had to be dropped.
    std::map<std::uint64_t, Row>
    read_rows(const std::string &file, const std::string &header, const std::uint64_t seed,
              const unsigned int n_responses, bool &damaged)
    {
      std::ifstream in(file, std::ios::binary);
      std::string   text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::map<std::uint64_t, Row> rows;
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
          const char         *p    = line.c_str();
          bool                good = true;
          while (*p && good)
            {
              char        *next = nullptr;
              const double x    = std::strtod(p, &next);
              good              = next != p && (*next == ',' || *next == '\0');
              fields.push_back(x);
              p = *next == ',' ? next + 1 : next;
            }
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
          Row row;
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

  MonteCarloTable
  run_realizations(const RealizationJob &job, const unsigned long n, const std::string &file,
                   const MPI_Comm comm, const std::string &label, Progress *const progress,
                   const unsigned long progress_offset)
  {
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    dealii::ConditionalOStream pcout(std::cout, rank == 0);
    const auto         start   = std::chrono::steady_clock::now();
    const std::vector<std::string> &names = job.names;
    const std::string  header = header_of(names);
    const std::uint64_t seed  = job.seed;
    const unsigned int n_responses = names.size();

    // Rank 0 reads what an earlier run left and decides what is missing.
    std::map<std::uint64_t, Row> rows;
    std::vector<unsigned long>   todo;
    std::string                  error, error_parameter;
    int                          error_line = 0;
    if (rank == 0)
      {
        try
          {
            if (std::filesystem::exists(file))
              {
                bool damaged = false;
                rows         = read_rows(file, header, seed, n_responses, damaged);
                if (damaged) // keep only the complete rows, atomically
                  {
                    std::string text = header + "\n";
                    for (const auto &[r, row] : rows)
                      text += format_row(row, seed);
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
            error_line      = e.line();
          }
        for (unsigned long r = 0; r < n; ++r)
          if (!rows.count(r))
            todo.push_back(r);
      }
    // Every rank learns the verdict and the missing realizations.
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(file, dealii::Utilities::MPI::broadcast(comm, error_line, 0),
                       dealii::Utilities::MPI::broadcast(comm, error_parameter, 0), error);
    todo = dealii::Utilities::MPI::broadcast(comm, todo, 0);
    if (rows.size() > 0 && !todo.empty())
      pcout << label << "resuming: " << (n - todo.size()) << " of " << n
                << " realizations are in " << file << "\n";

    std::vector<double> responses, message(n_responses + 2);
    std::unique_ptr<AppendFile> out;
    if (rank == 0)
      out = std::make_unique<AppendFile>(file);
    unsigned long n_done        = n - todo.size();
    const bool    show_progress = rank == 0 && progress != nullptr && progress->active();
    if (show_progress)
      progress->update(progress_offset + n_done);
    auto store = [&](Row row) {
      out->append(format_row(row, seed));
      rows.emplace(row.realization, std::move(row));
      ++n_done;
      const unsigned long step = std::max(1UL, n / 10);
      if (show_progress)
        progress->update(progress_offset + n_done);
      else if (n_done % step == 0 || n_done == n)
        pcout << label << n_done << " / " << n << " realizations" << std::endl;
    };

    // Stopping early (SIGINT or SIGTERM on any rank): no rank starts another
    // realization, and every finished one is written. Rank 0 sends each
    // worker exactly one stop message: when it stops, or else in answer to
    // the worker's done message, which the worker waits for; a worker that
    // stops on its own signal says so in its done message, and rank 0 then
    // stops the others. Rank 0 receives until every worker is done.
    bool                     stop = false; // rank 0: no new realization anywhere
    std::vector<char>        stop_sent(n_ranks, 0);
    std::vector<MPI_Request> stop_requests;
    auto send_stop = [&](const unsigned int worker) {
      if (stop_sent[worker])
        return;
      stop_sent[worker] = 1;
      stop_requests.emplace_back();
      MPI_Isend(nullptr, 0, MPI_DOUBLE, worker, stop_tag, comm, &stop_requests.back());
    };
    auto stop_all = [&]() {
      stop = true;
      for (unsigned int worker = 1; worker < n_ranks; ++worker)
        send_stop(worker);
    };
    unsigned int n_finished = 0; // workers done
    auto receive = [&](const MPI_Status &status) {
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
      Row row;
      row.realization = static_cast<std::uint64_t>(message[0]);
      row.completed   = message[1] != 0;
      row.responses.assign(message.begin() + 2, message.end());
      store(std::move(row));
    };

    unsigned long n_run    = 0;
    bool          released = false; // a worker: has its stop message
    std::size_t   i        = rank;
    for (; i < todo.size(); i += n_ranks)
      {
        if (rank == 0)
          {
            if (interruption_requested() && !stop)
              stop_all();
            if (stop)
              break;
          }
        else
          {
            int stopped = 0;
            MPI_Iprobe(0, stop_tag, comm, &stopped, MPI_STATUS_IGNORE);
            if (stopped)
              {
                MPI_Recv(nullptr, 0, MPI_DOUBLE, 0, stop_tag, comm, MPI_STATUS_IGNORE);
                released = true;
              }
            if (released || interruption_requested())
              break;
          }
        Row row;
        row.realization = todo[i];
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
    if (rank != 0)
      {
        message[0] = i < todo.size();
        MPI_Send(message.data(), message.size(), MPI_DOUBLE, 0, done_tag, comm);
        if (!released)
          MPI_Recv(nullptr, 0, MPI_DOUBLE, 0, stop_tag, comm, MPI_STATUS_IGNORE);
      }
    else
      {
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
      }

    MonteCarloTable table;
    table.n_run_now   = dealii::Utilities::MPI::sum(n_run, comm);
    table.interrupted = dealii::Utilities::MPI::broadcast(comm, rank == 0 && n_done < n, 0);
    table.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (rank != 0)
      return table;
    table.columns = names;
    for (auto &[r, row] : rows)
      if (r < n)
        {
          table.realizations.push_back(r);
          table.completed.push_back(row.completed);
          table.responses.push_back(std::move(row.responses));
        }
    return table;
  }

  namespace
  {
    /// Quantities with a PDF and CDF: (column, file stem, axis label).
    struct ResponseDistribution
    {
      unsigned int column;
      std::string  stem, label;
      bool         is_count = false; // whole numbers: bins centred on them
    };

    std::vector<ResponseDistribution>
    distributions(const RealizationRunner &runner)
    {
      std::vector<ResponseDistribution> d{
        {runner.column("max_drift_ratio"), "max_drift_ratio", "largest peak drift ratio"},
        {runner.column("max_floor_acceleration"), "max_floor_acceleration",
         "largest peak absolute floor acceleration (m/s^2)"}};
      for (const std::string &name : runner.response_names())
        if (name.rfind("peak_roof_displacement_", 0) == 0)
          d.push_back({runner.column(name), name, "peak roof displacement (m)"});
      if (runner.has_gaps())
        {
          d.push_back({runner.column("n_impacts"), "n_impacts", "number of impacts", true});
          d.push_back({runner.column("peak_contact_force"), "peak_contact_force",
                       "peak contact force (N)"});
          d.push_back({runner.column("min_clearance"), "min_clearance",
                       "minimum clearance (m; negative: penetration)"});
        }
      return d;
    }

    void
    write_probability(JsonWriter &json, const ProbabilityEstimate &p)
    {
      json.value("probability", p.probability)
        .value("coefficient_of_variation", p.coefficient_of_variation)
        .value("failures", p.n_failures)
        .value("realizations", p.n);
    }

    /// Pounding and drift-limit exceedance counts of a table.
    struct Exceedances
    {
      ProbabilityEstimate              pounding;
      std::vector<ProbabilityEstimate> drift;
    };

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
      return e;
    }

    std::string
    limit_name(const double limit)
    {
      return "drift_" + rounded(limit, 6);
    }
  } // namespace

  int
  montecarlo_command(const Analysis &analysis, const std::string &directory, const MPI_Comm comm)
  {
    const InputParameters     &input   = analysis.input;
    const unsigned int         rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int         n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    dealii::ConditionalOStream pcout(std::cout, rank == 0);
    // rank 0's own times: the other ranks leave before the output section
    dealii::TimerOutput timer(pcout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
    timer.enter_subsection("set-up");
    RealizationRunner runner(analysis);
    if (rank == 0) // an earlier run's realizations stay: it resumes from them
      prepare_output_directory(directory, {"realizations.csv"});
    timer.leave_subsection();
    const unsigned long n = input.monte_carlo.realizations;
    timer.enter_subsection("realizations");
    Progress              progress(std::cerr, "realizations", n);
    const MonteCarloTable table =
      run_monte_carlo(runner, n, 1.0, directory + "/realizations.csv", comm, "", &progress);
    progress.finish();
    timer.leave_subsection();
    const int status = table.interrupted ? interrupted_exit_status() : 0;
    if (rank != 0)
      return status;
    timer.enter_subsection("statistics and output");

    const unsigned long n_done      = table.realizations.size();
    const unsigned long n_completed = std::count(table.completed.begin(), table.completed.end(), true);
    // the Monte Carlo section's limits, then the Drift limits section's (named)
    const std::vector<DriftLimit> &named  = input.drift_limits.limits();
    std::vector<double>            limits = input.monte_carlo.drift_limits;
    for (const DriftLimit &limit : named)
      limits.push_back(limit.drift_ratio);
    const Exceedances   e = count_exceedances(table, runner, limits);
    JsonWriter          json;
    begin_summary(json, "montecarlo", input, table.interrupted ? "interrupted" : "completed");
    json.value("realizations", n)
      .value("realizations_done", n_done)
      .value("completed_realizations", n_completed)
      .value("failed_realizations", n_done - n_completed)
      .value("seed", static_cast<unsigned long>(runner.stochastic_load().seed()))
      .value("random_variables_per_realization", runner.n_variables())
      .value("ranks", n_ranks)
      .value("realizations_run_now", table.n_run_now)
      .value("wall_time_s", table.wall_time)
      .value("realizations_per_second",
             table.n_run_now > 0 ? table.n_run_now / table.wall_time : 0.0);
    json.begin_object("statistics");
    for (unsigned int c = 0; c < table.columns.size(); ++c)
      {
        const SampleStatistics st = describe(table.completed_values(c));
        json.begin_object(table.columns[c])
          .value("mean", st.mean)
          .value("standard_deviation", st.standard_deviation)
          .value("median", st.median)
          .value("percentile_16", st.percentile_16)
          .value("percentile_84", st.percentile_84)
          .value("min", st.min)
          .value("max", st.max)
          .end_object();
      }
    json.end_object();
    json.begin_object("probabilities");
    if (runner.has_gaps())
      {
        json.begin_object("pounding");
        write_probability(json, e.pounding);
        json.end_object();
      }
    json.begin_array("drift_limit_exceedance");
    for (std::size_t i = 0; i < e.drift.size(); ++i)
      {
        json.begin_object().value("drift_ratio_limit", limits[i]);
        if (i >= input.monte_carlo.drift_limits.size())
          json.value("name", named[i - input.monte_carlo.drift_limits.size()].name);
        write_probability(json, e.drift[i]);
        json.end_object();
      }
    json.end_array().end_object();

    // PDFs and empirical CDFs.
    std::vector<Plot> plots;
    json.begin_array("distributions");
    for (const ResponseDistribution &d : distributions(runner))
      {
        std::vector<double> values = table.completed_values(d.column);
        const Histogram     h      = d.is_count ? count_histogram(values, input.monte_carlo.histogram_bins) :
                                                 histogram(values, input.monte_carlo.histogram_bins);
        std::string         pdf    = "bin_low,bin_high,bin_center,count,density\n";
        for (std::size_t i = 0; i < h.counts.size(); ++i)
          {
            for (const double x : {h.edges[i], h.edges[i + 1], (h.edges[i] + h.edges[i + 1]) / 2})
              append_number(pdf, x), pdf += ',';
            pdf += std::to_string(h.counts[i]) + ",";
            append_number(pdf, h.density[i]);
            pdf += '\n';
          }
        std::sort(values.begin(), values.end());
        std::string cdf = "value,probability\n";
        for (std::size_t i = 0; i < values.size(); ++i)
          {
            append_number(cdf, values[i]);
            cdf += ',';
            append_number(cdf, (i + 1.0) / values.size());
            cdf += '\n';
          }
        write_file_atomically(directory + "/pdf_" + d.stem + ".csv", pdf);
        write_file_atomically(directory + "/cdf_" + d.stem + ".csv", cdf);
        json.begin_object()
          .value("response", d.stem)
          .value("pdf", "pdf_" + d.stem + ".csv")
          .value("cdf", "cdf_" + d.stem + ".csv")
          .end_object();
        plots.push_back(Plot{"pdf_" + d.stem + ".png", "PDF (histogram), " + std::to_string(values.size()) + " realizations",
                             d.label, "probability density",
                             {{"pdf_" + d.stem + ".csv", "3:5", "histogram", "boxes"}},
                             false,
                             true});
        plots.push_back(Plot{"cdf_" + d.stem + ".png", "empirical CDF", d.label,
                             "P(X <= x)", {{"cdf_" + d.stem + ".csv", "1:2", "ECDF", "steps"}}});
      }
    json.end_array().end_object();
    if (input.output.plots && !table.interrupted) // stop soon: the resumed run draws them
      draw_plots(directory, plots);
    write_file_atomically(directory + "/summary.json", json.str());
    timer.leave_subsection();

    if (table.interrupted)
      pcout << "Monte Carlo interrupted after " << n_done << " of " << n
            << " realizations: the results are over these; the same command runs the rest\n";
    pcout << "Monte Carlo: " << n_completed << " of " << n << " realizations completed";
    if (table.n_run_now > 0)
      pcout << " (" << table.n_run_now << " run now on " << n_ranks << " rank"
                << (n_ranks > 1 ? "s" : "") << ", " << rounded(table.n_run_now / table.wall_time)
                << " realizations/s)";
    pcout << "\n";
    if (runner.has_gaps())
      pcout << "P(pounding) = " << rounded(e.pounding.probability) << " (CoV "
                << rounded(e.pounding.coefficient_of_variation) << ")\n";
    for (std::size_t i = 0; i < e.drift.size(); ++i)
      pcout << "P(max drift ratio > " << limits[i]
                << ") = " << rounded(e.drift[i].probability) << " (CoV "
                << rounded(e.drift[i].coefficient_of_variation) << ")\n";
    pcout << "results in " << directory << "/ (summary.json, realizations.csv, pdf_*.csv, cdf_*.csv"
          << (input.output.plots && !table.interrupted ? ", *.png" : "") << ")\n";
    print_timing(timer);
    return status;
  }

  int
  fragility_command(const Analysis &analysis, const std::string &directory, const MPI_Comm comm)
  {
    const InputParameters     &input = analysis.input;
    const unsigned int         rank  = dealii::Utilities::MPI::this_mpi_process(comm);
    dealii::ConditionalOStream pcout(std::cout, rank == 0);
    dealii::TimerOutput timer(pcout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
    timer.enter_subsection("set-up");
    RealizationRunner  runner(analysis);
    const double       reference_pga = runner.reference_pga("fragility curves");
    if (rank == 0) // an earlier run's realizations stay: it resumes from them
      prepare_output_directory(directory, {"realizations.csv"});
    timer.leave_subsection();
    const std::vector<double> &all_levels = input.fragility.pga_levels;
    const std::vector<double> &limits     = input.monte_carlo.drift_limits;
    const unsigned long        per_level  = input.fragility.realizations_per_level;
    std::vector<Exceedances>   counts; // of the levels done
    bool                       interrupted = false;
    timer.enter_subsection("realizations");
    Progress progress(std::cerr, "realizations", all_levels.size() * per_level);
    for (std::size_t j = 0; j < all_levels.size() && !interrupted; ++j)
      {
        const std::string level_directory = directory + "/pga_" + rounded(all_levels[j], 6) + "g";
        if (rank == 0)
          create_directories(level_directory);
        const MonteCarloTable table =
          run_monte_carlo(runner, per_level, all_levels[j] / reference_pga,
                          level_directory + "/realizations.csv", comm,
                          "PGA " + rounded(all_levels[j]) + " g: ", &progress, j * per_level);
        interrupted = table.interrupted; // the same on every rank
        if (rank == 0 && !interrupted)
          counts.push_back(count_exceedances(table, runner, limits));
      }
    progress.finish();
    timer.leave_subsection();
    const int status = interrupted ? interrupted_exit_status() : 0;
    if (rank != 0)
      return status;
    timer.enter_subsection("fit and output");

    // Interrupted: the points and curves of the levels done.
    const std::vector<double> levels(all_levels.begin(), all_levels.begin() + counts.size());
    if (interrupted)
      pcout << "fragility interrupted after " << levels.size() << " of " << all_levels.size()
            << " PGA levels: the points and curves are of these; the same command runs the rest\n";
    JsonWriter json;
    begin_summary(json, "fragility", input, interrupted ? "interrupted" : "completed");
    json.value("intensity_measure", "PGA (g)")
      .value("pga_levels_g", all_levels)
      .value("completed_levels", levels.size())
      .value("realizations_per_level", per_level)
      .value("seed", static_cast<unsigned long>(runner.stochastic_load().seed()));
    if (levels.empty()) // nothing to fit
      {
        json.end_object();
        write_file_atomically(directory + "/summary.json", json.str());
        return status;
      }

    // One curve for pounding (if there are gaps) and one per drift limit.
    std::vector<std::string>                     curve_names;
    std::vector<std::vector<ProbabilityEstimate>> data;
    if (runner.has_gaps())
      {
        curve_names.push_back("pounding");
        data.emplace_back();
        for (const Exceedances &e : counts)
          data.back().push_back(e.pounding);
      }
    for (std::size_t i = 0; i < limits.size(); ++i)
      {
        curve_names.push_back(limit_name(limits[i]));
        data.emplace_back();
        for (const Exceedances &e : counts)
          data.back().push_back(e.drift[i]);
      }
    std::vector<LognormalFragility> curves;
    std::string points = "pga_g,realizations";
    for (const std::string &name : curve_names)
      points += "," + name + "_failures," + name + "_fraction";
    points += "\n";
    for (std::size_t j = 0; j < levels.size(); ++j)
      {
        append_number(points, levels[j]);
        points += "," + std::to_string(data.empty() ? 0 : data[0][j].n);
        for (const auto &curve : data)
          {
            points += "," + std::to_string(curve[j].n_failures) + ",";
            append_number(points, curve[j].probability);
          }
        points += "\n";
      }
    for (const auto &curve : data)
      {
        std::vector<unsigned long> failures, trials;
        for (const ProbabilityEstimate &p : curve)
          failures.push_back(p.n_failures), trials.push_back(p.n);
        curves.push_back(fit_lognormal_fragility(levels, failures, trials));
      }
    std::string fitted = "pga_g";
    for (const std::string &name : curve_names)
      fitted += "," + name;
    fitted += "\n";
    const double top = 1.5 * *std::max_element(levels.begin(), levels.end());
    for (unsigned int k = 1; k <= 200; ++k)
      {
        const double x = top * k / 200;
        append_number(fitted, x);
        for (const LognormalFragility &c : curves)
          {
            fitted += ',';
            if (c.fitted)
              append_number(fitted, fragility(c, x));
          }
        fitted += "\n";
      }
    write_file_atomically(directory + "/fragility_points.csv", points);
    write_file_atomically(directory + "/fragility_curves.csv", fitted);

    json.begin_array("curves");
    std::ostringstream range[2];
    range[0].precision(17), range[1].precision(17);
    range[0] << *std::min_element(levels.begin(), levels.end());
    range[1] << *std::max_element(levels.begin(), levels.end());
    const std::string lowest = range[0].str(), highest = range[1].str();
    Plot plot{"fragility.png", "lognormal fragility (maximum likelihood)", "PGA (g)",
              "P(exceedance | PGA)", {}};
    plot.settings = "set xrange [0:" + highest + " * 1.1]\nset yrange [0:1]\n";
    for (std::size_t i = 0; i < curves.size(); ++i)
      {
        const LognormalFragility &c = curves[i];
        json.begin_object().value("name", curve_names[i]).value("fitted", c.fitted);
        if (c.fitted)
          json.value("theta_g", c.theta).value("beta", c.beta).value("log_likelihood", c.log_likelihood);
        if (!c.note.empty())
          json.value("note", c.note);
        std::vector<double> fractions;
        for (const ProbabilityEstimate &p : data[i])
          fractions.push_back(p.probability);
        json.value("observed_fraction", fractions).end_object();
        // points and fit in one colour; the fit drawn over the PGA levels run
        const std::string column = std::to_string(3 + 2 * i + 1);
        const std::string colour = " lc " + std::to_string(i + 1);
        plot.series.push_back({"fragility_points.csv", "1:" + column, curve_names[i] + " (MC)",
                               "points pt 7 ps 1.2" + colour});
        if (c.fitted)
          plot.series.push_back({"fragility_curves.csv",
                                 "1:(($1 >= " + lowest + " && $1 <= " + highest + ") ? $" +
                                   std::to_string(i + 2) + " : 1/0)",
                                 curve_names[i] + " fit", "lines lw 2" + colour});
        pcout << curve_names[i] << ": ";
        if (c.fitted)
          pcout << "theta = " << rounded(c.theta) << " g, beta = " << rounded(c.beta);
        else
          pcout << "not fitted (" << c.note << ")";
        pcout << "\n";
      }
    json.end_array().end_object();
    if (input.output.plots && !interrupted) // stop soon: the resumed run draws it
      draw_plots(directory, {plot});
    write_file_atomically(directory + "/summary.json", json.str());
    timer.leave_subsection();
    pcout << "results in " << directory
          << "/ (summary.json, fragility_points.csv, fragility_curves.csv"
          << (input.output.plots && !interrupted ? ", fragility.png" : "") << ", pga_*/realizations.csv)\n";
    print_timing(timer);
    return status;
  }
} // namespace poundfe
