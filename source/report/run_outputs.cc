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
#include <poundfe/output/vtu_series.h>

#include <algorithm>
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

  RunResult
  run_time_history(const Analysis &analysis, const RunParameters &parameters,
                   const Excitation &excitation, const RunOptions &options)
  {
    const OutputParameters &output = parameters.output;
    const double            dt     = parameters.time_history.time_integration.newmark.time_step;
    TimeHistory  history(analysis, parameters.time_history, options.linear_solver);
    const unsigned long n_steps = history.n_steps(excitation); // refused before any output
    PeakResponse  peaks(analysis.model, history.nonlinear_elements());
    ResponseRange range(analysis.model, peaks, output.drift_warning, output.rotation_warning);
    Observers     observers{&peaks, &range}; // first: the recorders read the floor response
    std::vector<std::unique_ptr<StepObserver>> outputs;
    const std::string &directory = options.output_directory;
    if (!directory.empty())
      {
        std::vector<std::string> files; // of the recorders and VTU, for summary.json
        if (options.csv) // first: it checks its input before anything is written
          {
            Recorders recorders = make_recorders(output.recorders, parameters.time_history.input.file,
                                                 history.state(), peaks, dt, directory);
            outputs = std::move(recorders.observers);
            files   = std::move(recorders.files);
          }
        else // the recorders prepare it after checking their input
          prepare_output_directory(directory);
        if (options.csv && output.floor_spectra)
          {
            outputs.push_back(std::make_unique<FloorSpectra>(
              peaks, parameters.spectrum.periods(), parameters.spectrum.damping_ratios, directory));
            files.push_back(FloorSpectra::file_name);
          }
        if (options.vtu && output.vtu_interval > 0)
          {
            outputs.push_back(std::make_unique<VtuRecorder>(
              analysis.model, directory, vtu_steps_per_frame(output, dt, n_steps, options.console),
              output.field_format));
            if (output.field_format == FieldFormat::xdmf)
              files.insert(files.end(), {"solution.xdmf", "solution.h5"}); // the index, the data
            else
              files.insert(files.end(), {"solution.pvd", "solution/"}); // the index, the frames
          }
        outputs.push_back(std::make_unique<RunSummary>(
          analysis, parameters, excitation, peaks, range, directory, options.plots && output.plots,
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

} // namespace poundfe
