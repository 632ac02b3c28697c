// OpenSees's elasticBeamColumn in 3D: ElasticBeam3d on LinearCrdTransf3d or
// PDeltaCrdTransf3d (on CorotCrdTransf3d: make_elastic_corotational_3d,
// opensees_beam_columns.cc) (OpenSees 3.8, SRC/element/elasticBeamColumn/ and
// SRC/coordTransformation/), without offsets, releases or element loads;
// made on nodes that have moved, along and as long as it is then and u
// measured from the nodes' displacements then (the transformations'
// initialize: nodeIInitialDisp, nodeJInitialDisp).
//
// Local axes (LinearCrdTransf3d::getLocalAxes): x = (X_j - X_i)/L,
// y = vecxz × x / |vecxz × x|, z = x × y; u_l = R u_g node by node and
// translation/rotation by translation/rotation. Local stiffness: the
// Euler-Bernoulli member's, k_l = A^T k_b A with the basic forces
//   N = EA/L v_0, Mz_i,j = EIz/L (4 v_1 + 2 v_2, 2 v_1 + 4 v_2),
//   My_i,j = EIy/L (4 v_3 + 2 v_4, 2 v_3 + 4 v_4), T = GJ/L v_5
// (written out as the 12 x 12 matrix); P-Delta (PDeltaCrdTransf3d) adds
// N (u_l1 - u_l7)/L to the local forces 1 and -7, N (u_l2 - u_l8)/L to 2
// and -8, and N/L [[1, -1], [-1, 1]] on the DOFs (1, 7) and (2, 8) of the
// stiffness (N without its variation, as OpenSees's); the response
// localForce is k_l u_l without those shears (ElasticBeam3d::getResponse).
#include <poundfe/elements/displaced_chord.h>
#include <poundfe/opensees/opensees_domain.h>

#include <Eigen/Geometry>

#include <cmath>

namespace poundfe
{
  namespace opensees
  {
    Eigen::Matrix3d
    member_axes(const Domain                &domain,
                const int                    tag,
                const std::array<int, 2>    &nodes,
                const std::array<double, 3> &vecxz,
                double                      &L,
                const Eigen::VectorXd       &u_made)
    {
      const auto &a = domain.node(nodes[0]).coordinates, &b = domain.node(nodes[1]).coordinates;
      Eigen::Vector3d x = displaced_chord<3>(Eigen::Vector3d(a[0], a[1], a[2]),
                                             Eigen::Vector3d(b[0], b[1], b[2]), u_made);
      L                 = x.norm();
      if (!(L > 0))
        throw ScriptError("element " + std::to_string(tag) + " has zero length");
      x /= L;
      const Eigen::Vector3d v(vecxz[0], vecxz[1], vecxz[2]);
      Eigen::Vector3d       y = v.cross(x);
      if (!(y.norm() > 0))
        throw ScriptError("element " + std::to_string(tag) +
                          ": the transformation's vecxz is parallel to its axis");
      y /= y.norm();
      const Eigen::Vector3d z = x.cross(y);
      Eigen::Matrix3d       r;
      r.row(0) = x, r.row(1) = y, r.row(2) = z;
      return r;
    }

    namespace
    {
      /// The local stiffness of a 3D Euler-Bernoulli member of length L.
      Matrix
      local_stiffness(const ElasticSection3d &s, const double L)
      {
        Matrix       k   = Matrix::Zero(12, 12);
        const double EA  = s.E * s.A / L, GJ = s.G * s.J / L;
        const auto   add = [&](const int i, const int j, const double value) {
          k(i, j) += value;
          if (i != j)
            k(j, i) += value;
        };
        add(0, 0, EA), add(6, 6, EA), add(0, 6, -EA);
        add(3, 3, GJ), add(9, 9, GJ), add(3, 9, -GJ);
        // bending in the local x-y plane (about z: v = u_1, u_7; theta = u_5, u_11)
        // and in the x-z plane (about y: w = u_2, u_8; theta = u_4, u_10, of opposite sign)
        for (const int plane : {0, 1})
          {
            const double EI = s.E * (plane == 0 ? s.Iz : s.Iy);
            const int    w = plane == 0 ? 1 : 2, r = plane == 0 ? 5 : 4;
            const double sg = plane == 0 ? 1.0 : -1.0;
            const double a = 12 * EI / (L * L * L), b = 6 * EI / (L * L), c = 4 * EI / L,
                         d = 2 * EI / L;
            add(w, w, a), add(w + 6, w + 6, a), add(w, w + 6, -a);
            add(w, r, sg * b), add(w, r + 6, sg * b), add(w + 6, r, -sg * b),
              add(w + 6, r + 6, -sg * b);
            add(r, r, c), add(r + 6, r + 6, c), add(r, r + 6, d);
          }
        return k;
      }

