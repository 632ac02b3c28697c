// `poundfe montecarlo`: Monte Carlo over the random loading, on the MPI
// ranks (reliability/montecarlo.h runs the realizations); rank 0 writes the
// statistics, the exceedance probabilities and the PDFs and CDFs, and with
// Output/Demand tables each building's pelicun demand table over the
// realizations (output/demand_table.h).
#include <poundfe/input/engine_parameters.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/commands/command.h>
#include <poundfe/excitation/ground_motion.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/demand_table.h>
#include <poundfe/output/drift_limits.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/floor_response.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>
#include <poundfe/reliability/distribution_plots.h>
#include <poundfe/reliability/montecarlo.h>
#include <poundfe/reliability/random_parameters.h>
#include <poundfe/reliability/reliability_analysis_parameters.h>
#include <poundfe/reliability/statistics.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <iostream>
#include <memory>

namespace poundfe::commands
{
  namespace
  {
    /// Quantities with a PDF and CDF: (column, file stem, axis label).
    /// A response of the realizations table and its figures.
    struct ResponseDistribution
    {
      unsigned int   column;
      ResponseFigure figure;
    };

    std::vector<ResponseDistribution>
    distributions(const RealizationRunner &runner)
    {
      const double g = standard_gravity;
      std::vector<ResponseDistribution> d{
        {runner.column("max_drift_ratio"),
         {"max_drift_ratio", "Largest peak inter-storey drift ratio of all buildings",
          "largest peak drift ratio", ""}},
        {runner.column("max_floor_acceleration"),
         {"max_floor_acceleration", "Largest peak absolute floor acceleration of all buildings",
          "largest peak absolute floor acceleration (g)", "g", g}}};
      const std::string roof = "peak_roof_displacement_";
      for (const std::string &name : runner.response_names())
        if (name.rfind(roof, 0) == 0)
          d.push_back({runner.column(name),
                       {name, "Peak roof displacement of building " + name.substr(roof.size()),
                        "peak roof displacement (mm)", "mm", 1e-3}});
      if (runner.has_gaps())
        {
          d.push_back({runner.column("n_impacts"),
                       {"n_impacts", "Number of impacts of all gap elements", "number of impacts",
                        "", 1, true}});
          d.push_back({runner.column("peak_contact_force"),
                       {"peak_contact_force", "Peak contact force of all gap elements",
                        "peak contact force (kN)", "kN", 1e3}});
          d.push_back({runner.column("min_clearance"),
                       {"min_clearance", "Minimum clearance of all gap elements",
                        "minimum clearance (mm; negative: penetration)", "mm", 1e-3}});
        }
      return d;
    }

    /// The drift limits of the Monte Carlo section, then the Drift limits
    /// section's (named).
    std::vector<double>
    all_drift_limits(const InputParameters &input)
    {
      std::vector<double> limits = input.monte_carlo.drift_limits;
      for (const DriftLimit &limit : input.drift_limits.limits())
        limits.push_back(limit.drift_ratio);
      return limits;
    }

    /// summary.json's run, statistics and probabilities (the object left open).
    void
    write_statistics(JsonWriter &json, const InputParameters &input,
                     const RealizationRunner &runner, const MonteCarloTable &table,
                     const std::vector<double> &limits, const Exceedances &e,
                     const unsigned int n_ranks)
    {
      const unsigned long n      = input.monte_carlo.realizations;
      const unsigned long n_done = table.realizations.size();
      const unsigned long n_completed =
        std::count(table.completed.begin(), table.completed.end(), true);
      const std::vector<DriftLimit> &named = input.drift_limits.limits();
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
      json.end_array();
      write_damage_probabilities(json, runner, e);
      json.end_object();
    }

