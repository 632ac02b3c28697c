// `poundfe switching`: the Filippov switching analysis of a small model
// (integration/model_switching.h): every hit of a gap (g = 0), of a gap's
// rate in contact (the deepest penetration) and of a friction element's
// slip velocity (r' = 0), classified from the normal components of the
// fields on both sides as crossing, attracting sliding (stick), repulsive
// sliding, grazing or sliding exit; sliding by Filippov's convex method.
//   input:  the model, forces and initial conditions of a run; Time
//           integration/End time, Relative tolerance, Absolute tolerance,
//           Event resolution; Output/Output interval (the trajectory's samples)
//   output: switching.csv (the log, as the thesis's Tables 3.1 and 3.2),
//           trajectory.csv, summary.json (counts per surface, sliding
//           intervals), phase_portrait.png (equation 1, surfaces dashed,
//           sliding in red, the hits marked by class)
#include <poundfe/base/console.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/initial_conditions.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/integration/model_switching.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>
#include <poundfe/report/switching_plot.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <ostream>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// switching.csv: one row per hit, its state, surface, regions (-1, +1,
    /// 0: on the surface), h and the normal components a (side -), b (side +).
    void
    write_log(const ModelSwitching &analysis, const std::vector<SwitchingEvent> &events,
              const CommandRun &run)
    {
      const unsigned int n = analysis.n_equations();
      const std::string  path = run.directory + "/switching.csv";
      std::ostringstream csv;
      csv.precision(12);
      csv << "time_s";
      for (unsigned int i = 1; i <= n; ++i)
        csv << ",u_" << i;
      for (unsigned int i = 1; i <= n; ++i)
        csv << ",v_" << i;
      csv << ",surface,kind,region_before,region_after,h,normal_minus,normal_plus,class\n";
      for (const SwitchingEvent &e : events)
        {
          for (const double x : {e.time, e.value, e.normal_minus, e.normal_plus})
            if (!std::isfinite(x))
              throw_not_finite(x, "a switching event", path);
          csv << e.time;
          for (Eigen::Index i = 0; i < e.state.size(); ++i)
            csv << "," << e.state[i];
          csv << "," << analysis.system().switching_surfaces()[e.surface].name << ","
              << analysis.surface_kinds()[e.surface] << "," << e.region_before << ","
              << e.region_after << "," << e.value << "," << e.normal_minus << ","
              << e.normal_plus << "," << switching_class_name(e.kind) << "\n";
        }
      write_result_text(run.memory, run.directory, "switching.csv", csv.str());
    }

    /// trajectory.csv: the sampled state and the surface slid on (1-based; 0: none).
    void
    write_trajectory(const ModelSwitching &analysis, const CommandRun &run)
    {
      const unsigned int       n = analysis.n_equations();
      std::vector<std::string> header{"time_s"};
      for (unsigned int i = 1; i <= n; ++i)
        header.push_back("u_" + std::to_string(i));
      for (unsigned int i = 1; i <= n; ++i)
        header.push_back("v_" + std::to_string(i));
      header.push_back("sliding_surface");
      const std::unique_ptr<TableWriter> csv =
        result_table_writer(run.memory, run.directory, "trajectory", header);
      std::vector<double> row;
      for (const SwitchingSample &s : analysis.system().samples())
        {
          row.assign(s.state.data(), s.state.data() + s.state.size());
          row.push_back(s.sliding + 1);
          csv->add_row(s.time, row);
        }
      csv->commit();
    }

    struct SlidingInterval
    {
      std::string surface;
      double      entry = 0, exit = 0;
      bool        open  = false; // still sliding at the end
    };

    /// Each attracting sliding to its exit (or the end time).
    std::vector<SlidingInterval>
    sliding_intervals(const ModelSwitching &analysis, const std::vector<SwitchingEvent> &events,
                      const double t_end)
    {
      std::vector<SlidingInterval> intervals;
      for (const SwitchingEvent &e : events)
        {
          const std::string &name = analysis.system().switching_surfaces()[e.surface].name;
          if (e.kind == SwitchingClass::attracting_sliding)
            intervals.push_back({name, e.time, t_end, true});
          else if (e.kind == SwitchingClass::sliding_exit && !intervals.empty() &&
                   intervals.back().open)
            intervals.back().exit = e.time, intervals.back().open = false;
        }
      return intervals;
    }

    void
    write_summary(const InputParameters &input, const ModelSwitching &analysis,
                  const std::vector<SlidingInterval> &intervals, const double t_end,
                  const CommandRun &run)
    {
      JsonWriter json;
      begin_summary(json, "switching", input);
      json.value("end_time_s", t_end)
        .value("method", "Dormand-Prince 5(4), events located on the dense output; sliding by "
                         "Filippov's convex method (one surface at a time)")
        .value("classification", "a = n.f(side -), b = n.f(side +): a b > 0 crossing, "
                                 "a > 0 > b attracting sliding, a < 0 < b repulsive sliding, "
                                 "|a| or |b| <= 1e-8 max(|a|, |b|) grazing")
        .value("friction_on_the_surface",
               "mu_s for the two fields on the surface (the stick set), mu(r') in slip")
        .value("n_events", static_cast<unsigned long>(analysis.events().size()));
      json.begin_array("surfaces");
      for (const auto &[name, by_class] : analysis.counts())
        {
          json.begin_object().value("name", name);
          unsigned int total = 0;
          for (const auto &[kind, count] : by_class)
            json.value(kind, count), total += count;
          json.value("hits", total).end_object();
        }
      json.end_array().begin_array("sliding_intervals");
      for (const SlidingInterval &s : intervals)
        json.begin_object().value("surface", s.surface).value("entry_s", s.entry)
          .value("exit_s", s.exit).value("until_the_end", s.open).end_object();
      json.end_array().end_object();
      write_result_text(run.memory, run.directory, "summary.json", json.str());
    }

    /// The phase portrait of equation 1 (report/switching_plot.h), with the
    /// classes of hit that occurred and the unit of equation 1's DOF.
    void
    draw_phase_portrait(const ModelSwitching &analysis, const Model &model, const bool slides,
                        const std::string &directory)
    {
      std::set<std::string> classes;
      for (const auto &[surface, by_class] : analysis.counts())
        for (const auto &[kind, count] : by_class)
          if (count > 0)
            classes.insert(kind);
      const std::vector<int> &equation_of = model.equations();
      const auto first = std::find(equation_of.begin(), equation_of.end(), 0);
      const bool rotation = first != equation_of.end() &&
                            (first - equation_of.begin()) % n_dofs_per_node ==
                              static_cast<unsigned int>(Component::rz);
      draw_plots(directory, {switching_phase_portrait(analysis.system().switching_surfaces(),
                                                      analysis.n_equations(), classes, slides,
                                                      rotation)});
    }

    /// The end of the switching analysis: Time integration/End time, or
    /// the ground motion's duration when that is not given.
    double
    switching_end_time(const InputParameters &input, const TimeHistoryParameters &parameters,
                       const Excitation &excitation)
    {
      const double t_end = parameters.time_integration.end_time > 0 ?
                             parameters.time_integration.end_time :
                             excitation.ground_motion().duration();
      if (!(t_end > 0))
        input.fail("Time integration/End time", "needs a positive end time when there is no "
                                                "ground motion");
      return t_end;
    }

    /// The Filippov integrator's tolerances, those of the Dormand-Prince
    /// parameters, sampled at the output interval (the Newmark step if none).
    FilippovParameters
    filippov_parameters(const InputParameters &input, const TimeHistoryParameters &parameters,
                        const DormandPrinceParameters &dopri)
    {
      FilippovParameters filippov;
      filippov.relative_tolerance = dopri.relative_tolerance;
      filippov.absolute_tolerance = dopri.absolute_tolerance;
      filippov.event_resolution   = dopri.event_resolution;
      filippov.sample_interval    = input.output.interval > 0 ?
                                      input.output.interval :
                                      parameters.time_integration.newmark.time_step;
      return filippov;
    }

    /// switching.csv and trajectory.csv in a fresh output directory.
    void
    write_hits_and_trajectory(const ModelSwitching &analysis,
                              const std::vector<SwitchingEvent> &events, const CommandRun &run)
    {
      if (!run.memory)
        prepare_output_directory(run.directory);
      write_log(analysis, events, run);
      write_trajectory(analysis, run);
    }

    /// The hits by surface and class, the sliding intervals and the files
    /// written, on the terminal.
    void
    print_hits(const ModelSwitching &analysis, const std::vector<SwitchingEvent> &events,
               const std::vector<SlidingInterval> &intervals, const double t_end,
               const CommandRun &run)
    {
      run.out << "poundfe switching: " << events.size() << " hits in [0, " << t_end << "] s\n";
      for (const auto &[name, by_class] : analysis.counts())
        {
          run.out << "  " << name << ":";
          for (const auto &[kind, count] : by_class)
            run.out << " " << kind << " " << count;
          run.out << (by_class.empty() ? " none\n" : "\n");
        }
      for (const SlidingInterval &s : intervals)
        run.out << "  sliding on " << s.surface << " from " << s.entry << " s to " << s.exit
                << " s" << (s.open ? " (the end)" : "") << "\n";
      run.out << "results in " << run.results_place()
              << " (switching.csv, trajectory.csv, summary.json"
              << (run.memory ? "" : ", phase_portrait.png") << ")\n";
    }
  } // namespace
} // namespace poundfe

