// OpenSees's CorotTruss (element/truss/CorotTruss.cpp, OpenSees 3.8;
// Crisfield, Non-linear Finite Element Analysis of Solids and Structures,
// vol. 1, sec. 3.3): a truss of any displacement. With R the rows of
// direction cosines of the initial chord (x along it) and d = (L_0, 0, 0) +
// R (u_j - u_i) the current chord in those axes, L_n = |d|,
//   strain  (L_n - L_0) / L_0,   rate  d · R (v_j - v_i) / (L_n L_0),
//   force   ±R^T d q / L_n  with q = A sigma,
//   tangent ±R^T [A E_t / (L_n^2 L_0) d d^T + q / L_n (I - d d^T / L_n^2)] R,
// on the first ndm DOFs of each node (rotations, -ndf 3 in 2D or 6 in 3D,
// take nothing). Initial tangent A E_0 / L_0 along x. Its materials'
// damping tangent c (when not Rayleigh-damped) enters as OpenSees's getDamp
// forms it: R^T a (A c / L_0) a^T R with a = ((L_0 + d_1)/L_n, d_2/L_n, 0).
#include <poundfe/opensees/opensees_section_links.h>

namespace poundfe
{
  namespace opensees
  {
    namespace
    {
      class CorotTruss : public Element
      {
      public:
        CorotTruss(const Domain &domain, const int tag, const std::array<int, 2> nodes,
                   const Eigen::Matrix3d &R, const double L0, const double area,
                   std::unique_ptr<UniaxialLaw> material, const bool rayleigh)
          : Element(tag, {nodes[0], nodes[1]})
          , ndm(domain.ndm)
          , ndf(domain.ndf)
          , R(R)
          , L0(L0)
          , area(area)
          , law(std::move(material))
          , rayleigh(rayleigh)
          , d(L0, 0, 0)
          , Ln(L0)
        {
          committed_tangent = tangent();
        }

        unsigned int n_dofs() const override { return 2 * ndf; }
        bool         rayleigh_damped() const override { return rayleigh; }

        bool
        set_trial(const Vector &u, const Vector &v) override
        {
          Eigen::Vector3d du = Eigen::Vector3d::Zero(), dv = Eigen::Vector3d::Zero();
          for (unsigned int i = 0; i < ndm; ++i)
            {
              du[i] = u[ndf + i] - u[i];
              dv[i] = v[ndf + i] - v[i];
            }
          d                       = Eigen::Vector3d(L0, 0, 0) + R * du;
          const Eigen::Vector3d w = R * dv;
          Ln                      = d.norm();
          return law->set_trial((Ln - L0) / L0, d.dot(w) / Ln / L0);
        }

        Vector
        force() const override
        {
          const Eigen::Vector3d qg = R.transpose() * (d * (area * law->force() / Ln));
          Vector                f  = Vector::Zero(n_dofs());
          for (unsigned int i = 0; i < ndm; ++i)
            {
              f[i]       = -qg[i];
              f[ndf + i] = qg[i];
            }
          return f;
        }

        Matrix
        tangent() const override
        {
          const double    q  = area * law->force();
          const Eigen::Matrix3d ddT = d * d.transpose();
          const Eigen::Matrix3d kl =
            area * law->tangent() / (Ln * Ln * L0) * ddT +
            q / Ln * Eigen::Matrix3d::Identity() - q / (Ln * Ln * Ln) * ddT;
          return expanded(kl);
        }

        Matrix
        initial_tangent() const override
        {
          Eigen::Matrix3d kl = Eigen::Matrix3d::Zero();
          kl(0, 0)           = area * law->initial_stiffness() / L0;
          return expanded(kl);
        }

        Matrix
        material_damping() const override
        {
          const Eigen::Vector3d a((L0 + d[0]) / Ln, d[1] / Ln, 0.0);
          return expanded(a * (area * law->damping_tangent() / L0) * a.transpose());
        }

        void        commit() override { law->commit(); }
        void        revert() override { law->revert(); }
        void        reset() override { law->reset(); }
        std::string failure() const override { return law->failure(); }

        /// CorotTruss::setResponse: force (global), axialForce or basicForce
        /// (A sigma), deformation or basicDeformation (L_0 strain).
        std::vector<double>
        response(const std::vector<std::string> &words) const override
        {
          const std::string what = words.size() == 1 ? words[0] : "";
          if (what == "axialForce" || what == "basicForce" || what == "localForces" ||
              what == "basicForces")
            return {area * law->force()};
          if (what == "defo" || what == "deformation" || what == "deformations" ||
              what == "basicDefo" || what == "basicDeformation" || what == "basicDeformations")
            return {L0 * (Ln - L0) / L0};
          return Element::response(words);
        }

      private:
        /// R^T k R on each node's translations, +k on the diagonal blocks.
        Matrix
        expanded(const Eigen::Matrix3d &kl) const
        {
          const Eigen::Matrix3d kg = R.transpose() * kl * R;
          Matrix                K  = Matrix::Zero(n_dofs(), n_dofs());
          for (unsigned int i = 0; i < ndm; ++i)
            for (unsigned int j = 0; j < ndm; ++j)
              {
                K(i, j) = K(ndf + i, ndf + j) = kg(i, j);
                K(i, ndf + j) = K(ndf + i, j) = -kg(i, j);
              }
          return K;
        }

        const unsigned int           ndm, ndf;
        const Eigen::Matrix3d        R;
        const double                 L0, area;
        std::unique_ptr<UniaxialLaw> law;
        const bool                   rayleigh;
        Eigen::Vector3d              d; // the current chord in the initial axes
        double                       Ln;
      };

      /// CorotTruss::setDomain: x along the chord, y across it in the XY
      /// plane (or, for a chord in the YZ plane, (0, -x_Z, x_Y)), z by
      /// OpenSees's formula; the last two rows normalised.
      Eigen::Matrix3d
      chord_axes(const Eigen::Vector3d &x)
      {
        Eigen::Matrix3d R;
        R.row(0) = x;
        if (std::abs(x[0]) > 0.0)
          {
            R.row(1) = Eigen::Vector3d(-x[1], x[0], 0.0);
            R.row(2) = Eigen::Vector3d(-x[0] * x[2], -x[1] * x[2], x[0] * x[0] + x[1] * x[1]);
          }
        else
          {
            R.row(1) = Eigen::Vector3d(0.0, -x[2], x[1]);
            R.row(2) = Eigen::Vector3d(1.0, 0.0, 0.0);
          }
        R.row(1).normalize();
        R.row(2).normalize();
        return R;
      }
    } // namespace

    std::unique_ptr<Element>
    make_corot_truss(const Domain &domain, const int tag, const std::array<int, 2> nodes,
                     const double area, const int material, const bool rayleigh)
    {
      const std::string name = "corotTruss " + std::to_string(tag);
      auto              law  = make_domain_material(domain, material); // OpenSees's order
      const auto &a = domain.node(nodes[0]).coordinates, &b = domain.node(nodes[1]).coordinates;
      Eigen::Vector3d chord = Eigen::Vector3d::Zero();
      for (unsigned int k = 0; k < domain.ndm; ++k)
        chord[k] = b[k] - a[k];
      const double L0 = chord.norm();
      if (!(L0 > 0))
        throw ScriptError(name + " has zero length");
      return std::make_unique<CorotTruss>(domain, tag, nodes, chord_axes(chord / L0), L0, area,
                                          std::move(law), rayleigh);
    }
  } // namespace opensees
} // namespace poundfe
