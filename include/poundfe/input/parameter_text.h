// A parameter file's text read without a file (Python's Model): the same
// reader, checks and messages as read_parameters (input_parameters.h), the
// text named in messages as the caller says. Implemented in
// input_parameters.cc, beside the file's reader.
#ifndef poundfe_input_parameter_text_h
#define poundfe_input_parameter_text_h

#include <poundfe/input/input_parameters.h>

#include <string>
#include <vector>

namespace poundfe
{
  /// Reads and checks `text`, a .prm file's text (`name` ends in .prm) or a
  /// .json file's (`name` ends in .json), with `overrides` as
  /// read_parameters does. Messages name `name` and the line in `text`;
  /// relative file names it holds are taken against the working directory.
  /// The Input's `file` is `name`, which need not exist: a command that
  /// reads its file again (a sweep) needs a file.
  InputParameters read_parameter_text(const std::string &name, const std::string &text,
                                      const std::vector<ParameterOverride> &overrides);
} // namespace poundfe

#endif
