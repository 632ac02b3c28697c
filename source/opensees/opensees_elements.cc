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
//   Its responses: force, localForce, basicForce, basicDeformation.
//   A uniform load wy (transverse), wx (axial) adds the fixed-end basic
//   forces q_0 = (-wx L/2, -wy L^2/12, wy L^2/12) to q (P-Delta's N too)
//   and the basic reactions p_0 = (-wx L, -wy L/2, -wy L/2) to the local
//   forces 0, 1 and 4 (ElasticBeam2d::addLoad, LOAD_TAG_Beam2dUniformLoad).
//
// truss (Truss, small strains): the zeroLength's row t along the member's
//   axis x, strain t u / L, force A t^T sigma, tangent (A/L) t^T E t;
//   Rayleigh-damped only with -doRayleigh 1 (OpenSees's default 0); made
//   on nodes that have moved, x and L those of the moved member and u
//   measured from then (Truss::setDomain's initialDisp, -useInitialDisp).
//
// zeroLength (ZeroLength): the local axes x, y (-orient), z = x × y,
//   y = z × x; material m along direction d (1-3: translation along axis
//   d, 4-6: rotation about axis d - 3; in a planar model 3 is the rotation
//   about z, as 6) has the row t_m of the local
//   deformation over the global DOFs (the axis' components at node j, their
//   negatives at node i, within the DOFs the model's ndm/ndf give; a
//   direction the node has no DOF for contributes nothing, as in
//   ZeroLength::setTran1d); strain t_m u, rate t_m v, u and v from the
//   nodes' state when it was made (ZeroLength::setDomain's d0, v0); force sum t_m^T
//   sigma_m, tangent sum t_m^T E_m t_m, damping sum t_m^T eta_m t_m.
//
// twoNodeLink (TwoNodeLink.cpp): the zeroLength's frame with t = T_lb T_gl:
//   T_gl the direction cosines (x from node i to j or -orient's, yp global
//   Y unless given, in 2D y across x) on each node's translations (and
//   rotations), T_lb node j's local DOF d minus node i's, the shears of a
//   link of length L with the end rotations times -s L, -(1 - s) L (local
//   y; +s L, +(1 - s) L for local z), s of -shearDist (0.5). -pDelta adds
//   to the local forces the shears N (u_j - u_i)/L (1 - r_1 - r_2) of the
//   axial force N and the end moments r_i N (u_j - u_i), and to the local
//   stiffness their derivatives with N held (addPDeltaForces,
//   addPDeltaStiff).
#include <poundfe/elements/beam_column.h>
#include <poundfe/opensees/opensees_domain.h>

#include <Eigen/Geometry>

