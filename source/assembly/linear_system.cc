#include <poundfe/assembly/linear_system.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/elements/frame_element.h>
#include <poundfe/elements/frame_element_3d.h>
#include <poundfe/elements/member_element.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

namespace poundfe
{
  namespace
  {
    /// The entries of a matrix being assembled, kept as the assembly asks
    /// (doc/theory.md §3.5d): all of them (the whole model); only those
    /// whose row and column lie in one run of equations (a rank's part of
    /// a model partitioned by building, the other rows and columns left
    /// empty); or none, noting instead each pair of buildings that an
    /// entry joins (the couplings the partition must respect).
    class Triplets
    {
    public:
      /// Keep every entry.
      Triplets() = default;

      /// Keep the entries in kept x kept.
      explicit Triplets(const EquationRange kept)
        : kept(kept)
      {}

      /// Keep nothing: add to `joined` the buildings (a < b) of each
      /// entry whose row and column are in different buildings
      /// (`building_of` each equation's).
      Triplets(const std::vector<unsigned int>               &building_of,
               std::set<std::array<unsigned int, 2>>         &joined)
        : building_of(&building_of)
        , joined(&joined)
      {}

      void
      emplace_back(const int row, const int column, const double value)
      {
        if (joined)
          {
            const unsigned int a = (*building_of)[row], b = (*building_of)[column];
            if (a != b && value != 0)
              joined->insert(std::array<unsigned int, 2>{{std::min(a, b), std::max(a, b)}});
            return;
          }
        const bool row_kept    = unsigned(row) >= kept[0] && unsigned(row) < kept[1];
        const bool column_kept = unsigned(column) >= kept[0] && unsigned(column) < kept[1];
        if (row_kept && column_kept)
          entries.emplace_back(row, column, value);
        else if (row_kept != column_kept && value != 0)
          crossing = true;
      }

      /// Whether an element on `dofs` may have a kept entry: false only when
      /// none of its equations is kept (so its matrix need not be formed:
      /// a rank's part skips the other ranks' elements).
      bool
      may_keep(const Model &model, const std::vector<unsigned int> &dofs) const
      {
        if (joined || (kept[0] == 0 && kept[1] >= model.n_equations()) ||
            model.has_combinations()) // a DOF may stand for other equations
          return true;
        return std::any_of(dofs.begin(), dofs.end(), [&](const unsigned int dof) {
          const int e = model.equation(dof);
          return e >= 0 && unsigned(e) >= kept[0] && unsigned(e) < kept[1];
        });
      }

      /// The n x n matrix of the kept entries.
      SparseMatrix
      matrix(const unsigned int n) const
      {
        // the partition is made from coupled_buildings: an entry across
        // its cut means the two disagree, and the part would be wrong
        AssertThrow(!crossing,
                    dealii::ExcMessage("an entry of M or K joins equations [" +
                                       std::to_string(kept[0]) + ", " + std::to_string(kept[1]) +
                                       ") to another equation: the partition by building "
                                       "missed a coupling"));
        SparseMatrix matrix(n, n);
        matrix.setFromTriplets(entries.begin(), entries.end());
        matrix.makeCompressed();
        return matrix;
      }

    private:
      EquationRange                                 kept{{0, std::numeric_limits<unsigned int>::max()}};
      bool                                          crossing = false;
      std::vector<Eigen::Triplet<double>>           entries;
      const std::vector<unsigned int>              *building_of = nullptr;
      std::set<std::array<unsigned int, 2>>        *joined      = nullptr;
    };

    /// Scatter over DOFs of which some are combinations of others (exact
    /// master-slave constraints): Tᵀ A T, T the DOFs' equation terms.
    template <typename ElementMatrix>
    void
    scatter_combined(const Model &model, const std::vector<unsigned int> &dofs,
                     const ElementMatrix &matrix, Triplets &triplets)
    {
      std::vector<std::vector<std::pair<int, double>>> terms(dofs.size());
      for (unsigned int i = 0; i < dofs.size(); ++i)
        model.equation_terms(dofs[i], terms[i]);
      for (unsigned int i = 0; i < dofs.size(); ++i)
        for (const auto &[row, a] : terms[i])
          for (unsigned int j = 0; j < dofs.size(); ++j)
            if (matrix(i, j) != 0)
              for (const auto &[column, b] : terms[j])
                triplets.emplace_back(row, column, a * matrix(i, j) * b);
    }

