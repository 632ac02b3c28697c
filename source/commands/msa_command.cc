// `poundfe msa`: multiple-stripe analysis of the IDA section's record suite
// at the MSA section's intensities and the return periods of a hazard
// curve, and the cloud of the unscaled records (assessment/msa.h), over
// the ranks; rank 0 writes msa.csv (every run: stripe, record, every
// demand), msa_stripes.csv (per stripe the runs exceeding each limit
// state), msa_fragility.csv (each limit state's lognormal fit by the
// binomial likelihood and its annual rate on the hazard curve),
// msa_curves.csv and msa.png (the fitted curves), cloud.csv (with Cloud),
// summary.json and, with Output/Demand tables, each building's pelicun
// demand table at each stripe (commands/ida_loss.h). The journal
// (journal/stripes, journal/cloud) stays, so that the same command resumes
// an interrupted run.
#include "ida_loss.h"

#include <poundfe/assessment/msa.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/commands/command.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>

namespace poundfe::commands
{
  namespace
  {
    /// The stripes: MSA/Intensities, then those of MSA/Return periods on
    /// the hazard curve; each stripe's return period (NaN: given directly).
    struct Stripes
    {
      std::vector<double>        intensity, return_period;
      std::optional<HazardCurve> hazard;
    };

    Stripes
    msa_stripes(const InputParameters &input)
    {
      const MsaParameters &msa = input.msa;
      Stripes              stripes;
      stripes.intensity = msa.intensities;
      stripes.return_period.assign(msa.intensities.size(), std::nan(""));
      if (!msa.hazard_curve.empty())
        stripes.hazard = read_hazard_curve(input.resolve(msa.hazard_curve), msa.hazard_column);
      for (const double t : msa.return_periods)
        {
          const double x = stripes.hazard->intensity_of_return_period(t);
          if (std::isnan(x))
            input.fail("MSA/Return periods",
                       "the return period " + rounded(t) + " years is outside the hazard curve's (" +
                         rounded(1 / stripes.hazard->rate.front()) + " to " +
                         rounded(1 / stripes.hazard->rate.back()) + " years)");
          stripes.intensity.push_back(x);
          stripes.return_period.push_back(t);
        }
      if (stripes.intensity.empty())
        input.fail("MSA/Intensities", "msa needs stripes: MSA/Intensities or MSA/Return periods");
      return stripes;
    }

    /// A limit state's name as a column name: "max_drift_ratio_gt_0.01".
    std::string
    column_label(const LimitState &state)
    {
      std::string label = state.name;
      const std::size_t at = label.find(" > ");
      return at == std::string::npos ? label : label.replace(at, 3, "_gt_");
    }

    /// msa.csv: one row per run.
    void
    write_runs(const CommandRun &run, const IdaRunner &runner, const MsaResult &result,
               const Stripes &stripes)
    {
      std::string text = "stripe,intensity,return_period_years,record,name,scale_factor,collapsed";
      for (const std::string &n : runner.demand_names())
        text += "," + n;
      text += "\n";
      for (std::size_t j = 0; j < result.runs.size(); ++j)
        for (std::size_t r = 0; r < result.runs[j].size(); ++r)
          {
            const IdaPoint &p = result.runs[j][r];
            if (p.demands.empty()) // not run (interrupted)
              continue;
            text += std::to_string(j + 1);
            append_field(text, stripes.intensity[j]);
            append_field(text, stripes.return_period[j]);
            text += "," + std::to_string(r + 1) + "," + runner.suite().records[r].name;
            append_field(text, p.scale_factor);
            append_field(text, p.collapsed ? 1.0 : 0.0);
            for (const double x : p.demands)
              append_field(text, x);
            text += "\n";
          }
      write_result_text(run.memory, run.directory, "msa.csv", text);
    }

    /// Each limit state's counts at every stripe (the runs done).
    std::vector<std::vector<StripeCount>>
    count_stripes(const MsaResult &result, const std::vector<LimitState> &states)
    {
      std::vector<std::vector<StripeCount>> counts(states.size());
      for (std::size_t j = 0; j < result.runs.size(); ++j)
        for (std::size_t s = 0; s < states.size(); ++s)
          {
            StripeCount count{result.stripes[j], 0, 0};
            for (const IdaPoint &p : result.runs[j])
              if (!p.demands.empty())
                ++count.runs, count.exceeded += states[s].exceeded(p) ? 1 : 0;
            if (count.runs > 0)
              counts[s].push_back(count);
          }
      return counts;
    }

