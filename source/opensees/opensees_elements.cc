// The elements of an OpenSees script, as OpenSees 3.8 defines them.
//
// elasticBeamColumn 2D (ElasticBeam2d with LinearCrdTransf2d or
//   PDeltaCrdTransf2d): local displacements u_l = R u_g (R: the rotation by
//   the chord's angle at each node), basic deformations u_b = A u_l,
//     A = [[-1, 0, 0, 1, 0, 0], [0, 1/L, 1, 0, -1/L, 0], [0, 1/L, 0, 0, -1/L, 1]],
//   basic forces q = k_b u_b, k_b = [[EA/L, 0, 0], [0, 4EI/L, 2EI/L], [0, 2EI/L, 4EI/L]],
//   resisting force R^T A^T q and stiffness R^T A^T k_b A R. P-Delta adds
//   q_0 (u_l1 - u_l4)/L to the local transverse forces (+ at i, - at j) and
//   the geometric stiffness q_0/L [[1, -1], [-1, 1]] on those two DOFs
//   (PDeltaCrdTransf2d::getGlobalResistingForce, getGlobalStiffMatrix).
//   A uniform load wy (transverse), wx (axial) adds the fixed-end basic
//   forces q_0 = (-wx L/2, -wy L^2/12, wy L^2/12) to q (P-Delta's N too)
//   and the basic reactions p_0 = (-wx L, -wy L/2, -wy L/2) to the local
//   forces 0, 1 and 4 (ElasticBeam2d::addLoad, LOAD_TAG_Beam2dUniformLoad).
//
// truss (Truss, small strains): the zeroLength's row t along the member's
//   axis x, strain t u / L, force A t^T sigma, tangent (A/L) t^T E t;
//   Rayleigh-damped only with -doRayleigh 1 (OpenSees's default 0).
//
// zeroLength (ZeroLength): the local axes x, y (-orient), z = x × y,
//   y = z × x; material m along direction d (1-3: translation along axis
//   d, 4-6: rotation about axis d - 3) has the row t_m of the local
//   deformation over the global DOFs (the axis' components at node j, their
//   negatives at node i, within the DOFs the model's ndm/ndf give; a
//   direction the node has no DOF for contributes nothing, as in
//   ZeroLength::setTran1d); strain t_m u, rate t_m v; force sum t_m^T
//   sigma_m, tangent sum t_m^T E_m t_m, damping sum t_m^T eta_m t_m.
#include <poundfe/opensees/opensees_domain.h>

#include <Eigen/Geometry>

#include <cmath>

namespace poundfe
{
  namespace opensees
  {
    namespace
    {
      class ElasticBeam2d : public Element
      {
      public:
        ElasticBeam2d(const Domain &domain, const int tag, const std::array<int, 2> nodes,
                      const double A, const double E, const double I, const bool p_delta)
          : Element(tag, {nodes[0], nodes[1]})
          , p_delta(p_delta)
        {
          const auto &a = domain.node(nodes[0]).coordinates, &b = domain.node(nodes[1]).coordinates;
          const double dx = b[0] - a[0], dy = b[1] - a[1];
          L               = std::hypot(dx, dy);
          if (!(L > 0))
            throw ScriptError("element " + std::to_string(tag) + " has zero length");
          const double c = dx / L, s = dy / L;
          R.setZero(6, 6);
          for (unsigned int n = 0; n < 2; ++n)
            {
              R.block<3, 3>(3 * n, 3 * n) << c, s, 0, -s, c, 0, 0, 0, 1;
            }
          B.setZero(3, 6);
          B << -1, 0, 0, 1, 0, 0, 0, 1 / L, 1, 0, -1 / L, 0, 0, 1 / L, 0, 0, -1 / L, 1;
          kb << E * A / L, 0, 0, 0, 4 * E * I / L, 2 * E * I / L, 0, 2 * E * I / L, 4 * E * I / L;
          ul.setZero(6);
          q.setZero();
          q0.setZero();
          p0.setZero();
          committed_tangent = tangent();
        }