    /// q(dof) from the equations' values u (0 on a fixed DOF).
    double
    value_of(const Model &model, const Vector &u, const unsigned int dof)
    {
      std::vector<std::pair<int, double>> terms;
      model.equation_terms(dof, terms);
      double value = 0;
      for (const auto &[equation, coefficient] : terms)
        value += coefficient * u[equation];
      return value;
    }

    /// Scatter an element matrix over node DOFs; fixed DOFs are dropped
    /// (homogeneous supports, so they contribute nothing to the free rows).
    template <typename ElementMatrix>
    void
    scatter(const Model &model, const std::vector<unsigned int> &dofs,
            const ElementMatrix &matrix, Triplets &triplets)
    {
      if (model.has_combinations())
        {
          scatter_combined(model, dofs, matrix, triplets);
          return;
        }
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

    FrameElement
    element_of(const Model &model, const Member &member)
    {
      return {model.nodes[member.nodes[0]].position, model.nodes[member.nodes[1]].position,
              member.section};
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

    /// A storey's spring or dashpot of constant k on its deformation: on
    /// ux(bottom), ux(top) (fixed base), or on a compliant foundation also on
    /// the base rotation θ, d = ux(top) - ux(bottom) - h θ (k a a^T).
    void
    scatter_storey(const Model &model, const StoreyLink &link, const double k,
                   Triplets &triplets)
    {
      if (link.rocking_node < 0)
        {
          scatter(model, link_dofs(link), two_node_spring(k), triplets);
          return;
        }
      const Eigen::Vector3d a(-1.0, 1.0, -link.rocking_arm);
      scatter(model,
              {Model::dof(link.nodes[0], Component::ux), Model::dof(link.nodes[1], Component::ux),
               Model::dof(link.rocking_node, Component::rz)},
              Eigen::Matrix3d(k * a * a.transpose()), triplets);
    }

    /// The foundations' springs (or, with `mass`, their masses and rotary
    /// inertias): k a aᵀ (m a aᵀ) of each part.
    void
    add_foundation_terms(const Model &model, const bool mass, Triplets &triplets)
    {
      for (const Foundation &f : model.foundations)
        for (const FoundationPart &part : f.parts)
          {
            const Eigen::Map<const Eigen::VectorXd> a(part.coefficients.data(),
                                                      part.coefficients.size());
            scatter(model, part.dofs,
                    Eigen::MatrixXd((mass ? part.inertia : part.stiffness) * a * a.transpose()),
                    triplets);
          }
    }

    SparseMatrix
    from_triplets(const unsigned int n, const Triplets &triplets)
    {
      return triplets.matrix(n);
    }

    /// The resisting planes (k a a^T) and the polar moments of 3D floors.
    void
    add_plan_terms(const Model &model, Triplets &k_triplets, Triplets &m_triplets)
    {
      for (const PlaneLink &link : model.plane_links)
        {
          std::vector<unsigned int> dofs;
          std::vector<double>       weights;
          link.terms(dofs, weights);
          const Eigen::Map<const Eigen::VectorXd> a(weights.data(), weights.size());
          scatter(model, dofs, Eigen::MatrixXd(link.stiffness * a * a.transpose()), k_triplets);
        }
      for (const NodalMass &mass : model.masses)
        if (mass.polar_moment != 0)
          {
            const int row = model.equation(Model::dof(mass.node, Component::rz));
            if (row >= 0)
              m_triplets.emplace_back(row, row, mass.polar_moment);
          }
    }

    FrameElement3D
    element_of(const Member3D &member)
    {
      using Point3 = Eigen::Map<const Eigen::Vector3d>;
      return {Point3(member.ends[0].data()), Point3(member.ends[1].data()),
              Point3(member.orientation.data()), member.section};
    }

    /// T of a 3D member: its 12 end DOFs from its model DOFs.
    using MemberMap = Eigen::Map<const Eigen::Matrix<double, 12, Eigen::Dynamic, Eigen::RowMajor>>;
    MemberMap
    map_of(const Member3D &member)
    {
      return MemberMap(member.map.data(), 12, member.dofs.size());
    }

    /// The members of 3D frames (T_eᵀ K_e T_e, T_eᵀ M_e T_e over their model
    /// DOFs: the diaphragm's master-slave reduction and the hinges), the
    /// hinges' initial stiffness and the joints' vertical masses.
    void
    add_frame_3d_terms(const Model &model, Triplets &k_triplets, Triplets &m_triplets)
    {
      for (const Member3D &member : model.members_3d)
        {
          const FrameElement3D element = element_of(member);
          const MemberMap      t       = map_of(member);
          // a fibre member: its virgin tangent, K_ref of its MemberElement
          const Eigen::MatrixXd k = member.fibre.fibre() ?
                                      Eigen::MatrixXd(make_beam_column(model, member)->initial_tangent()) :
                                      Eigen::MatrixXd(element.stiffness());
          scatter(model, member.dofs, Eigen::MatrixXd(t.transpose() * k * t), k_triplets);
          scatter(model, member.dofs,
                  Eigen::MatrixXd(t.transpose() * element.mass(model.mass_matrix) * t),
                  m_triplets);
        }
      for (const Hinge3D &hinge : model.hinges_3d)
        scatter(model, {n_dofs_per_node * hinge.node + hinge.slot},
                Eigen::Matrix<double, 1, 1>(hinge.law.stiffness), k_triplets);
      for (const DofMass &mass : model.dof_masses)
        if (mass.inertia) // else a weight only (Vertical floor mass = none)
          scatter(model, {mass.dof}, Eigen::Matrix<double, 1, 1>(mass.mass), m_triplets);
    }

    /// 1 on the free equations of component c of every node.
    Vector
    influence_of(const Model &model, const Component c)
    {
      Vector r = Vector::Zero(model.n_equations());
      for (unsigned int node = 0; node < model.n_nodes(); ++node)
        {
          if (model.nodes[node].generalized) // not (ux, uy, rz): a 3D joint's (uz, rx, ry)
            continue;
          const int row = model.equation(Model::dof(node, c));
          if (row >= 0)
            r[row] = 1;
        }
      return r;
    }

    /// 1 on the free vertical translations: uy of the (ux, uy, rz) nodes in
    /// 2D, slot 0 (uz) of the 3D frame joints' generalized nodes in 3D.
    Vector
    vertical_influence_of(const Model &model)
    {
      if (model.dimension != 3)
        return influence_of(model, Component::uy);
      Vector r = Vector::Zero(model.n_equations());
      for (unsigned int node = 0; node < model.n_nodes(); ++node)
        if (model.nodes[node].joint_translation_z)
          if (const int row = model.equation(n_dofs_per_node * node); row >= 0)
            r[row] = 1;
      return r;
    }

    /// The rigid-floor motion q = (ux, uy, θz) about `centre` moved to `point`:
    /// q(point) = T q(centre).
    Eigen::Matrix3d
    floor_transfer(const Point2 &centre, const Point2 &point)
    {
      Eigen::Matrix3d t = Eigen::Matrix3d::Identity();
      t(0, 2)           = -(point.y - centre.y);
      t(1, 2)           = point.x - centre.x;
      return t;
    }

    /// P-Delta of the storeys of torsionally coupled shear buildings
    /// (doc/theory.md §1.12): the weight P of the floors above storey i,
    /// carried down at the floors' mass, acts on the storey's drift Δ(p) at
    /// every point p as P Δ / h: about the centroid G of those masses
    ///   K_G = -(P / h) B^T diag(1, 1, r^2) B,  B = [-T(C_{i-1}, G), T(C_i, G)],
    /// r^2 = sum_j (I_j + m_j |C_j - G|^2) / sum_j m_j the polar radius of
    /// gyration of the masses above about G (Wilson & Habibullah 1987).
    void
    add_plan_storey_p_delta(const Model &model, Triplets &triplets)
    {
      std::vector<std::array<double, 2>> mass_of_node(model.nodes.size(), {{0, 0}});
      for (const NodalMass &m : model.masses)
        {
          mass_of_node[m.node][0] += m.mass;
          mass_of_node[m.node][1] += m.polar_moment;
        }
      for (const PlaneLink &link : model.plane_links)
        {
          if (link.plane != 1)
            continue; // one per storey
          const Building    &building = model.buildings[link.building];
          const unsigned int i        = link.storey - 1;
          double             mass = 0, inertia = 0;
          Point2             g{0, 0};
          for (unsigned int j = i; j < building.floors.size(); ++j)
            {
              const double m = mass_of_node[building.floors[j].nodes[0]][0];
              mass += m;
              g.x += m * building.plan[j].mass_centre.x;
              g.y += m * building.plan[j].mass_centre.y;
            }
          g = {g.x / mass, g.y / mass};
          for (unsigned int j = i; j < building.floors.size(); ++j)
            {
              const auto  &m = mass_of_node[building.floors[j].nodes[0]];
              const Point2 c = building.plan[j].mass_centre;
              inertia += m[1] + m[0] * ((c.x - g.x) * (c.x - g.x) + (c.y - g.y) * (c.y - g.y));
            }
          const Point2 below = i > 0 ? building.plan[i - 1].mass_centre : building.plan[0].mass_centre;
          Eigen::Matrix<double, 3, 6> b;
          b << -floor_transfer(below, g), floor_transfer(building.plan[i].mass_centre, g);
          const double      p = model.gravity * mass, h = building.floors[i].storey_height;
          const Eigen::Vector3d arms(1, 1, inertia / mass);
          std::vector<unsigned int> dofs;
          for (const unsigned int node : link.nodes)
            for (const Component c : {Component::ux, Component::uy, Component::rz})
              dofs.push_back(Model::dof(node, c));
          scatter(model, dofs, Eigen::MatrixXd(-(p / h) * b.transpose() * arms.asDiagonal() * b),
                  triplets);
        }
    }

    /// The superstructure's K and M terms (without the foundations'):
    /// every element's, scattered into `k` and `m`.
    void
    scatter_structure(const Model &model, Triplets &k, Triplets &m)
    {
      for (const Member &member : model.members)
        {
          const auto dofs = member_dofs(member);
          if (!k.may_keep(model, dofs))
            continue;
          const FrameElement element = element_of(model, member);
          // a fibre member: its virgin tangent, K_ref of its MemberElement
          if (member.fibre.fibre())
            scatter(model, dofs, make_beam_column(model, member)->initial_tangent(), k);
          else
            scatter(model, dofs, element.stiffness(), k);
          scatter(model, dofs, element.mass(model.mass_matrix), m);
        }
      for (const StoreyLink &link : model.links)
        scatter_storey(model, link, link.stiffness, k);
      // The linear part of the nonlinear springs to the ground (SD: K, Duffing: k1).
      for (const Spring &spring : model.springs)
        scatter(model, {Model::dof(spring.node, Component::ux)},
                Eigen::Matrix<double, 1, 1>(spring.law.stiffness), k);
      // Hinges enter with their initial stiffness: the linear part of K (and
      // of stiffness-proportional damping) is the elastic structure.
      for (const Hinge &hinge : model.hinges)
        scatter(model,
                {Model::dof(hinge.member_node, Component::rz),
                 Model::dof(hinge.joint_node, Component::rz)},
                two_node_spring(hinge.law.stiffness), k);
      for (const NodalMass &mass : model.masses)
        for (const Component c : {Component::ux, Component::uy})
          {
            const int row = model.equation(Model::dof(mass.node, c));
            if (row >= 0)
              m.emplace_back(row, row, mass.mass);
          }
      add_plan_terms(model, k, m);
      add_frame_3d_terms(model, k, m);
    }

    /// K_G's terms under the members' `axial_forces` and the storeys'
    /// compressions.
    void
    scatter_geometric_stiffness(const Model &model, const std::vector<double> &axial_forces,
                                const std::vector<double> &storey_compressions, Triplets &triplets)
    {
      AssertDimension(axial_forces.size(), model.members.size() + model.members_3d.size());
      AssertDimension(storey_compressions.size(), model.links.size());
      for (unsigned int m = 0; m < model.members.size(); ++m)
        {
          const Member &member = model.members[m];
          const auto    dofs   = member_dofs(member);
          if (triplets.may_keep(model, dofs))
            scatter(model, dofs, element_of(model, member).geometric_stiffness(axial_forces[m]),
                    triplets);
        }
      for (unsigned int m = 0; m < model.members_3d.size(); ++m)
        {
          const Member3D &member = model.members_3d[m];
          const MemberMap t      = map_of(member);
          const double    n      = axial_forces[model.members.size() + m];
          scatter(model, member.dofs,
                  Eigen::MatrixXd(t.transpose() * element_of(member).geometric_stiffness(n) * t),
                  triplets);
        }
      for (unsigned int l = 0; l < model.links.size(); ++l)
        {
          const StoreyLink &link   = model.links[l];
          const double      height = model.nodes[link.nodes[1]].position.y -
                                model.nodes[link.nodes[0]].position.y;
          Assert(height > 0, dealii::ExcMessage("a storey link of zero height"));
          scatter(model, link_dofs(link), two_node_spring(-storey_compressions[l] / height),
                  triplets);
        }
      add_plan_storey_p_delta(model, triplets);
    }

    /// The members' axial forces under the displacements u.
    std::vector<double>
    member_axial_forces_under(const Model &model, const Vector &u)
    {
      std::vector<double> forces;
      for (const Member &member : model.members)
        {
          const FrameElement element = element_of(model, member);
          const auto dofs = member_dofs(member);
          Vector6    end_displacements;
          for (unsigned int i = 0; i < 6; ++i)
            end_displacements[i] = value_of(model, u, dofs[i]);
          forces.push_back(element.axial_force(end_displacements));
        }
      for (const Member3D &member : model.members_3d)
        {
          Vector on_dofs(member.dofs.size());
          for (unsigned int i = 0; i < member.dofs.size(); ++i)
            {
              const int equation = model.equation(member.dofs[i]);
              on_dofs[i]         = equation >= 0 ? u[equation] : 0.0;
            }
          forces.push_back(element_of(member).axial_force(map_of(member) * on_dofs));
        }
      return forces;
    }

    /// u of K_E u = loads on the equations `kept` (0 elsewhere): the
    /// gravity analysis of those buildings, which carry no other's load.
    Vector
    gravity_displacements(const SparseMatrix &stiffness, const Vector &loads,
                          const EquationRange kept)
    {
      const unsigned int n = kept[1] - kept[0];
      Eigen::SimplicialLLT<SparseMatrix> cholesky;
      if (n == stiffness.rows())
        cholesky.compute(stiffness);
      else
        cholesky.compute(block(stiffness, kept));
      if (cholesky.info() != Eigen::Success)
        throw NumericalError("P-Delta gravity analysis: the stiffness matrix is singular or not "
                             "positive definite (is the structure a mechanism? check the supports)");
      Vector u           = Vector::Zero(stiffness.rows());
      u.segment(kept[0], n) = cholesky.solve(loads.segment(kept[0], n));
      return u;
    }

    /// K = K_E + K_G from the gravity loads (the header's P-Delta), on the
    /// equations `kept`.
    void
    add_p_delta(const Model &model, const EquationRange kept, LinearSystem &system)
    {
      const std::vector<double> forces = member_axial_forces_under(
        model, gravity_displacements(system.stiffness, total_gravity_loads(model), kept));
      Triplets triplets(kept);
      scatter_geometric_stiffness(model, forces, storey_gravity_loads(model), triplets);
      system.geometric_stiffness = from_triplets(model.n_equations(), triplets);
      system.stiffness += system.geometric_stiffness;
      system.stiffness.makeCompressed();
      if (system.structure_stiffness.rows() > 0)
        system.structure_stiffness += system.geometric_stiffness;
    }
  } // namespace

  LinearSystem
  assemble_mass_and_stiffness(const Model &model)
  {
    return assemble_mass_and_stiffness(model, {{0, model.n_equations()}});
  }

  LinearSystem
  assemble_mass_and_stiffness(const Model &model, const EquationRange kept)
  {
    AssertThrow(kept[0] <= kept[1] && kept[1] <= model.n_equations(),
                dealii::ExcMessage("equations to keep beyond the model's"));
    const unsigned int n = model.n_equations();
    Triplets           k_triplets(kept), m_triplets(kept);
    scatter_structure(model, k_triplets, m_triplets);
    LinearSystem system;
    if (!model.foundations.empty())
      {
        system.structure_stiffness = from_triplets(n, k_triplets);
        system.structure_mass      = from_triplets(n, m_triplets);
        add_foundation_terms(model, false, k_triplets);
        add_foundation_terms(model, true, m_triplets);
      }
    system.stiffness = from_triplets(n, k_triplets);
    system.mass      = from_triplets(n, m_triplets);
    system.damping   = SparseMatrix(n, n);
    system.influence   = influence_of(model, Component::ux);
    system.influence_z = vertical_influence_of(model);
    if (model.dimension == 3)
      {
        system.influence_y  = influence_of(model, Component::uy);
        system.influence_rz = influence_of(model, Component::rz);
      }
    if (model.geometric_nonlinearity == GeometricNonlinearity::p_delta)
      add_p_delta(model, kept, system);
    return system;
  }

  std::vector<unsigned int>
  building_of_equations(const Model &model)
  {
    std::vector<unsigned int> building_of(model.n_equations());
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const EquationRange range = model.equation_range(b);
        std::fill(building_of.begin() + range[0], building_of.begin() + range[1], b);
      }
    return building_of;
  }