#include <algorithm>

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
          // made on nodes that have moved: along and as long as the member
          // is then, its displacements measured from then
          // (LinearCrdTransf2d::initialize's nodeIInitialDisp, nodeJInitialDisp)
          const Node &i = domain.node(nodes[0]), &j = domain.node(nodes[1]);
          u_at_creation   = displacements_when_made(domain, nodes, 3);
          const double dx = j.coordinates[0] - i.coordinates[0] + u_at_creation[3] - u_at_creation[0];
          const double dy = j.coordinates[1] - i.coordinates[1] + u_at_creation[4] - u_at_creation[1];
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
          ul = R * (u - u_at_creation);
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
        add_beam_uniform(const double wy, const double wx, const double) override
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

        /// ElasticBeam2d::getResponse: localForce (-N + p0_0, V + p0_1, M1,
        /// N, -V + p0_2, M2 with V = (M1 + M2)/L), basicForce q (with q_0)
        /// and basicDeformation (the transformation's basic displacements).
        std::vector<double>
        response(const std::vector<std::string> &words) const override
        {
          const std::string what = words.size() == 1 ? words[0] : "";
          const Eigen::Vector3d qq = q + q0;
          if (what == "localForce" || what == "localForces")
            {
              const double V = (qq[1] + qq[2]) / L;
              return {-qq[0] + p0[0], V + p0[1], qq[1], qq[0], -V + p0[2], qq[2]};
            }
          if (what == "basicForce" || what == "basicForces")
            return {qq[0], qq[1], qq[2]};
          if (what == "basicDeformation" || what == "basicDeformations" ||
              what == "chordRotation" || what == "chordDeformation")
            {
              const Eigen::Vector3d v = B * ul;
              return {v[0], v[1], v[2]};
            }
          return Element::response(words);
        }

      private:
        bool                   p_delta;
        double                 L = 0;
        Matrix                 R, B;
        Eigen::Matrix3d        kb;
        Vector                 ul, u_at_creation;
        Eigen::Vector3d        q;
        Eigen::Vector3d        q0, p0; // element loads: basic fixed-end forces, reactions
      };

      class ZeroLength : public Element, protected UniaxialRows
      {
      public:
        /// Material m (the domain's tag materials[m]) on row m of t.
        ZeroLength(const Domain &domain, const int tag, const std::array<int, 2> nodes,
                   Matrix rows, const std::vector<int> &materials, const bool rayleigh)
          : Element(tag, {nodes[0], nodes[1]})
          , rayleigh(rayleigh)
        {
          t = std::move(rows);
          for (const int material : materials)
            laws.push_back(make_domain_material(domain, material));
          committed_tangent = tangent();
        }

        unsigned int n_dofs() const override { return t.cols(); }
        bool         rayleigh_damped() const override { return rayleigh; }

        /// OpenSees's zeroLength made on nodes that have moved
        /// (ZeroLength::setDomain's d0 and v0): its strains and rates
        /// measured from the nodes' displacements and velocities now; a
        /// truss's strains only (Truss::setDomain's initialDisp).
        void
        measure_from_now(const Domain &domain, const bool rates = true)
        {
          Vector u(n_dofs()), v(n_dofs());
          const unsigned int ndf = n_dofs() / 2;
          for (unsigned int a = 0; a < 2; ++a)
            {
              const Node &node = domain.node(node_tags[a]);
              // a node of another -ndf is refused when the element is added
              for (unsigned int k = 0; k < std::min<std::size_t>(ndf, node.disp.size()); ++k)
                {
                  u[a * ndf + k] = node.disp[k];
                  v[a * ndf + k] = node.vel[k];
                }
            }
          if (!u.isZero(0))
            u_at_creation = u;
          if (rates && !v.isZero(0))
            v_at_creation = v;
        }

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
        set_trial(const Vector &u_total, const Vector &v_total) override
        {
          if (u_at_creation.size() > 0)
            u_since_creation = u_total - u_at_creation;
          if (v_at_creation.size() > 0)
            v_since_creation = v_total - v_at_creation;
          const Vector &u = u_at_creation.size() > 0 ? u_since_creation : u_total;
          const Vector &v = v_at_creation.size() > 0 ? v_since_creation : v_total;
          // t u and t v by rows into the members' storage: Eigen's dynamic
          // product costs more than these few terms. Kept in step with
          // UniaxialLinksOf::set_trial (opensees_analysis.cc), which repeats
          // these operations in this order for small models: edit both.
          rate.resize(laws.size());
          strain.resize(laws.size());
          for (unsigned int m = 0; m < laws.size(); ++m)
            {
              double e = 0, e_dot = 0;
              for (Eigen::Index j = 0; j < t.cols(); ++j)
                {
                  e_dot += t(m, j) * v[j];
                  e += t(m, j) * u[j];
                }
              rate[m]   = e_dot * strain_scale;
              strain[m] = e * strain_scale;
            }
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
          Vector f;
          force_into(f);
          return f;
        }

        void
        force_into(Vector &f) const override
        {
          // sum_m t_m^T sigma_m by rows: t is mostly zeros, and a product
          // of Eigen's dynamic matrices allocates its temporaries. Kept in
          // step with UniaxialLinksOf::subtract_forces (opensees_analysis.cc).
          f.setZero(t.cols());
          for (unsigned int m = 0; m < laws.size(); ++m)
            {
              const double stress = laws[m]->force();
              for (Eigen::Index j = 0; j < t.cols(); ++j)
                f[j] += t(m, j) * stress;
            }
          f *= force_scale;
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
          const std::string what = words.size() == 1 ? words[0] : "";
          // ZeroLength::getResponse: each material's stress, or its strain
          if (!truss && (what == "basicForce" || what == "basicForces" ||
                         what == "localForce" || what == "localForces"))
            {
              std::vector<double> stresses;
              for (const auto &law : laws)
                stresses.push_back(law->force());
              return stresses;
            }
          if (!truss && (what == "deformation" || what == "deformations" || what == "defo" ||
                         what == "basicDeformation"))
            {
              std::vector<double> strains(laws.size(), 0.0);
              for (Eigen::Index m = 0; m < strain.size(); ++m)
                strains[m] = strain[m];
              return strains;
            }
          return Element::response(words);
        }

        ResponseReader
        response_reader(const std::vector<std::string> &words) const override
        {
          if (words.size() != 3 || words[0] != "material")
            return Element::response_reader(words);
          const auto [i, kind] = material_response_of(words[1], words[2]);
          return [this, i = i, kind = kind](std::vector<double> &values) {
            material_values(i, kind, values);
          };
        }

        Matrix tangent() const override { return as_value(&ZeroLength::tangent_into); }
        Matrix
        initial_tangent() const override
        {
          return as_value(&ZeroLength::initial_tangent_into);
        }
        Matrix
        material_damping() const override
        {
          return as_value(&ZeroLength::material_damping_into);
        }
        void
        tangent_into(Matrix &k) const override
        {
          weighted([](auto &l) { return l.tangent(); }, k);
        }
        void
        tangent_and_damping_into(const double c_k, const double c_c, Matrix &k,
                                 Matrix &c) const override
        {
          // the sums of tangent_into and material_damping_into in one pass
          // over the materials, then Element's c_k K + c_c C
          if (c_c == 0)
            weighted([](auto &l) { return l.tangent(); }, k);
          else
            weighted([](auto &l) { return l.tangent(); }, k,
                     [](auto &l) { return l.damping_tangent(); }, &c);
          k *= c_k;
          if (c_c != 0)
            k += c_c * c;
        }
        void
        initial_tangent_into(Matrix &k) const override
        {
          weighted([](auto &l) { return l.initial_stiffness(); }, k);
        }
        void
        material_damping_into(Matrix &c) const override
        {
          weighted([](auto &l) { return l.damping_tangent(); }, c);
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
        /// None when made on moved nodes: the typed loops read total
        /// displacements.
        UniaxialRows *
        uniaxial_rows() override
        {
          return u_at_creation.size() + v_at_creation.size() > 0 ? nullptr : this;
        }
        /// The rows whatever uniaxial_rows() says (link_rows).
        UniaxialRows *rows() { return this; }

      protected:
        /// OpenSees's `material i stress|strain|tangent|stressStrain|
        /// stressStrainTangent` (ZeroLength::setResponse passing the rest of
        /// the words to UniaxialMaterial::setResponse).
        enum class MaterialResponse
        {
          stress,
          strain,
          tangent,
          stress_strain,
          stress_strain_tangent
        };

        /// The 0-based material of `number` and the kind of `what`;
        /// ScriptError when the element has no such material or response.
        std::pair<unsigned int, MaterialResponse>
        material_response_of(const std::string &number, const std::string &what) const
        {
          const int i = std::atoi(number.c_str());
          if (i < 1 || i > static_cast<int>(laws.size()))
            throw ScriptError("element " + std::to_string(tag) + " has no material " + number +
                              " (1 to " + std::to_string(laws.size()) + ")");
          using R = MaterialResponse;
          const std::pair<const char *, R> kinds[] = {
            {"stress", R::stress},
            {"strain", R::strain},
            {"tangent", R::tangent},
            {"stressStrain", R::stress_strain},
            {"stressANDstrain", R::stress_strain},
            {"stressAndStrain", R::stress_strain},
            {"stressStrainTangent", R::stress_strain_tangent},
            {"stressANDstrainANDtangent", R::stress_strain_tangent}};
          for (const auto &[name, kind] : kinds)
            if (what == name)
              return {static_cast<unsigned int>(i - 1), kind};
          throw ScriptError("element " + std::to_string(tag) + ": material response '" + what +
                            "' is not supported");
        }

        /// The values of material i's response appended to `values`.
        void
        material_values(const unsigned int i, const MaterialResponse what,
                        std::vector<double> &values) const
        {
          const UniaxialLaw &law = *laws[i];
          const double       e   = strain.size() > 0 ? strain[i] : 0.0;
          switch (what)
            {
              case MaterialResponse::stress:
                values.push_back(law.force());
                break;
              case MaterialResponse::strain:
                values.push_back(e);
                break;
              case MaterialResponse::tangent:
                values.push_back(law.tangent());
                break;
              case MaterialResponse::stress_strain:
                values.insert(values.end(), {law.force(), e});
                break;
              case MaterialResponse::stress_strain_tangent:
                values.insert(values.end(), {law.force(), e, law.tangent()});
                break;
            }
        }

        std::vector<double>
        material_response(const std::string &number, const std::string &what) const
        {
          const auto [i, kind] = material_response_of(number, what);
          std::vector<double> values;
          material_values(i, kind, values);
          return values;
        }

        /// One of the *_into matrices as a new matrix.
        Matrix
        as_value(void (ZeroLength::*into)(Matrix &) const) const
        {
          Matrix k;
          (this->*into)(k);
          return k;
        }

        /// sum_m t_m^T d_m t_m into k, d_m = value(law m).
        template <typename Value>
        void
        weighted(const Value &value, Matrix &k) const
        {
          weighted(value, k, value, nullptr);
        }

        /// The same, and with `c` the sum of other_value into c, in one
        /// pass over the materials.
        template <typename Value, typename OtherValue>
        void
        weighted(const Value &value, Matrix &k, const OtherValue &other_value, Matrix *c) const
        {
          // by rows, skipping t_m's zeros (as force()). Kept in step with
          // UniaxialLinksOf::add_tangents (opensees_analysis.cc).
          const Eigen::Index n = t.cols();
          k.setZero(n, n);
          if (c)
            c->setZero(n, n);
          for (unsigned int m = 0; m < laws.size(); ++m)
            {
              const double d = value(*laws[m]), e = c ? other_value(*laws[m]) : 0.0;
              for (Eigen::Index i = 0; i < n; ++i)
                if (t(m, i) != 0)
                  for (Eigen::Index j = 0; j < n; ++j)
                    {
                      k(i, j) += t(m, i) * d * t(m, j);
                      if (c)
                        (*c)(i, j) += t(m, i) * e * t(m, j);
                    }
            }
          k *= force_scale * strain_scale;
          if (c)
            *c *= force_scale * strain_scale;
        }

        Vector committed_strain; // the materials' committed strains
        /// The nodes' displacements and velocities when it was made, if any
        /// is not zero (measure_from_now), and storage for u - u_at_creation.
        Vector u_at_creation, v_at_creation, u_since_creation, v_since_creation;
        bool   rayleigh = false;
      };

      /// OpenSees's kinds of twoNodeLink by the model's ndm and ndf: D1N2,
      /// D2N4, D2N6, D3N6, D3N12.
      enum class LinkKind
      {
        d1n2,
        d2n4,
        d2n6,
        d3n6,
        d3n12
      };

      /// The P-Delta of a twoNodeLink: its kind, length, directions
      /// (0-based) and moment ratios rMy1 rMy2 rMz1 rMz2.
      struct LinkPDelta
      {
        LinkKind                  kind;
        double                    L;
        std::vector<int>          directions;
        std::array<double, 4>     ratios;
      };

      class TwoNodeLink : public ZeroLength
      {
      public:
        TwoNodeLink(const Domain &domain, const int tag, const TwoNodeLinkData &data,
                    const Matrix &Tgl, const Matrix &Tlb, LinkPDelta p_delta)
          : ZeroLength(domain, tag, data.nodes, Tlb * Tgl, data.materials, data.rayleigh)
          , Tgl(Tgl)
          , Tlb(Tlb)
          , ul(Vector::Zero(Tgl.rows()))
          , p_delta(std::move(p_delta))
          , with_p_delta(!data.p_delta.empty())
        {}

        bool
        set_trial(const Vector &u, const Vector &v) override
        {
          ul = Tgl * u;
          return ZeroLength::set_trial(u, v);
        }
        UniaxialRows *uniaxial_rows() override { return nullptr; } // ul, P-Delta
        Vector
        force() const override
        {
          return with_p_delta ? Vector(Tgl.transpose() * local_force()) : ZeroLength::force();
        }
        Matrix
        tangent() const override
        {
          if (!with_p_delta)
            return ZeroLength::tangent();
          Matrix kl = Tlb.transpose() * basic(&UniaxialLaw::tangent).asDiagonal() * Tlb;
          add_p_delta_stiffness(kl);
          return Tgl.transpose() * kl * Tgl;
        }
        // with P-Delta the values above, without it ZeroLength's in place
        void
        force_into(Vector &f) const override
        {
          with_p_delta ? void(f = force()) : ZeroLength::force_into(f);
        }
        void
        tangent_into(Matrix &k) const override
        {
          with_p_delta ? void(k = tangent()) : ZeroLength::tangent_into(k);
        }
        void
        tangent_and_damping_into(const double c_k, const double c_c, Matrix &k,
                                 Matrix &c) const override
        {
          with_p_delta ? Element::tangent_and_damping_into(c_k, c_c, k, c) :
                         ZeroLength::tangent_and_damping_into(c_k, c_c, k, c);
        }
        std::vector<double>
        response(const std::vector<std::string> &words) const override
        {
          const std::string what = words.size() == 1 ? words[0] : "";
          const auto        list = [](const Vector &x) {
            return std::vector<double>(x.data(), x.data() + x.size());
          };
          if (what == "localForce" || what == "localForces")
            return list(local_force());
          if (what == "basicForce" || what == "basicForces")
            return list(basic(&UniaxialLaw::force));
          if (what == "localDisplacement" || what == "localDisplacements")
            return list(ul);
          if (what == "deformation" || what == "deformations" || what == "basicDeformation" ||
              what == "basicDeformations" || what == "basicDisplacement" ||
              what == "basicDisplacements")
            return list(strain);
          return ZeroLength::response(words);
        }

      private:
        Vector
        basic(double (UniaxialLaw::*value)() const) const
        {
          Vector q(laws.size());
          for (unsigned int i = 0; i < laws.size(); ++i)
            q[i] = ((*laws[i]).*value)();
          return q;
        }
        Vector
        local_force() const
        {
          Vector pl = Tlb.transpose() * basic(&UniaxialLaw::force);
          if (with_p_delta)
            add_p_delta_forces(pl);
          return pl;
        }
        /// The axial force N (of direction 1's material; 0 without one).
        double axial_force() const;
        void   add_p_delta_forces(Vector &pl) const;
        void   add_p_delta_stiffness(Matrix &kl) const;

        Matrix     Tgl, Tlb; // global to local, local to basic
        Vector     ul;       // local displacements of the trial
        LinkPDelta p_delta;
        bool       with_p_delta;
      };

      double
      TwoNodeLink::axial_force() const
      {
        double N = 0;
        for (unsigned int i = 0; i < laws.size(); ++i)
          if (p_delta.directions[i] == 0)
            N = laws[i]->force();
        return N;
      }

      /// OpenSees's TwoNodeLink::addPDeltaForces: shears N delta / L times
      /// the share not taken by the end moments, and those moments.
      void
      TwoNodeLink::add_p_delta_forces(Vector &pl) const
      {
        const LinkPDelta &p = p_delta;
        const auto       &r = p.ratios;
        const int         h = pl.size() / 2;
        const bool        has_y = std::count(p.directions.begin(), p.directions.end(), 1) > 0;
        const bool        has_z = std::count(p.directions.begin(), p.directions.end(), 2) > 0;
        const bool        three = p.kind == LinkKind::d3n6 || p.kind == LinkKind::d3n12;
        const double      N  = axial_force();
        const double      d1 = has_y && p.kind != LinkKind::d1n2 ? ul[1 + h] - ul[1] : 0.0;
        const double      d2 = has_z && three ? ul[2 + h] - ul[2] : 0.0;
        if (N == 0.0 || (d1 == 0.0 && d2 == 0.0) || p.kind == LinkKind::d1n2)
          return;
        for (const int dir : p.directions)
          if (dir == 1)
            {
              const double V = N * d1 / p.L * (1.0 - r[2] - r[3]);
              pl[1] -= V;
              pl[h + 1] += V;
            }
          else if (dir == 2 && p.kind == LinkKind::d2n6)
            {
              pl[2] += r[2] * N * d1;
              pl[5] += r[3] * N * d1;
            }
          else if (dir == 2 && three)
            {
              const double V = N * d2 / p.L * (1.0 - r[0] - r[1]);
              pl[2] -= V;
              pl[h + 2] += V;
            }
          else if (dir == 4 && p.kind == LinkKind::d3n12)
            {
              pl[4] -= r[0] * N * d2;
              pl[10] -= r[1] * N * d2;
            }
          else if (dir == 5 && p.kind == LinkKind::d3n12)
            {
              pl[5] += r[2] * N * d1;
              pl[11] += r[3] * N * d1;
            }
      }

      /// OpenSees's TwoNodeLink::addPDeltaStiff (N held constant).
      void
      TwoNodeLink::add_p_delta_stiffness(Matrix &kl) const
      {
        const LinkPDelta &p = p_delta;
        const auto       &r = p.ratios;
        const int         h = kl.rows() / 2;
        const double      N = axial_force();
        const bool        three = p.kind == LinkKind::d3n6 || p.kind == LinkKind::d3n12;
        if (N == 0.0 || p.kind == LinkKind::d1n2)
          return;
        const auto shear = [&](const int k, const double n_over_l) {
          kl(k, k) += n_over_l;
          kl(k, h + k) -= n_over_l;
          kl(h + k, k) -= n_over_l;
          kl(h + k, h + k) += n_over_l;
        };
        const auto moment = [&](const int row, const int col, const double m) {
          kl(row, col) -= m;
          kl(row, h + col) += m;
        };
        for (const int dir : p.directions)
          if (dir == 1)
            shear(1, N / p.L * (1.0 - r[2] - r[3]));
          else if (dir == 2 && p.kind == LinkKind::d2n6)
            {
              moment(2, 1, r[2] * N);
              moment(5, 1, r[3] * N);
            }
          else if (dir == 2 && three)
            shear(2, N / p.L * (1.0 - r[0] - r[1]));
          else if (dir == 4 && p.kind == LinkKind::d3n12)
            {
              moment(4, 2, -r[0] * N);
              moment(10, 2, -r[1] * N);
            }
          else if (dir == 5 && p.kind == LinkKind::d3n12)
            {
              moment(5, 1, r[2] * N);
              moment(11, 1, r[3] * N);
            }
      }

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

      /// The rows of the zeroLength's materials over its nodes' DOFs.
      Matrix
      zero_length_rows(const Domain &domain, const int tag, const ZeroLengthData &data)
      {
        domain.node(data.nodes[0]);
        domain.node(data.nodes[1]);
        const Eigen::Matrix3d axes = zero_length_axes(data, tag);
        const unsigned int    ndf = domain.ndf, ndm = domain.ndm;
        // the node's DOFs of translations and of rotations, in order
        const unsigned int n_translations = std::min(ndm, ndf);
        const unsigned int n_rotations    = ndf > ndm ? ndf - ndm : 0;
        Matrix t = Matrix::Zero(data.materials.size(), 2 * ndf);
        for (unsigned int m = 0; m < data.materials.size(); ++m)
          {
            int direction = data.directions[m] - 1;
            if (direction < 0 || direction > 5)
              throw ScriptError("zeroLength " + std::to_string(tag) + ": -dir " +
                                std::to_string(direction + 1) + " is not one of 1 to 6");
            // In a planar model OpenSees reads -dir 3 as the rotation about z
            // (ZeroLength's constructors: direction 2 becomes 5 when ndm = 2).
            if (direction == 2 && ndm == 2)
              direction = 5;
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
          }
        return t;
      }
    } // namespace

    void
    add_uniform_beam_load(const double L, const double wy, const double wx, Eigen::Vector3d &q0,
                          Eigen::Vector3d &p0)
    {
      const UniformLoadForces<2> f = uniform_load_forces<2>(L, MemberLoad<2>(wx, wy));
      p0 += f.p0;
      q0 += f.q0;
    }

    void
    Element::tangent_and_damping_into(const double c_k, const double c_c, Matrix &k,
                                      Matrix &c) const
    {
      tangent_into(k);
      k *= c_k;
      if (c_c == 0)
        return;
      material_damping_into(c);
      k += c_c * c;
    }

    Element::ResponseReader
    Element::response_reader(const std::vector<std::string> &words) const
    {
      response(words); // refuses what the element does not give
      return [this, words](std::vector<double> &values) {
        const std::vector<double> v = response(words);
        values.insert(values.end(), v.begin(), v.end());
      };
    }

    std::vector<double>
    Element::response(const std::vector<std::string> &words) const
    {
      if (is_global_force(words))
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
        {
          return make_elastic_corotational_2d(domain, tag, nodes, A, E, I);
        }
      return std::make_unique<ElasticBeam2d>(domain, tag, nodes, A, E, I,
                                             transformation == Transformation::pdelta);
    }

    Vector
    displacements_when_made(const Domain &domain, const std::array<int, 2> &nodes,
                            const unsigned int n_node_dofs)
    {
      Vector made = Vector::Zero(2 * n_node_dofs);
      for (unsigned int end = 0; end < 2; ++end)
        {
          const std::vector<double> &disp = domain.node(nodes[end]).disp;
          for (unsigned int k = 0; k < std::min<std::size_t>(n_node_dofs, disp.size()); ++k)
            made[end * n_node_dofs + k] = disp[k];
        }
      return made;
    }

    std::unique_ptr<Element>
    make_zero_length(const Domain &domain, const int tag, const ZeroLengthData &data)
    {
      auto element = std::make_unique<ZeroLength>(domain, tag, data.nodes,
                                                  zero_length_rows(domain, tag, data),
                                                  data.materials, data.rayleigh);
      element->measure_from_now(domain);
      return element;
    }

    /// TwoNodeLink::setUp: x along the nodes (or -orient's), yp global Y
    /// (global -X or X when x is along +Y or -Y; or -orient's), in 2D
    /// y across x in the plane; the rows of direction cosines x, y, z.
    Eigen::Matrix3d
    two_node_link_axes(const Domain &domain, const int tag, const TwoNodeLinkData &data,
                       double &L)
    {
      const auto &a = domain.node(data.nodes[0]).coordinates,
                 &b = domain.node(data.nodes[1]).coordinates;
      Eigen::Vector3d x = Eigen::Vector3d::Zero(), y(0, 1, 0);
      for (unsigned int i = 0; i < domain.ndm; ++i)
        x[i] = b[i] - a[i];
      L = x.norm();
      if (L > 0 && x[0] == 0.0 && x[2] == 0.0)
        y = Eigen::Vector3d(x[1] > 0 ? -1 : 1, 0, 0);
      const std::vector<double> &o = data.orient;
      if (o.size() == 6 || (o.size() == 3 && domain.ndm < 3))
        x = Eigen::Vector3d(o[0], o[1], o[2]);
      if (o.size() == 6 || (o.size() == 3 && domain.ndm == 3))
        y = Eigen::Vector3d(o[o.size() - 3], o[o.size() - 2], o[o.size() - 1]);
      if (domain.ndm == 1)
        x = Eigen::Vector3d(1, 0, 0), y = Eigen::Vector3d(0, 1, 0);
      if (!(x.norm() > 0))
        throw ScriptError("twoNodeLink " + std::to_string(tag) +
                          ": its nodes coincide; -orient must give its local x");
      x /= x.norm();
      if (domain.ndm == 2)
        y = Eigen::Vector3d(-x[1], x[0], 0);
      const Eigen::Vector3d z = x.cross(y);
      y                       = z.cross(x);
      if (!(y.norm() > 0) || !(z.norm() > 0))
        throw ScriptError("twoNodeLink " + std::to_string(tag) +
                          ": -orient vectors are zero or parallel");
      Eigen::Matrix3d trans;
      trans.row(0) = x / x.norm();
      trans.row(1) = y / y.norm();
      trans.row(2) = z / z.norm();
      return trans;
    }

    namespace
    {
      LinkKind
      link_kind(const Domain &domain, const int tag)
      {
        const unsigned int ndm = domain.ndm, ndf = domain.ndf;
        if (ndm == 1 && ndf == 1)
          return LinkKind::d1n2;
        if (ndm == 2 && (ndf == 2 || ndf == 3))
          return ndf == 2 ? LinkKind::d2n4 : LinkKind::d2n6;
        if (ndm == 3 && (ndf == 3 || ndf == 6))
          return ndf == 3 ? LinkKind::d3n6 : LinkKind::d3n12;
        throw ScriptError("twoNodeLink " + std::to_string(tag) + ": -ndm " +
                          std::to_string(ndm) + " -ndf " + std::to_string(ndf) +
                          " is not a model OpenSees's twoNodeLink takes");
      }

      /// TwoNodeLink::setTranGlobalLocal: the direction cosines on each
      /// node's translations (and rotations).
      Matrix
      link_global_to_local(const LinkKind kind, const Eigen::Matrix3d &trans, const int n_dofs)
      {
        Matrix    T = Matrix::Zero(n_dofs, n_dofs);
        const int h = n_dofs / 2;
        const int translations =
          kind == LinkKind::d1n2 ? 1 : kind == LinkKind::d2n4 || kind == LinkKind::d2n6 ? 2 : 3;
        for (const int node : {0, h})
          {
            T.block(node, node, translations, translations) =
              trans.topLeftCorner(translations, translations);
            if (kind == LinkKind::d2n6)
              T(node + 2, node + 2) = trans(2, 2);
            if (kind == LinkKind::d3n12)
              T.block(node + 3, node + 3, 3, 3) = trans;
          }
        return T;
      }

      /// TwoNodeLink::setTranLocalBasic: node j's local DOF minus node i's,
      /// a shear with the moments of its distance from each node.
      Matrix
      link_local_to_basic(const LinkKind kind, const std::vector<int> &directions,
                          const int n_dofs, const double L, const std::array<double, 2> &s)
      {
        Matrix    T = Matrix::Zero(directions.size(), n_dofs);
        const int h = n_dofs / 2;
        for (unsigned int i = 0; i < directions.size(); ++i)
          {
            const int dir   = directions[i];
            T(i, dir)       = -1.0;
            T(i, dir + h)   = 1.0;
            if (kind == LinkKind::d2n6 && dir == 1)
              T(i, 2) = -s[0] * L, T(i, 5) = -(1.0 - s[0]) * L;
            if (kind == LinkKind::d3n12 && dir == 1)
              T(i, 5) = -s[0] * L, T(i, 11) = -(1.0 - s[0]) * L;
            if (kind == LinkKind::d3n12 && dir == 2)
              T(i, 4) = s[1] * L, T(i, 10) = (1.0 - s[1]) * L;
          }
        return T;
      }
    } // namespace

    UniaxialRows *
    link_rows(Element &element)
    {
      auto *link = dynamic_cast<ZeroLength *>(&element);
      return link ? link->rows() : nullptr;
    }

    std::unique_ptr<Element>
    make_two_node_link(const Domain &domain, const int tag, const TwoNodeLinkData &data)
    {
      const std::string name = "twoNodeLink " + std::to_string(tag);
      const LinkKind    kind = link_kind(domain, tag);
      const int         n_dofs = 2 * domain.ndf;
      LinkPDelta        p{kind, 0.0, {}, {{0, 0, 0, 0}}};
      const Eigen::Matrix3d trans = two_node_link_axes(domain, tag, data, p.L);
      for (const int d : data.directions)
        {
          if (d < 1 || d > static_cast<int>(domain.ndf))
            throw ScriptError(name + ": -dir " + std::to_string(d) + " is not one of 1 to " +
                              std::to_string(domain.ndf));
          p.directions.push_back(d - 1);
        }
      std::array<double, 2> shear{{0.5, 0.5}};
      std::copy(data.shear_distance.begin(), data.shear_distance.end(), shear.begin());
      for (const double ratio : shear)
        if (!(ratio >= 0 && ratio <= 1))
          throw ScriptError(name + ": -shearDist ratios must be in [0, 1]");
      const std::vector<double> &r = data.p_delta;
      std::copy(r.begin(), r.end(), p.ratios.begin() + (4 - r.size()));
      if (!r.empty() && (*std::min_element(r.begin(), r.end()) < 0 ||
                         p.ratios[0] + p.ratios[1] > 1 || p.ratios[2] + p.ratios[3] > 1))
        throw ScriptError(name + ": -pDelta ratios must be >= 0 with each pair's sum <= 1");
      if (!r.empty() && !(p.L > 0))
        throw ScriptError(name + ": -pDelta on a link of zero length");
      const Matrix Tgl = link_global_to_local(kind, trans, n_dofs);
      const Matrix Tlb = link_local_to_basic(kind, p.directions, n_dofs, p.L, shear);
      return std::make_unique<TwoNodeLink>(domain, tag, data, Tgl, Tlb, std::move(p));
    }

    std::unique_ptr<Element>
    make_truss(const Domain &domain, const int tag, const std::array<int, 2> nodes,
               const double area, const int material, const bool rayleigh)
    {
      const auto     &a = domain.node(nodes[0]).coordinates, &b = domain.node(nodes[1]).coordinates;
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      for (unsigned int k = 0; k < std::min(a.size(), b.size()); ++k) // nodes of two -ndm
        d[k] = b[k] - a[k];
      // made on nodes that have moved: along and as long as the member is
      // then (Truss::setDomain with -useInitialDisp, OpenSees's default)
      const auto     &u_a = domain.node(nodes[0]).disp, &u_b = domain.node(nodes[1]).disp;
      Eigen::Vector3d moved = Eigen::Vector3d::Zero();
      for (unsigned int k = 0; k < std::min({a.size(), b.size(), u_a.size(), u_b.size()}); ++k)
        moved[k] = u_b[k] - u_a[k];
      if (!moved.isZero(0))
        d += moved;
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
      auto truss = std::make_unique<ZeroLength>(
        domain, tag, nodes, zero_length_rows(domain, tag, data), data.materials, rayleigh);
      truss->as_truss(length, area);
      truss->measure_from_now(domain, false);
      return truss;
    }
  } // namespace opensees
} // namespace poundfe
