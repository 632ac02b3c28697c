// One checked input per value of a parameter sweep (base/sweep_parameters.h):
// read_parameters of the file with the override, so every value goes
// through the checks the file does. `poundfe sweep` is commands/sweep_command.cc.
#ifndef poundfe_input_sweep_h
#define poundfe_input_sweep_h

#include <poundfe/base/sweep_parameters.h>

#include <string>
#include <vector>

namespace poundfe
{
  struct InputParameters;
  struct ParameterOverride;

  /// The input of `file` with `sweep`'s parameter set to `value` (and then
  /// the `more` overrides), checked. Throws InputError naming the path and
  /// the value.
  InputParameters sweep_input(const SweepParameters &sweep, const std::string &file, double value,
                              const std::vector<ParameterOverride> &more = {});
  /// The same for the file `input` was read from, with the overrides it
  /// was read with first.
  InputParameters sweep_input(const SweepParameters &sweep, const InputParameters &input,
                              double value, const std::vector<ParameterOverride> &more = {});
} // namespace poundfe

#endif
