#include <poundfe/analysis/run.h>
#include <poundfe/base/exceptions.h>
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
#include <memory>
#include <optional>

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

    double
    end_time_of(const InputParameters &input, const Excitation &excitation)
    {
      if (input.end_time > 0)
        return input.end_time;
      return excitation.ground_motion().duration();
    }
  } // namespace

  Excitation
  make_excitation(const Analysis &analysis)
  {
    return Excitation(analysis.system, make_ground_motion(analysis.input),
                      make_nodal_forces(analysis.input, analysis.model));
  }

  RunResult
  run_time_history(const Analysis &analysis, const Excitation &excitation,
                   const RunOptions &options)
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

    auto solver = create_linear_solver(options.linear_solver.empty() ? input.linear_solver :
                                                                        options.linear_solver);
    NewmarkIntegrator integrator(analysis.system, *solver,
                                 {dt, input.newmark_gamma, input.newmark_beta});
    Vector load(analysis.system.n_equations());
    excitation.load(0, load);
    integrator.initialize(load);

    FloorResponse response(model);
    const bool    files = !options.output_directory.empty();
    const std::string &dir = options.output_directory;
    std::optional<CsvWriter> drift_csv, acceleration_csv, displacement_csv, ground_csv;
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
      if (drift_csv && step % csv_every == 0)
        {
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
            excitation.load(step * dt, load);
            integrator.advance(load);
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
    if (!files)
      return result;

    for (auto *writer : {&drift_csv, &acceleration_csv, &displacement_csv, &ground_csv})
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
    json.begin_object()
      .value("program", "poundfe")
      .value("command", "run")
      .value("input", input.file)
      .value("status", result.completed ? "completed" : "failed");
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
    json.begin_object("analysis")
      .value("integrator", "Newmark")
      .value("gamma", input.newmark_gamma)
      .value("beta", input.newmark_beta)
      .value("time_step_s", dt)
      .value("end_time_s", result.end_time)
      .value("steps", result.steps)
      .value("linear_solver", solver->name())
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
        for (const auto &f : draw_plots(dir, {drift, accel, roof, ground}))
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
    std::cout << "results in " << output_directory << "/ (summary.json, drift.csv, "
              << "floor_acceleration.csv, floor_displacement.csv, solution.pvd, *.png)\n";
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
  ground_motion_command(const InputParameters &input, const std::string &output_directory)
  {
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
