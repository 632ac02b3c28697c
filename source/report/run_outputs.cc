// A time history with the standard observers (report/run_outputs.h): the
// observers are chosen from the Output section, attached in the order they
// must see each step (the peaks first: the recorders read the floor
// response), and the run's scalars returned.
#include <poundfe/report/run_outputs.h>
#include <poundfe/report/run_summary.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/output/floor_spectra.h>
#include <poundfe/output/number_text.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/recorders.h>
#include <poundfe/output/response_range.h>
#include <poundfe/output/section_limit_states.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/vtu_series.h>

#include <poundfe/dynamics/partitioned_stepper.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <exception>
#include <iostream>
#include <memory>

namespace poundfe
{
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

    /// Steps between VTU frames: Output/VTU interval, widened (with a note
    /// on `console`, when given) so that a run of `n_steps` of `dt` writes
    /// at most Output/Maximum VTU frames frames.
    unsigned int
    vtu_steps_per_frame(const OutputParameters &output, const double dt,
                        const unsigned long n_steps, std::ostream *console)
    {
      const unsigned long max      = output.max_vtu_frames;
      const unsigned int  every    = steps_per_interval(output.vtu_interval, dt);
      const unsigned long n_frames = n_steps / every + 1;
      if (n_frames <= max)
        return every;
      const unsigned long wider = (n_steps + max - 2) / (max - 1); // n_steps / wider + 1 <= max
      if (console)
        *console << "poundfe: note: Output/VTU interval = " << number_text(output.vtu_interval)
                 << " s would write " << n_frames << " VTU frames, more than Output/Maximum VTU "
                 << "frames = " << max << ": writing one every " << number_text(wider * dt)
                 << " s instead\n";
      return static_cast<unsigned int>(std::min<unsigned long>(wider, 4000000000ul));
    }

  } // namespace

  namespace
  {
    /// The standard observers of a run, in the order they see each step:
    /// the peaks and the response range first (the recorders read the
    /// floor response), then with an output directory the base shears,
    /// the input's recorders, the floor spectra, the field output and the
    /// summary, the progress on a terminal, and the caller's own. With
    /// `ranks` (observation by rank) the recorders' rows go through it, the
    /// field output is `field_recorder`'s (given the steps between frames)
    /// and a rank that does not write the files has no summary and no
    /// progress.
    class StandardObservers
    {
    public:
      /// The field recorder of a partitioned run: the steps between frames, whether
      /// it adds impact-peak frames.
      using FieldRecorderMaker =
        std::function<std::unique_ptr<StepObserver>(unsigned int, bool)>;

      StandardObservers(const Analysis &analysis, const RunParameters &parameters,
                        const Excitation &excitation, const ResponseView &view,
                        const NonlinearElements &elements, unsigned long n_steps,
                        const std::string &solver, const std::string &tangent_update,
                        const RunOptions &options, RowSink *ranks = nullptr,
                        const FieldRecorderMaker &field_recorder = {});

      /// Observation by rank: the peaks, the range, the base shears, the
      /// plan and the floor spectra merge themselves (StepObserver::merge).
      const Observers &all() const { return observers; }
      /// The run's scalars after it ended with `status`.
      RunResult result(const RunStatus &status, const ResponseView &state) const;

    private:
      PeakResponse   peaks;
      ResponseRange  range;
      // observed with an output directory only, for the summary: each
      // building's peak base shear, and a 3D model's plan at the steps
      BaseShearPeaks base_shears;
      PlanResponse   plan;
      std::unique_ptr<FloorSpectra> spectra; // with floor spectra
      // the fibre members' limit states, for the summary (one process only)
      std::unique_ptr<SectionLimitStates> section_limits;
      std::vector<std::unique_ptr<StepObserver>> outputs;
      Observers      observers;
    };

    StandardObservers::StandardObservers(const Analysis &analysis, const RunParameters &parameters,
                                         const Excitation &excitation, const ResponseView &view,
                                         const NonlinearElements &elements,
                                         const unsigned long n_steps, const std::string &solver,
                                         const std::string &tangent_update,
                                         const RunOptions &options, RowSink *ranks,
                                         const FieldRecorderMaker &field_recorder)
      : peaks(analysis.model, elements)
      , range(analysis.model, peaks, parameters.output.drift_warning,
              parameters.output.rotation_warning)
      , plan(analysis.model)
      , observers{&peaks, &range}
    {
      const OutputParameters &output    = parameters.output;
      const double            dt        = parameters.time_history.time_integration.newmark.time_step;
      const std::string      &directory = options.output_directory;
      const bool              writes    = !ranks || ranks->writes_files();
      MemoryResults *const    memory    = options.memory;
      Assert(!memory || (directory.empty() && !ranks), dealii::ExcNotImplemented());
      if (!directory.empty() || memory)
        {
          observers.insert(observers.end(), {&base_shears, &plan});
          std::vector<std::string> files; // of the recorders and VTU, for summary.json
          if (options.csv) // first: it checks its input before anything is written
            {
              Recorders recorders =
                make_recorders(output.recorders, parameters.time_history.input.file, view, peaks,
                               dt, directory, ranks, memory);
              if (options.console && writes)
                for (const TableShape &table : recorders.tables)
                  *options.console << large_table_note(table, n_steps, output.recorders.format);
              outputs = std::move(recorders.observers);
              files   = std::move(recorders.files);
            }
          else if (writes && !memory) // the recorders prepare it after checking their input
            prepare_output_directory(directory);
          if (options.csv && output.floor_spectra) // on every rank: merged by floor
            {
              spectra = std::make_unique<FloorSpectra>(
                peaks, parameters.spectrum.periods(), parameters.spectrum.damping_ratios, directory,
                memory);
              observers.push_back(spectra.get());
              files.push_back(FloorSpectra::file_name);
            }
          if (options.vtu && !memory && output.vtu_interval > 0 && (writes || field_recorder))
            {
              const unsigned int every =
                vtu_steps_per_frame(output, dt, n_steps, writes ? options.console : nullptr);
              if (field_recorder) // on every rank
                outputs.push_back(field_recorder(every, output.vtu_impact_peaks));
              else
                outputs.push_back(std::make_unique<VtuRecorder>(analysis.model, directory, every,
                                                                output.field_format,
                                                                output.vtu_impact_peaks));
              if (output.field_format == FieldFormat::xdmf)
                files.insert(files.end(), {"solution.xdmf", "solution.h5"}); // the index, the data
              else
                files.insert(files.end(), {"solution.pvd", "solution/"}); // the index, the frames
            }
          if (!ranks) // a rank of a partitioned run sees only its part of the members
            {
              section_limits = std::make_unique<SectionLimitStates>(analysis.model, elements,
                                                                    parameters.section_limits);
              if (!section_limits->empty())
                observers.push_back(section_limits.get());
            }
          if (writes)
            outputs.push_back(std::make_unique<RunSummary>(
              analysis, parameters, excitation, peaks, range, base_shears, plan, directory,
              options.plots && output.plots, solver, tangent_update, files, memory,
              section_limits && !section_limits->empty() ? section_limits.get() : nullptr));
        }
      if (options.progress && writes)
        outputs.push_back(std::make_unique<ProgressReport>(n_steps));
      for (const auto &output : outputs)
        observers.push_back(output.get());
      observers.insert(observers.end(), options.observers.begin(), options.observers.end());
    }

    RunResult
    StandardObservers::result(const RunStatus &status, const ResponseView &state) const
    {
      RunResult result;
      result.status               = status;
      result.statistics           = state.statistics();
      result.energy               = state.energy();
      result.max_energy_error     = state.max_energy_error();
      result.n_nonlinear_elements = state.elements.size();
      result.n_impacts            = state.impact_log().impacts().size();
      result.warnings             = range.warnings();
      return result;
    }

    /// A warning per massless equation (no mass in its row: a frame's joint
    /// rotation) given a displacement or velocity at t = 0 that the Newmark
    /// start replaces by the equilibrium's (integration/massless_start.cc).
    std::vector<std::string>
    replaced_initial_values(const Analysis &analysis, const TimeHistoryParameters &parameters)
    {
      const InitialConditionParameters &given = parameters.initial_conditions;
      if (given.at_rest() || parameters.time_integration.method == TimeIntegrationMethod::dopri ||
          parameters.time_integration.contact_model == ContactModel::nonsmooth)
        return {};
      const InitialState state = initial_state(given, analysis.model, parameters.input);
      const SparseMatrix &mass = analysis.system.mass;
      std::vector<bool>   massive(mass.rows(), false);
      for (int column = 0; column < mass.outerSize(); ++column)
        for (SparseMatrix::InnerIterator it(mass, column); it; ++it)
          if (it.value() != 0)
            massive[it.row()] = true;
      const std::vector<std::string> names = equation_names(analysis.model);
      std::string                    replaced;
      unsigned int                   n_replaced = 0;
      for (unsigned int i = 0; i < massive.size(); ++i)
        if (!massive[i] && (state.displacement[i] != 0 || state.velocity[i] != 0) &&
            n_replaced++ < 3)
          replaced += (replaced.empty() ? "" : ", ") + std::to_string(i) + " (" + names[i] + ")";
      if (n_replaced > 3)
        replaced += " and " + std::to_string(n_replaced - 3) + " more";
      std::vector<std::string> warnings;
      if (n_replaced > 0)
        warnings.push_back("Initial conditions: equation" + std::string(n_replaced > 1 ? "s " : " ") +
                           replaced + " carr" + (n_replaced > 1 ? "y" : "ies") +
                           " no mass: the displacement and velocity given are replaced by "
                           "those in equilibrium with the massive equations (a massless "
                           "equation has no state of its own)");
      return warnings;
    }
  } // namespace

  RunResult
  run_time_history(const Analysis &analysis, const RunParameters &parameters,
                   const Excitation &excitation, const RunOptions &options)
  {
    TimeHistory history(analysis, parameters.time_history, options.linear_solver);
    const unsigned long     n_steps = history.n_steps(excitation); // refused before any output
    const StandardObservers observers(analysis, parameters, excitation, history.state(),
                                      history.nonlinear_elements(), n_steps,
                                      history.linear_solver_name(), history.tangent_update(),
                                      options);
    const RunStatus status = history.run(excitation, observers.all(), options.interruptible);
    RunResult       result = observers.result(status, history.state());
    for (std::string &warning : replaced_initial_values(analysis, parameters.time_history))
      result.warnings.push_back(std::move(warning));
    return result;
  }

  RunResult
  run_partitioned_time_history(Analysis &analysis, const RunParameters &parameters,
                               const RunOptions &options, const MPI_Comm communicator)
  {
    // a caller's observers would see only this rank's part
    AssertThrow(options.observers.empty(), dealii::ExcNotImplemented());
    PartitionedStepper  stepper(analysis, parameters.time_history, communicator);
    TimeHistory         history(analysis, parameters.time_history, stepper);
    const Excitation   &excitation = stepper.excitation();
    const unsigned long n_steps    = history.n_steps(excitation);
    const auto field_recorder = [&](const unsigned int every, const bool impact_peaks) {
      return stepper.field_recorder(analysis.model, options.output_directory,
                                    parameters.output.field_format, every, impact_peaks);
    };
    // an error of a rank's observers (a recorder's bad entry) on every rank
    std::unique_ptr<StandardObservers> observers;
    std::exception_ptr                 error;
    try
      {
        observers = std::make_unique<StandardObservers>(
          analysis, parameters, excitation, history.state(), history.nonlinear_elements(), n_steps,
          stepper.history().linear_solver_name(), "refactorize", options, &stepper.rows(),
          field_recorder);
      }
    catch (const std::exception &)
      {
        error = std::current_exception();
      }
    agree_on_error(error, communicator);
    const RunStatus status = history.run(excitation, observers->all(), options.interruptible);
    if (!stepper.writes_files()) // the status and the integrator's figures
      {
        const PartitionedHistory &part = stepper.history();
        return {status,        part.statistics(),       part.energy(),
                part.max_energy_error(), part.n_local_elements(), 0, {}};
      }
    return observers->result(status, history.state());
  }
} // namespace poundfe
