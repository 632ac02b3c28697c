// The nonlinear elements of a model, with their equations, in the order
// Bouc-Wen hinges, Bouc-Wen storeys, Bouc-Wen resisting planes (3D), gaps (in model.gaps order), springs,
// friction elements.
#ifndef poundfe_assembly_nonlinear_elements_h
#define poundfe_assembly_nonlinear_elements_h

#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/model/model.h>

namespace poundfe
{
  NonlinearElements make_nonlinear_elements(const Model &model);
} // namespace poundfe

#endif