    /// summary.json's random model parameters and the probabilities of the
    /// limit states over the realizations (Random parameters).
    void
    write_limit_states(JsonWriter &json, const RandomParameterParameters &p,
                       const ResponseLimitStates *limit_states, const MonteCarloTable &table,
                       LimitStateProbabilities &probabilities)
    {
      if (p.has_variables())
        {
          json.begin_array("random_model_parameters");
          for (unsigned int i = 0; i < p.names.size(); ++i)
            json.begin_object()
              .value("name", p.names[i])
              .value("path", p.paths[i])
              .value("distribution", distribution_name(p.distributions[i].type()))
              .value("mean", p.distributions[i].mean())
              .value("standard_deviation", p.distributions[i].standard_deviation())
              .end_object();
          json.end_array();
        }
      if (!limit_states)
        return;
      probabilities = limit_state_probabilities(*limit_states, table.responses, table.completed,
                                                table.realizations);
      json.begin_object("limit_states").begin_array("limit_states");
      for (unsigned int k = 0; k < limit_states->n_limit_states(); ++k)
        {
          json.begin_object()
            .value("name", p.limit_state_names[k])
            .value("expression", p.expressions[k]);
          write_probability(json, probabilities.limit_states[k]);
          json.end_object();
        }
      json.end_array().begin_object("system").value("type",
                                                     system_names().name(p.system));
      write_probability(json, probabilities.system);
      json.end_object().end_object();
    }

    /// pdf_*.csv and cdf_*.csv of each distribution, their entries in
    /// summary.json and their plots.
    std::vector<Plot>
    write_distributions(JsonWriter &json, const CommandRun &run,
                        const RealizationRunner &runner, const MonteCarloTable &table,
                        const unsigned int histogram_bins)
    {
      std::vector<Plot> plots;
      json.begin_array("distributions");
      for (const ResponseDistribution &d : distributions(runner))
        {
          std::vector<double> values = table.completed_values(d.column);
          const Histogram     h      = d.figure.is_count ? count_histogram(values, histogram_bins) :
                                                   histogram(values, histogram_bins);
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
          write_result_text(run.memory, run.directory, "pdf_" + d.figure.stem + ".csv", pdf);
          write_result_text(run.memory, run.directory, "cdf_" + d.figure.stem + ".csv", cdf);
          json.begin_object()
            .value("response", d.figure.stem)
            .value("pdf", "pdf_" + d.figure.stem + ".csv")
            .value("cdf", "cdf_" + d.figure.stem + ".csv")
            .end_object();
          for (Plot &plot : distribution_plots(d.figure, h, values))
            plots.push_back(std::move(plot));
        }
      json.end_array();
      return plots;
    }

    /// The demands of a realization's row (its optional responses asked
    /// for: demand_table_responses).
    ResponseDemands
    row_demands(const RealizationRunner &runner, const std::vector<double> &row)
    {
      const Model         &model = runner.model();
      const FloorResponse  floors(model);
      const auto values = [&](const std::vector<std::string> &names) {
        std::vector<double> v;
        for (const std::string &name : names)
          v.push_back(row.at(runner.column(name)));
        return v;
      };
      ResponseDemands d;
      d.pga               = row.at(runner.column("peak_ground_acc_m_s2"));
      d.peak_drift        = values(floors.column_names("storey", "peak_drift_ratio"));
      d.peak_acceleration = values(floors.column_names("floor", "peak_acc_m_s2"));
      d.residual_drift    = values(floors.column_names("storey", "residual_drift_ratio"));
      if (model.dimension == 3)
        {
          d.pga_y               = row.at(runner.column("peak_ground_acc_y_m_s2"));
          d.peak_drift_y        = values(floors.column_names("storey", "peak_drift_ratio_y"));
          d.peak_acceleration_y = values(floors.column_names("floor", "peak_acc_y_m_s2"));
          d.peak_rotation       = values(floors.column_names("floor", "peak_rotation_rad"));
          d.residual_drift_y    = values(floors.column_names("storey", "residual_drift_ratio_y"));
        }
      for (unsigned int g = 1; g <= model.gaps.size(); ++g)
        {
          const std::string gap = "gap" + std::to_string(g);
          d.impacts.push_back(row.at(runner.column(gap + "_impacts")));
          d.impact_force.push_back(row.at(runner.column(gap + "_peak_contact_force")));
          d.impact_velocity.push_back(row.at(runner.column(gap + "_peak_impact_velocity")));
        }
      return d;
    }

