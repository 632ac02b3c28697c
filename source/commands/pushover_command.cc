// `poundfe pushover`: the static pushover of the model after its gravity
// state (dynamics/pushover.h): pushover.csv (the curve, each storey's
// drift, each hinge's force and deformation), the equal-energy bilinear
// idealisation of the control building's curve and, with a Spectrum/Target,
// the N2 target displacement (dynamics/capacity_curve.h) and/or ASCE 41's
// (dynamics/asce41_target.h), summary.json and pushover.png (the curve, the
// idealisations and the targets); with fibre members, their limit states along the push and
// each storey's damage state at the target displacement. A push that cannot go on keeps the curve so far and exits 2.
#include <poundfe/commands/command.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/dynamics/asce41_target.h>
#include <poundfe/dynamics/capacity_curve.h>
#include <poundfe/dynamics/pushover.h>
#include <poundfe/excitation/response_spectrum.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>
#include <poundfe/report/run_summary.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>

namespace poundfe
{
  namespace
  {
    /// pushover.csv: one row per committed point; with fibre members each
    /// storey's damage state so far as its number in the order of
    /// damage_state_name (0 none, 1 yield, 2 spalling, 3 crushing, 4
    /// fracture).
    void
    write_pushover_csv(const CommandRun &run, const Model &model, const PushoverResult &r)
    {
      std::vector<std::string> header{"step", "load_factor", "control_displacement_m",
                                      "base_shear_N"};
      for (const Building &b : model.buildings)
        header.push_back("base_shear_" + b.name + "_N");
      for (const std::string &s : r.storeys)
        header.push_back("drift " + s);
      for (const std::string &e : r.elements)
        {
          header.push_back(e + " force");
          header.push_back(e + " deformation");
        }
      header.push_back("arc_length");
      if (!r.points.empty() && !r.points.front().storey_damage.empty()) // fibre members
        for (const std::string &s : r.storeys)
          header.push_back("damage_state " + s);
      const std::unique_ptr<TableWriter> csv =
        result_table_writer(run.memory, run.directory, "pushover", header);
      std::vector<double> row;
      for (unsigned int i = 0; i < r.points.size(); ++i)
        {
          const PushoverPoint &p = r.points[i];
          double total = 0;
          for (const double v : p.base_shears)
            total += v;
          row.assign({p.lambda, p.control_displacement, total});
          row.insert(row.end(), p.base_shears.begin(), p.base_shears.end());
          row.insert(row.end(), p.drifts.begin(), p.drifts.end());
          for (unsigned int e = 0; e < p.element_forces.size(); ++e)
            {
              row.push_back(p.element_forces[e]);
              row.push_back(p.element_deformations[e]);
            }
          row.push_back(p.arc_length);
          for (const int worst : p.storey_damage) // 0 none, 1 yield ... 4 fracture
            row.push_back(worst + 1);
          csv->add_row(i, row);
        }
      csv->commit();
    }

    /// The control building's first excursion from the start: its control
    /// displacement d and base shear V, both from (0, 0) and positive.
    void
    control_curve(const PushoverResult &r, const unsigned int building, std::vector<double> &d,
                  std::vector<double> &V)
    {
      const PushoverPoint &start = r.points.front();
      for (const PushoverPoint &p : r.points)
        {
          const double displacement = std::abs(p.control_displacement - start.control_displacement);
          if (!d.empty() && displacement < d.back())
            break; // the first excursion ends
          d.push_back(displacement);
          V.push_back(std::abs(p.base_shears[building] - start.base_shears[building]));
        }
    }
  } // namespace
} // namespace poundfe

namespace poundfe::commands
{
  namespace
  {
    /// The control building's curve, its idealisations and the targets
    /// the Target method asks for.
    struct Capacity
    {
      std::vector<double> d, V; // the first excursion (control_curve)
      BilinearCurve       ec8;  // of the equivalent system (d / Gamma, V / Gamma)
      bool                has_n2 = false, has_asce41 = false;
      N2Target            n2;
      Asce41Target        asce41;
      std::string         asce41_missing; // why ASCE 41 asked for has no target
    };

    /// Why the coefficient method cannot run on the curve (d, V) of `r`;
    /// empty where it can.
    std::string
    asce41_missing(const std::vector<double> &d, const std::vector<double> &V,
                   const PushoverResult &r, const DesignSpectrum target)
    {
      if (target == DesignSpectrum::none)
        return "no Spectrum/Target";
      if (d.size() < 2 || !(d.back() > 0))
        return "the push does not move the control node forward";
      if (!(r.first_period > 0))
        return "the control building's first period is not positive";
      const auto first_step = std::find_if(d.begin(), d.end(), [](const double x) { return x > 0; });
      if (!(V[first_step - d.begin()] > 0))
        return "the curve's first step has no positive stiffness";
      return "";
    }

