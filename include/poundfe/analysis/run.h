// The commands: time history (`run`), `modal`, `ground-motion`.
#ifndef poundfe_analysis_run_h
#define poundfe_analysis_run_h

#include <poundfe/analysis/analysis.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/integration/newmark.h>

#include <string>
#include <vector>

namespace poundfe
{
  struct RunOptions
  {
    std::string output_directory; // empty: no files at all (benchmarks, tests)
    std::string linear_solver;    // empty: the input's choice
    bool        csv   = true;
    bool        vtu   = true;
    bool        plots = true;
  };

  struct RunResult
  {
    bool                completed = false;
    std::string         message;
    unsigned long       steps     = 0;
    double              end_time  = 0;
    double              wall_time = 0; // s, stepping loop with outputs
    std::vector<double> peak_drift_ratio;   // FloorResponse layout
    std::vector<double> peak_acceleration;
    std::vector<double> peak_displacement;
    // Nonlinear elements (hinges, Bouc-Wen storeys), in model order.
    std::vector<std::string> element_labels;
    std::vector<double>      peak_element_deformation;
    std::vector<double>      element_ductility;
    IterationStatistics      statistics;
    EnergyBalance            energy;
    double                   max_energy_error = 0;
    std::vector<Impact>      impacts; // every contact episode
    double min_clearance = 0; // smallest gap opening (negative: penetration); inf without gaps
    std::vector<std::string> files;
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

    RunResult run(const Excitation &excitation, const RunOptions &options);

  private:
    const Analysis   &analysis;
    NonlinearElements elements; // before the integrator, which points to them
    NewmarkIntegrator integrator;
  };

  /// Time history with Newmark (Newton on the nonlinear elements); writes the outputs of RunOptions.
  /// A NumericalError during stepping is caught: the results so far are
  /// written and `completed` is false.
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

  /// The Newmark and Newton settings of the input's Time integration and
  /// Contact sections.
  NewmarkParameters newmark_parameters(const InputParameters &input);

  /// The excitation the input describes.
  Excitation make_excitation(const Analysis &analysis);
} // namespace poundfe

#endif
