// The nonlinear elements of a model, with their equations, in the order
// fibre members (beam-columns of Member model = fibre), Bouc-Wen hinges, Bouc-Wen storeys, Bouc-Wen resisting planes (3D), gaps (in model.gaps order), springs,
// friction elements.
#ifndef poundfe_assembly_nonlinear_elements_h
#define poundfe_assembly_nonlinear_elements_h

#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/model/model.h>

#include <array>

namespace poundfe
{
  NonlinearElements make_nonlinear_elements(const Model &model);

  /// Only the elements with an equation in [first, last) (a rank's share
  /// of a model partitioned by building: those on its equations, the gaps
  /// to other ranks' buildings included), the others never kept.
  NonlinearElements make_nonlinear_elements(const Model &model, std::array<unsigned int, 2> kept);
} // namespace poundfe

#endif