    Capacity
    capacity_of(const InputParameters &input, const PushoverResult &r)
    {
      Capacity c;
      control_curve(r, input.pushover.control_building - 1, c.d, c.V);
      const SpectrumParameters &s = input.spectrum;
      const auto spectrum = [&s](const double period) { return s.target_psa(0.05, period); };
      if (input.pushover.asce41())
        c.asce41_missing = asce41_missing(c.d, c.V, r, s.target);
      c.has_asce41 = input.pushover.asce41() && c.asce41_missing.empty();
      if (c.has_asce41)
        {
          Asce41Building building;
          building.initial_period = r.first_period;
          building.c0             = r.first_mode_c0;
          building.mass           = r.building_mass;
          building.mass_factor    = input.pushover.effective_mass_factor;
          building.site_class     = input.pushover.site_class;
          c.asce41                = asce41_target(c.d, c.V, building, spectrum);
        }
      if (c.d.size() < 2)
        return c;
      std::vector<double> d_star, F_star;
      for (unsigned int i = 0; i < c.d.size(); ++i)
        {
          d_star.push_back(c.d[i] / r.gamma);
          F_star.push_back(c.V[i] / r.gamma);
        }
      c.ec8 = ec8_bilinear(d_star, F_star);
      if (s.target == DesignSpectrum::none || !(c.ec8.yield_force > 0))
        return c;
      c.has_n2 = input.pushover.n2() && c.ec8.yield_displacement > 0;
      if (c.has_n2)
        c.n2 = ec8_n2_target(c.ec8, r.equivalent_mass, r.gamma, spectrum,
                             ec8_ground_parameters(s.target, s.ground_type).TC);
      return c;
    }

    /// summary.json's "capacity" "asce41" and its lines of the report.
    void
    write_asce41(JsonWriter &json, const PushoverParameters &p, const PushoverResult &r,
                 const Asce41Target &t, std::ostream &out)
    {
      const Asce41Bilinear &b = t.bilinear;
      json.begin_object("asce41")
        .value("computed", true)
        .value("site_class", site_class_names().name(p.site_class))
        .value("site_factor_a", asce41_site_factor(p.site_class))
        .value("seismic_mass_kg", r.building_mass)
        .value("initial_period_s", r.first_period)
        .value("initial_stiffness_N_m", t.initial_stiffness)
        .value("yield_base_shear_N", b.yield_force)
        .value("yield_displacement_m", b.yield_displacement)
        .value("effective_stiffness_N_m", b.effective_stiffness)
        .value("post_yield_stiffness_ratio", b.post_yield_ratio)
        .value("idealisation_end_displacement_m", b.end_displacement)
        .value("idealisation_end_base_shear_N", b.end_force)
        .value("elastic_to_target", b.elastic)
        .value("effective_period_s", t.effective_period)
        .value("spectral_acceleration_m_s2", t.spectral_acceleration)
        .value("effective_mass_factor", t.mass_factor)
        .value("strength_ratio", t.strength_ratio)
        .value("C0", t.c0).value("C1", t.c1).value("C2", t.c2)
        .value("target_displacement_m", t.target)
        .value("iterations", t.iterations)
        .value("converged", t.converged)
        .value("target_beyond_curve", t.beyond_curve)
        .value("degrading_slope_ratio", t.degrading_slope_ratio) // null: the curve does not fall
        .value("max_strength_ratio", t.max_strength_ratio)
        .value("strength_ratio_exceeds_limit", t.exceeds_strength_limit)
        .end_object();
      out << "ASCE 41 target displacement: " << t.target << " m (T_e " << t.effective_period
          << " s, C0 " << t.c0 << ", C1 " << t.c1 << ", C2 " << t.c2 << ", mu_strength "
          << t.strength_ratio << ")\n";
      if (t.exceeds_strength_limit)
        out << "ASCE 41: mu_strength " << t.strength_ratio << " exceeds mu_max "
            << t.max_strength_ratio << " (strength degradation, 7.4.3.3.2): the nonlinear "
            << "static procedure does not apply; a nonlinear dynamic one is required\n";
      if (t.beyond_curve)
        out << "ASCE 41: the target lies beyond the push (" << r.points.back().control_displacement
            << " m): raise Pushover/Target drift\n";
      if (!t.converged)
        out << "ASCE 41: no fixed point of the target and its idealisation within the push: "
            << "delta_t - Delta_d jumps across zero at Delta_d = " << b.end_displacement
            << " m; the target given is delta_t there\n";
    }

