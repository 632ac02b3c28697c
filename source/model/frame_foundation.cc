// A compliant foundation under a 2D shear building or frame (equations and
// sources: include/poundfe/model/frame_foundation.h; doc/theory.md §1.16).
#include <poundfe/model/frame_foundation.h>

namespace poundfe
{
  Foundation
  planar_foundation(const FoundationParameters &p, const unsigned int b, const unsigned int node,
                    const bool vertical)
  {
    const FoundationImpedance &z = p.impedance;
    Foundation                 f;
    f.node                 = node;
    f.building             = b;
    f.horizontal_stiffness = z.horizontal_stiffness;
    f.rocking_stiffness    = z.rocking_stiffness;
    f.horizontal_damping   = z.horizontal_damping;
    f.rocking_damping      = z.rocking_damping;
    f.mass                 = p.mass;
    f.rotary_inertia       = p.rotary_inertia;
    f.parts = {{{Model::dof(node, Component::ux)}, {1.0}, f.horizontal_stiffness,
                f.horizontal_damping, f.mass, "_sway"}};
    if (vertical)
      f.parts.push_back({{Model::dof(node, Component::uy)}, {1.0}, z.vertical_stiffness,
                         z.vertical_damping, p.mass + z.added_mass, "_vertical"});
    // the rocking last (output/foundation_report.cc)
    f.parts.push_back({{Model::dof(node, Component::rz)}, {1.0}, f.rocking_stiffness,
                       f.rocking_damping, f.rotary_inertia, "_rocking"});
    return f;
  }

  void
  add_planar_foundation(Model &model, const FoundationParameters &p, const unsigned int b,
                        const unsigned int node, const bool vertical)
  {
    model.nodes[node].fixed = {{false, !vertical, false}};
    model.foundations.push_back(planar_foundation(p, b, node, vertical));
  }

  unsigned int
  add_frame_foundation(Model &model, const FoundationParameters &p, const unsigned int b,
                       const Building &building)
  {
    const double x_o = 0.5 * (building.left + building.right);
    Node         o;
    o.position = {x_o, building.base_level};
    o.building = b;
    model.nodes.push_back(o);
    const unsigned int foundation = model.nodes.size() - 1;
    add_planar_foundation(model, p, b, foundation, true);

    const unsigned int u_0   = Model::dof(foundation, Component::ux);
    const unsigned int v_0   = Model::dof(foundation, Component::uy);
    const unsigned int theta = Model::dof(foundation, Component::rz);
    const auto         tie   = [&](const unsigned int node, const double x, const bool clamped) {
      model.constraints.push_back({Model::dof(node, Component::ux), {{u_0, 1.0}}});
      model.constraints.push_back(
        {Model::dof(node, Component::uy), {{v_0, 1.0}, {theta, x - x_o}}});
      if (clamped)
        model.constraints.push_back({Model::dof(node, Component::rz), {{theta, 1.0}}});
      model.nodes[node].fixed = {{false, false, false}};
    };
    // the supports (column bases) and the hinge nodes that share their
    // translations (a base hinge's own rotation stays free)
    for (unsigned int n = 0; n < foundation; ++n)
      {
        const Node &node = model.nodes[n];
        if (node.building != b || node.tied_to >= 0 || !(node.fixed[0] && node.fixed[1]))
          continue;
        const double x = node.position.x;
        for (unsigned int h = 0; h < foundation; ++h)
          if (model.nodes[h].tied_to == int(n))
            tie(h, x, false);
        tie(n, x, node.fixed[2]);
      }
    return foundation;
  }
} // namespace poundfe
