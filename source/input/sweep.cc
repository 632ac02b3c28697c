// One checked input per value of a parameter sweep (input/sweep.h).
#include <poundfe/input/input_parameters.h>
#include <poundfe/input/override_origin.h>
#include <poundfe/input/sweep.h>
#include <poundfe/base/exceptions.h>

namespace poundfe
{
  InputParameters
  sweep_input(const SweepParameters &sweep, const std::string &file, const double value,
              const std::vector<ParameterOverride> &more)
  {
    InputParameters input;
    input.file = file;
    return sweep_input(sweep, input, value, more);
  }

  InputParameters
  sweep_input(const SweepParameters &sweep, const InputParameters &input, const double value,
              const std::vector<ParameterOverride> &more)
  {
    const std::string &section = sweep.section, &parameter = sweep.parameter;
    std::vector<ParameterOverride> overrides = input.overrides;
    overrides.push_back({parameter, format_value(value)});
    overrides.insert(overrides.end(), more.begin(), more.end());
    try
      {
        return read_parameters(input.file, overrides, input.overrides.size());
      }
    catch (const InputError &e) // say which value of the sweep it was
      {
        throw SweepValueError(e.file(), e.line(), e.parameter(),
                              "at " + section + " value " + parameter + " = " +
                                format_value(value) + ": " + e.problem());
      }
  }
} // namespace poundfe