    /// summary.json's "asce41" and a line of the report where ASCE 41 was
    /// asked for but has no target.
    void
    write_asce41_missing(JsonWriter &json, const std::string &why, std::ostream &out)
    {
      json.begin_object("asce41").value("computed", false).value("why", why).end_object();
      out << "ASCE 41 target displacement: not computed (" << why << ")\n";
    }

    /// summary.json's "capacity": the idealisation and the targets asked for.
    void
    write_capacity(JsonWriter &json, const PushoverResult &r, const PushoverParameters &p,
                   const Capacity &c, std::ostream &out)
    {
      if (c.d.size() < 2)
        {
          if (!c.asce41_missing.empty())
            {
              json.begin_object("capacity");
              write_asce41_missing(json, c.asce41_missing, out);
              json.end_object();
            }
          return;
        }
      json.begin_object("capacity")
        .value("gamma", r.gamma)
        .value("equivalent_mass_kg", r.equivalent_mass)
        .value("yield_force_N", c.ec8.yield_force)
        .value("yield_displacement_m", c.ec8.yield_displacement)
        .value("ultimate_displacement_m", c.ec8.ultimate_displacement)
        .value("energy_J", c.ec8.energy);
      out << "equivalent system: Gamma " << r.gamma << ", m* " << r.equivalent_mass
          << " kg, F_y* " << c.ec8.yield_force << " N, d_y* " << c.ec8.yield_displacement
          << " m\n";
      if (c.has_n2)
        {
          const N2Target &t = c.n2;
          json.value("period_s", t.period)
            .value("spectral_acceleration_m_s2", t.spectral_acceleration)
            .value("elastic_displacement_m", t.elastic_displacement)
            .value("reduction_factor", t.reduction)
            .value("target_displacement_sdof_m", t.target_sdof)
            .value("target_displacement_m", t.target);
          out << "N2 target displacement: " << t.target << " m (T* " << t.period << " s)\n";
        }
      if (c.has_asce41)
        write_asce41(json, p, r, c.asce41, out);
      else if (!c.asce41_missing.empty())
        write_asce41_missing(json, c.asce41_missing, out);
      json.end_object();
    }

    /// The target displacement the storeys' damage states are read at (m,
    /// from the start; NaN without one): N2's or ASCE 41's, the larger of
    /// the two when both are asked for; `method` names it.
    double
    governing_target(const Capacity &c, std::string &method)
    {
      double target = std::numeric_limits<double>::quiet_NaN();
      if (c.has_n2)
        {
          target = c.n2.target;
          method = "N2";
        }
      if (c.has_asce41 && !(c.asce41.target <= target))
        {
          target = c.asce41.target;
          method = "ASCE41";
        }
      return target;
    }

    /// pushover.png: the control building's curve (pushover.csv's column of
    /// its base shear), and the idealisations and targets asked for (drawn
    /// from the start of the push, along the first excursion).
    Plot
    capacity_plot(const PushoverResult &r, const Model &model, const unsigned int building,
                  const Capacity &c)
    {
      Plot plot{"pushover.png", "capacity curve", "control displacement (m)", "base shear (N)",
                {PlotSeries{"pushover.csv", "3:" + std::to_string(5 + building),
                            "base shear, " + model.buildings[building].name, "lines"}}};
      const PushoverPoint &start = r.points.front();
      const double sign = c.d.size() > 1 && r.points[c.d.size() - 1].control_displacement <
                                              start.control_displacement ? -1.0 : 1.0;
      std::ostringstream blocks, settings;
      blocks.precision(12);
      settings.precision(12);
      const auto polyline = [&](const std::string &name, const std::vector<double> &d,
                                const std::vector<double> &V, const std::string &title) {
        blocks << name << " << EOD\ndisplacement,shear\n";
        for (unsigned int i = 0; i < d.size(); ++i)
          blocks << start.control_displacement + sign * d[i] << ','
                 << start.base_shears[building] + sign * V[i] << '\n';
        blocks << "EOD\n";
        plot.series.push_back({name, "1:2", title, "lines dt 2 lw 2"});
      };
      const auto target_line = [&](const double target, const std::string &label,
                                   const double height) { // labels of near targets apart
        const double x = start.control_displacement + sign * target;
        settings << "set arrow from " << x << ", graph 0 to " << x << ", graph 1 nohead dt 3\n"
                 << "set label '" << label << "' at " << x << ", graph " << height
                 << " left offset 0.5, 0\n";
      };
      if (c.has_n2)
        {
          const double g = r.gamma; // Annex B's curve back on the building's axes
          polyline("$ec8", {0, g * c.ec8.yield_displacement, g * c.ec8.ultimate_displacement},
                   {0, g * c.ec8.yield_force, g * c.ec8.yield_force}, "EC8 idealisation");
          target_line(c.n2.target, "N2 target", 0.06);
        }
      if (c.has_asce41)
        {
          const Asce41Bilinear &b = c.asce41.bilinear;
          polyline("$asce41", {0, b.yield_displacement, b.end_displacement},
                   {0, b.yield_force, b.end_force}, "ASCE 41 idealisation");
          target_line(c.asce41.target, "ASCE 41 target", 0.14);
        }
      plot.data_blocks = blocks.str();
      plot.settings    = settings.str();
      return plot;
    }

