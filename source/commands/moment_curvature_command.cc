// `poundfe moment-curvature`: the moment–curvature curve of one section of
// the Sections section under the constant axial force of the Moment
// curvature section (sections/moment_curvature.h): moment_curvature.csv,
// summary.json (first yield, peak, ultimate, ductility, the events) and
// moment_curvature.png.
#include <poundfe/base/console.h>
#include <poundfe/commands/command.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <vector>

namespace poundfe
{
  namespace
  {
    void
    write_curve(const MomentCurvatureResult &result, const std::string &directory)
    {
      CsvWriter csv(directory + "/moment_curvature.csv",
                    {"curvature_1_m", "moment_N_m", "axial_strain", "concrete_strain_min",
                     "steel_strain_max", "steel_strain_min", "tangent_N_m2", "moment_z_N_m",
                     "moment_y_N_m"});
      for (const MomentCurvaturePoint &p : result.points)
        csv.add_row(p.curvature, {p.moment, p.axial_strain, p.concrete_strain, p.steel_strain_max,
                                  p.steel_strain_min, p.tangent, p.moment_z, p.moment_y});
      csv.commit();
    }

    void
    write_point(JsonWriter &json, const std::string &key, const MomentCurvaturePoint &p)
    {
      json.begin_object(key)
        .value("curvature_1_m", p.curvature)
        .value("moment_N_m", p.moment)
        .value("axial_strain", p.axial_strain)
        .value("concrete_strain_min", p.concrete_strain)
        .value("steel_strain_max", p.steel_strain_max)
        .end_object();
    }

    void
    write_moment_curvature_summary(const InputParameters &input, const MomentCurvatureResult &r,
                                   const unsigned int n_fibres, const std::string &directory)
    {
      const MomentCurvatureParameters &m = input.moment_curvature;
      JsonWriter                       json;
      begin_summary(json, "moment-curvature", input);
      json.value("section", m.section)
        .value("fibres", n_fibres)
        .value("axial_force_N", m.settings.axial_force)
        .value("angle_deg", m.settings.angle)
        .value("stop_reason", r.stop_reason);
      if (r.yielded)
        write_point(json, "first_yield", r.first_yield);
      write_point(json, "peak", r.peak);
      write_point(json, "ultimate", r.ultimate);
      json.value("curvature_ductility", r.ductility());
      json.begin_array("events");
      for (const MomentCurvatureEvent &e : r.events)
        json.begin_object()
          .value("what", e.what)
          .value("curvature_1_m", e.at.curvature)
          .value("moment_N_m", e.at.moment)
          .end_object();
      json.end_array().end_object();
      write_file_atomically(directory + "/summary.json", json.str());
    }

    void
    draw_moment_curvature(const MomentCurvatureResult &r, const std::string &section,
                          const std::string &directory)
    {
      Plot plot{"moment_curvature.png", "moment-curvature of section " + section,
                "curvature (1/m)", "moment (kN m)",
                {{"moment_curvature.csv", "1:($2/1000)", "M(kappa)", "lines lw 2 lc rgb 'black'"}}};
      std::string marks = "set datafile separator ','\n";
      // events at (nearly) the same point: one label a line below the other
      std::vector<const MomentCurvaturePoint *> placed;
      for (const MomentCurvatureEvent &e : r.events)
        {
          const auto near = [&](const MomentCurvaturePoint *p) {
            return std::abs(p->curvature - e.at.curvature) <= 0.15 * r.ultimate.curvature &&
                   std::abs(p->moment - e.at.moment) <= 0.1 * std::abs(r.peak.moment);
          };
          const long   below = std::count_if(placed.begin(), placed.end(), near);
          const bool   right = e.at.curvature > 0.6 * r.ultimate.curvature;
          const std::string dy = std::to_string(-1 - 1.2 * below);
          marks += "set label '" + e.what + "' at first " + std::to_string(e.at.curvature) +
                   ", first " + std::to_string(e.at.moment / 1000) + " point pt 7 " +
                   (right ? "right offset -1," : "offset 1,") + dy + "\n";
          placed.push_back(&e.at);
        }
      plot.settings = marks;
      draw_plots(directory, {plot});
    }

    void
    print_moment_curvature(const MomentCurvatureResult &r, std::ostream &out)
    {
      char line[200];
      const auto row = [&](const char *what, const MomentCurvaturePoint &p) {
        std::snprintf(line, sizeof(line), "  %-12s curvature %11.5g 1/m  moment %11.5g kN m\n",
                      what, p.curvature, p.moment / 1000);
        out << line;
      };
      if (r.yielded)
        row("first yield", r.first_yield);
      row("peak", r.peak);
      row("ultimate", r.ultimate);
      out << "  (" << r.stop_reason << "); curvature ductility " << r.ductility() << "\n";
      for (const MomentCurvatureEvent &e : r.events)
        {
          std::snprintf(line, sizeof(line), "  event: %s at %.5g 1/m, %.5g kN m\n", e.what.c_str(),
                        e.at.curvature, e.at.moment / 1000);
          out << line;
        }
    }
  } // namespace
} // namespace poundfe

namespace poundfe::commands
{
  int
  moment_curvature(const CommandRun &run)
  {
    const InputParameters           &input = *run.input;
    const MomentCurvatureParameters &m     = input.moment_curvature;
    dealii::TimerOutput timer(run.out, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);
    timer.enter_subsection("analysis");
    unsigned int                n_fibres = 0;
    const MomentCurvatureResult result   = m.run(input, input.sections, n_fibres);
    timer.leave_subsection();

    timer.enter_subsection("output");
    prepare_output_directory(run.directory);
    write_curve(result, run.directory);
    write_moment_curvature_summary(input, result, n_fibres, run.directory);
    if (input.output.plots)
      draw_moment_curvature(result, m.section, run.directory);
    timer.leave_subsection();

    run.out << "poundfe moment-curvature: section " << m.section << ", "
            << n_fibres << " fibres, N = " << m.settings.axial_force
            << " N\n";
    print_moment_curvature(result, run.out);
    run.out << "results in " << run.directory
            << "/ (moment_curvature.csv, summary.json, moment_curvature.png)\n";
    print_timing(timer);
    return 0;
  }
} // namespace poundfe::commands
