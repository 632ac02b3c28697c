#include <poundfe/analysis/run.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/excitation/stochastic_load.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/floor_response.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/plots.h>
#include <poundfe/output/vtu_series.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

namespace poundfe
{
  namespace
  {
    const char *
    type_name(const BuildingType type)
    {
      switch (type)
        {
          case BuildingType::frame:
            return "frame";
          case BuildingType::mesh:
            return "mesh";
          default:
            return "shear";
        }
    }

    void
    write_modes(JsonWriter &json, const std::string &key, const Modes &modes)
    {
      std::vector<double> f, T;
      for (unsigned int i = 0; i < modes.n_modes(); ++i)
        {
          f.push_back(modes.frequency(i));
          T.push_back(modes.period(i));
        }
      json.begin_object(key)
        .value("frequencies_hz", f)
        .value("periods_s", T)
        .value("participating_mass_ratio_x", modes.participating_mass_ratio)
        .end_object();
    }

    void
    write_model(JsonWriter &json, const Analysis &analysis)
    {
      const Model &model = analysis.model;
      json.begin_object("model")
        .value("nodes", model.n_nodes())
        .value("dofs", model.n_dofs())
        .value("equations", model.n_equations())
        .value("members", static_cast<unsigned int>(model.members.size()))
        .value("storey_links", static_cast<unsigned int>(model.links.size()))
        .value("buildings", static_cast<unsigned int>(model.buildings.size()))
        .end_object();
      write_modes(json, "modes", analysis.modes);
    }

    unsigned int
    steps_per_interval(const double interval, const double dt)
    {
      return interval <= 0 ? 1 : std::max(1u, static_cast<unsigned int>(std::lround(interval / dt)));
    }

    const char *
    component_name(const unsigned int c)
    {
      return c == 0 ? "ux" : (c == 1 ? "uy" : "rz");
    }

    /// "A3 node 12 (6, 3) rz" for each equation (the first DOF that maps to it).
    std::vector<std::string>
    equation_names(const Model &model)
    {
      std::vector<std::string> names(model.n_equations());
      for (unsigned int dof = 0; dof < model.n_dofs(); ++dof)
        {
          const int eq = model.equation(dof);
          if (eq < 0 || !names[eq].empty())
            continue;
          const Node        &node = model.nodes[dof / n_dofs_per_node];
          std::ostringstream s;
          s << model.buildings[node.building].name << " node " << dof / n_dofs_per_node
            << " at (" << node.position.x << ", " << node.position.y << ") "
            << component_name(dof % n_dofs_per_node);
          names[eq] = s.str();
        }
      return names;
    }

    const char *
    kind_name(const ElementKind kind)
    {
      return kind == ElementKind::hinge ? "hinge" : (kind == ElementKind::storey ? "storey" : "gap");
    }

    double
    end_time_of(const InputParameters &input, const Excitation &excitation)
    {
      if (input.end_time > 0)
        return input.end_time;
      return excitation.ground_motion().duration();
    }