    /// summary.json's "storey_damage_states": each storey's damage state
    /// (theory §13.5) at the first point of the first excursion whose
    /// displacement from the start reaches `target` (NaN, or not reached:
    /// the last point, said so by "at").
    void
    write_storey_damage(JsonWriter &json, const Model &model, const PushoverResult &r,
                        const double target, const std::string &method)
    {
      const double start = r.points.front().control_displacement;
      unsigned int at    = r.points.size() - 1;
      bool         found = false;
      for (unsigned int i = 0; i < r.points.size() && !std::isnan(target) && !found; ++i)
        if (std::abs(r.points[i].control_displacement - start) >= std::abs(target))
          {
            at    = i;
            found = true;
          }
      json.begin_object("storey_damage_states")
        .value("at", found ? "target displacement" : "end of the push")
        .value("target_method", method.empty() ? "none" : method)
        .value("point", at)
        .value("control_displacement_m", r.points[at].control_displacement);
      json.begin_array("buildings");
      unsigned int k = 0;
      for (const Building &b : model.buildings)
        {
          std::vector<std::string> states;
          for (unsigned int f = 0; f < b.floors.size(); ++f)
            states.push_back(damage_state_name(r.points[at].storey_damage[k++]));
          json.begin_object().value("building", b.name).value("storeys", states).end_object();
        }
      json.end_array().end_object();
    }
  } // namespace

  int
  pushover(const CommandRun &run)
  {
    const InputParameters &input    = *run.input;
    const Analysis         analysis = prepare_analysis(input);
    const PushoverResult   result =
      run_pushover(analysis, input.pushover, input, &input.section_limits);
    if (!run.memory)
      prepare_output_directory(run.directory);
    write_pushover_csv(run, analysis.model, result);
    if (!result.completed)
      throw NumericalError(result.failure);
    const Capacity           capacity = capacity_of(input, result);
    std::vector<std::string> figures; // none in memory
    if (input.output.plots && !run.memory)
      figures = draw_plots(run.directory, {capacity_plot(result, analysis.model,
                                                         input.pushover.control_building - 1,
                                                         capacity)});
    JsonWriter json;
    begin_summary(json, "pushover", input);
    write_model(json, analysis);
    json.value("control", result.control_name)
      .value("control_height_m", result.control_height)
      .value("points", static_cast<unsigned int>(result.points.size()))
      .value("iterations", result.iterations)
      .value("arc_length_steps", result.arc_length_steps)
      .value("step_cuts", result.step_cuts)
      .value("peak_base_shear_N", [&] {
        double peak = 0;
        for (const PushoverPoint &p : result.points)
          for (const double v : p.base_shears)
            peak = std::max(peak, std::abs(v));
        return peak;
      }());
    write_capacity(json, result, input.pushover, capacity, run.out);
    if (result.section_limits)
      {
        std::string  method;
        const double target = governing_target(capacity, method);
        result.section_limits->write_json(json, analysis.model, "first_control_displacement_m");
        write_storey_damage(json, analysis.model, result, target, method);
      }
    std::vector<std::string> files{"pushover.csv", "summary.json"};
    files.insert(files.end(), figures.begin(), figures.end());
    json.begin_object("output").value("directory", run.memory ? "" : run.directory)
      .value("files", files).end_object();
    json.end_object();
    write_result_text(run.memory, run.directory, "summary.json", json.str());
    run.out << result.points.size() << " points to the control displacement "
            << result.points.back().control_displacement << " m; results in "
            << run.results_place() << " (pushover.csv, summary.json"
            << (run.memory ? "" : ", pushover.png") << ")\n";
    return 0;
  }
} // namespace poundfe::commands
