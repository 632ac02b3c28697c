#include <poundfe/assembly/linear_system.h>
#include <poundfe/elements/frame_element.h>

namespace poundfe
{
  namespace
  {
    using Triplets = std::vector<Eigen::Triplet<double>>;

    /// Scatter an element matrix over node DOFs; fixed DOFs are dropped
    /// (homogeneous supports, so they contribute nothing to the free rows).
    template <typename ElementMatrix>
    void
    scatter(const Model &model, const std::vector<unsigned int> &dofs,
            const ElementMatrix &matrix, Triplets &triplets)
    {
      for (unsigned int i = 0; i < dofs.size(); ++i)
        {
          const int row = model.equation(dofs[i]);
          if (row < 0)
            continue;
          for (unsigned int j = 0; j < dofs.size(); ++j)
            {
              const int column = model.equation(dofs[j]);
              if (column >= 0 && matrix(i, j) != 0)
                triplets.emplace_back(row, column, matrix(i, j));
            }
        }
    }

    std::vector<unsigned int>
    member_dofs(const Member &member)
    {
      std::vector<unsigned int> dofs;
      for (const unsigned int node : member.nodes)
        for (unsigned int c = 0; c < n_dofs_per_node; ++c)
          dofs.push_back(n_dofs_per_node * node + c);
      return dofs;
    }

    std::vector<unsigned int>
    link_dofs(const StoreyLink &link)
    {
      return {Model::dof(link.nodes[0], Component::ux), Model::dof(link.nodes[1], Component::ux)};
    }

    Eigen::Matrix2d
    two_node_spring(const double k)
    {
      Eigen::Matrix2d m;
      m << k, -k, -k, k;
      return m;
    }

    SparseMatrix
    from_triplets(const unsigned int n, const Triplets &triplets)
    {
      SparseMatrix matrix(n, n);
      matrix.setFromTriplets(triplets.begin(), triplets.end());
      matrix.makeCompressed();
      return matrix;
    }
  } // namespace

  LinearSystem
  assemble_mass_and_stiffness(const Model &model)
  {
    const unsigned int n = model.n_equations();
    Triplets           k_triplets, m_triplets;
    for (const Member &member : model.members)
      {
        const FrameElement element(model.nodes[member.nodes[0]].position,
                                   model.nodes[member.nodes[1]].position, member.section);
        const auto dofs = member_dofs(member);
        scatter(model, dofs, element.stiffness(), k_triplets);
        scatter(model, dofs, element.mass(model.mass_matrix), m_triplets);
      }
    for (const StoreyLink &link : model.links)
      scatter(model, link_dofs(link), two_node_spring(link.stiffness), k_triplets);
    // The linear part of the nonlinear springs to the ground (SD: K, Duffing: k1).
    for (const Spring &spring : model.springs)
      scatter(model, {Model::dof(spring.node, Component::ux)},
              Eigen::Matrix<double, 1, 1>(spring.law.stiffness), k_triplets);
    // Hinges enter with their initial stiffness: the linear part of K (and of
    // stiffness-proportional damping) is the elastic structure.
    for (const Hinge &hinge : model.hinges)
      scatter(model,
              {Model::dof(hinge.member_node, Component::rz),
               Model::dof(hinge.joint_node, Component::rz)},
              two_node_spring(hinge.law.stiffness), k_triplets);
    for (const NodalMass &mass : model.masses)
      for (const Component c : {Component::ux, Component::uy})
        {
          const int row = model.equation(Model::dof(mass.node, c));
          if (row >= 0)
            m_triplets.emplace_back(row, row, mass.mass);
        }

    LinearSystem system;
    system.stiffness = from_triplets(n, k_triplets);
    system.mass      = from_triplets(n, m_triplets);
    system.damping   = SparseMatrix(n, n);
    system.influence = Vector::Zero(n);
    for (unsigned int node = 0; node < model.n_nodes(); ++node)
      {
        const int row = model.equation(Model::dof(node, Component::ux));
        if (row >= 0)
          system.influence[row] = 1;
      }
    return system;
  }

  std::array<double, 2>
  rayleigh_coefficients(const double damping_ratio, const double omega_i, const double omega_j)
  {
    return {{2 * damping_ratio * omega_i * omega_j / (omega_i + omega_j),
             2 * damping_ratio / (omega_i + omega_j)}};
  }

  SparseMatrix
  block(const SparseMatrix &matrix, const std::array<unsigned int, 2> range)
  {
    const unsigned int n = range[1] - range[0];
    return matrix.block(range[0], range[0], n, n);
  }

  void
  assemble_damping(const Model &model, const std::vector<std::array<double, 2>> &coefficients,
                   LinearSystem &system)
  {
    const unsigned int n = system.n_equations();
    Triplets           triplets;
    // Buildings own disjoint equation blocks, so per-building Rayleigh terms
    // are the global M and K entries scaled by the owner's coefficients.
    std::vector<unsigned int> owner(n);
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const auto range = model.equation_range(b);
        for (unsigned int e = range[0]; e < range[1]; ++e)
          owner[e] = b;
      }
    for (const SparseMatrix *matrix : {&system.mass, &system.stiffness})
      {
        const unsigned int which = (matrix == &system.mass) ? 0 : 1;
        for (int column = 0; column < matrix->outerSize(); ++column)
          for (SparseMatrix::InnerIterator it(*matrix, column); it; ++it)
            {
              const double a = coefficients[owner[it.row()]][which];
              if (a != 0)
                triplets.emplace_back(it.row(), it.col(), a * it.value());
            }
      }
    for (const StoreyLink &link : model.links)
      if (link.damping > 0)
        scatter(model, link_dofs(link), two_node_spring(link.damping), triplets);
    system.damping = from_triplets(n, triplets);
    system.rayleigh = coefficients;
  }
} // namespace poundfe