    /// `ground-motion --realizations N`: the samples of realizations 0..N-1
    /// and their ensemble PSD against the target.
    int
    ensemble_command(const InputParameters &input, const std::string &directory,
                     const unsigned int n_realizations)
    {
      const std::string &type = input.ground_motion.type;
      if (type != "kanai-tajimi" && type != "clough-penzien" && type != "white-noise")
        throw InputError(input.file, input.line_of("Ground motion/Type"), "Ground motion/Type",
                         "--realizations needs a stochastic ground motion, got '" + type + "'");
      const MotionGenerator generator = make_motion_generator(input);
      const double          scale     = input.ground_motion.scale_factor;
      create_directories(directory);
      std::vector<std::string> header{"time"};
      for (unsigned int r = 0; r < n_realizations; ++r)
        header.push_back("realization_" + std::to_string(r));
      std::vector<std::vector<double>> samples(n_realizations);
      std::vector<double>              xi(generator.n_variables());
      double                           variance = 0;
      for (unsigned int r = 0; r < n_realizations; ++r)
        {
          standard_normals(generator.motion().seed, r, xi);
          generator.generate(xi.data(), samples[r]);
          for (double &a : samples[r])
            a *= scale, variance += a * a / (n_realizations * generator.n_samples());
        }
      CsvWriter csv(directory + "/ground_motion_samples.csv", header);
      for (unsigned int k = 0; k < generator.n_samples(); ++k)
        {
          csv.begin_row(k * generator.motion().sample_interval);
          for (unsigned int r = 0; r < n_realizations; ++r)
            csv.add(samples[r][k]);
          csv.end_row();
        }
      csv.commit();
      // about 200 points up to 10 omega_g (filtered) or the cutoff (white noise)
      const double top = type == "white-noise" ?
                           generator.cutoff_frequency() :
                           std::min(generator.cutoff_frequency(), 10 * generator.motion().filter.omega_g);
      const double dw  = 2 * M_PI / (generator.n_samples() * generator.motion().sample_interval);
      const unsigned int band = std::max(1u, static_cast<unsigned int>(top / dw / 200));
      const EnsemblePsd  psd  = ensemble_psd(generator, n_realizations, band, top);
      CsvWriter          out(directory + "/ensemble_psd.csv",
                             {"omega", "estimated_psd", "target_psd", "ratio"});
      for (std::size_t i = 0; i < psd.omega.size(); ++i)
        {
          out.begin_row(psd.omega[i]);
          out.add(psd.estimate[i] * scale * scale);
          out.add(psd.target[i] * scale * scale);
          out.add(psd.estimate[i] / psd.target[i]);
          out.end_row();
        }
      out.commit();
      if (input.plots)
        draw_plots(directory,
                   {Plot{"ensemble_psd.png",
                         "ensemble PSD of " + std::to_string(n_realizations) + " realizations",
                         "omega (rad/s)", "two-sided PSD (m^2/s^3)",
                         {{"ensemble_psd.csv", "1:2", "estimate", "lines"},
                          {"ensemble_psd.csv", "1:3", "target", "lines"}}, true},
                    Plot{"ground_motion_samples.png", generator.description(), "time (s)",
                         "ground acceleration (m/s^2)",
                         {{"ground_motion_samples.csv", "1:2", "realization 0", "lines"}}}});
      std::cout << n_realizations << " realizations of " << generator.description()
                << ": " << generator.n_samples() << " samples each, " << generator.n_variables()
                << " random variables; ensemble mean square " << variance << " m^2/s^4\n"
                << "written to " << directory << "/ground_motion_samples.csv and ensemble_psd.csv\n";
      return 0;
    }
  } // namespace

  NewmarkParameters
  newmark_parameters(const InputParameters &input)
  {
    NewmarkParameters p;
    p.time_step                 = input.time_step;
    p.gamma                     = input.newmark_gamma;
    p.beta                      = input.newmark_beta;
    p.newton.residual_tolerance = input.newton_residual_tolerance;
    p.newton.energy_tolerance   = input.newton_energy_tolerance;
    p.newton.max_iterations     = input.newton_max_iterations;
    p.newton.max_step_cuts      = input.max_step_cuts;
    p.newton.tangent_update     = input.tangent_update;
    p.newton.event_refinement   = input.contact.event_refinement;
    return p;
  }

  Excitation
  make_excitation(const Analysis &analysis)
  {
    Excitation excitation(analysis.system, make_ground_motion(analysis.input),
                          make_nodal_forces(analysis.input, analysis.model));
    if (!analysis.input.white_noise_forces.empty())
      {
        const StochasticLoad load(analysis.input, excitation);
        std::vector<double>  xi;
        load.standard_normals(analysis.input.ground_motion.realization, xi);
        load.apply(xi, excitation);
      }
    return excitation;
  }

  TimeHistory::TimeHistory(const Analysis &analysis_, const std::string &linear_solver)
    : analysis(analysis_)
    , elements(make_nonlinear_elements(analysis_.model))
    , integrator(analysis_.system,
                 linear_solver.empty() ? analysis_.input.linear_solver : linear_solver,
                 newmark_parameters(analysis_.input), &elements)
  {
    integrator.set_equation_names(equation_names(analysis_.model));
  }

