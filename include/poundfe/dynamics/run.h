// The time loop and the commands: time history (`run`), `modal`, `ground-motion`.
#ifndef poundfe_dynamics_run_h
#define poundfe_dynamics_run_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/output/observer.h>

#include <string>
#include <vector>

namespace poundfe
{
  struct RunOptions
  {
    std::string output_directory; // empty: no files at all (benchmarks, tests)
    std::string linear_solver;    // empty: the input's choice
    bool        csv   = true;     // the recorders of the input (Output/Recorders)
    bool        vtu   = true;
    bool        plots = true;
    bool        progress      = false; // steps, rate and ETA on a terminal
    bool        interruptible = false; // SIGINT/SIGTERM end the run after the current step
    /// The caller's own observers, after the standard ones (e.g. the Python
    /// module's callback every N steps).
    Observers   observers;
  };

  /// What a run with the standard observers reports to its caller.
  struct RunResult
  {
    RunStatus           status;
    IterationStatistics statistics;
    EnergyBalance       energy;
    double              max_energy_error   = 0;
    unsigned int        n_nonlinear_elements = 0;
    std::size_t         n_impacts          = 0;
    /// Where the response left the model's range (output/response_range.h).
    std::vector<std::string> warnings;
  };

  /// The time-history engine of one model: the nonlinear elements and the
  /// integrator (with its factorisations) are set up once, and each run()
  /// starts again from rest. Monte Carlo runs every realization through one.
  class TimeHistory
  {
  public:
    explicit TimeHistory(const Analysis &analysis, const std::string &linear_solver = "");
    TimeHistory(const TimeHistory &) = delete;
    TimeHistory &operator=(const TimeHistory &) = delete;

    /// From rest to the end time under `excitation`; the observers see the
    /// initial state, every step and the end. A NumericalError ends the
    /// run with status failed; when `interruptible`, SIGINT/SIGTERM end it
    /// after the current step with status interrupted. (A realization of a
    /// probabilistic analysis is not interruptible: its driver stops
    /// between realizations, so no partial realization is ever recorded.)
    RunStatus run(const Excitation &excitation, const Observers &observers,
                  bool interruptible = false);
    /// The same from (u0, v0) at t = 0 instead of rest (e.g. a
    /// continuation from an earlier run's final state).
    RunStatus run(const Vector &u0, const Vector &v0, const Excitation &excitation,
                  const Observers &observers, bool interruptible = false);

    /// The view observers read; valid for the life of this object.
    const ResponseView &state() const { return view; }
    const NonlinearElements &nonlinear_elements() const { return elements; }
    std::string tangent_update() const
    {
      return tangent_update_names().name(integrator.tangent_update());
    }
    std::string linear_solver_name() const { return integrator.linear_solver_name(); }

    /// Steps of the analysis time step to the end time.
    unsigned long n_steps(const Excitation &excitation) const;

    /// The nonlinear elements made again from `model`, a copy of the
    /// analysis' model whose nonlinear laws (not M, K, C, nor which DOFs an
    /// element joins) differ: the integrator keeps its factorisations, which
    /// depend on the elements' DOFs and tangent bases only.
    void replace_nonlinear_elements(const Model &model);

  private:
    const Analysis   &analysis;
    NonlinearElements elements; // before the integrator, which points to them
    NewmarkIntegrator integrator;
    ResponseView      view;
  };

  /// A time history with the standard observers: peaks, and with an output
  /// directory the input's recorders, the VTU series and the summary
  /// (summary.json, impacts.csv, profiles, plots).
  RunResult run_time_history(const Analysis &analysis, const Excitation &excitation,
                             const RunOptions &options);

  /// The `run` command: returns the exit status (0, or 2 on numerical failure).
  int run_command(const Analysis &analysis, const std::string &output_directory);
  /// The `modal` command.
  int modal_command(const Analysis &analysis, const std::string &output_directory);
  /// The `ground-motion` command; with n_realizations > 0, the samples of
  /// realizations 0..n-1 and their ensemble PSD against the target.
  int ground_motion_command(const InputParameters &input, const std::string &output_directory,
                            unsigned int n_realizations = 0);

  /// The excitation the input describes.
  Excitation make_excitation(const Analysis &analysis);
} // namespace poundfe

#endif