    /// msa_stripes.csv: per stripe, the runs and the fraction exceeding each state.
    void
    write_stripes(const CommandRun &run, const std::vector<LimitState> &states,
                  const std::vector<std::vector<StripeCount>> &counts, const Stripes &stripes)
    {
      std::string text = "intensity,return_period_years,runs";
      for (const LimitState &state : states)
        text += ",exceeded_" + column_label(state) + ",fraction_" + column_label(state);
      text += "\n";
      for (std::size_t j = 0; j < counts[0].size(); ++j)
        {
          append_number(text, counts[0][j].intensity);
          const auto at = std::find(stripes.intensity.begin(), stripes.intensity.end(),
                                    counts[0][j].intensity);
          append_field(text, stripes.return_period[at - stripes.intensity.begin()]);
          text += "," + std::to_string(counts[0][j].runs);
          for (const std::vector<StripeCount> &c : counts)
            {
              text += "," + std::to_string(c[j].exceeded);
              append_field(text, double(c[j].exceeded) / c[j].runs);
            }
          text += "\n";
        }
      write_result_text(run.memory, run.directory, "msa_stripes.csv", text);
    }

    /// A fitted limit state: by the stripes' binomial likelihood, its rate.
    struct FittedState
    {
      LognormalFragility fragility;
      double             rate = std::nan(""), bound = std::nan(""); // bound: msa.h, NestedRate
    };

    /// The nesting of the states over the stripes' runs, and the rates'
    /// bounds and warnings.
    NestedRate
    nest_rates(const std::vector<LimitState> &states, const MsaResult &result,
               std::vector<FittedState> &fits)
    {
      std::vector<const IdaPoint *> points;
      for (const std::vector<IdaPoint> &stripe : result.runs)
        for (const IdaPoint &p : stripe)
          points.push_back(&p);
      std::vector<double> rates;
      for (const FittedState &fit : fits)
        rates.push_back(fit.fragility.fitted ? fit.rate : std::nan(""));
      const NestedRate nested =
        order_nested_rates(states, nested_limit_states(states, points), rates);
      for (std::size_t s = 0; s < fits.size(); ++s)
        fits[s].bound = nested.bound[s];
      return nested;
    }

    /// msa_fragility.csv and msa_curves.csv (100 intensities up to twice the top stripe).
    std::vector<FittedState>
    write_fragilities(const CommandRun &run, const std::vector<LimitState> &states,
                      const std::vector<std::vector<StripeCount>> &counts, const Stripes &stripes,
                      const MsaResult &result, std::vector<std::string> &warnings)
    {
      std::vector<FittedState> fits;
      for (std::size_t s = 0; s < states.size(); ++s)
        {
          fits.push_back({fit_stripe_fragility(counts[s])});
          if (stripes.hazard)
            fits.back().rate = exceedance_rate(*stripes.hazard, fits.back().fragility);
        }
      warnings = nest_rates(states, result, fits).warnings;
      std::string text =
        "limit_state,fitted,theta,beta,annual_rate_per_year,annual_rate_bound_per_year,note\n";
      for (std::size_t s = 0; s < states.size(); ++s)
        {
          const FittedState &fit = fits[s];
          text += column_label(states[s]) + (fit.fragility.fitted ? ",1" : ",0");
          for (const double x : {fit.fragility.theta, fit.fragility.beta, fit.rate, fit.bound})
            append_field(text, fit.fragility.fitted ? x : std::nan(""));
          text += "," + fit.fragility.note + "\n";
        }
      write_result_text(run.memory, run.directory, "msa_fragility.csv", text);
      const double top = 2 * *std::max_element(stripes.intensity.begin(), stripes.intensity.end());
      std::string  curves = "intensity";
      for (const LimitState &state : states)
        curves += ",p_" + column_label(state);
      curves += "\n";
      for (unsigned int k = 1; k <= 100; ++k)
        {
          append_number(curves, top * k / 100);
          for (const FittedState &fit : fits)
            append_field(curves, fit.fragility.fitted ? exceedance_probability(fit.fragility, top * k / 100) :
                                                        std::nan(""));
          curves += "\n";
        }
      write_result_text(run.memory, run.directory, "msa_curves.csv", curves);
      return fits;
    }