    /// demands_<building>.csv: a row per completed realization (a failed
    /// one, whose integration stopped, has no peaks to give a loss model);
    /// their entry in summary.json.
    void
    write_demand_tables(JsonWriter &json, const CommandRun &run, const RealizationRunner &runner,
                        const MonteCarloTable &table)
    {
      const Model             &model = runner.model();
      std::vector<DemandTable> tables;
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        tables.emplace_back(model, b, false);
      unsigned long rows = 0;
      for (std::size_t i = 0; i < table.responses.size(); ++i)
        if (table.completed[i])
          {
            const ResponseDemands d = row_demands(runner, table.responses[i]);
            for (DemandTable &t : tables)
              t.add(d);
            ++rows;
          }
      std::vector<std::string> files;
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        {
          files.push_back(demand_table_file(model, b));
          write_result_text(run.memory, run.directory, files.back(), tables[b].csv());
        }
      json.begin_object("demand_tables")
        .value("files", files)
        .value("realizations", rows)
        .value("failed_left_out", static_cast<unsigned long>(table.responses.size() - rows))
        .end_object();
    }

    /// The console lines of rank 0.
    void
    report(const dealii::ConditionalOStream &out, const InputParameters &input, const RealizationRunner &runner,
           const MonteCarloTable &table, const std::vector<double> &limits, const Exceedances &e,
           const std::string &place, const unsigned int n_ranks)
    {
      const unsigned long n      = input.monte_carlo.realizations;
      const unsigned long n_completed =
        std::count(table.completed.begin(), table.completed.end(), true);
      if (table.interrupted)
        out << "Monte Carlo interrupted after " << table.realizations.size() << " of " << n
            << " realizations: the results are over these; the same command runs the rest\n";
      out << "Monte Carlo: " << n_completed << " of " << n << " realizations completed";
      if (table.n_run_now > 0)
        out << " (" << table.n_run_now << " run now on " << n_ranks << " rank"
            << (n_ranks > 1 ? "s" : "") << ", " << rounded(table.n_run_now / table.wall_time)
            << " realizations/s)";
      out << "\n";
      if (runner.has_gaps())
        out << "P(pounding) = " << rounded(e.pounding.probability) << " (CoV "
            << rounded(e.pounding.coefficient_of_variation) << ")\n";
      for (std::size_t i = 0; i < e.drift.size(); ++i)
        out << "P(max drift ratio > " << limits[i] << ") = " << rounded(e.drift[i].probability)
            << " (CoV " << rounded(e.drift[i].coefficient_of_variation) << ")\n";
      for (std::size_t k = 0; k < e.damage.size(); ++k) // a storey's line
        {
          out << "P(damage state) " << runner.response_names()[runner.damage_state_columns()[k]]
              << ":";
          for (unsigned int l = 0; l < n_section_limits; ++l)
            out << " " << damage_state_name(l) << " " << rounded(e.damage[k][l].probability);
          out << "\n";
        }
      out << "results in " << place << " (summary.json, realizations.csv, pdf_*.csv, cdf_*.csv"
          << (input.output.demand_tables ? ", demands_*.csv" : "")
          << (input.output.plots && !table.interrupted ? ", *.png" : "") << ")\n";
    }

    /// The runner's responses (the damage states of the section limits, the
    /// demand tables' columns when asked for) and its random variables.
    void
    set_responses_and_variables(RealizationRunner &runner, const InputParameters &input)
    {
      runner.set_section_limits(input.section_limits);
      if (input.output.demand_tables) // the columns the tables read
        runner.add_optional_responses(runner.optional_response_names());
      attach_random_parameters(runner, input.random_parameters, input, input.model, input.contact,
                               input.modal.eigensolver);
    }

