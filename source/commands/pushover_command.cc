// `poundfe pushover`: the static pushover of the model after its gravity
// state (dynamics/pushover.h): pushover.csv (the curve, each storey's
// drift, each hinge's force and deformation), the equal-energy bilinear
// idealisation of the control building's curve and, with a Spectrum/Target,
// the N2 target displacement (dynamics/capacity_curve.h), summary.json and
// pushover.png; with fibre members, their limit states along the push and
// each storey's damage state at the target displacement. A push that cannot go on keeps the curve so far and exits 2.
#include <poundfe/commands/command.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/dynamics/capacity_curve.h>
#include <poundfe/dynamics/pushover.h>
#include <poundfe/excitation/response_spectrum.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>
#include <poundfe/report/run_summary.h>

#include <cmath>
#include <limits>
#include <ostream>

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

    /// The control building's first excursion as the equivalent system's
    /// curve (d*, F*), from (0, 0).
    void
    sdof_curve(const PushoverResult &r, const unsigned int building, std::vector<double> &d,
               std::vector<double> &F)
    {
      const double start = r.points.front().control_displacement;
      for (const PushoverPoint &p : r.points)
        {
          const double displacement = (p.control_displacement - start) / r.gamma;
          if (!d.empty() && std::abs(displacement) < std::abs(d.back()))
            break; // the first excursion ends
          d.push_back(std::abs(displacement));
          F.push_back(std::abs(p.base_shears[building] - r.points.front().base_shears[building]) /
                      r.gamma);
        }
    }
  } // namespace
} // namespace poundfe

namespace poundfe::commands
{
  namespace
  {
    /// summary.json's "capacity": the idealisation and the N2 target; the
    /// target displacement (m, from the start; NaN without one).
    double
    write_capacity(JsonWriter &json, const InputParameters &input, const PushoverResult &r,
                   std::ostream &out)
    {
      double              target = std::numeric_limits<double>::quiet_NaN();
      std::vector<double> d, F;
      sdof_curve(r, input.pushover.control_building - 1, d, F);
      if (d.size() < 2)
        return target;
      const BilinearCurve bilinear = ec8_bilinear(d, F);
      json.begin_object("capacity")
        .value("gamma", r.gamma)
        .value("equivalent_mass_kg", r.equivalent_mass)
        .value("yield_force_N", bilinear.yield_force)
        .value("yield_displacement_m", bilinear.yield_displacement)
        .value("ultimate_displacement_m", bilinear.ultimate_displacement)
        .value("energy_J", bilinear.energy);
      out << "equivalent system: Gamma " << r.gamma << ", m* " << r.equivalent_mass
          << " kg, F_y* " << bilinear.yield_force << " N, d_y* " << bilinear.yield_displacement
          << " m\n";
      const SpectrumParameters &s = input.spectrum;
      if (s.target != DesignSpectrum::none && bilinear.yield_force > 0 &&
          bilinear.yield_displacement > 0)
        {
          const double   tc = ec8_ground_parameters(s.target, s.ground_type).TC;
          const N2Target t  = ec8_n2_target(
            bilinear, r.equivalent_mass, r.gamma,
            [&s](const double period) { return s.target_psa(0.05, period); }, tc);
          json.value("period_s", t.period)
            .value("spectral_acceleration_m_s2", t.spectral_acceleration)
            .value("elastic_displacement_m", t.elastic_displacement)
            .value("reduction_factor", t.reduction)
            .value("target_displacement_sdof_m", t.target_sdof)
            .value("target_displacement_m", t.target);
          out << "N2 target displacement: " << t.target << " m (T* " << t.period << " s)\n";
          target = t.target;
        }
      json.end_object();
      return target;
    }

    /// summary.json's "storey_damage_states": each storey's damage state
    /// (theory §13.5) at the first point of the first excursion whose
    /// displacement from the start reaches `target` (NaN, or not reached:
    /// the last point, said so by "at").
    void
    write_storey_damage(JsonWriter &json, const Model &model, const PushoverResult &r,
                        const double target)
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
    std::vector<std::string> figures; // none in memory
    if (input.output.plots && !run.memory)
      figures = draw_plots(
        run.directory, {Plot{"pushover.png", "capacity curve", "control displacement (m)",
                             "base shear (N)",
                             {PlotSeries{"pushover.csv", "3:4", "base shear", "lines"}}}});
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
    const double target = write_capacity(json, input, result, run.out);
    if (result.section_limits)
      {
        result.section_limits->write_json(json, analysis.model, "first_control_displacement_m");
        write_storey_damage(json, analysis.model, result, target);
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
