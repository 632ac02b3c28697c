// `poundfe bifurcation`: Poincare samples, periods and Lyapunov exponents
// against a parameter (dynamics/bifurcation.h).
//   points: every value's input read and checked, then each value run
//           (input/bifurcation_input.h)
//   output: bifurcation.csv, bifurcation_classification.csv, summary.json,
//           bifurcation.png; the console report
#include <poundfe/base/console.h>
#include <poundfe/base/interruption.h>
#include <poundfe/commands/command.h>
#include <poundfe/input/bifurcation_input.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <ostream>

namespace poundfe
{
  namespace
  {
    /// "m", "m/s", "rad" or "rad/s".
    std::string
    response_unit(const BifurcationParameters &b)
    {
      const bool rotation = b.response.find("rz") != std::string::npos;
      return std::string(rotation ? "rad" : "m") + (b.quantity == "velocity" ? "/s" : "");
    }

    /// The response's CSV column: "displacement_m", "velocity_rad_s", ...
    std::string
    response_column(const BifurcationParameters &b)
    {
      std::string unit = response_unit(b);
      std::replace(unit.begin(), unit.end(), '/', '_');
      return b.quantity + "_" + unit;
    }

    void
    write_tables(const InputParameters &input, const std::vector<BifurcationPoint> &points,
                 const CommandRun &run)
    {
      const BifurcationParameters &b = input.bifurcation;
      const std::string x = b.sweep.column_name();
      const std::unique_ptr<TableWriter> samples = result_table_writer(
        run.memory, run.directory, "bifurcation", {x, "sample", response_column(b)});
      const std::unique_ptr<TableWriter> classes =
        result_table_writer(run.memory, run.directory, "bifurcation_classification",
                            {x, "period", "lyapunov_exponent_1_s", "forcing_period_s",
                             "time_step_s", "response_range", "completed"});
      for (const BifurcationPoint &point : points)
        {
          for (std::size_t k = 0; k < point.samples.size(); ++k)
            samples->add_row(point.value, {double(k + 1), point.samples[k]});
          classes->add_row(point.value, {double(point.period), point.lyapunov_exponent,
                                         point.forcing_period, point.time_step,
                                         point.response_range, point.completed ? 1.0 : 0.0});
        }
      samples->commit();
      classes->commit();
    }

    /// summary.json: the settings, how time was stepped, and per value the
    /// period (0: non-periodic) and the Lyapunov exponent.
    void
    write_summary(const InputParameters &input, const std::vector<BifurcationPoint> &points,
                  const CommandRun &run, const double wall_time, const bool interrupted)
    {
      const BifurcationParameters &b = input.bifurcation;
      std::vector<double> values, periods, exponents, forcing, steps;
      bool                all = true;
      for (const BifurcationPoint &point : points)
        {
          values.push_back(point.value), periods.push_back(point.period);
          exponents.push_back(point.lyapunov_exponent), forcing.push_back(point.forcing_period);
          steps.push_back(point.time_step), all = all && point.completed;
        }
      JsonWriter json;
      begin_summary(json, "bifurcation", input,
                    interrupted ? "interrupted" : all ? "completed" : "failed");
      json.value("parameter", b.sweep.parameter).value("response", b.response)
        .value("response_quantity", b.quantity).value("transient_periods", b.transient_periods)
        .value("sampled_periods", b.sampled_periods)
        .value("time_step_rule", "dt = T / round(T / dt_input): steps land on every k T, "
                                 "no interpolation")
        .value("period_rule", "smallest n <= 16 with |x_{k+n} - x_k| <= tolerance * range "
                              "for every sample; 0: non-periodic")
        .value("period_tolerance", b.period_tolerance)
        .value("continuation", b.continuation)
        .value("lyapunov_exponent", b.lyapunov_exponent)
        .value("lyapunov_method", "Benettin two-trajectory, renormalised every period, "
                                  "d0 = perturbation * |(u, v / omega)|")
        .value("perturbation", b.perturbation).value("wall_time_s", wall_time)
        .value("values", values).value("periods", periods).value("lyapunov_exponents_1_s", exponents)
        .value("forcing_periods_s", forcing).value("time_steps_s", steps).end_object();
      write_result_text(run.memory, run.directory, "summary.json", json.str());
    }

    /// The diagram (Poincaré samples as dots against the value) with the
    /// Lyapunov exponent in a panel under it.
    void
    draw_diagram(const InputParameters &input, const std::string &directory)
    {
      const BifurcationParameters &b = input.bifurcation;
      const std::string label = b.quantity + " (" + response_unit(b) + ")";
      Plot diagram{"bifurcation.png", "bifurcation diagram: Poincare samples of " + b.response +
                                        " " + b.quantity, b.sweep.axis_label(), label,
                   {{"bifurcation.csv", "1:3", "x(kT)", "points pt 7 ps 0.3"}}};
      if (b.lyapunov_exponent)
        diagram.below.push_back(Plot{"", "largest Lyapunov exponent", b.sweep.axis_label(),
                                     "lambda (1/s)",
                                     {{"bifurcation_classification.csv", "1:3", "lambda",
                                       "linespoints"}}});
      draw_plots(directory, {diagram});
    }
  } // namespace

} // namespace poundfe

namespace poundfe::commands
{
  int
  bifurcation(const CommandRun &run)
  {
    const InputParameters       &input = *run.input;
    const BifurcationParameters &b     = input.bifurcation;
    dealii::TimerOutput timer(run.out, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);

    timer.enter_subsection("points");
    const std::vector<BifurcationPoint> points = bifurcation_points(input);
    timer.leave_subsection();
    const double wall_time =
      timer.get_summary_data(dealii::TimerOutput::total_wall_time).at("points");
    // SIGINT/SIGTERM stop between values: the values finished are written
    // (status "interrupted"), as a Monte Carlo writes its realizations.
    const bool interrupted = interruption_requested();

    timer.enter_subsection("output");
    if (!run.memory)
      prepare_output_directory(run.directory);
    write_tables(input, points, run);
    write_summary(input, points, run, wall_time, interrupted);
    if (input.output.plots && !points.empty() && !run.memory)
      draw_diagram(input, run.directory);
    timer.leave_subsection();
    if (interrupted)
      {
        run.err << "poundfe: bifurcation interrupted ("
                << (run.memory ? "the summary" : run.directory + "/summary.json")
                << " says interrupted): " << points.size() << " of "
                << b.sweep.values().size() << " values kept in bifurcation.csv\n";
        return interrupted_exit_status();
      }

    const auto n_failed = std::count_if(points.begin(), points.end(),
                                        [](const BifurcationPoint &p) { return !p.completed; });
    run.out << "poundfe bifurcation: " << points.size() << " values of " << b.sweep.parameter
            << " in " << wall_time << " s\nresults in " << run.results_place()
            << " (bifurcation.csv, bifurcation_classification.csv, summary.json"
            << (run.memory ? "" : ", bifurcation.png") << ")\n";
    print_timing(timer);
    if (n_failed > 0)
      {
        run.err << "poundfe: numerical failure at " << n_failed
                << " values (completed = 0 in bifurcation_classification.csv)\n";
        return 2;
      }
    return 0;
  }
} // namespace poundfe::commands