  std::vector<std::array<unsigned int, 2>>
  coupled_buildings(const Model &model)
  {
    const std::vector<unsigned int>       building_of = building_of_equations(model);
    std::set<std::array<unsigned int, 2>> joined;
    Triplets                              noting(building_of, joined);
    scatter_structure(model, noting, noting);
    add_foundation_terms(model, false, noting);
    add_foundation_terms(model, true, noting);
    // K_G's pattern: unit forces stand for the gravity analysis's
    if (model.geometric_nonlinearity == GeometricNonlinearity::p_delta)
      scatter_geometric_stiffness(
        model, std::vector<double>(model.members.size() + model.members_3d.size(), 1.0),
        std::vector<double>(model.links.size(), 1.0), noting);
    // C: M and K scaled per building, and the storeys' dashpots (on the
    // storey springs' equations)
    return {joined.begin(), joined.end()};
  }

  namespace
  {
    /// Loads on the equations of a model, added DOF by DOF (a constrained
    /// DOF's to its masters').
    class EquationLoads
    {
    public:
      explicit EquationLoads(const Model &model)
        : model(model)
        , loads(Vector::Zero(model.n_equations()))
      {}
      void
      operator()(const unsigned int dof, const double value)
      {
        model.equation_terms(dof, terms);
        for (const auto &[row, coefficient] : terms)
          loads[row] += coefficient * value;
      }

