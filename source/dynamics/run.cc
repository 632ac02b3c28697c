#include <poundfe/dynamics/run.h>
#include <poundfe/report/run_summary.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/excitation/stochastic_load.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/floor_spectra.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/recorders.h>
#include <poundfe/output/response_range.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>
#include <poundfe/output/vtu_series.h>

#include <deal.II/base/mpi.h>

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

    /// SIGINT/SIGTERM, agreed by every rank (mpirun may deliver it to the
    /// ranks at different steps; a rank that stopped alone would leave the
    /// others waiting in the distributed solver).
    bool
    stop_requested()
    {
      int initialized = 0;
      MPI_Initialized(&initialized);
      if (!initialized || dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1)
        return interruption_requested();
      return dealii::Utilities::MPI::logical_or(interruption_requested(), MPI_COMM_WORLD);
    }

    /// Steps between VTU frames: Output/VTU interval, widened (with a note
    /// on the console) so that a run of `n_steps` writes at most
    /// Output/Maximum VTU frames frames.
    unsigned int
    vtu_steps_per_frame(const InputParameters &input, const unsigned long n_steps)
    {
      const double        dt       = input.time_integration.newmark.time_step;
      const unsigned long max      = input.output.max_vtu_frames;
      const unsigned int  every    = steps_per_interval(input.output.vtu_interval, dt);
      const unsigned long n_frames = n_steps / every + 1;
      if (n_frames <= max)
        return every;
      const unsigned long wider = (n_steps + max - 2) / (max - 1); // n_steps / wider + 1 <= max
      std::cout << "poundfe: note: Output/VTU interval = " << number_text(input.output.vtu_interval)
                << " s would write " << n_frames << " VTU frames, more than Output/Maximum VTU "
                << "frames = " << max << ": writing one every " << number_text(wider * dt)
                << " s instead\n";
      return static_cast<unsigned int>(std::min<unsigned long>(wider, 4000000000ul));
    }

    double
    end_time_of(const InputParameters &input, const Excitation &excitation)
    {
      if (input.time_integration.end_time > 0)
        return input.time_integration.end_time;
      return excitation.ground_motion().duration();
    }

    /// `ground-motion --realizations N`: the samples of realizations 0..N-1
    /// and their ensemble PSD against the target.
    int
    ensemble_command(const InputParameters &input, const std::string &directory,
                     const unsigned int n_realizations)
    {
      const GroundMotionType type = input.ground_motion.type;
      if (!input.ground_motion.is_stochastic())
        input.fail("Ground motion/Type", "--realizations needs a stochastic ground motion, got '" +
                                           ground_motion_type_names().name(type) + "'");
      const MotionGenerator generator =
        make_motion_generator(input.ground_motion, input.time_integration.newmark.time_step);
      const double          scale     = input.ground_motion.scale_factor;
      // all samples are held, then written: the guard before either
      require_free_space(directory, csv_table_bytes(generator.n_samples(), n_realizations + 1.0),
                         "ground-motion samples (" + std::to_string(generator.n_samples()) +
                           " rows of " + std::to_string(n_realizations) + " realizations)");
      prepare_output_directory(directory);
      std::vector<std::string> header{"time"};
      for (unsigned int r = 0; r < n_realizations; ++r)
        header.push_back("realization_" + std::to_string(r));
      std::vector<std::vector<double>> samples(n_realizations);
      std::vector<double>              xi(generator.n_variables());
      double                           variance = 0;
      for (unsigned int r = 0; r < n_realizations; ++r)
        {
          throw_if_interrupted();
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
      const double top = type == GroundMotionType::white_noise ?
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
      if (input.output.plots)
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

  Excitation
  make_excitation(const Analysis &analysis)
  {
    const InputParameters &input = analysis.input;
    const double           dt    = input.time_integration.newmark.time_step;
    Excitation             excitation(analysis.system, make_ground_motion(input.ground_motion, input, dt),
                          make_nodal_forces(input.nodal_forces, input.ground_motion, dt, input,
                                            analysis.model));
    if (!analysis.input.nodal_forces.white_noise.empty())
      {
        const StochasticLoad load(input.ground_motion, dt, excitation);
        std::vector<double>  xi;
        load.standard_normals(input.ground_motion.realization, xi);
        load.apply(xi, excitation);
      }
    return excitation;
  }

  TimeHistory::TimeHistory(const Analysis &analysis_, const std::string &linear_solver)
    : analysis(analysis_)
    , elements(make_nonlinear_elements(analysis_.model))
    , integrator(analysis_.system,
                 linear_solver.empty() ? analysis_.input.time_integration.linear_solver : linear_solver,
                 analysis_.input.time_integration.newmark, &elements)
    , view(analysis_.model, analysis_.system, elements, integrator)
  {
    integrator.set_equation_names(equation_names(analysis_.model));
  }

  unsigned long
  TimeHistory::n_steps(const Excitation &excitation) const
  {
    const InputParameters &input = analysis.input;
    const double           end   = end_time_of(input, excitation);
    if (!(end > 0))
      throw InputError(input.file, input.line_of("Time integration/End time"),
                       "Time integration/End time",
                       "needs a positive end time when there is no ground motion");
    // what set the end: End time, else the record or the stochastic motion's duration
    const std::string end_path = input.time_integration.end_time > 0 ? "Time integration/End time" :
                                 input.ground_motion.type == GroundMotionType::record ?
                                                                     "Ground motion/Record/File" :
                                                                     "Ground motion/Stochastic/Duration";
    return input.time_integration.n_steps_to(end, input, end_path);
  }

  RunStatus
  TimeHistory::run(const Excitation &excitation, const Observers &observers,
                   const bool interruptible)
  {
    const Vector rest = Vector::Zero(analysis.system.n_equations());
    return run(rest, rest, excitation, observers, interruptible);
  }

  RunStatus
  TimeHistory::run(const Vector &u0, const Vector &v0, const Excitation &excitation,
                   const Observers &observers, const bool interruptible)
  {
    const unsigned long n = n_steps(excitation);
    const double        dt = analysis.input.time_integration.newmark.time_step;
    const LoadFunction  load = [&excitation](const double t, Vector &p) { excitation.load(t, p); };
    Vector p0(analysis.system.n_equations());
    load(0, p0);
    integrator.initialize(p0, u0, v0);
    view.set_step(0, excitation.ground_acceleration(0));
    for (StepObserver *observer : observers)
      observer->initialize(view);

    RunStatus     status;
    unsigned long step = 0;
    integrator.set_substep_callback([&]() {
      view.set_step(step, excitation.ground_acceleration(integrator.time()));
      for (StepObserver *observer : observers)
        observer->observe_substep(view);
    });
    struct Forget // the callback refers to this call's locals
    {
      NewmarkIntegrator &integrator;
      ~Forget() { integrator.set_substep_callback(nullptr); }
    } forget{integrator};
    const auto start = std::chrono::steady_clock::now();
    try
      {
        for (step = 1; step <= n; ++step)
          {
            if (interruptible && stop_requested())
              {
                status.kind = RunStatus::Kind::interrupted;
                break;
              }
            throw_if_interrupted(); // a command that stops at safe points (sweep, ...)
            integrator.advance(load);
            view.set_step(step, excitation.ground_acceleration(step * dt));
            for (StepObserver *observer : observers)
              observer->observe_step(view);
          }
      }
    catch (const NumericalError &e)
      {
        status.kind    = RunStatus::Kind::failed;
        status.message = e.what();
      }
    catch (const OutputError &e) // a full disk: stop, and say so in what still fits
      {
        status.kind          = RunStatus::Kind::failed;
        status.output_failed = true;
        status.message       = e.what();
      }
    status.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    status.steps     = integrator.steps();
    status.end_time  = integrator.time();
    // Every observer finishes (or removes) its files even when one cannot:
    // the summary, last, then reports the file that failed.
    for (StepObserver *observer : observers)
      try
        {
          observer->finish(view, status);
        }
      catch (const OutputError &e)
        {
          if (status.message.find(e.what()) == std::string::npos) // not a file's second word
            status.message += std::string(status.output_failed ? "; " : "") + e.what();
          status.kind          = RunStatus::Kind::failed;
          status.output_failed = true;
        }
    return status;
  }

  namespace
  {
    /// Steps done, their rate and the time left, on a terminal.
    class ProgressReport : public StepObserver
    {
    public:
      explicit ProgressReport(const unsigned long n_steps)
        : progress(std::cerr, "run: steps", n_steps)
      {}
      void
      observe_step(const ResponseView &state) override
      {
        if (state.step() % 64 == 0) // the clock is read in update(): not every step
          progress.update(state.step());
      }
      void finish(const ResponseView &, const RunStatus &) override { progress.finish(); }

    private:
      Progress progress;
    };
  } // namespace

  RunResult
  run_time_history(const Analysis &analysis, const Excitation &excitation,
                   const RunOptions &options)
  {
    TimeHistory  history(analysis, options.linear_solver);
    const unsigned long n_steps = history.n_steps(excitation); // refused before any output
    PeakResponse  peaks(analysis.model, history.nonlinear_elements());
    ResponseRange range(analysis.model, peaks, analysis.input.output.drift_warning,
                        analysis.input.output.rotation_warning);
    Observers     observers{&peaks, &range}; // first: the recorders read the floor response
    std::vector<std::unique_ptr<StepObserver>> outputs;
    const std::string &directory = options.output_directory;
    if (!directory.empty())
      {
        const InputParameters   &input = analysis.input;
        std::vector<std::string> files; // of the recorders and VTU, for summary.json
        if (options.csv) // first: it checks its input before anything is written
          {
            Recorders recorders = make_recorders(input.output.recorders, input.file, history.state(),
                                                 peaks, input.time_integration.newmark.time_step,
                                                 directory);
            outputs = std::move(recorders.observers);
            files   = std::move(recorders.files);
          }
        else // the recorders prepare it after checking their input
          prepare_output_directory(directory);
        if (options.csv && input.output.floor_spectra)
          {
            outputs.push_back(std::make_unique<FloorSpectra>(
              peaks, input.spectrum.periods(), input.spectrum.damping_ratios, directory));
            files.push_back(FloorSpectra::file_name);
          }
        if (options.vtu && input.output.vtu_interval > 0)
          {
            outputs.push_back(std::make_unique<VtuRecorder>(
              analysis.model, directory, vtu_steps_per_frame(input, n_steps)));
            files.insert(files.end(), {"solution.pvd", "solution/"}); // the index, the frames
          }
        outputs.push_back(std::make_unique<RunSummary>(
          analysis, excitation, peaks, range, directory, options.plots && input.output.plots,
          history.linear_solver_name(), history.tangent_update(), files));
      }
    if (options.progress)
      outputs.push_back(std::make_unique<ProgressReport>(n_steps));
    for (const auto &output : outputs)
      observers.push_back(output.get());
    observers.insert(observers.end(), options.observers.begin(), options.observers.end());

    RunResult result;
    result.status               = history.run(excitation, observers, options.interruptible);
    const ResponseView &state   = history.state();
    result.statistics           = state.statistics();
    result.energy               = state.energy();
    result.max_energy_error     = state.max_energy_error();
    result.n_nonlinear_elements = state.elements.size();
    result.n_impacts            = state.impact_log().impacts().size();
    result.warnings             = range.warnings();
    return result;
  }

  int
  run_command(const Analysis &analysis, const std::string &output_directory)
  {
    const Excitation excitation = make_excitation(analysis);
    const bool       root       = writes_outputs();
    RunOptions       options;
    options.output_directory = root ? output_directory : "";
    options.progress         = root;
    options.interruptible    = true;
    const RunResult  result  = run_time_history(analysis, excitation, options);
    const RunStatus &status  = result.status;
    if (!root)
      return status.output_failed ? 1 :
             status.kind == RunStatus::Kind::failed ? 2 :
             status.kind == RunStatus::Kind::interrupted ? interrupted_exit_status() : 0;
    std::cout << "poundfe run: " << status.steps << " steps to t = " << status.end_time << " s in "
              << status.wall_time << " s\n";
    if (result.n_nonlinear_elements > 0)
      std::cout << result.n_nonlinear_elements << " nonlinear elements; Newton "
                << double(result.statistics.iterations) / std::max(1ul, result.statistics.steps)
                << " iterations per step (max " << result.statistics.max_iterations << "), "
                << result.statistics.step_cuts << " step cuts\n";
    if (!analysis.model.gaps.empty())
      std::cout << analysis.model.gaps.size() << " gap elements, " << result.n_impacts
                << " impacts (impacts.csv)\n";
    std::cout << "energy balance error " << result.max_energy_error << " (max relative)\n";
    for (const std::string &warning : result.warnings)
      std::cerr << "poundfe: warning: " << warning << "\n";
    std::cout << "results in " << output_directory << "/ (summary.json lists the files)\n";
    if (status.output_failed)
      {
        std::cerr << "poundfe: error: " << status.message << " (the run stopped at t = "
                  << status.end_time << " s; every other file is complete to that time, "
                  << "and summary.json says what failed unless it is the file named)\n";
        return 1;
      }
    if (status.kind == RunStatus::Kind::failed)
      {
        std::cerr << "poundfe: numerical failure: " << status.message
                  << " (results up to that time are written)\n";
        return 2;
      }
    if (status.kind == RunStatus::Kind::interrupted)
      {
        std::cerr << "poundfe: interrupted at t = " << status.end_time
                  << " s (results up to that time are written)\n";
        return interrupted_exit_status();
      }
    return 0;
  }

  int
  modal_command(const Analysis &analysis, const std::string &output_directory)
  {
    prepare_output_directory(output_directory);
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
      modes.write_mode(i + 1, analysis.modes.frequency(i), analysis.modes.shapes.col(i));
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
    const GroundMotion motion =
      make_ground_motion(input.ground_motion, input, input.time_integration.newmark.time_step);
    if (motion.empty())
      throw InputError(input.file, input.line_of("Ground motion/Type"), "Ground motion/Type",
                       "there is no ground motion to write (type none)");
    prepare_output_directory(output_directory);
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
    if (input.output.plots)
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
