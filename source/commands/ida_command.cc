// `poundfe ida`: incremental dynamic analysis of the IDA section's record
// suite (assessment/ida.h) over the ranks; rank 0 writes ida.csv (every run:
// record, intensity, every demand), ida_records.csv (each record's
// intensity measures), ida_fractiles.csv (16/50/84 % of the largest drift
// ratio against the intensity), collapse_fragility.csv, ida.png,
// summary.json (with FEMA P-695's collapse margin) and the pelicun demand
// tables at IDA/Demand intensities (commands/ida_loss.h). The rounds' journal (journal/round_<k>/realizations.csv)
// stays, so that the same command resumes an interrupted run.
#include "ida_loss.h"

#include <poundfe/assessment/ida.h>
#include <poundfe/assessment/ida_demands.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/base/standard_normal.h>
#include <poundfe/commands/command.h>
#include <poundfe/excitation/response_spectrum.h>
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
#include <limits>

namespace poundfe::commands
{
  namespace
  {
    /// ida.csv: one row per run, by record and intensity.
    void
    write_runs(const CommandRun &run, const IdaRunner &runner, const IdaResult &result)
    {
      std::string text = "record,name,intensity,scale_factor,collapsed";
      for (const std::string &n : runner.demand_names())
        text += "," + n;
      text += "\n";
      for (std::size_t r = 0; r < result.records.size(); ++r)
        for (const IdaPoint &p : result.records[r].points)
          {
            text += std::to_string(r + 1) + "," + runner.suite().records[r].name;
            for (const double x : {p.intensity, p.scale_factor, p.collapsed ? 1.0 : 0.0})
              append_field(text, x);
            for (const double x : p.demands)
              append_field(text, x);
            text += "\n";
          }
      write_result_text(run.memory, run.directory, "ida.csv", text);
    }

    /// ida_records.csv: each record's metadata and intensity measures as
    /// scaled in the suite (the first component's; a pair's Sa as well by
    /// the geometric mean, RotD50 and RotD100).
    void
    write_records(const CommandRun &run, const IdaRunner &runner, const double period,
                  const double zeta)
    {
      const RecordSuite &suite = runner.suite();
      std::string text = "record,name,event,station,magnitude,distance_km,vs30_m_s,suite_scale,"
                         "time_step_s,points,im,pga_g,pgv_m_s,sa_g,arias_m_s,cav_m_s,d5_75_s,d5_95_s";
      text += suite.pairs() ? ",sa_geometric_mean_g,sa_rotd50_g,sa_rotd100_g\n" : "\n";
      for (std::size_t r = 0; r < suite.records.size(); ++r)
        {
          const SuiteRecord          &record = suite.records[r];
          const GroundMotion         &a      = record.components[0];
          const GroundMotionIntensity m      = ground_motion_intensity(a);
          text += std::to_string(r + 1) + "," + record.name + "," + record.event + "," +
                  record.station;
          for (const double x : {record.magnitude, record.distance_km, record.vs30_m_s,
                                 record.scale_factor, a.time_step(), double(a.samples().size()),
                                 runner.base_intensities()[r], m.pga / standard_gravity, m.pgv,
                                 pseudo_spectral_acceleration(a, period, zeta) / standard_gravity,
                                 m.arias_intensity, m.cumulative_absolute_velocity,
                                 m.significant_duration_5_75, m.significant_duration})
            append_field(text, x);
          if (suite.pairs())
            for (const PairMeasure pair :
                 {PairMeasure::geometric_mean, PairMeasure::rotd50, PairMeasure::rotd100})
              append_field(text, intensity_of(record.components, IntensityMeasure::sa, pair,
                                              {period}, zeta));
          text += "\n";
        }
      write_result_text(run.memory, run.directory, "ida_records.csv", text);
    }

    /// ida_fractiles.csv: the 16/50/84 % fractiles over 50 intensities.
    void
    write_fractiles(const CommandRun &run, const IdaRunner &runner,
                    const IdaResult &result, const double top)
    {
      std::string text = "intensity,max_drift_ratio_16,max_drift_ratio_50,max_drift_ratio_84,"
                         "records\n";
      for (unsigned int k = 1; k <= 50; ++k)
        {
          const double        x = top * k / 50;
          std::vector<double> demands;
          for (const IdaRecordResult &record : result.records)
            {
              const double d = demand_at(record, runner.max_drift_column(), x);
              if (!std::isnan(d))
                demands.push_back(d);
            }
          if (demands.empty())
            continue;
          append_number(text, x);
          for (const double p : {0.16, 0.5, 0.84})
            append_field(text, empirical_quantile(demands, p));
          text += "," + std::to_string(demands.size()) + "\n";
        }
      write_result_text(run.memory, run.directory, "ida_fractiles.csv", text);
    }