        unsigned int n_dofs() const override { return 6; }
        bool         rayleigh_damped() const override { return true; }

        bool
        set_trial(const Vector &u, const Vector &) override
        {
          ul = R * u;
          q  = kb * (B * ul);
          return q.allFinite();
        }

        bool takes_beam_loads() const override { return true; }
        void
        zero_loads() override
        {
          q0.setZero();
          p0.setZero();
        }

        void
        add_beam_uniform(const double wy, const double wx) override
        {
          add_uniform_beam_load(L, wy, wx, q0, p0);
        }

        Vector
        force() const override
        {
          const Eigen::Vector3d qq = q + q0;
          Vector                pl = B.transpose() * qq;
          pl[0] += p0[0];
          pl[1] += p0[1];
          pl[4] += p0[2];
          if (p_delta)
            {
              const double n_over_l = (ul[1] - ul[4]) * qq[0] / L;
              pl[1] += n_over_l;
              pl[4] -= n_over_l;
            }
          return R.transpose() * pl;
        }

        Matrix
        tangent() const override
        {
          Matrix kl = B.transpose() * kb * B;
          if (p_delta)
            {
              const double n_over_l = (q[0] + q0[0]) / L;
              kl(1, 1) += n_over_l;
              kl(4, 4) += n_over_l;
              kl(1, 4) -= n_over_l;
              kl(4, 1) -= n_over_l;
            }
          return R.transpose() * kl * R;
        }

        Matrix
        initial_tangent() const override
        {
          return R.transpose() * (B.transpose() * kb * B) * R;
        }

      private:
        bool                   p_delta;
        double                 L = 0;
        Matrix                 R, B;
        Eigen::Matrix3d        kb;
        Vector                 ul;
        Eigen::Vector3d        q;
        Eigen::Vector3d        q0, p0; // element loads: basic fixed-end forces, reactions
      };

      class ZeroLength : public Element
      {
      public:
        ZeroLength(const Domain &domain, const int tag, const ZeroLengthData &data);

        unsigned int n_dofs() const override { return t.cols(); }
        bool         rayleigh_damped() const override { return rayleigh; }

        /// A truss of length L and area A along direction 1: strain t u / L,
        /// force A t^T sigma.
        void
        as_truss(const double length, const double area)
        {
          strain_scale      = 1 / length;
          force_scale       = area;
          committed_tangent = tangent();
        }

        bool
        set_trial(const Vector &u, const Vector &v) override
        {
          const Vector rate = strain_scale * (t * v);
          strain            = strain_scale * (t * u);
          for (unsigned int m = 0; m < laws.size(); ++m)
            if (!laws[m]->set_trial(strain[m], rate[m]))
              {
                why = laws[m]->failure();
                return false;
              }
          return true;
        }

        Vector
        force() const override
        {
          Vector stress(laws.size());
          for (unsigned int m = 0; m < laws.size(); ++m)
            stress[m] = laws[m]->force();
          return force_scale * (t.transpose() * stress);
        }

        std::vector<double>
        response(const std::vector<std::string> &words) const override
        {
          const bool truss = strain_scale != 1 || force_scale != 1;
          if (truss && words.size() == 1 &&
              (words[0] == "axialForce" || words[0] == "basicForce" || words[0] == "basicForces"))
            return {force_scale * laws[0]->force()};
          if (words.size() == 3 && words[0] == "material")
            return material_response(words[1], words[2]);
          return Element::response(words);
        }

