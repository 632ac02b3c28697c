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
      fixed.nodes[f.node].fixed = {{true, true, true}};
    for (StoreyLink &link : fixed.links)
      {
        link.rocking_node = -1;
        link.rocking_arm  = 0;
      }
    fixed.foundations.clear();
    fixed.number_equations();
    return fixed;
  }

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
        const Vector r           = fixed_system.influence.segment(range[0], n);
        const double gamma       = mass_phi.dot(r); // φ mass-normalised: M* = Γ²
        Vector       heights     = Vector::Zero(n);
        for (unsigned int node = 0; node < fixed.n_nodes(); ++node)
          {
            const int e = fixed.equation(Model::dof(node, Component::ux));
            if (e >= int(range[0]) && e < int(range[1]))
              heights[e - range[0]] =
                fixed.nodes[node].position.y - model.nodes[f.node].position.y;
          }
        p.effective_height    = mass_phi.dot(heights) / gamma;
        const double omega    = 2 * pi / p.fixed_base_period;
        p.effective_stiffness = gamma * gamma * omega * omega;
        const double k_x = f.horizontal_stiffness, k_theta = f.rocking_stiffness;
        p.code_ratio = std::sqrt(1 + p.effective_stiffness / k_x *
                                       (1 + k_x * p.effective_height * p.effective_height /
                                              k_theta));
        result.push_back(p);
      }
    return result;
  }
} // namespace poundfe