namespace poundfe::commands
{
  int
  switching(const CommandRun &run)
  {
    const InputParameters &input = *run.input;
    dealii::TimerOutput timer(run.out, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
    timer.enter_subsection("model");
    const Analysis              analysis   = prepare_analysis(input);
    const TimeHistoryParameters parameters = time_history_parameters(input);
    const Excitation            excitation = make_excitation(analysis, input);
    NonlinearElements           elements   = make_nonlinear_elements(analysis.model);
    const DormandPrinceParameters dopri    = parameters.time_integration.dormand_prince();
    if (const std::string why = ModelSwitching::unsupported(analysis.system, analysis.model,
                                                            elements, dopri.max_equations);
        !why.empty())
      input.fail("Model/Number of buildings", "the switching analysis " + why);
    const double       t_end = switching_end_time(input, parameters, excitation);
    const InitialState initial =
      initial_state(parameters.initial_conditions, analysis.model, parameters.input);
    ModelSwitching switching_analysis(
      analysis.system, analysis.model, elements,
      [&excitation](const double t, Vector &p) { excitation.load(t, p); },
      filippov_parameters(input, parameters, dopri));
    timer.leave_subsection();

    timer.enter_subsection("integration");
    try
      {
        switching_analysis.run(initial.displacement, initial.velocity, t_end);
      }
    catch (const NumericalError &)
      {
        // the hits and the trajectory up to the failure are results: kept,
        // and the guard's summary.json says "failed" with the reason
        write_hits_and_trajectory(switching_analysis, switching_analysis.events(), run);
        throw;
      }
    timer.leave_subsection();

    timer.enter_subsection("output");
    const std::vector<SwitchingEvent> events = switching_analysis.events();
    const auto intervals = sliding_intervals(switching_analysis, events, t_end);
    write_hits_and_trajectory(switching_analysis, events, run);
    write_summary(input, switching_analysis, intervals, t_end, run);
    if (input.output.plots && !run.memory)
      draw_phase_portrait(switching_analysis, analysis.model, !intervals.empty(), run.directory);
    timer.leave_subsection();

    print_hits(switching_analysis, events, intervals, t_end, run);
    print_timing(timer);
    return 0;
  }
} // namespace poundfe::commands