        Matrix tangent() const override { return weighted([](auto &l) { return l.tangent(); }); }
        Matrix
        initial_tangent() const override
        {
          return weighted([](auto &l) { return l.initial_stiffness(); });
        }
        Matrix
        material_damping() const override
        {
          return weighted([](auto &l) { return l.damping_tangent(); });
        }
        void
        commit() override
        {
          for (auto &law : laws)
            law->commit();
          committed_strain = strain;
        }
        void
        revert() override
        {
          for (auto &law : laws)
            law->revert();
          strain = committed_strain;
        }
        void
        reset() override
        {
          for (auto &law : laws)
            law->reset();
          strain = committed_strain = Vector::Zero(laws.size());
        }
        std::string failure() const override { return why; }

      private:
        /// OpenSees's `material i stress|strain|tangent|stressStrain|
        /// stressStrainTangent` (ZeroLength::setResponse passing the rest of
        /// the words to UniaxialMaterial::setResponse).
        std::vector<double>
        material_response(const std::string &number, const std::string &what) const
        {
          const int i = std::atoi(number.c_str());
          if (i < 1 || i > static_cast<int>(laws.size()))
            throw ScriptError("element " + std::to_string(tag) + " has no material " + number +
                              " (1 to " + std::to_string(laws.size()) + ")");
          const UniaxialLaw &law = *laws[i - 1];
          const double       e = strain.size() > 0 ? strain[i - 1] : 0.0;
          if (what == "stress")
            return {law.force()};
          if (what == "strain")
            return {e};
          if (what == "tangent")
            return {law.tangent()};
          if (what == "stressStrain" || what == "stressANDstrain" || what == "stressAndStrain")
            return {law.force(), e};
          if (what == "stressStrainTangent" || what == "stressANDstrainANDtangent")
            return {law.force(), e, law.tangent()};
          throw ScriptError("element " + std::to_string(tag) + ": material response '" + what +
                            "' is not supported");
        }

        template <typename Value>
        Matrix
        weighted(const Value &value) const
        {
          Vector d(laws.size());
          for (unsigned int m = 0; m < laws.size(); ++m)
            d[m] = value(*laws[m]);
          return force_scale * strain_scale * (t.transpose() * d.asDiagonal() * t);
        }

        Matrix                                    t; // materials x DOFs
        std::vector<std::unique_ptr<UniaxialLaw>> laws;
        Vector strain, committed_strain; // the materials' trial and committed strains
        bool                                      rayleigh = false;
        std::string                               why;
        double strain_scale = 1, force_scale = 1; // a truss: 1/L and A
      };

      /// The unit local axes x, y, z of a zeroLength from its -orient vectors.
      Eigen::Matrix3d
      zero_length_axes(const ZeroLengthData &data, const int tag)
      {
        const Eigen::Vector3d x(data.x[0], data.x[1], data.x[2]);
        const Eigen::Vector3d yp(data.y[0], data.y[1], data.y[2]);
        const Eigen::Vector3d z = x.cross(yp);
        if (!(x.norm() > 0) || !(z.norm() > 0))
          throw ScriptError("zeroLength " + std::to_string(tag) +
                            ": -orient vectors are zero or parallel");
        Eigen::Matrix3d axes;
        axes.row(0) = x.normalized();
        axes.row(2) = z.normalized();
        axes.row(1) = axes.row(2).cross(axes.row(0));
        return axes;
      }

      ZeroLength::ZeroLength(const Domain &domain, const int tag, const ZeroLengthData &data)
        : Element(tag, {data.nodes[0], data.nodes[1]})
        , rayleigh(data.rayleigh)
      {
        domain.node(data.nodes[0]);
        domain.node(data.nodes[1]);
        const Eigen::Matrix3d axes = zero_length_axes(data, tag);
        const unsigned int    ndf = domain.ndf, ndm = domain.ndm;
        // the node's DOFs of translations and of rotations, in order
        const unsigned int n_translations = std::min(ndm, ndf);
        const unsigned int n_rotations    = ndf > ndm ? ndf - ndm : 0;
        t.setZero(data.materials.size(), 2 * ndf);
        for (unsigned int m = 0; m < data.materials.size(); ++m)
          {
            const int direction = data.directions[m] - 1;
            if (direction < 0 || direction > 5)
              throw ScriptError("zeroLength " + std::to_string(tag) + ": -dir " +
                                std::to_string(direction + 1) + " is not one of 1 to 6");
            const unsigned int axis = direction % 3;
            if (direction < 3)
              for (unsigned int k = 0; k < n_translations; ++k)
                t(m, ndf + k) = axes(axis, k);
            else if (n_rotations == 1) // planar: the rotation about z
              t(m, ndf + ndm) = axes(axis, 2);
            else if (n_rotations == 3)
              for (unsigned int k = 0; k < 3; ++k)
                t(m, ndf + ndm + k) = axes(axis, k);
            t.block(m, 0, 1, ndf) = -t.block(m, ndf, 1, ndf);
            laws.push_back(make_domain_material(domain, data.materials[m]));
          }
        committed_tangent = tangent();
      }
    } // namespace

