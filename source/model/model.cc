#include <poundfe/model/model.h>

#include <cmath>

namespace poundfe
{
  void
  Model::number_equations()
  {
    equation_of_dof.assign(n_dofs(), -1);
    constraint_of_dof.assign(n_dofs(), -1);
    combined = false;
    for (unsigned int i = 0; i < constraints.size(); ++i)
      constraint_of_dof[constraints[i].dof] = i;
    first_equation_of_building.assign(buildings.size() + 1, 0);
    n_free = 0;
    for (unsigned int b = 0; b < buildings.size(); ++b)
      {
        first_equation_of_building[b] = n_free;
        // A building's nodes need not be contiguous: contact splits columns
        // after all buildings are built.
        for (unsigned int n = 0; n < nodes.size(); ++n)
          if (nodes[n].building == b)
            for (unsigned int c = 0; c < n_dofs_per_node; ++c)
              if (!nodes[n].fixed[c] && (nodes[n].tied_to < 0 || c == 2) &&
                  constraint_of_dof[n_dofs_per_node * n + c] < 0)
                equation_of_dof[n_dofs_per_node * n + c] = n_free++;
        // Slaves of one master with coefficient 1 share its equation (the
        // masters are free DOFs of the same building, numbered above).
        for (const DofConstraint &constraint : constraints)
          if (nodes[constraint.dof / n_dofs_per_node].building == b)
            {
              const bool shared =
                constraint.masters.size() == 1 && constraint.masters[0].second == 1.0;
              equation_of_dof[constraint.dof] =
                shared ? equation_of_dof[constraint.masters[0].first] : -1;
              combined = combined || !shared;
            }
        // Hinge nodes share their joint's translations.
        for (unsigned int n = 0; n < nodes.size(); ++n)
          if (nodes[n].building == b && nodes[n].tied_to >= 0)
            for (unsigned int c = 0; c < 2; ++c)
              equation_of_dof[n_dofs_per_node * n + c] =
                equation_of_dof[n_dofs_per_node * nodes[n].tied_to + c];
      }
    first_equation_of_building[buildings.size()] = n_free;
  }

  void
  Model::equation_terms(const unsigned int dof, std::vector<std::pair<int, double>> &terms) const
  {
    terms.clear();
    const int own = equation_of_dof[dof];
    if (own >= 0)
      {
        terms.emplace_back(own, 1.0);
        return;
      }
    const int c = constraint_of_dof[dof];
    if (c < 0)
      return;
    for (const auto &[master, coefficient] : constraints[c].masters)
      if (equation_of_dof[master] >= 0)
        terms.emplace_back(equation_of_dof[master], coefficient);
  }

  void
  PlaneLink::terms(std::vector<unsigned int> &dofs, std::vector<double> &weights) const
  {
    dofs.clear();
    for (const unsigned int node : nodes)
      for (const Component c : {Component::ux, Component::uy, Component::rz})
        dofs.push_back(Model::dof(node, c));
    weights.assign(coefficients.begin(), coefficients.end());
    if (rocking_node < 0)
      return;
    for (unsigned int slot = 1; slot <= 2; ++slot)
      {
        dofs.push_back(n_dofs_per_node * rocking_node + slot);
        weights.push_back(rocking_coefficients[slot - 1]);
      }
  }

  std::array<unsigned int, 2>
  Model::equation_range(const unsigned int b) const
  {
    return {{first_equation_of_building[b], first_equation_of_building[b + 1]}};
  }

  double
  Model::total_mass(const unsigned int b) const
  {
    double mass = 0;
    for (const NodalMass &m : masses)
      if (nodes[m.node].building == b)
        mass += m.mass;
    for (const Member &member : members)
      if (member.building == b)
        {
          const Point2 &p0 = nodes[member.nodes[0]].position;
          const Point2 &p1 = nodes[member.nodes[1]].position;
          mass += member.section.mass_per_length *
                  std::hypot(p1.x - p0.x, p1.y - p0.y);
        }
    for (const Member3D &member : members_3d)
      if (member.building == b)
        mass += member.section.mass_per_length *
                std::hypot(member.ends[1][0] - member.ends[0][0],
                           member.ends[1][1] - member.ends[0][1],
                           member.ends[1][2] - member.ends[0][2]);
    return mass;
  }
} // namespace poundfe