      class ElasticBeam3d : public Element
      {
      public:
        ElasticBeam3d(const Domain &domain, const int tag, const std::array<int, 2> nodes,
                      const ElasticSection3d &section, const bool p_delta,
                      const std::array<double, 3> &vecxz)
          : Element(tag, {nodes[0], nodes[1]})
          , p_delta(p_delta)
        {
          // made on nodes that may have moved: along and as long as the
          // member is then, measured from then (displacements_when_made)
          u_made                  = displacements_when_made(domain, nodes, 6);
          const Eigen::Matrix3d r = member_axes(domain, tag, nodes, vecxz, L, u_made);
          R.setZero(12, 12);
          for (unsigned int block = 0; block < 4; ++block)
            R.block<3, 3>(3 * block, 3 * block) = r;
          kl0 = local_stiffness(section, L);
          EA  = section.E * section.A;
          ul.setZero(12);
          committed_tangent = tangent();
        }

        unsigned int n_dofs() const override { return 12; }
        bool         rayleigh_damped() const override { return true; }
        bool
        set_trial(const Vector &u, const Vector &) override
        {
          ul = R * (u - u_made);
          return ul.allFinite();
        }
        Vector
        force() const override
        {
          Vector pl = kl0 * ul;
          if (p_delta)
            for (const int k : {1, 2})
              {
                const double shear = axial_force() * (ul[k] - ul[k + 6]) / L;
                pl[k] += shear;
                pl[k + 6] -= shear;
              }
          return R.transpose() * pl;
        }
        Matrix
        tangent() const override
        {
          Matrix kl = kl0;
          if (p_delta)
            for (const int k : {1, 2})
              {
                const double n_over_l = axial_force() / L;
                kl(k, k) += n_over_l, kl(k + 6, k + 6) += n_over_l;
                kl(k, k + 6) -= n_over_l, kl(k + 6, k) -= n_over_l;
              }
          return R.transpose() * kl * R;
        }
        Matrix initial_tangent() const override { return R.transpose() * kl0 * R; }
        std::vector<double>
        response(const std::vector<std::string> &words) const override
        {
          // ElasticBeam3d's local forces are its basic forces' (shears (M_i +
          // M_j)/L): PDeltaCrdTransf3d's shears N (u_l1 - u_l7)/L enter the
          // resisting force, not this response
          if (words.size() == 1 && (words[0] == "localForce" || words[0] == "localForces"))
            {
              const Vector pl = kl0 * ul;
              return std::vector<double>(pl.data(), pl.data() + pl.size());
            }
          return Element::response(words);
        }

      private:
        /// N = EA/L (u_l6 - u_l0), the basic axial force.
        double axial_force() const { return EA / L * (ul[6] - ul[0]); }

        bool   p_delta;
        double L = 0, EA = 0;
        Matrix R, kl0;
        Vector ul, u_made;
      };
    } // namespace

    std::unique_ptr<Element>
    make_elastic_beam_3d(const Domain &domain, const int tag, const std::array<int, 2> nodes,
                         const ElasticSection3d &section, const Transformation transformation,
                         const std::array<double, 3> &vecxz)
    {
      if (transformation == Transformation::corotational)
        return make_elastic_corotational_3d(domain, tag, nodes, section, vecxz);
      return std::make_unique<ElasticBeam3d>(domain, tag, nodes, section,
                                             transformation == Transformation::pdelta, vecxz);
    }
  } // namespace opensees
} // namespace poundfe