    /// cloud.csv and the regression of the cloud demand on the intensity.
    CloudFit
    write_cloud(const CommandRun &run, const IdaRunner &runner, const MsaResult &result,
                const InputParameters &input)
    {
      const std::vector<std::string> &names = runner.demand_names();
      const auto column = std::find(names.begin(), names.end(), input.msa.cloud_demand);
      if (column == names.end())
        input.fail("MSA/Cloud demand", "'" + input.msa.cloud_demand + "' is not a demand of this "
                                       "model (a column of msa.csv after 'collapsed')");
      std::string text = "record,name,intensity,collapsed";
      for (const std::string &n : names)
        text += "," + n;
      text += "\n";
      std::vector<double> x, d;
      for (std::size_t r = 0; r < result.cloud.size(); ++r)
        {
          const IdaPoint &p = result.cloud[r];
          if (p.demands.empty())
            continue;
          text += std::to_string(r + 1) + "," + runner.suite().records[r].name;
          append_field(text, p.intensity);
          append_field(text, p.collapsed ? 1.0 : 0.0);
          for (const double v : p.demands)
            append_field(text, v);
          text += "\n";
          if (!p.collapsed)
            x.push_back(p.intensity), d.push_back(p.demands[column - names.begin()]);
        }
      write_result_text(run.memory, run.directory, "cloud.csv", text);
      return fit_cloud(x, d);
    }

    /// msa.png: each limit state's fitted curve and, beside it in its
    /// colour and in the key, the fraction of each stripe's runs that
    /// exceeded it (collapse is the first state: its fraction is the
    /// stripe's collapses).
    Plot
    msa_plot(const std::vector<LimitState> &states, const std::string &measure)
    {
      Plot plot{"msa.png", "Fragility of each limit state from the stripes (lognormal fit) against " + measure,
                measure, "P(limit state exceeded)", {}};
      // the observed fractions reach 0 and 1, the last stripe the axis' end:
      // margins keep their markers whole
      plot.settings = "set xrange [0:*]\nset yrange [-0.02:1.05]\nset offsets 0, graph 0.04, 0, 0\n";
      for (std::size_t s = 0; s < states.size(); ++s)
        {
          const std::string colour = " lc " + std::to_string(s + 1);
          plot.series.push_back({"msa_curves.csv", "1:" + std::to_string(2 + s),
                                 states[s].name + " (fit)", "lines lw 2" + colour});
          plot.series.push_back({"msa_stripes.csv", "1:" + std::to_string(5 + 2 * s),
                                 states[s].name + " (observed fraction)", "points pt 7 ps 1" + colour});
        }
      return plot;
    }

    /// summary.json's stripes, fits, cloud; the report's lines.
    void
    write_summary(JsonWriter &json, std::ostream &out, const MsaResult &result,
                  const std::vector<LimitState> &states, const std::vector<FittedState> &fits,
                  const std::optional<CloudFit> &cloud, const std::string &unit)
    {
      json.value("stripes", result.stripes)
        .value("runs", result.counters.n_runs)
        .value("runs_now", result.counters.n_run_now)
        .value("wall_time_s", result.counters.wall_time);
      json.begin_array("limit_states");
      for (std::size_t s = 0; s < states.size(); ++s)
        {
          const LognormalFragility &f = fits[s].fragility;
          json.begin_object().value("name", states[s].name).value("fitted", f.fitted);
          if (f.fitted)
            json.value("theta", f.theta).value("beta", f.beta);
          if (std::isfinite(fits[s].rate))
            json.value("annual_rate_per_year", fits[s].rate);
          if (std::isfinite(fits[s].bound))
            json.value("annual_rate_bound_per_year", fits[s].bound);
          if (!f.note.empty())
            json.value("note", f.note);
          json.end_object();
          out << states[s].name << ": "
              << (f.fitted ? "theta = " + rounded(f.theta) + " " + unit + ", beta = " + rounded(f.beta) :
                             f.note)
              << (std::isfinite(fits[s].rate) ? ", " + rounded(fits[s].rate) + " per year" : "")
              << "\n";
        }
      json.end_array();
      if (!cloud)
        return;
      json.begin_object("cloud").value("fitted", cloud->fitted).value("points", cloud->points);
      if (cloud->fitted)
        json.value("a", cloud->a).value("b", cloud->b).value("dispersion", cloud->dispersion);
      else
        json.value("note", cloud->note);
      json.end_object();
      out << "cloud: "
          << (cloud->fitted ? "ln D = " + rounded(std::log(cloud->a)) + " + " + rounded(cloud->b) +
                                " ln IM, dispersion " + rounded(cloud->dispersion) :
                              cloud->note)
          << "\n";
    }

