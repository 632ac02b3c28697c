// `poundfe subset`: Subset Simulation (reliability/subset.h) of the
// probability that a peak response of the random loading exceeds a
// threshold; rank 0 writes subset_levels.csv, summary.json and the plot.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>
#include <poundfe/reliability/random_parameters.h>
#include <poundfe/reliability/subset.h>
#include <poundfe/reliability/subset_journal.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

namespace poundfe::commands
{
  namespace
  {
    /// The CoV of P(Y > b_k) from the levels up to k: sqrt(sum delta_i^2)
    /// (levels uncorrelated, a lower bound) and sum delta_i (fully
    /// correlated, Au & Beck 2001's upper bound), level by level.
    std::vector<std::pair<double, double>>
    cumulative_cov_bounds(const SubsetResult &result)
    {
      std::vector<std::pair<double, double>> bounds;
      double                                 variance = 0, sum = 0;
      for (const SubsetLevel &L : result.levels)
        {
          variance += L.coefficient_of_variation * L.coefficient_of_variation;
          sum += L.coefficient_of_variation;
          bounds.emplace_back(std::sqrt(variance), sum);
        }
      return bounds;
    }

    /// subset_levels.png: P(Y > b_k) at each level's threshold, with bars of
    /// +-1 CoV at its upper bound (the levels fully correlated: the bars are
    /// not too short), and the target threshold as a vertical line.
    Plot
    subset_plot(const SubsetResult &result, const double target, const std::string &label)
    {
      std::ostringstream block;
      block.precision(10);
      block << "$levels << EOD\nthreshold,probability,low,high\n";
      const std::vector<std::pair<double, double>> bounds = cumulative_cov_bounds(result);
      double                                       probability = 1;
      for (std::size_t i = 0; i < result.levels.size(); ++i)
        {
          const SubsetLevel &L = result.levels[i];
          probability *= L.conditional_probability;
          const double cov = bounds[i].second;
          block << L.threshold << ',' << probability << ',' << probability * std::max(1 - cov, 1e-3)
                << ',' << probability * (1 + cov) << '\n';
        }
      Plot plot{"subset_levels.png",
                "Subset Simulation: P(" + label + " > b) at the level thresholds, " +
                  std::to_string(result.levels.size()) + " levels",
                label, "exceedance probability", {{"$levels", "1:2:3:4", "levels (bars: +-1 CoV, upper bound)",
                                                   "yerrorlines pt 7"}}, true};
      plot.data_blocks = block.str() + "EOD\n";
      std::ostringstream arrow;
      arrow.precision(10);
      arrow << "set arrow from " << target << ", graph 0 to " << target
            << ", graph 1 nohead dt 2 lw 2\nset label 'threshold' at " << target
            << ", graph 0.95 right offset -0.5, 0\n";
      plot.settings = arrow.str();
      return plot;
    }

    /// The response columns whose largest value is Y, and its unit.
    std::vector<unsigned int>
    response_columns(const InputParameters &input, const RealizationRunner &runner,
                     std::string &unit)
    {
      const SubsetParameters   &ss = input.subset;
      std::vector<unsigned int> columns;
      if (ss.response == SubsetResponse::peak_drift_ratio)
        {
          columns = runner.drift_columns(ss.building, ss.storey);
        }
      else if (ss.response == SubsetResponse::peak_roof_displacement)
        columns = {runner.roof_displacement_column(ss.building)}, unit = " m";
      else if (ss.response == SubsetResponse::limit_state)
        {
          if (!input.random_parameters.has_limit_states())
            throw InputError(input.file, input.line_of("Subset simulation/Response"),
                             "Subset simulation/Response",
                             "limit state needs Random parameters/Limit states");
        }
      else
        {
          if (!runner.has_gaps())
            throw InputError(input.file, input.line_of("Subset simulation/Response"),
                             "Subset simulation/Response",
                             "peak contact force needs contact elements (Contact/Law)");
          columns = {runner.column("peak_contact_force")}, unit = " N";
        }
      return columns;
    }

    /// The response with what it is of, for the figure: "peak drift ratio
    /// of building A, storey 2", "peak roof displacement of building A",
    /// "peak contact force of all gap elements".
    std::string
    response_of(const Model &model, const SubsetParameters &ss)
    {
      const std::string name = subset_response_names().name(ss.response);
      if (ss.response == SubsetResponse::peak_contact_force)
        return name + " of all gap elements";
      std::string of = name + " of building " + model.buildings.at(ss.building - 1).name;
      if (ss.response == SubsetResponse::peak_drift_ratio)
        of += ss.storey > 0 ? ", storey " + std::to_string(ss.storey) : " (largest storey)";
      return of;
    }