      const Model                        &model;
      Vector                              loads;
      std::vector<std::pair<int, double>> terms;
    };
  } // namespace

  Vector
  gravity_loads(const Model &model)
  {
    EquationLoads add(model);
    Vector       &loads = add.loads;
    // Element by element, so that a member's weight shared with a support
    // goes there (M r_y restricted to the free DOFs would lose the coupling
    // terms of a consistent mass to the supported ones).
    // A member's self-weight as a distributed load replaces its mass's
    // weight: an elastic member's consistent nodal loads, a fibre member's
    // element load (its element, not the load vector, carries it).
    Vector6 vertical;
    vertical << 0, 1, 0, 0, 1, 0;
    for (const Member &member : model.members)
      {
        if (member.weight_per_length != 0 && member.fibre.fibre())
          continue;
        const Vector6 weight =
          member.weight_per_length != 0 ?
            Vector6(-self_weight_end_forces(model, member)) :
            Vector6(-model.gravity *
                    (element_of(model, member).mass(model.mass_matrix) * vertical));
        const auto dofs = member_dofs(member);
        for (unsigned int i = 0; i < 6; ++i)
          add(dofs[i], weight[i]);
      }
    if (model.dimension == 3)
      {
        // 3D frames: z is up; the joints' vertical masses and the members'
        // self-weight (the nodal masses of a floor are its plan inertia).
        for (const DofMass &mass : model.dof_masses)
          add(mass.dof, -model.gravity * mass.mass);
        Vector12 vertical = Vector12::Zero();
        vertical[2] = vertical[8] = 1;
        for (const Member3D &member : model.members_3d)
          {
            if (member.weight_per_length != 0 && member.fibre.fibre())
              continue;
            const Vector12 weight =
              member.weight_per_length != 0 ?
                Vector12(-self_weight_end_forces(member)) :
                Vector12(-model.gravity * (element_of(member).mass(model.mass_matrix) * vertical));
            const Vector on_dofs = map_of(member).transpose() * weight;
            for (unsigned int i = 0; i < member.dofs.size(); ++i)
              add(member.dofs[i], on_dofs[i]);
          }
        return loads;
      }
    for (const NodalMass &mass : model.masses)
      add(Model::dof(mass.node, Component::uy), -model.gravity * mass.mass);
    return loads;
  }