    /// The collapse intensities and the fit; collapse_fragility.csv.
    CollapseFragility
    write_fragility(const CommandRun &run, const IdaResult &result, const double upper)
    {
      std::vector<double> collapse;
      unsigned int        censored = 0;
      for (const IdaRecordResult &record : result.records)
        if (record.collapse_intensity)
          collapse.push_back(*record.collapse_intensity);
        else if (record.done)
          ++censored;
      const CollapseFragility fit = fit_collapse_fragility(collapse, censored, upper);
      std::string             text = "intensity,observed_fraction,fitted_probability\n";
      for (unsigned int k = 1; k <= 100; ++k)
        {
          const double x = upper * k / 100;
          append_number(text, x);
          const double n = std::count_if(collapse.begin(), collapse.end(),
                                         [x](const double c) { return c <= x; });
          append_field(text, n / std::max<std::size_t>(1, collapse.size() + censored));
          append_field(text, fit.fitted ? standard_normal_cdf(std::log(x / fit.theta) / fit.beta) :
                                          std::nan(""));
          text += "\n";
        }
      write_result_text(run.memory, run.directory, "collapse_fragility.csv", text);
      return fit;
    }
    /// ida.png: each record's curve (largest drift ratio against the
    /// intensity, the runs that did not collapse) and the fractiles.
    Plot
    ida_plot(const IdaRunner &runner, const std::string &measure)
    {
      const std::string column = std::to_string(6 + runner.max_drift_column());
      Plot plot{"ida.png",
                "IDA curves of " + std::to_string(runner.suite().records.size()) +
                  " records: largest peak drift ratio of all buildings against " + measure,
                "largest peak drift ratio of all buildings", measure, {}};
      plot.settings = "set xrange [0:*]\nset yrange [0:*]\n";
      for (std::size_t r = 0; r < runner.suite().records.size(); ++r)
        plot.series.push_back({"ida.csv",
                               "(($1 == " + std::to_string(r + 1) + " && $5 == 0) ? $" + column +
                                 " : 1/0):3",
                               runner.suite().records[r].name, "linespoints pt 7 ps 0.6 lc rgb 'gray'"});
      const char *levels[] = {"16 %", "50 %", "84 %"};
      for (unsigned int i = 0; i < 3; ++i)
        plot.series.push_back({"ida_fractiles.csv", std::to_string(2 + i) + ":1",
                               std::string(levels[i]) + " fractile", "lines lw 3"});
      if (runner.suite().records.size() > 12)
        for (std::size_t r = 0; r < runner.suite().records.size(); ++r)
          plot.series[r].title = "";
      return plot;
    }

    /// summary.json's records, measure and fragility; the report's lines.
    void
    write_summary(JsonWriter &json, std::ostream &out, const IdaRunner &runner,
                  const IdaResult &result, const IdaParameters &ida, const CollapseFragility &fit)
    {
      const std::string unit = intensity_unit(ida.measure);
      json.value("intensity_measure", intensity_measure_names().name(ida.measure))
        .value("unit", unit)
        .value("periods_s", runner.measure_periods())
        .value("damping_ratio", ida.damping_ratio)
        .value("upper_intensity", ida.upper_intensity)
        .value("tolerance", ida.tolerance)
        .value("runs", result.n_runs)
        .value("runs_now", result.n_run_now)
        .value("wall_time_s", result.wall_time);
      if (runner.suite().pairs())
        json.value("pair_measure", pair_measure_names().name(ida.pair));
      json.begin_array("records");
      for (std::size_t r = 0; r < result.records.size(); ++r)
        {
          const IdaRecordResult &record = result.records[r];
          const std::string     &name   = runner.suite().records[r].name;
          json.begin_object().value("name", name).value("suite_intensity", runner.base_intensities()[r])
            .value("runs", static_cast<unsigned long>(record.points.size()));
          if (record.collapse_intensity)
            json.value("collapse_intensity", *record.collapse_intensity)
              .value("highest_survived", record.highest_survived);
          else
            json.value("collapse", record.done ? "no collapse below the upper intensity" :
                                                 "not reached (interrupted)");
          json.end_object();
          out << name << ": "
              << (record.collapse_intensity ? "collapse at " + rounded(*record.collapse_intensity) + " " + unit :
                  record.done ? "no collapse below " + rounded(ida.upper_intensity) + " " + unit :
                                std::string("interrupted"))
              << " (" << record.points.size() << " runs)\n";
        }
      json.end_array();
      json.begin_object("collapse_fragility").value("fitted", fit.fitted)
        .value("collapsed", fit.n_collapsed).value("censored", fit.n_censored);
      if (fit.fitted)
        json.value("theta", fit.theta).value("beta", fit.beta);
      if (!fit.note.empty())
        json.value("note", fit.note);
      json.end_object();
      out << "collapse fragility: "
          << (fit.fitted ? "theta = " + rounded(fit.theta) + " " + unit + ", beta = " + rounded(fit.beta) :
                           fit.note)
          << "\n";
    }