    SubsetSettings
    settings_of(const SubsetParameters &ss, const RealizationRunner &runner)
    {
      SubsetSettings settings;
      settings.samples_per_level       = ss.samples_per_level;
      settings.conditional_probability = ss.conditional_probability;
      settings.max_levels              = ss.max_levels;
      settings.proposal_spread         = ss.proposal_spread;
      settings.seed                    = runner.stochastic_load().seed();
      return settings;
    }

    /// A coefficient of variation as text: empty in a CSV cell (and
    /// "undefined" on the terminal) when the level's samples cannot estimate
    /// it (NaN, null in summary.json), never "nan".
    std::string
    defined_or_empty(const double x, const char *undefined = "", const int digits = 10)
    {
      if (!std::isfinite(x))
        return undefined;
      std::ostringstream text;
      text.precision(digits);
      text << x;
      return text.str();
    }

    /// subset_levels.csv: each level's threshold and probabilities.
    void
    write_levels(const CommandRun &command, const SubsetResult &result)
    {
      std::string csv = "level,threshold,conditional_probability,exceedance_probability,"
                        "acceptance_rate,coefficient_of_variation,"
                        "exceedance_cov_lower_bound,exceedance_cov_upper_bound\n";
      const std::vector<std::pair<double, double>> bounds = cumulative_cov_bounds(result);
      double                                       cumulative = 1;
      for (std::size_t i = 0; i < result.levels.size(); ++i)
        {
          const SubsetLevel &L = result.levels[i];
          cumulative *= L.conditional_probability;
          std::ostringstream row;
          row.precision(10);
          row << i << "," << L.threshold << "," << L.conditional_probability << "," << cumulative
              << "," << L.acceptance_rate << "," << defined_or_empty(L.coefficient_of_variation)
              << "," << defined_or_empty(bounds[i].first) << ","
              << defined_or_empty(bounds[i].second) << "\n";
          csv += row.str();
        }
      write_result_text(command.memory, command.directory, "subset_levels.csv", csv);
    }

    /// The run's facts besides the result (summary.json).
    struct SubsetRun
    {
      std::string   response_name;
      unsigned int  n_variables = 0;
      unsigned int  n_parameters = 0; // of them, random model parameters
      unsigned long failed_runs = 0;
      unsigned int  n_ranks     = 1;
      double        wall_time   = 0; // s
    };

    void
    write_summary(const CommandRun &command, const InputParameters &input,
                  const SubsetRun &run, const SubsetResult &result)
    {
      const SubsetParameters &ss = input.subset;
      JsonWriter              json;
      begin_summary(json, "subset", input, result.interrupted ? "interrupted" : "completed");
      json.value("response", run.response_name)
        .value("building", ss.building)
        .value("storey", ss.storey)
        .value("threshold", ss.threshold)
        .value("samples_per_level", ss.samples_per_level)
        .value("conditional_probability", ss.conditional_probability)
        .value("random_variables", run.n_variables);
      if (run.n_parameters > 0)
        json.value("random_model_parameters", run.n_parameters);
      if (!result.interrupted) // otherwise there is no estimate at the threshold
        json.value("failure_probability", result.probability)
          // levels uncorrelated: a lower bound of the CoV
          .value("coefficient_of_variation", undefined_if_infinite(result.coefficient_of_variation))
          // levels fully correlated (Au & Beck 2001): an upper bound
          .value("coefficient_of_variation_upper_bound",
                 undefined_if_infinite(result.coefficient_of_variation_upper_bound));
      json.value("reached_threshold", result.reached_threshold)
        .value("model_runs", result.model_runs)
        .value("resumed_model_runs", result.resumed_runs)
        .value("failed_model_runs", run.failed_runs)
        .value("ranks", run.n_ranks)
        .value("wall_time_s", run.wall_time);
      json.begin_array("levels");
      for (const SubsetLevel &L : result.levels)
        json.begin_object()
          .value("threshold", L.threshold)
          .value("conditional_probability", L.conditional_probability)
          .value("acceptance_rate", L.acceptance_rate)
          .value("coefficient_of_variation", undefined_if_infinite(L.coefficient_of_variation))
          .end_object();
      json.end_array().end_object();
      write_result_text(command.memory, command.directory, "summary.json", json.str());
    }