  RunResult
  run_time_history(const Analysis &analysis, const Excitation &excitation,
                   const RunOptions &options)
  {
    return TimeHistory(analysis, options.linear_solver).run(excitation, options);
  }

  RunResult
  TimeHistory::run(const Excitation &excitation, const RunOptions &options)
  {
    const InputParameters &input = analysis.input;
    const Model           &model = analysis.model;
    const double           dt    = input.time_step;
    const double           end   = end_time_of(input, excitation);
    if (!(end > 0))
      throw InputError(input.file, input.line_of("Time integration/End time"),
                       "Time integration/End time",
                       "needs a positive end time when there is no ground motion");
    const unsigned long n_steps = static_cast<unsigned long>(std::llround(end / dt));

    Vector load(analysis.system.n_equations());
    excitation.load(0, load);
    integrator.initialize(load);
    const LoadFunction load_at = [&excitation](const double t, Vector &p) { excitation.load(t, p); };

    const unsigned int  n_elements = elements.size();
    // elements are hinges and storeys first, then gaps
    unsigned int n_hysteretic = 0;
    while (n_hysteretic < n_elements && elements[n_hysteretic].kind != ElementKind::gap)
      ++n_hysteretic;
    const unsigned int n_gaps = n_elements - n_hysteretic;
    std::vector<double> peak_deformation(n_elements, 0.0), peak_force(n_elements, 0.0),
      time_of_peak(n_elements, 0.0), peak_plastic(n_elements, 0.0);
    double min_clearance = std::numeric_limits<double>::infinity();

    FloorResponse response(model);
    const bool    files = !options.output_directory.empty();
    const std::string &dir = options.output_directory;
    std::optional<CsvWriter> drift_csv, acceleration_csv, displacement_csv, ground_csv,
      hinges_csv, energy_csv, contact_csv;
    std::unique_ptr<VtuSeries> vtu;
    if (files)
      {
        create_directories(dir);
        if (options.csv)
          {
            auto header = [&](const std::string &what, const std::string &first) {
              std::vector<std::string> h{first};
              for (const auto &n : response.column_names(what))
                h.push_back(n);
              return h;
            };
            drift_csv.emplace(dir + "/drift.csv", header("storey", "time"));
            acceleration_csv.emplace(dir + "/floor_acceleration.csv", header("floor", "time"));
            displacement_csv.emplace(dir + "/floor_displacement.csv", header("floor", "time"));
            ground_csv.emplace(dir + "/ground_motion.csv",
                               std::vector<std::string>{"time", "ground_acceleration"});
            energy_csv.emplace(dir + "/energy.csv",
                               std::vector<std::string>{"time", "input", "kinetic", "damping",
                                                        "strain", "hysteretic", "contact",
                                                        "balance_error"});
            if (n_hysteretic > 0)
              {
                std::vector<std::string> h{"time"};
                for (unsigned int i = 0; i < n_hysteretic; ++i)
                  for (const char *what : {"_force", "_deformation", "_z"})
                    h.push_back(elements[i].label + what);
                hinges_csv.emplace(dir + "/hinges.csv", h);
              }
            if (n_gaps > 0)
              {
                std::vector<std::string> h{"time"};
                for (unsigned int i = n_hysteretic; i < n_elements; ++i)
                  for (const char *what : {"_force", "_penetration"})
                    h.push_back(elements[i].label + what);
                contact_csv.emplace(dir + "/contact_force.csv", h);
              }
          }
        if (options.vtu && input.vtu_interval > 0)
          vtu = std::make_unique<VtuSeries>(model, dir, "solution");
      }
    const unsigned int csv_every = steps_per_interval(input.output_interval, dt);
    const unsigned int vtu_every = steps_per_interval(input.vtu_interval, dt);

    auto record = [&](const unsigned long step) {
      const double t  = step * dt;
      const double ag = excitation.ground_acceleration(t);
      response.evaluate(t, integrator.displacement(), integrator.acceleration(), ag);
      for (unsigned int h = 0; h < n_elements; ++h)
        {
          const double d = elements[h].deformation(integrator.displacement());
          if (std::abs(d) > peak_deformation[h])
            {
              peak_deformation[h] = std::abs(d);
              time_of_peak[h]     = t;
            }
          const double f = elements[h].force();
          peak_force[h]  = std::max(peak_force[h], std::abs(f));
          if (h >= n_hysteretic) // a gap: its opening is minus its penetration
            min_clearance = std::min(min_clearance, -elements[h].history_variable());
          // plastic part: the deformation left after elastic unloading
          const double k0 = elements[h].initial_stiffness();
          if (k0 > 0)
            peak_plastic[h] = std::max(peak_plastic[h], std::abs(d - f / k0));
        }
      if (drift_csv && step % csv_every == 0)
        {
          const EnergyBalance e = integrator.energy();
          energy_csv->begin_row(t);
          for (const double x :
               {e.input, e.kinetic, e.damping, e.strain, e.hysteretic, e.contact,
                integrator.max_energy_error()})
            energy_csv->add(x);
          energy_csv->end_row();
          if (hinges_csv)
            {
              hinges_csv->begin_row(t);
              for (unsigned int i = 0; i < n_hysteretic; ++i)
                {
                  const NonlinearElement &e = elements[i];
                  hinges_csv->add(e.force());
                  hinges_csv->add(e.deformation(integrator.displacement()));
                  hinges_csv->add(e.history_variable());
                }
              hinges_csv->end_row();
            }
          if (contact_csv)
            {
              contact_csv->begin_row(t);
              for (unsigned int i = n_hysteretic; i < n_elements; ++i)
                {
                  contact_csv->add(elements[i].force());
                  contact_csv->add(elements[i].history_variable());
                }
              contact_csv->end_row();
            }
          const std::pair<CsvWriter *, const std::vector<double> *> rows[] = {
            {&*drift_csv, &response.drift_ratio()},
            {&*acceleration_csv, &response.absolute_acceleration()},
            {&*displacement_csv, &response.displacement()}};
          for (const auto &[writer, values] : rows)
            {
              writer->begin_row(t);
              for (const double v : *values)
                writer->add(v);
              writer->end_row();
            }
          ground_csv->begin_row(t);
          ground_csv->add(ag);
          ground_csv->end_row();
        }
      if (vtu && step % vtu_every == 0)
        vtu->write(t, integrator.displacement());
    };

    RunResult  result;
    const auto start = std::chrono::steady_clock::now();
    record(0);
    try
      {
        for (unsigned long step = 1; step <= n_steps; ++step)
          {
            integrator.advance(load_at);
            record(step);
          }
        result.completed = true;
      }
    catch (const NumericalError &e)
      {
        result.message = e.what();
      }
    result.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.steps     = integrator.steps();
    result.end_time  = integrator.time();
    result.peak_drift_ratio  = response.peak_drift_ratio();
    result.peak_acceleration = response.peak_acceleration();
    result.peak_displacement = response.peak_displacement();
    result.statistics        = integrator.statistics();
    result.energy            = integrator.energy();
    result.max_energy_error  = integrator.max_energy_error();
    result.impacts = integrator.impact_log().impacts();
    result.min_clearance = min_clearance;
    for (const Impact &impact : result.impacts) // the log locates the deepest point within steps
      result.min_clearance = std::min(result.min_clearance, -impact.max_penetration);
    for (unsigned int h = 0; h < n_hysteretic; ++h)
      {
        const double yield = elements[h].yield_deformation();
        result.element_labels.push_back(elements[h].label);
        result.peak_element_deformation.push_back(peak_deformation[h]);
        result.element_ductility.push_back(yield > 0 ? peak_deformation[h] / yield : 0.0);
      }
    if (!files)
      return result;

    for (auto *writer : {&drift_csv, &acceleration_csv, &displacement_csv, &ground_csv,
                         &energy_csv, &hinges_csv, &contact_csv})
      if (*writer)
        {
          (*writer)->commit();
          result.files.push_back((*writer)->path());
        }
    if (vtu)
      {
        vtu->finish();
        result.files.push_back(dir + "/solution.pvd");
      }

    // Peak profiles, for the plots and for spreadsheets.
    std::string drift_profile = "building,storey,peak_drift_ratio,time_of_peak\n";
    std::string accel_profile = "building,floor,peak_absolute_acceleration,peak_displacement\n";
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      for (unsigned int f = 0; f < model.buildings[b].floors.size(); ++f)
        {
          const unsigned int i = response.index(b, f);
          drift_profile += std::to_string(b + 1) + "," + std::to_string(f + 1) + "," +
                           std::to_string(response.peak_drift_ratio()[i]) + "," +
                           std::to_string(response.peak_drift_time()[i]) + "\n";
          accel_profile += std::to_string(b + 1) + "," + std::to_string(f + 1) + "," +
                           std::to_string(response.peak_acceleration()[i]) + "," +
                           std::to_string(response.peak_displacement()[i]) + "\n";
        }
    write_file_atomically(dir + "/drift_profile.csv", drift_profile);
    write_file_atomically(dir + "/acceleration_profile.csv", accel_profile);

    JsonWriter json;
    begin_summary(json, "run", input, result.completed ? "completed" : "failed");
    if (!result.completed)
      json.value("message", result.message);
    write_model(json, analysis);
    json.begin_object("ground_motion")
      .value("description", excitation.ground_motion().description())
      .value("pga_m_s2", excitation.ground_motion().peak())
      .value("pga_g", excitation.ground_motion().peak() / standard_gravity)
      .value("duration_s", excitation.ground_motion().duration())
      .value("time_step_s", excitation.ground_motion().time_step())
      .end_object();
    json.begin_array("buildings");
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const Building &building = model.buildings[b];
        json.begin_object()
          .value("name", building.name)
          .value("type", type_name(building.type))
          .value("storeys", static_cast<unsigned int>(building.floors.size()))
          .value("rayleigh_a0", analysis.system.rayleigh[b][0])
          .value("rayleigh_a1", analysis.system.rayleigh[b][1]);
        write_modes(json, "modes", analysis.building_modes[b]);
        const unsigned int roof = response.index(b, building.floors.size() - 1);
        json.value("peak_roof_displacement_m", response.peak_displacement()[roof]);
        json.begin_array("storeys");
        for (unsigned int f = 0; f < building.floors.size(); ++f)
          {
            const unsigned int i = response.index(b, f);
            json.begin_object()
              .value("storey", f + 1)
              .value("height_m", building.floors[f].storey_height)
              .value("peak_drift_ratio", response.peak_drift_ratio()[i])
              .value("time_of_peak_drift_s", response.peak_drift_time()[i])
              .value("peak_absolute_floor_acceleration_m_s2", response.peak_acceleration()[i])
              .value("peak_floor_displacement_m", response.peak_displacement()[i])
              .end_object();
          }
        json.end_array().end_object();
      }
    json.end_array();
    if (n_hysteretic > 0)
      {
        json.begin_array("hinges");
        for (unsigned int h = 0; h < n_hysteretic; ++h)
          {
            const NonlinearElement &e = elements[h];
            json.begin_object()
              .value("label", e.label)
              .value("kind", kind_name(e.kind))
              .value("building", model.buildings[e.building].name)
              .value("yield_deformation", e.yield_deformation())
              .value("peak_deformation", peak_deformation[h])
              .value("time_of_peak_deformation_s", time_of_peak[h])
              .value("ductility", result.element_ductility[h])
              .value("peak_plastic_deformation", peak_plastic[h])
              .value("peak_force", peak_force[h])
              .value("dissipated_energy_J",
                     integrator.element_work(h) - e.stored_energy())
              .end_object();
          }
        json.end_array();
      }
    if (n_gaps > 0)
      {
        const ContactLawParameters &law = model.contact;
        json.begin_object("contact")
          .value("law", law.law)
          .value("stiffness", law.stiffness)
          .value("damping_parameter", law.damping)
          .value("damping_from", input.contact.damping_from)
          .value("coefficient_of_restitution", input.contact.restitution)
          .end_object();
        std::string impacts_csv = "gap,buildings,level,start_time,max_penetration_time,end_time,"
                                  "approach_velocity,separation_velocity,max_penetration,"
                                  "peak_force,impulse\n";
        std::vector<unsigned int> count(n_gaps, 0);
        std::vector<double>       peak(n_gaps, 0.0), penetration(n_gaps, 0.0), impulse(n_gaps, 0.0);
        for (const Impact &impact : result.impacts)
          {
            const unsigned int g   = impact.element - n_hysteretic;
            const Gap         &gap = model.gaps[g];
            ++count[g];
            peak[g]        = std::max(peak[g], impact.peak_force);
            penetration[g] = std::max(penetration[g], impact.max_penetration);
            impulse[g] += impact.impulse;
            std::ostringstream row;
            row.precision(10);
            row << gap.label << "," << model.buildings[gap.buildings[0]].name;
            if (gap.nodes[0] >= 0 && gap.nodes[1] >= 0)
              row << "|" << model.buildings[gap.buildings[1]].name;
            else
              row << "|barrier";
            row << "," << gap.level << "," << impact.start_time << ","
                << impact.max_penetration_time << ",";
            if (impact.end_time >= 0)
              row << impact.end_time;
            row << "," << impact.approach_velocity << "," << impact.separation_velocity << ","
                << impact.max_penetration << "," << impact.peak_force << "," << impact.impulse
                << "\n";
            impacts_csv += row.str();
          }
        write_file_atomically(dir + "/impacts.csv", impacts_csv);
        result.files.push_back(dir + "/impacts.csv");
        json.begin_array("gaps");
        for (unsigned int g = 0; g < n_gaps; ++g)
          {
            const Gap             &gap = model.gaps[g];
            const NonlinearElement &e   = elements[n_hysteretic + g];
            json.begin_object()
              .value("label", gap.label)
              .value("level_m", gap.level)
              .value("initial_gap_m", gap.initial_gap)
              .value("effective_mass_kg", gap.effective_mass)
              .value("impacts", count[g])
              .value("peak_force_N", peak[g])
              .value("max_penetration_m", penetration[g])
              .value("total_impulse_N_s", impulse[g])
              .value("dissipated_energy_J",
                     integrator.element_work(n_hysteretic + g) - e.stored_energy())
              .end_object();
          }
        json.end_array();
      }
    const EnergyBalance &energy = result.energy;
    json.begin_object("energy")
      .value("initial_J", energy.initial)
      .value("input_J", energy.input)
      .value("kinetic_J", energy.kinetic)
      .value("damping_J", energy.damping)
      .value("strain_J", energy.strain)
      .value("hysteretic_J", energy.hysteretic)
      .value("contact_J", energy.contact)
      .value("max_relative_balance_error", result.max_energy_error)
      .end_object();
    const IterationStatistics &stats = result.statistics;
    json.begin_object("newton")
      .value("nonlinear_elements", n_elements)
      .value("tangent_update", n_elements > 0 ? integrator.tangent_update() : "none")
      .value("mean_iterations_per_step",
             stats.steps > 0 ? double(stats.iterations) / stats.steps : 0.0)
      .value("max_iterations_per_step", stats.max_iterations)
      .value("step_cuts", static_cast<unsigned long>(stats.step_cuts))
      .value("event_refinements", static_cast<unsigned long>(stats.event_refinements))
      .value("smallest_time_step_s", stats.smallest_time_step)
      .value("steps_including_substeps", static_cast<unsigned long>(stats.steps))
      .end_object();
    json.begin_object("analysis")
      .value("integrator", "Newmark")
      .value("gamma", input.newmark_gamma)
      .value("beta", input.newmark_beta)
      .value("time_step_s", dt)
      .value("end_time_s", result.end_time)
      .value("steps", result.steps)
      .value("linear_solver", integrator.linear_solver_name())
      .value("wall_time_s", result.wall_time)
      .value("steps_per_second", result.steps / std::max(result.wall_time, 1e-12))
      .end_object();
    json.end_object();
    write_file_atomically(dir + "/summary.json", json.str());
    result.files.push_back(dir + "/summary.json");

