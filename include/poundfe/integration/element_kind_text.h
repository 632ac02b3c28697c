// What a nonlinear element is ("a plastic hinge", "a friction element"),
// for the messages of the methods that do not take it (Dormand-Prince, the
// switching analysis).
#ifndef poundfe_integration_element_kind_text_h
#define poundfe_integration_element_kind_text_h

#include <poundfe/elements/nonlinear_element.h>

#include <string>

namespace poundfe
{
  std::string element_kind_text(const NonlinearElement &e);
} // namespace poundfe

#endif
