// The consistent masses of a script's elements (-cMass 1; OpenSees's
// Truss/CorotTruss::getMass with cMass: rho L/6 [2 1; 1 2] on each
// translation; ElasticBeam2d/3d and DispBeamColumn2d/3d::getMass: the cubic
// Hermitian mass T^T m_l T, below): a matrix M_e on the element's DOFs
// beside the nodes' diagonal M, as OpenSees's TransientIntegrator assembles
// getMass:
//   residual  -M_e (a + alpha_M v + n r a_g),   tangent  (c_m + c_c alpha_M) M_e,
// r a_g the ground acceleration along each row's DOF (the element's
// addInertiaLoadToUnbalance, -M R a_g; n = 2 for ElasticBeam2d, whose
// getResistingForce and getResistingForceIncInertia both subtract it, else
// 1), alpha_M the element's Rayleigh factor when it is Rayleigh-damped
// (Element::getDamp's alpha_M M). A beam's m_l on the local DOFs
// (u, v, theta_z) of each end in 2D, (u, v, w, theta_x, theta_y, theta_z)
// in 3D, m = rho L/420: axially and on the twists (times J/A in
// ElasticBeam3d, 0 in DispBeamColumn3d) m [140 70; 70 140]; in each
// bending plane (v, theta_z; in 3D also w, theta_y with s = -1, s = 1 else)
//   m [156  22sL   54  -13sL;  22sL  4L^2  13sL  -3L^2;
//      54   13sL  156  -22sL; -13sL -3L^2 -22sL   4L^2].
#include <poundfe/opensees/opensees_analysis.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace opensees
  {
    namespace
    {
      /// The Hermitian bending mass of the plane of transverse DOF v and
      /// rotation t (n DOFs a node) into ml.
      void
      add_bending_mass(Matrix &ml, const unsigned int v, const unsigned int t, const unsigned int n,
                       const double m, const double L, const double s)
      {
        const unsigned int dofs[4]     = {v, t, v + n, t + n};
        const double       block[4][4] = {{156, 22 * s * L, 54, -13 * s * L},
                                          {22 * s * L, 4 * L * L, 13 * s * L, -3 * L * L},
                                          {54, 13 * s * L, 156, -22 * s * L},
                                          {-13 * s * L, -3 * L * L, -22 * s * L, 4 * L * L}};
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = 0; j < 4; ++j)
            ml(dofs[i], dofs[j]) = m * block[i][j];
      }

      /// m [140 70; 70 140] on DOF k of both ends into ml.
      void
      add_axial_mass(Matrix &ml, const unsigned int k, const unsigned int n, const double m)
      {
        ml(k, k) = ml(k + n, k + n) = 140 * m;
        ml(k, k + n) = ml(k + n, k) = 70 * m;
      }
    } // namespace

    Matrix
    beam_consistent_mass(const Domain &domain, const int tag, const std::array<int, 2> &nodes,
                         const double rho, const double torsion_ratio,
                         const std::array<double, 3> *vecxz)
    {
      Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
      double          L = 0;
      if (vecxz)
        r = member_axes(domain, tag, nodes, *vecxz, L);
      else
        {
          const auto &a = domain.node(nodes[0]).coordinates, &b = domain.node(nodes[1]).coordinates;
          L = std::hypot(b[0] - a[0], b[1] - a[1]);
          if (!(L > 0))
            throw ScriptError("element " + std::to_string(tag) + " has zero length");
          const double c = (b[0] - a[0]) / L, s = (b[1] - a[1]) / L;
          r.topLeftCorner<2, 2>() << c, s, -s, c;
        }
      const unsigned int n  = vecxz ? 6 : 3; // DOFs a node
      const double       m  = rho * L / 420.0;
      Matrix             ml = Matrix::Zero(2 * n, 2 * n), T = Matrix::Zero(2 * n, 2 * n);
      add_axial_mass(ml, 0, n, m);
      add_bending_mass(ml, 1, n - 1, n, m, L, 1.0);
      if (vecxz)
        {
          add_axial_mass(ml, 3, n, m * torsion_ratio);
          add_bending_mass(ml, 2, 4, n, m, L, -1.0);
        }
      for (unsigned int block = 0; block < 2 * n / 3; ++block)
        T.block<3, 3>(3 * block, 3 * block) = r;
      return T.transpose() * ml * T;
    }

    void
    Analysis::number_coupled_masses()
    {
      coupled_masses.clear();
      for (const Domain::ConsistentMass &m : domain.consistent_masses)
        {
          CoupledMass c;
          c.matrix = &m.matrix;
          for (const int tag : m.nodes)
            {
              for (const RigidTie &d : domain.rigid_ties)
                if (std::find(d.constrained.begin(), d.constrained.end(), tag) !=
                    d.constrained.end())
                  throw ScriptError("element " + std::to_string(m.element) +
                                    ": a consistent mass (-cMass) on node " +
                                    std::to_string(tag) + ", which a " + d.name() +
                                    " constrains");
              const Node &node = domain.node(tag);
              for (unsigned int k = 0; k < node.equation.size(); ++k)
                {
                  if (node.equation[k] <= first_combination) // an equalDOF to a tie's node
                    throw ScriptError("element " + std::to_string(m.element) +
                                      ": a consistent mass (-cMass) on node " +
                                      std::to_string(tag) + ", whose DOF " +
                                      std::to_string(k + 1) +
                                      " follows a rigid tie's constrained node");
                  c.equations.push_back(std::max(node.equation[k], -1));
                  c.dofs.push_back(k);
                }
            }
          const auto element = domain.elements.find(m.element);
          if (element != domain.elements.end() && element->second->rayleigh_damped())
            c.alpha_m = domain.rayleigh_of(m.element).alpha_m;
          c.n_ground_loads = m.ground_load_twice ? 2.0 : 1.0;
          coupled_masses.push_back(std::move(c));
        }
    }

    void
    Analysis::subtract_coupled_inertia(Vector &r, const Vector &v)
    {
      for (const CoupledMass &c : coupled_masses)
        {
          Vector &x = coupled_work;
          x.resize(c.equations.size());
          for (unsigned int i = 0; i < x.size(); ++i)
            {
              const int eq = c.equations[i];
              x[i] = (eq >= 0 ? A[eq] + c.alpha_m * v[eq] : 0.0) +
                     c.n_ground_loads * ground[c.dofs[i]];
            }
          const Vector f = *c.matrix * x;
          for (unsigned int i = 0; i < x.size(); ++i)
            if (c.equations[i] >= 0)
              r[c.equations[i]] -= f[i];
        }
    }

    void
    Analysis::add_coupled_masses(const double c_m, const double c_c)
    {
      for (const CoupledMass &c : coupled_masses)
        {
          const double factor = c_m + c_c * c.alpha_m;
          if (factor == 0)
            continue;
          const auto &eq = c.equations;
          for (unsigned int i = 0; i < eq.size(); ++i)
            for (unsigned int j = 0; j < eq.size(); ++j)
              if (eq[i] >= 0 && eq[j] >= 0 && (*c.matrix)(i, j) != 0)
                {
                  if (dense())
                    dense_tangent(eq[i], eq[j]) += factor * (*c.matrix)(i, j);
                  else
                    tangent_entries.emplace_back(eq[i], eq[j], factor * (*c.matrix)(i, j));
                }
        }
    }

    Vector
    Analysis::mass_times(const Vector &x) const
    {
      Vector y = mass_of_equation.cwiseProduct(x);
      for (const CoupledMass &c : coupled_masses)
        {
          const auto &eq = c.equations;
          for (unsigned int i = 0; i < eq.size(); ++i)
            for (unsigned int j = 0; j < eq.size(); ++j)
              if (eq[i] >= 0 && eq[j] >= 0)
                y[eq[i]] += (*c.matrix)(i, j) * x[eq[j]];
        }
      return y;
    }
  } // namespace opensees
} // namespace poundfe
