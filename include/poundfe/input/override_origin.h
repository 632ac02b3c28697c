// Where a refused entry came from when no line of the file holds it: the
// override that set it (--set on the command line, overrides= in Python),
// named before the problem, e.g.
//   frame.prm: parameter 'Building 1/Group sections': --set 'Building
//   1/Group sections=col, beam': has 2 names ...
// The reader applies it to the checks that follow the parsing
// (read_parameters), the dispatcher to the refusals of a command's run (the
// model builder's), so that the command line and Python say the same.
#ifndef poundfe_input_override_origin_h
#define poundfe_input_override_origin_h

#include <poundfe/base/exceptions.h>

#include <string>
#include <vector>

namespace poundfe
{
  struct ParameterOverride;

  /// "--set 'Section/Entry=value': ", what a refusal of the entry `o` set
  /// starts its problem with.
  std::string override_origin(const ParameterOverride &o);

  /// `error` with its problem led by the last override of its entry (a
  /// field override "Section/Entry:k" counts as its entry), when it has no
  /// line and an override set that entry; otherwise `error` itself.
  InputError with_override_origin(const InputError                     &error,
                                  const std::vector<ParameterOverride> &overrides);
} // namespace poundfe

#endif