  Vector
  member_element_loads(const Model &model)
  {
    EquationLoads add(model);
    for (const Member &member : model.members)
      if (member.weight_per_length != 0 && member.fibre.fibre())
        {
          const Vector6 weight = -self_weight_end_forces(model, member);
          const auto    dofs   = member_dofs(member);
          for (unsigned int i = 0; i < 6; ++i)
            add(dofs[i], weight[i]);
        }
    for (const Member3D &member : model.members_3d)
      if (member.weight_per_length != 0 && member.fibre.fibre())
        {
          const Vector on_dofs = map_of(member).transpose() * (-self_weight_end_forces(member));
          for (unsigned int i = 0; i < member.dofs.size(); ++i)
            add(member.dofs[i], on_dofs[i]);
        }
    return add.loads;
  }

  Vector
  floor_loads(const Model &model)
  {
    Vector loads = Vector::Zero(model.n_equations());
    if (model.dimension != 2)
      return loads;
    std::vector<std::pair<int, double>> terms;
    for (const Building &building : model.buildings)
      for (const Floor &floor : building.floors)
        if (floor.gravity_load != 0 && building.type != BuildingType::shear)
          for (const unsigned int node : floor.nodes)
            {
              model.equation_terms(Model::dof(node, Component::uy), terms);
              for (const auto &[row, coefficient] : terms)
                loads[row] -= coefficient * floor.gravity_load / floor.nodes.size();
            }
    return loads;
  }

