// `poundfe template KIND`: commented starting files for new models, one per
// kind of study (input/templates/KIND.prm, compiled into the program so
// that it needs no installed data). Each is tested to run as written
// (cli/templates).
#ifndef poundfe_input_templates_h
#define poundfe_input_templates_h

#include <string>
#include <vector>

namespace poundfe
{
  /// The kinds, sorted: frame, mesh, pounding, shear, stochastic.
  std::vector<std::string> template_kinds();

  /// The starting file of `kind`; nullptr if there is none.
  const std::string *input_template(const std::string &kind);
} // namespace poundfe

#endif