    void
    report(const dealii::ConditionalOStream &out, const InputParameters &input,
           const std::string &place, const SubsetRun &run, const std::string &unit,
           const SubsetResult &result, const bool drawn)
    {
      if (result.interrupted)
        out << "Subset Simulation interrupted after " << result.levels.size()
            << " levels (no estimate at the threshold; subset_levels.csv has the levels), "
            << result.model_runs << " model runs; the same command resumes from "
            << "subset_runs.csv";
      else
        {
          out << "Subset Simulation: P(";
          if (input.subset.response == SubsetResponse::limit_state)
            out << "g <= 0";
          else
            out << run.response_name << " > " << input.subset.threshold << unit;
          out << ") = " << result.probability << " (CoV between "
              << defined_or_empty(result.coefficient_of_variation, "undefined", 6)
              << ", the levels uncorrelated, and "
              << defined_or_empty(result.coefficient_of_variation_upper_bound, "undefined", 6)
              << ", fully correlated), "
              << result.levels.size() << " levels, " << result.model_runs
              << " model runs"
              << (result.reached_threshold ? "" : " (stopped at Maximum levels)");
        }
      if (result.resumed_runs > 0)
        out << " (and " << result.resumed_runs << " resumed from subset_runs.csv)";
      out << "\nresults in " << place << " (summary.json, subset_levels.csv, subset_runs.csv"
          << (drawn ? ", subset_levels.png" : "") << ")\n";
    }
    /// The journal as the sampler sees it, for a limit state that can be
    /// undefined (NaN) at a sample: find() says which sample is about to
    /// run (for the message), and a sample found undefined is not recorded
    /// (a resumed run computes it again and fails again, rather than
    /// reading a stand-in value as safe).
    class UndefinedSampleJournal : public SubsetJournal
    {
    public:
      explicit UndefinedSampleJournal(SubsetRunsFile &journal)
        : journal(journal)
      {}
      bool
      find(const unsigned int level, const unsigned int sample, double &response) const override
      {
        current = "sample " + std::to_string(sample) + " of level " + std::to_string(level) +
                  " of Subset Simulation";
        return journal.find(level, sample, response);
      }
      void
      record(const unsigned int level, const unsigned int sample, const double response) override
      {
        if (undefined.empty())
          journal.record(level, sample, response);
      }
      /// The sample under way (the last one find() was asked about).
      const std::string &sample() const { return current; }
      /// The first limit state found undefined on this rank ("": none).
      std::string undefined;

    private:
      SubsetRunsFile     &journal;
      mutable std::string current;
    };

    /// -g of the system at the sample under way; a limit state undefined
    /// there stops the sampler at the end of the level on every rank
    /// (request_stop: the ranks meet there) and is reported after it.
    double
    negated_limit_state(const ResponseLimitStates &limit_states,
                        const std::vector<double> &responses, UndefinedSampleJournal &journal)
    {
      try
        {
          return -limit_states.system_value(responses, journal.sample());
        }
      catch (const NumericalError &e)
        {
          journal.undefined = e.what();
          request_stop();
          return -std::numeric_limits<double>::infinity(); // in a level that is dropped
        }
    }

    /// The sampler's response Y of one model run: -g of the system of
    /// `limit_states` when there are any, else the largest of `columns`.
    ResponseFunction
    sampled_response(RealizationRunner &runner, SubsetRunsFile &journal,
                     UndefinedSampleJournal &sampled, const ResponseLimitStates *limit_states,
                     const std::vector<unsigned int> &columns)
    {
      auto responses = std::make_shared<std::vector<double>>();
      return [&runner, &journal, &sampled, limit_states, columns,
              responses](const std::vector<double> &xi) {
        if (!sampled.undefined.empty()) // the rest of the level is dropped: no time history
          return -std::numeric_limits<double>::infinity();
        if (!runner.run(xi, *responses))
          journal.mark_failed();
        if (limit_states)
          return negated_limit_state(*limit_states, *responses, sampled);
        double y = 0;
        for (const unsigned int c : columns)
          y = std::max(y, (*responses)[c]);
        return y;
      };
    }

    /// NumericalError on every rank when a limit state was undefined at a
    /// sample of any rank (the message of the lowest such rank).
    void
    throw_if_undefined(const UndefinedSampleJournal &journal, const MPI_Comm comm)
    {
      for (const std::string &message : dealii::Utilities::MPI::all_gather(comm, journal.undefined))
        if (!message.empty())
          throw NumericalError(message);
    }

