// First periods on compliant and fixed bases, and the ASCE 7-16 §19.2.1.1
// lengthening (equations and sources: include/poundfe/dynamics/
// foundation_periods.h, doc/theory.md §1.16).
#include <poundfe/assembly/linear_system.h>
#include <poundfe/dynamics/foundation_periods.h>
#include <poundfe/dynamics/modal.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    /// The first mode of building b alone (its block of M and K).
    Modes
    first_mode(const Model &model, const LinearSystem &system, const unsigned int b)
    {
      const auto range = model.equation_range(b);
      return compute_modes(block(system.mass, range), block(system.stiffness, range),
                           system.influence.segment(range[0], range[1] - range[0]), 1);
    }
  } // namespace

  Model
  fixed_base_model(const Model &model)
  {
    Model fixed = model;
    for (const Foundation &f : model.foundations)
      {
        fixed.nodes[f.node].fixed = {{true, true, true}};
        if (f.rocking_node >= 0)
          fixed.nodes[f.rocking_node].fixed = {{true, true, true}};
      }
    for (StoreyLink &link : fixed.links)
      {
        link.rocking_node = -1;
        link.rocking_arm  = 0;
      }
    for (PlaneLink &link : fixed.plane_links)
      link.rocking_node = -1;
    fixed.foundations.clear();
    fixed.number_equations();
    return fixed;
  }

  namespace
  {
    /// In 3D: the foundation's sway stiffness along the horizontal unit
    /// vector e and its rocking stiffness about n = (-e_y, e_x) (the
    /// rotation that moves the building along e): e^T K e over the parts.
    std::array<double, 2>
    stiffnesses_along(const Foundation &f, const std::array<double, 2> &e)
    {
      std::array<double, 2> k{{0, 0}};
      for (const FoundationPart &part : f.parts)
        if (part.dofs.size() == 2)
          {
            const bool   rocking = part.dofs[0] % n_dofs_per_node == 1; // θ_x: slot 1
            const double a = rocking ? -part.coefficients[0] * e[1] + part.coefficients[1] * e[0] :
                                       part.coefficients[0] * e[0] + part.coefficients[1] * e[1];
            k[rocking ? 1 : 0] += part.stiffness * a * a;
          }
      return k;
    }
  } // namespace

  std::vector<FoundationPeriods>
  foundation_periods(const Model &model)
  {
    if (model.foundations.empty())
      return {};
    const Model        fixed          = fixed_base_model(model);
    const LinearSystem flexible_system = assemble_mass_and_stiffness(model);
    const LinearSystem fixed_system    = assemble_mass_and_stiffness(fixed);
    std::vector<FoundationPeriods> result;
    for (const Foundation &f : model.foundations)
      {
        FoundationPeriods p;
        p.building               = f.building;
        const Modes rigid        = first_mode(fixed, fixed_system, f.building);
        p.fixed_base_period      = rigid.period(0);
        p.flexible_base_period   = first_mode(model, flexible_system, f.building).period(0);
        const auto   range       = fixed.equation_range(f.building);
        const auto   n           = range[1] - range[0];
        const Vector mass_phi    = block(fixed_system.mass, range) * rigid.shapes.col(0);
        // the mode's direction in plan (3D): e along (Γ_x, Γ_y), Γ_e = |Γ|
        std::array<double, 2> e{{1, 0}};
        if (f.rocking_node >= 0)
          {
            const double gx = mass_phi.dot(fixed_system.influence.segment(range[0], n));
            const double gy = mass_phi.dot(fixed_system.influence_y.segment(range[0], n));
            e = {{gx / std::hypot(gx, gy), gy / std::hypot(gx, gy)}};
          }
        Vector heights = Vector::Zero(n), r = Vector::Zero(n);
        for (unsigned int node = 0; node < fixed.n_nodes(); ++node)
          for (const Component c : {Component::ux, Component::uy})
            {
              const int eq = fixed.equation(Model::dof(node, c));
              if (fixed.nodes[node].generalized || eq < int(range[0]) || eq >= int(range[1]))
                continue;
              // assigned, not summed: a frame's hinge nodes share their joint's
              // equations (the same height and direction)
              const double along = c == Component::ux ? e[0] : e[1];
              heights[eq - range[0]] =
                along * (fixed.nodes[node].position.y - model.nodes[f.node].position.y);
              r[eq - range[0]] = along;
            }
        const double gamma    = mass_phi.dot(r); // φ mass-normalised: M* = Γ²
        p.effective_height    = mass_phi.dot(heights) / gamma;
        const double omega    = 2 * pi / p.fixed_base_period;
        p.effective_stiffness = gamma * gamma * omega * omega;
        const std::array<double, 2> k =
          f.rocking_node >= 0 ? stiffnesses_along(f, e) :
                                std::array<double, 2>{{f.horizontal_stiffness, f.rocking_stiffness}};
        const double k_x = k[0], k_theta = k[1];
        p.code_ratio = std::sqrt(1 + p.effective_stiffness / k_x *
                                       (1 + k_x * p.effective_height * p.effective_height /
                                              k_theta));
        result.push_back(p);
      }
    return result;
  }
} // namespace poundfe
