// The mass of a floor and the colliding masses of a 2D gap, as the model
// builder sets a gap's effective mass when Contact/Effective mass is not
// given: m_e = m1 m2/(m1 + m2) of the floors of the two buildings nearest
// the gap's level (the floor itself for a barrier). A random floor mass
// (dynamics/model_parameter.h) sets it again from the same function.
#ifndef poundfe_model_floor_mass_h
#define poundfe_model_floor_mass_h

#include <poundfe/model/model.h>

namespace poundfe
{
  /// Mass lumped at the nodes of `floor`.
  double floor_mass(const Model &model, const Floor &floor);

  /// The floors' effective mass of a 2D gap (between two buildings: m1 m2/(m1
  /// + m2); a barrier: the floor's mass).
  double floor_effective_mass(const Model &model, const Gap &gap);
} // namespace poundfe

#endif