    void
    add_uniform_beam_load(const double L, const double wy, const double wx, Eigen::Vector3d &q0,
                          Eigen::Vector3d &p0)
    {
      const double V = 0.5 * wy * L, P = wx * L, M = V * L / 6.0;
      p0 -= Eigen::Vector3d(P, V, V);
      q0 -= Eigen::Vector3d(0.5 * P, M, -M);
    }

    std::vector<double>
    Element::response(const std::vector<std::string> &words) const
    {
      if (words.size() == 1 && (words[0] == "force" || words[0] == "forces" ||
                                words[0] == "globalForce" || words[0] == "globalForces"))
        {
          const Vector f = force();
          return std::vector<double>(f.data(), f.data() + f.size());
        }
      std::string text;
      for (const std::string &w : words)
        text += (text.empty() ? "" : " ") + w;
      throw ScriptError("element " + std::to_string(tag) + " has no response '" + text +
                        "' in poundfe");
    }

    std::unique_ptr<Element>
    make_elastic_beam_2d(const Domain &domain, const int tag, const std::array<int, 2> nodes,
                         const double A, const double E, const double I,
                         const Transformation transformation)
    {
      if (transformation == Transformation::corotational)
        return make_elastic_corotational_2d(domain, tag, nodes, A, E, I);
      return std::make_unique<ElasticBeam2d>(domain, tag, nodes, A, E, I,
                                             transformation == Transformation::pdelta);
    }

    std::unique_ptr<Element>
    make_zero_length(const Domain &domain, const int tag, const ZeroLengthData &data)
    {
      return std::make_unique<ZeroLength>(domain, tag, data);
    }

    std::unique_ptr<Element>
    make_truss(const Domain &domain, const int tag, const std::array<int, 2> nodes,
               const double area, const int material, const bool rayleigh)
    {
      const auto     &a = domain.node(nodes[0]).coordinates, &b = domain.node(nodes[1]).coordinates;
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      for (unsigned int k = 0; k < a.size(); ++k)
        d[k] = b[k] - a[k];
      const double length = d.norm();
      if (!(length > 0))
        throw ScriptError("truss " + std::to_string(tag) + " has zero length");
      if (!(area > 0))
        throw ScriptError("truss " + std::to_string(tag) + " needs A > 0");
      ZeroLengthData data;
      data.nodes     = nodes;
      data.materials = {material};
      data.directions = {1};
      data.rayleigh  = rayleigh;
      // any y across the member: the truss strains along x only
      const Eigen::Vector3d x = d / length;
      const Eigen::Vector3d y = std::abs(x[2]) < 0.9 ? Eigen::Vector3d(-x[1], x[0], 0).normalized() :
                                                      Eigen::Vector3d(1, 0, 0);
      for (unsigned int k = 0; k < 3; ++k)
        {
          data.x[k] = x[k];
          data.y[k] = y[k];
        }
      auto truss = std::make_unique<ZeroLength>(domain, tag, data);
      truss->as_truss(length, area);
      return truss;
    }
  } // namespace opensees
} // namespace poundfe