    /// ida.csv, the journal's files (held in memory: what journal/ would
    /// hold), ida_records.csv, ida_fractiles.csv and collapse_fragility.csv;
    /// returns the collapse fragility fitted.
    CollapseFragility
    write_ida_tables(const CommandRun &run, const Analysis &analysis, const IdaRunner &runner,
                     const IdaResult &result)
    {
      const IdaParameters &ida   = run.input->ida;
      const double         upper = ida.upper_intensity;
      write_runs(run, runner, result);
      for (const auto &[name, text] : result.journals)
        write_result_text(run.memory, run.directory, "journal/" + name, text);
      const std::vector<double> &periods = runner.measure_periods();
      const double first = analysis.modes.omega.empty() ? 1.0 : 2 * M_PI / analysis.modes.omega[0];
      write_records(run, runner, ida.measure == IntensityMeasure::sa ? periods[0] : first,
                    ida.damping_ratio);
      write_fractiles(run, runner, result, upper);
      return write_fragility(run, result, upper);
    }

    /// The runs done, their rate and the files written, on the terminal.
    void
    print_ida_runs(const dealii::ConditionalOStream &out, const CommandRun &run,
                   const IdaResult &result, const bool demand_tables, const bool draws)
    {
      out << result.n_runs << " runs (" << result.n_run_now << " now, "
          << rounded(result.n_run_now / std::max(1e-9, result.wall_time)) << " runs/s); results in "
          << run.results_place() << " (summary.json, ida.csv, ida_records.csv, ida_fractiles.csv, "
          << "collapse_fragility.csv" << (demand_tables ? ", demands_*.csv" : "")
          << (draws ? ", ida.png" : "") << ", journal/)\n";
    }
  } // namespace

  int
  ida(const CommandRun &run)
  {
    const InputParameters     &input     = *run.input;
    const std::string         &directory = run.directory;
    const MPI_Comm             comm      = run.communicator;
    const unsigned int         rank      = dealii::Utilities::MPI::this_mpi_process(comm);
    dealii::ConditionalOStream pcout(run.out, rank == 0);
    dealii::TimerOutput timer(pcout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);

    timer.enter_subsection("set-up");
    const IdaParameters &ida = input.ida;
    if (ida.suite.empty())
      input.fail("IDA/Suite", "ida needs a record suite (a .csv, a .json or a folder of .AT2)");
    RecordSuite    suite    = read_record_suite(input.resolve(ida.suite), "IDA/Suite");
    const Analysis analysis = prepare_analysis(input);
    IdaRunner      runner(analysis, time_history_parameters(input), ida, std::move(suite));
    if (rank == 0 && !run.memory) // the rounds of an earlier run stay: it resumes from them
      prepare_output_directory(directory, {"realizations.csv"});
    timer.leave_subsection();

    timer.enter_subsection("runs");
    Progress progress(std::cerr, "IDA runs",
                      runner.suite().records.size() * static_cast<unsigned long>(ida.runs_per_record));
    // "": the journal in memory
    const IdaResult result = run_ida(runner, run.memory ? "" : directory + "/journal", comm, &progress);
    progress.finish();
    timer.leave_subsection();
    const int status = result.interrupted ? interrupted_exit_status() : 0;
    if (rank != 0)
      return status;

    timer.enter_subsection("output");
    if (result.interrupted)
      pcout << "ida interrupted after " << result.n_runs << " runs: the results are of these; "
            << "the same command runs the rest\n";
    const CollapseFragility fit = write_ida_tables(run, analysis, runner, result);
    JsonWriter json;
    begin_summary(json, "ida", input, result.interrupted ? "interrupted" : "completed");
    write_summary(json, run.out, runner, result, ida, fit);
    write_collapse_margin(runner, result, ida, json, run.out);
    std::vector<std::string> tables;
    write_ida_demand_tables(run, analysis.model, runner, result, ida, json, run.out, tables);
    json.end_object();
    const std::string measure = intensity_measure_names().name(ida.measure) + " (" +
                                intensity_unit(ida.measure) + ")";
    const bool draws = input.output.plots && !result.interrupted && !run.memory;
    if (draws)
      draw_plots(directory, {ida_plot(runner, measure)});
    write_result_text(run.memory, directory, "summary.json", json.str());
    timer.leave_subsection();
    print_ida_runs(pcout, run, result, !tables.empty(), draws);
    print_timing(timer);
    return status;
  }
} // namespace poundfe::commands