    if (options.plots && input.plots && drift_csv)
      {
        std::vector<Plot> plots;
        Plot drift{"drift_profile.png", "Peak inter-storey drift ratio", "peak |IDR|", "storey", {}};
        Plot accel{"acceleration_profile.png", "Peak absolute floor acceleration",
                   "peak |a| (m/s^2)", "floor", {}};
        Plot roof{"roof_displacement.png", "Roof displacement (relative to the ground)",
                  "time (s)", "displacement (m)", {}};
        unsigned int column = 2;
        for (unsigned int b = 0; b < model.buildings.size(); ++b)
          {
            const std::string name = model.buildings[b].name;
            const std::string sel  = "($1==" + std::to_string(b + 1) + "?";
            drift.series.push_back({"drift_profile.csv", sel + "$3:NaN):2", name, "linespoints"});
            accel.series.push_back(
              {"acceleration_profile.csv", sel + "$3:NaN):2", name, "linespoints"});
            column += model.buildings[b].floors.size();
            roof.series.push_back(
              {"floor_displacement.csv", "1:" + std::to_string(column - 1), name, "lines"});
          }
        Plot ground{"ground_motion.png", excitation.ground_motion().description(), "time (s)",
                    "ground acceleration (m/s^2)",
                    {{"ground_motion.csv", "1:2", "a_g", "lines"}}};
        Plot energy_plot{"energy.png", "Energy balance (relative coordinates)", "time (s)",
                         "energy (J)", {}};
        const char *terms[] = {"input", "kinetic", "damping", "strain", "hysteretic", "contact"};
        for (unsigned int i = 0; i < 6; ++i)
          energy_plot.series.push_back(
            {"energy.csv", "1:" + std::to_string(i + 2), terms[i], "lines"});
        std::vector<Plot> all{drift, accel, roof, ground, energy_plot};
        // Hysteresis loops of the (up to four) most demanded elements.
        std::vector<unsigned int> order(n_hysteretic);
        for (unsigned int h = 0; h < n_hysteretic; ++h)
          order[h] = h;
        std::stable_sort(order.begin(), order.end(), [&](unsigned int x, unsigned int y) {
          return result.element_ductility[x] > result.element_ductility[y];
        });
        for (unsigned int i = 0; i < std::min(4u, n_hysteretic); ++i)
          {
            const unsigned int     h = order[i];
            const NonlinearElement &e = elements[h];
            const bool             hinge = e.kind == ElementKind::hinge;
            std::ostringstream     title;
            title << e.label << " (ductility " << result.element_ductility[h] << ")";
            all.push_back(Plot{"hysteresis_" + e.label + ".png", title.str(),
                               hinge ? "rotation (rad)" : "drift (m)",
                               hinge ? "moment (N m)" : "force (N)",
                               {{"hinges.csv",
                                 std::to_string(3 * h + 3) + ":" + std::to_string(3 * h + 2),
                                 e.label, "lines"}}});
          }
        if (n_gaps > 0)
          {
            Plot contact{"contact_force.png", "Contact forces", "time (s)", "force (N)", {}};
            for (unsigned int g = 0; g < n_gaps; ++g)
              contact.series.push_back({"contact_force.csv", "1:" + std::to_string(2 * g + 2),
                                        model.gaps[g].label, "lines"});
            all.push_back(contact);
          }
        for (const auto &f : draw_plots(dir, all))
          result.files.push_back(dir + "/" + f);
      }
    return result;
  }

  int
  run_command(const Analysis &analysis, const std::string &output_directory)
  {
    const Excitation excitation = make_excitation(analysis);
    RunOptions       options;
    options.output_directory = output_directory;
    const RunResult result   = run_time_history(analysis, excitation, options);
    std::cout << "poundfe run: " << result.steps << " steps to t = " << result.end_time
              << " s in " << result.wall_time << " s\n";
    if (!result.element_labels.empty())
      std::cout << result.element_labels.size() << " nonlinear elements; Newton "
                << double(result.statistics.iterations) / std::max(1ul, result.statistics.steps)
                << " iterations per step (max " << result.statistics.max_iterations << "), "
                << result.statistics.step_cuts << " step cuts\n";
    if (!analysis.model.gaps.empty())
      std::cout << analysis.model.gaps.size() << " gap elements, " << result.impacts.size()
                << " impacts (impacts.csv)\n";
    std::cout << "energy balance error " << result.max_energy_error << " (max relative)\n";
    std::cout << "results in " << output_directory << "/ (summary.json, drift.csv, "
              << "floor_acceleration.csv, floor_displacement.csv, energy.csv"
              << (result.element_labels.empty() ? "" : ", hinges.csv")
              << ", solution.pvd, *.png)\n";
    if (!result.completed)
      {
        std::cerr << "poundfe: numerical failure: " << result.message
                  << " (results up to that time are written)\n";
        return 2;
      }
    return 0;
  }

  int
  modal_command(const Analysis &analysis, const std::string &output_directory)
  {
    create_directories(output_directory);
    JsonWriter json;
    json.begin_object().value("program", "poundfe").value("command", "modal").value(
      "input", analysis.input.file);
    write_model(json, analysis);
    json.begin_array("buildings");
    for (unsigned int b = 0; b < analysis.model.buildings.size(); ++b)
      {
        json.begin_object().value("name", analysis.model.buildings[b].name);
        write_modes(json, "modes", analysis.building_modes[b]);
        json.value("rayleigh_a0", analysis.system.rayleigh[b][0])
          .value("rayleigh_a1", analysis.system.rayleigh[b][1])
          .end_object();
      }
    json.end_array().end_object();

    VtuSeries modes(analysis.model, output_directory, "modes");
    for (unsigned int i = 0; i < analysis.modes.n_modes(); ++i)
      modes.write(i + 1, analysis.modes.shapes.col(i), false);
    modes.finish();
    write_file_atomically(output_directory + "/summary.json", json.str());

    std::cout << "mode  frequency (Hz)  period (s)  mass ratio (x)\n";
    for (unsigned int i = 0; i < analysis.modes.n_modes(); ++i)
      std::printf("%4u  %14.4f  %10.4f  %14.4f\n", i + 1, analysis.modes.frequency(i),
                  analysis.modes.period(i), analysis.modes.participating_mass_ratio[i]);
    std::cout << "results in " << output_directory << "/ (summary.json, modes.pvd)\n";
    return 0;
  }

  int
  ground_motion_command(const InputParameters &input, const std::string &output_directory,
                        const unsigned int n_realizations)
  {
    if (n_realizations > 0)
      return ensemble_command(input, output_directory, n_realizations);
    const GroundMotion motion = make_ground_motion(input);
    if (motion.empty())
      throw InputError(input.file, input.line_of("Ground motion/Type"), "Ground motion/Type",
                       "there is no ground motion to write (type none)");
    create_directories(output_directory);
    {
      CsvWriter csv(output_directory + "/ground_motion.csv", {"time", "ground_acceleration"});
      for (std::size_t i = 0; i < motion.samples().size(); ++i)
        {
          csv.begin_row(i * motion.time_step());
          csv.add(motion.samples()[i]);
          csv.end_row();
        }
      csv.commit();
    }
    if (input.plots)
      draw_plots(output_directory, {Plot{"ground_motion.png", motion.description(), "time (s)",
                                         "ground acceleration (m/s^2)",
                                         {{"ground_motion.csv", "1:2", "a_g", "lines"}}}});
    std::cout << motion.description() << ": " << motion.samples().size() << " samples, dt = "
              << motion.time_step() << " s, PGA = " << motion.peak() << " m/s^2 ("
              << motion.peak() / standard_gravity << " g)\n"
              << "written to " << output_directory << "/ground_motion.csv\n";
    return 0;
  }
} // namespace poundfe
