// The compliant foundation of a 3D shear building (equations and sources:
// include/poundfe/model/plan_foundation.h; doc/theory.md §1.16).
#include <poundfe/model/plan_foundation.h>

#include <cmath>

namespace poundfe
{
  Foundation
  plan_foundation(const FoundationParameters &p, const unsigned int b, const unsigned int base,
                  const unsigned int rocking_node, const std::array<double, 2> &direction,
                  const bool vertical)
  {
    const FoundationImpedance3D &z = p.impedance_3d;
    const double c = direction[0], s = direction[1];
    const std::vector<unsigned int> sway{Model::dof(base, Component::ux),
                                         Model::dof(base, Component::uy)};
    const std::vector<unsigned int> rotation{n_dofs_per_node * rocking_node + 1,
                                             n_dofs_per_node * rocking_node + 2};
    Foundation f;
    f.node                 = base;
    f.rocking_node         = rocking_node;
    f.building             = b;
    f.horizontal_stiffness = z.sway_stiffness[0];
    f.rocking_stiffness    = z.rocking_stiffness[1];
    f.horizontal_damping   = z.sway_damping[0];
    f.rocking_damping      = z.rocking_damping[1];
    f.mass                 = p.mass;
    f.rotary_inertia       = p.rotary_inertia;
    f.parts = {
      {sway, {c, s}, z.sway_stiffness[0], z.sway_damping[0], p.mass, "_sway_x"},
      {sway, {-s, c}, z.sway_stiffness[1], z.sway_damping[1], p.mass, "_sway_y"},
      {{Model::dof(base, Component::rz)}, {1.0}, z.torsional_stiffness, z.torsional_damping,
       p.polar_inertia, "_torsion"},
      {rotation, {c, s}, z.rocking_stiffness[0], z.rocking_damping[0], p.rotary_inertia_x,
       "_rocking_x"},
      {rotation, {-s, c}, z.rocking_stiffness[1], z.rocking_damping[1], p.rotary_inertia,
       "_rocking_y"}};
    if (vertical) // before the rockings (the rocking about y last: foundation_report.cc)
      f.parts.insert(f.parts.begin() + 3,
                     {{n_dofs_per_node * rocking_node}, {1.0}, z.vertical_stiffness,
                      z.vertical_damping, p.mass + z.added_mass, "_vertical"});
    return f;
  }

  unsigned int
  add_plan_foundation(Model &model, const FoundationParameters &p, const unsigned int b,
                      const unsigned int base, const double angle, const bool vertical)
  {
    model.nodes[base].fixed = {{false, false, false}};
    Node rocking;
    rocking.position    = model.nodes[base].position;
    rocking.building    = b;
    rocking.generalized = true;                 // (u_z, θ_x, θ_y)
    rocking.fixed       = {{!vertical, false, false}}; // vertical motion: frames only
    // free vertically (under a frame) its slot 0 is a vertical translation:
    // the vertical ground motion loads the foundation's mass too
    rocking.joint_translation_z = vertical;
    model.nodes.push_back(rocking);
    const unsigned int rocking_node = model.nodes.size() - 1;

    model.foundations.push_back(
      plan_foundation(p, b, base, rocking_node, {{std::cos(angle), std::sin(angle)}}, vertical));
    return rocking_node;
  }
} // namespace poundfe