  Vector
  total_gravity_loads(const Model &model)
  {
    Vector loads = gravity_loads(model);
    for (const Building &building : model.buildings)
      for (const Floor &floor : building.floors)
        if (floor.gravity_load != 0)
          return loads + floor_loads(model);
    return loads;
  }

  std::vector<double>
  member_axial_forces_at(const Model &model, const Vector &u)
  {
    return member_axial_forces_under(model, u);
  }

  std::vector<double>
  member_axial_forces(const Model &model, const SparseMatrix &stiffness, const Vector &loads)
  {
    return member_axial_forces_under(
      model, gravity_displacements(stiffness, loads, {{0, unsigned(stiffness.rows())}}));
  }

  std::vector<double>
  storey_gravity_loads(const Model &model)
  {
    std::vector<double> compressions;
    for (const StoreyLink &link : model.links)
      {
        const Point2 &top    = model.nodes[link.nodes[1]].position;
        const Point2 &bottom = model.nodes[link.nodes[0]].position;
        const double  height = top.y - bottom.y;
        double        mass   = 0;
        for (const NodalMass &m : model.masses)
          if (model.nodes[m.node].building == link.building &&
              model.nodes[m.node].position.y >= top.y - 1e-9 * std::abs(height))
            mass += m.mass;
        double floor_load = 0;
        for (const Floor &floor : model.buildings[link.building].floors)
          if (floor.level >= top.y - 1e-9 * std::abs(height))
            floor_load += floor.gravity_load;
        compressions.push_back(floor_load == 0 ? model.gravity * mass :
                                                 model.gravity * mass + floor_load);
      }
    return compressions;
  }

  SparseMatrix
  geometric_stiffness(const Model &model, const std::vector<double> &axial_forces,
                      const std::vector<double> &storey_compressions)
  {
    Triplets triplets;
    scatter_geometric_stiffness(model, axial_forces, storey_compressions, triplets);
    return from_triplets(model.n_equations(), triplets);
  }

  bool
  is_positive_definite(const SparseMatrix &matrix)
  {
    return Eigen::SimplicialLLT<SparseMatrix>(matrix).info() == Eigen::Success;
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
    const std::vector<unsigned int> owner = building_of_equations(model);
    // Rayleigh damping is the superstructure's: the soil's is its dashpots
    // (foundation elements), so the foundations' M and K are left out.
    const bool          structure = system.structure_mass.rows() > 0;
    const SparseMatrix &mass      = structure ? system.structure_mass : system.mass;
    const SparseMatrix &stiffness = structure ? system.structure_stiffness : system.stiffness;
    for (const SparseMatrix *matrix : {&mass, &stiffness})
      {
        const unsigned int which = (matrix == &mass) ? 0 : 1;
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
        scatter_storey(model, link, link.damping, triplets);
    system.damping = from_triplets(n, triplets);
    system.rayleigh = coefficients;
  }
} // namespace poundfe
