// Where a refused entry came from when no line of the file holds it: the
// override that set it (--set on the command line, overrides= in Python),
// named after the problem, e.g.
//   frame.prm: parameter 'Building 1/Group sections': has 2 names ...
//   (--set 'Building 1/Group sections=col, beam')
// The reader applies it to the checks that follow the parsing
// (read_parameters), the dispatcher to the refusals of a command's run (the
// model builder's), so that the command line and Python say the same. Only
// the user's own overrides are named, once: a command that reads the file
// again with overrides of its own (a sweep's value, bifurcation's time step
// and end time) names none of those.
#ifndef poundfe_input_override_origin_h
#define poundfe_input_override_origin_h

#include <poundfe/base/exceptions.h>

#include <cstddef>
#include <string>
#include <vector>

namespace poundfe
{
  struct InputParameters;
  struct ParameterOverride;

  /// " (--set 'Section/Entry=value')", what a refusal of the entry `o` set
  /// ends its problem with.
  std::string override_origin(const ParameterOverride &o);

  /// `error` with its problem followed by the last override of its entry (a
  /// field override "Section/Entry:k" counts as its entry), when it has no
  /// line, that override is one of the first `n_named` (the user's; the
  /// others a command's own) and the problem does not name it yet;
  /// otherwise `error` itself.
  InputError with_override_origin(const InputError                     &error,
                                  const std::vector<ParameterOverride> &overrides,
                                  std::size_t                           n_named);
  /// The same with every override the user's.
  InputError with_override_origin(const InputError                     &error,
                                  const std::vector<ParameterOverride> &overrides);

  /// read_parameters(file, overrides) (input_parameters.h) where only the
  /// first `n_named` overrides are the user's, the rest a command's own:
  /// a refusal names only the user's.
  InputParameters read_parameters(const std::string                    &file,
                                  const std::vector<ParameterOverride> &overrides,
                                  std::size_t                           n_named);

  /// The refusal of one value of a sweep (input/sweep.h), whose origin the
  /// sweep has named already: the swept value or a command's own override
  /// is no --set, a --set of another entry is. The dispatcher leaves it as
  /// it is.
  class SweepValueError : public InputError
  {
  public:
    using InputError::InputError;
  };
} // namespace poundfe

#endif
