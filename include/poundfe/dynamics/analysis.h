// Everything a command needs before it starts: prm -> Model -> M, K ->
// per-building modes -> Rayleigh C. Built once; read-only afterwards.
#ifndef poundfe_dynamics_analysis_h
#define poundfe_dynamics_analysis_h

#include <poundfe/dynamics/modal.h>
#include <poundfe/assembly/linear_system.h>
#include <poundfe/model/model.h>
#include <poundfe/input/input_parameters.h>

#include <string>
#include <vector>

namespace dealii
{
  class TimerOutput;
}

namespace poundfe
{
  class JsonWriter;

  struct Analysis
  {
    InputParameters    input;
    Model              model;
    LinearSystem       system;
    std::vector<Modes> building_modes; // for Rayleigh damping and reports
    Modes              modes;          // whole model
    /// Input that is valid but probably not what was meant (damping_warnings).
    std::vector<std::string> warnings;
  };

  /// Throws InputError (bad input) or NumericalError (e.g. a mechanism).
  /// Prints each of the analysis' warnings once per process, on stderr
  /// ("poundfe: warning: ..."), where writes_outputs().
  Analysis prepare_analysis(const InputParameters &input);

  /// The suspicious damping choices of each building: Rayleigh damping
  /// fitted at a mode whose kinetic energy is mostly vertical (a beam or
  /// column mode of a frame, not a storey mode), mass-proportional damping
  /// alone (a1 = 0: the higher modes nearly undamped), given coefficients
  /// both 0 (no damping), and damping entries the chosen Type ignores.
  std::vector<std::string> damping_warnings(const Analysis &analysis);

  /// Whether this process writes files and messages: rank 0 of
  /// MPI_COMM_WORLD, or the only process when MPI is not initialised.
  /// (With a solver that needs MPI, every rank of `mpirun -np P poundfe
  /// run` runs the same analysis; rank 0 alone writes.)
  bool writes_outputs();

  /// Opens a command's summary.json with program, command, input and status.
  void begin_summary(JsonWriter &json, const std::string &command, const InputParameters &input,
                     const std::string &status = "completed");

  /// A command's timer table, on a terminal only (stdout and stderr are
  /// terminals: pipes, log files and tests see nothing).
  void print_timing(const dealii::TimerOutput &timer);
} // namespace poundfe

#endif