    /// Writes every file of a finished (or interrupted) run on rank 0.
    void
    write_msa(const CommandRun &run, const IdaRunner &runner, const MsaResult &result,
              const Stripes &stripes)
    {
      const InputParameters  &input = *run.input;
      const IdaParameters    &ida   = input.ida;
      const std::vector<LimitState> states =
        input.msa.parse_limit_states(input, runner.demand_names());
      write_runs(run, runner, result, stripes);
      for (const auto &[name, text] : result.counters.journals) // in memory: journal/'s texts
        write_result_text(run.memory, run.directory, "journal/" + name, text);
      const auto counts = count_stripes(result, states);
      write_stripes(run, states, counts, stripes);
      std::vector<std::string>       warnings;
      const std::vector<FittedState> fits =
        write_fragilities(run, states, counts, stripes, result, warnings);
      std::optional<CloudFit> cloud;
      if (input.msa.cloud && !result.cloud.empty())
        cloud = write_cloud(run, runner, result, input);
      const std::string unit = intensity_unit(ida.measure);
      JsonWriter        json;
      begin_summary(json, "msa", input, result.counters.interrupted ? "interrupted" : "completed");
      json.value("intensity_measure", intensity_measure_names().name(ida.measure))
        .value("unit", unit)
        .value("periods_s", runner.measure_periods());
      write_summary(json, run.out, result, states, fits, cloud, unit);
      if (input.output.demand_tables) // a table per stripe, of its runs, and the cloud's
        {
          std::vector<IdaDemandSample> samples;
          std::vector<std::string>     labels;
          for (std::size_t j = 0; j < result.runs.size(); ++j)
            {
              samples.push_back(stripe_demands(runner, result.runs[j], result.stripes[j]));
              labels.push_back("_stripe" + std::to_string(j + 1));
            }
          if (!result.cloud.empty())
            {
              samples.push_back(cloud_demands(runner, result.cloud));
              labels.push_back("_cloud");
            }
          std::vector<std::string> files;
          write_demand_samples(run, runner.model(), runner, ida, samples, labels, json, run.out,
                               files);
        }
      if (!warnings.empty())
        json.value("warnings", warnings);
      for (const std::string &w : warnings)
        run.out << "warning: " << w << "\n";
      json.end_object();
      if (input.output.plots && !result.counters.interrupted && !run.memory)
        draw_plots(run.directory, {msa_plot(states, intensity_measure_names().name(ida.measure) +
                                                     " (" + unit + ")")});
      write_result_text(run.memory, run.directory, "summary.json", json.str());
    }
  } // namespace

  int
  msa(const CommandRun &run)
  {
    const InputParameters     &input = *run.input;
    const MPI_Comm             comm  = run.communicator;
    const unsigned int         rank  = dealii::Utilities::MPI::this_mpi_process(comm);
    dealii::ConditionalOStream pcout(run.out, rank == 0);
    dealii::TimerOutput timer(pcout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);

    timer.enter_subsection("set-up");
    if (input.ida.suite.empty())
      input.fail("IDA/Suite", "msa needs a record suite (a .csv, a .json or a folder of .AT2)");
    const Stripes  stripes  = msa_stripes(input);
    RecordSuite    suite    = read_record_suite(input.resolve(input.ida.suite), "IDA/Suite");
    const Analysis analysis = prepare_analysis(input);
    IdaRunner      runner(analysis, time_history_parameters(input), input.ida, std::move(suite));
    input.msa.parse_limit_states(input, runner.demand_names()); // refused before any run
    if (rank == 0 && !run.memory) // the journal of an earlier run stays: it resumes from it
      prepare_output_directory(run.directory, {"realizations.csv"});
    timer.leave_subsection();

    timer.enter_subsection("runs");
    const unsigned long n_records = runner.suite().records.size();
    Progress progress(std::cerr, "MSA runs",
                      n_records * (stripes.intensity.size() + (input.msa.cloud ? 1 : 0)));
    const MsaResult result =
      run_msa(runner, stripes.intensity, input.msa.cloud, run.memory ? "" : run.directory + "/journal",
              comm, &progress); // "": the journal in memory
    progress.finish();
    timer.leave_subsection();
    const int status = result.counters.interrupted ? interrupted_exit_status() : 0;
    if (rank != 0)
      return status;

    timer.enter_subsection("output");
    if (result.counters.interrupted)
      pcout << "msa interrupted after " << result.counters.n_runs << " runs: the results are of "
            << "these; the same command runs the rest\n";
    write_msa(run, runner, result, stripes);
    timer.leave_subsection();
    pcout << result.counters.n_runs << " runs (" << result.counters.n_run_now << " now); results in "
          << run.results_place() << " (summary.json, msa.csv, msa_stripes.csv, msa_fragility.csv, "
          << "msa_curves.csv" << (input.msa.cloud ? ", cloud.csv" : "")
          << (input.output.demand_tables ? ", demands_*.csv" : "")
          << (input.output.plots && !result.counters.interrupted && !run.memory ? ", msa.png" : "")
          << ", journal/)\n";
    print_timing(timer);
    return status;
  }
} // namespace poundfe::commands