    /// The model runs of an earlier run that this one resumes from, if any.
    void
    print_resumed_runs(const dealii::ConditionalOStream &out, const SubsetRunsFile &journal,
                       const std::string &directory)
    {
      if (journal.n_resumed() > 0)
        out << "subset: resuming: " << journal.n_resumed()
            << " model runs of an earlier run are in " << directory << "/subset_runs.csv\n";
    }

    /// subset_runs.csv (held in memory; a run into files merged it as it
    /// went), the levels, summary.json and the plot of the levels (not
    /// after a stop: it should stop soon); returns whether it drew it.
    bool
    write_subset_results(const CommandRun &run, const Model &model, const SubsetRunsFile &journal,
                         const SubsetRun &facts, const SubsetResult &result,
                         const double threshold, const bool limit_state, const std::string &unit)
    {
      const InputParameters &input = *run.input;
      if (run.memory)
        write_result_text(run.memory, run.directory, "subset_runs.csv", journal.text());
      write_levels(run, result);
      write_summary(run, input, facts, result);
      const bool draws = input.output.plots && !result.interrupted && !run.memory;
      if (draws)
        draw_plots(run.directory, {subset_plot(result, threshold,
                                               limit_state ?
                                                 "-g (system)" :
                                                 response_of(model, input.subset) + unit)});
      return draws;
    }
  } // namespace

  int
  subset(const CommandRun &run)
  {
    const InputParameters     &input     = *run.input;
    const std::string         &directory = run.directory;
    const MPI_Comm             comm      = run.communicator;
    const SubsetParameters    &ss        = input.subset;
    const unsigned int         rank      = dealii::Utilities::MPI::this_mpi_process(comm);
    dealii::ConditionalOStream pcout(run.out, rank == 0);
    // rank 0's own times: the other ranks leave before the output section
    dealii::TimerOutput timer(pcout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);

    timer.enter_subsection("set-up");
    const Analysis    analysis = prepare_analysis(input);
    RealizationRunner runner(analysis, time_history_parameters(input));
    attach_random_parameters(runner, input.random_parameters, input, input.model, input.contact, input.modal.eigensolver);
    std::string       unit;
    const std::vector<unsigned int> columns = response_columns(input, runner, unit);
    // Response = limit state: Y = -g of the system, failure Y > 0
    const bool limit_state = ss.response == SubsetResponse::limit_state;
    const std::unique_ptr<const ResponseLimitStates> limit_states =
      limit_state ? std::make_unique<const ResponseLimitStates>(
                      input.random_parameters, runner.response_names(), input) :
                    nullptr;
    const double         threshold = limit_state ? 0.0 : ss.threshold;
    const SubsetSettings settings  = settings_of(ss, runner);
    if (rank == 0 && !run.memory) // an earlier run's journal stays: this run resumes from it
      prepare_output_directory(directory, subset_journal_files(directory));
    SubsetRunsFile journal(run.memory ? "" : directory, // "": in memory
                           subset_journal_settings(settings, runner.n_variables(), threshold),
                           comm);
    print_resumed_runs(pcout, journal, directory);
    timer.leave_subsection();

    timer.enter_subsection("levels");
    SubsetRun           facts{subset_response_names().name(ss.response), runner.n_variables(),
                    runner.n_parameters(), 0, dealii::Utilities::MPI::n_mpi_processes(comm), 0};
    UndefinedSampleJournal sampled(journal);
    const ResponseFunction response =
      sampled_response(runner, journal, sampled, limit_states.get(), columns);
    const auto         start  = std::chrono::steady_clock::now();
    const SubsetResult result =
      subset_simulation(response, runner.n_variables(), threshold, settings, comm, &sampled);
    facts.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    facts.failed_runs = journal.finish(); // of this run and the runs it resumed
    request_stop(false);
    throw_if_undefined(sampled, comm);
    timer.leave_subsection();
    const int status = result.interrupted ? interrupted_exit_status() : 0;
    if (rank != 0)
      return status;

    timer.enter_subsection("output");
    const bool draws = write_subset_results(run, analysis.model, journal, facts, result,
                                            threshold, limit_state, unit);
    timer.leave_subsection();

    report(pcout, input, run.results_place(), facts, unit, result, draws);
    print_timing(timer);
    return status;
  }
} // namespace poundfe::commands
