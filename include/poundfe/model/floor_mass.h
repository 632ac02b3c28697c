// The mass of a floor and the colliding masses of a 2D gap, as the model
// builder sets a gap's effective mass when Contact/Effective mass is not
// given: m_e = m1 m2/(m1 + m2) of the floors of the two buildings nearest
// the gap's level (the floor itself for a barrier). A random floor mass
// (dynamics/model_parameter.h) sets it again from the same function.
#ifndef poundfe_model_floor_mass_h
#define poundfe_model_floor_mass_h

#include <poundfe/model/model.h>

#include <vector>

namespace poundfe
{
  /// The entries of Model::masses of each node, for the floor masses of
  /// many floors at once: entries[start[n], start[n + 1]) are node n's, in
  /// their order in Model::masses.
  struct MassesByNode
  {
    std::vector<unsigned int> start, entries;
  };

  /// The index of `model`'s masses by node (O(nodes + masses)).
  MassesByNode masses_by_node(const Model &model);

  /// Mass lumped at the nodes of `floor`: the masses on its nodes summed in
  /// their order in Model::masses. With `index` (masses_by_node of the
  /// same model) in O(floor nodes), else by a scan of every mass.
  double floor_mass(const Model &model, const Floor &floor, const MassesByNode *index = nullptr);

  /// The floors' effective mass of a 2D gap (between two buildings: m1 m2/(m1
  /// + m2); a barrier: the floor's mass). `index` as for floor_mass: a
  /// builder making many gaps gives one (without it, a row of 100 frames
  /// of 290 storeys spent half its set-up here).
  double floor_effective_mass(const Model &model, const Gap &gap,
                              const MassesByNode *index = nullptr);
} // namespace poundfe

#endif
