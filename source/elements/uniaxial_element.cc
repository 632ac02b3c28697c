#include <poundfe/elements/uniaxial_element.h>

namespace poundfe
{
  UniaxialElement
  UniaxialElement::clone() const
  {
    UniaxialElement copy;
    copy.kind                = kind;
    copy.building            = building;
    copy.label               = label;
    copy.equations           = equations;
    copy.signs               = signs;
    copy.reference_stiffness = reference_stiffness;
    copy.law                 = law ? law->clone() : nullptr;
    return copy;
  }
} // namespace poundfe
