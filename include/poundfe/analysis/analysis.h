// Everything a command needs before it starts: prm -> Model -> M, K ->
// per-building modes -> Rayleigh C. Built once; read-only afterwards.
#ifndef poundfe_analysis_analysis_h
#define poundfe_analysis_analysis_h

#include <poundfe/analysis/modal.h>
#include <poundfe/assembly/linear_system.h>
#include <poundfe/model/model.h>
#include <poundfe/analysis/input_parameters.h>

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
  };

  /// Throws InputError (bad input) or NumericalError (e.g. a mechanism).
  Analysis prepare_analysis(const InputParameters &input);

  /// Opens a command's summary.json with program, command, input and status.
  void begin_summary(JsonWriter &json, const std::string &command, const InputParameters &input,
                     const std::string &status = "completed");

  /// A command's timer table, on a terminal only (stdout and stderr are
  /// terminals: pipes, log files and tests see nothing).
  void print_timing(const dealii::TimerOutput &timer);
} // namespace poundfe

#endif