    /// P(g_k <= 0) of each limit state and, with more than one, the system's.
    void
    print_limit_state_probabilities(const dealii::ConditionalOStream &out,
                                    const RandomParameterParameters  &random,
                                    const LimitStateProbabilities    &probabilities)
    {
      for (unsigned int k = 0; k < probabilities.limit_states.size(); ++k)
        out << "P(" << random.limit_state_names[k]
            << " <= 0) = " << rounded(probabilities.limit_states[k].probability) << " (CoV "
            << rounded(probabilities.limit_states[k].coefficient_of_variation) << ")\n";
      if (probabilities.limit_states.size() > 1)
        out << "P(" << system_names().name(random.system)
            << " system fails) = " << rounded(probabilities.system.probability) << " (CoV "
            << rounded(probabilities.system.coefficient_of_variation) << ")\n";
    }
  } // namespace

  int
  montecarlo(const CommandRun &run)
  {
    const InputParameters     &input     = *run.input;
    const std::string         &directory = run.directory;
    const MPI_Comm             comm      = run.communicator;
    const unsigned int         rank      = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int         n_ranks   = dealii::Utilities::MPI::n_mpi_processes(comm);
    dealii::ConditionalOStream pcout(run.out, rank == 0);
    // rank 0's own times: the other ranks leave before the output section
    dealii::TimerOutput timer(pcout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);

    timer.enter_subsection("set-up");
    const Analysis    analysis = prepare_analysis(input);
    RealizationRunner runner(analysis, time_history_parameters(input));
    set_responses_and_variables(runner, input);
    const std::unique_ptr<const ResponseLimitStates> limit_states =
      input.random_parameters.has_limit_states() ?
        std::make_unique<const ResponseLimitStates>(input.random_parameters,
                                                    runner.response_names(), input) :
        nullptr;
    if (rank == 0 && !run.memory) // an earlier run's realizations stay: it resumes from them
      prepare_output_directory(directory, {"realizations.csv"});
    timer.leave_subsection();

    timer.enter_subsection("realizations");
    const unsigned long   n = input.monte_carlo.realizations;
    Progress              progress(std::cerr, "realizations", n);
    const MonteCarloTable table = run_monte_carlo(
      runner, n, 1.0, run.memory ? "" : directory + "/realizations.csv", comm, "", &progress);
    progress.finish();
    timer.leave_subsection();
    const int status = table.interrupted ? interrupted_exit_status() : 0;
    if (rank != 0)
      return status;

    timer.enter_subsection("statistics and output");
    const std::vector<double> limits = all_drift_limits(input);
    const Exceedances         e      = count_exceedances(table, runner, limits);
    JsonWriter                json;
    write_statistics(json, input, runner, table, limits, e, n_ranks);
    LimitStateProbabilities probabilities;
    write_limit_states(json, input.random_parameters, limit_states.get(), table, probabilities);
    const std::vector<Plot> plots =
      write_distributions(json, run, runner, table, input.monte_carlo.histogram_bins);
    if (input.output.demand_tables)
      write_demand_tables(json, run, runner, table);
    json.end_object();
    if (input.output.plots && !table.interrupted && !run.memory) // the resumed run draws them
      draw_plots(directory, plots);
    if (run.memory) // the journal's rows, which a run into files appended as they came
      write_result_text(run.memory, directory, "realizations.csv", realizations_text(table));
    write_result_text(run.memory, directory, "summary.json", json.str());
    timer.leave_subsection();

    print_limit_state_probabilities(pcout, input.random_parameters, probabilities);
    report(pcout, input, runner, table, limits, e, run.results_place(), n_ranks);
    print_timing(timer);
    return status;
  }
} // namespace poundfe::commands
