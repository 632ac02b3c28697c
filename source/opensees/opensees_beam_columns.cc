// The distributed-plasticity beam-columns of an OpenSees script in the
// plane and in space (BeamColumn<2>, BeamColumn<3>; in space on a Linear,
// PDelta or Corotational transformation with the geomTransf's vecxz, the localForce of ForceBeamColumn3d: (-N, Vy, -Vz, -T, MyI, MzI, N, -Vy,
// Vz, T, MyJ, MzJ)): forceBeamColumn (nonlinearBeamColumn) and dispBeamColumn on the
// sections of a `beamIntegration` (elements/beam_column.h: OpenSees's
// ForceBeamColumn2d and DispBeamColumn2d state determinations), and
// elasticBeamColumn on a Corotational transformation (plane and space); the force-based one
// iterates as OpenSees's (OpenSeesIteration). Their responses as
// OpenSees's ForceBeamColumn2d::getResponse gives them:
//   force       the global resisting force (6 values, node I then J);
//   localForce  (-N, V, MI, N, -V, MJ) with q = (N, MI, MJ) and
//               V = (MI + MJ)/L0 (L0 the initial length, as OpenSees);
//   basicForce  q;  basicDeformation (chordRotation, chordDeformation)  v;
//   section i force | deformation  the resultants (N, M) or deformations
//               (eps0, kappa) of integration point i (1-based, from end I).
// A dispBeamColumn on a Linear or PDelta transformation takes uniform
// element loads as OpenSees's DispBeamColumn2d: the fixed-end basic forces
// q0 added to q (so to P-Delta's N and its N/L tangent), the basic
// reactions p0 to the local end forces 0, 1 and 4; the sections do not
// see the load. A forceBeamColumn on a Linear or PDelta transformation,
// and both elements in space, take them through the member's own load
// (BeamColumn::set_uniform_load at factor 1, the patterns' factors in the
// load): the force-based sections carry s = b q + s_p (OpenSees's
// ForceBeamColumn2d/3d::computeSectionForces, the whole load in every
// iteration), the basic reactions p0 enter the resisting force and
// localForce as OpenSees's computeReactions gives them.
// Made on nodes that have moved, a member is along and as long as it is
// then and measured from the nodes' displacements then (the
// transformations' initialize: nodeIInitialDisp, nodeJInitialDisp), which
// its CrdTransformation keeps (u_made).
#include <poundfe/base/exceptions.h>
#include <poundfe/elements/beam_column.h>
#include <poundfe/elements/displaced_chord.h>
#include <poundfe/opensees/opensees_domain.h>
#include <poundfe/opensees/opensees_section_links.h>
#include <poundfe/sections/aggregator_section.h>
#include <poundfe/sections/elastic_section.h>

#include <Eigen/Geometry>

#include <cmath>
#include <optional>

namespace poundfe
{
  namespace opensees
  {
    namespace
    {
      class BeamColumnElement : public Element
      {
      public:
        /// `loads`: none, the displacement-based q0 and p0 kept here, or
        /// the member's own load (force-based).
        enum class Loads
        {
          none,
          fixed_end_forces,
          member
        };
        BeamColumnElement(const int tag, const std::array<int, 2> nodes,
                          std::unique_ptr<BeamColumn<2>> beam, const Loads loads = Loads::none)
          : Element(tag, {nodes[0], nodes[1]})
          , member(std::move(beam))
          , takes_loads(loads == Loads::fixed_end_forces)
          , member_loads(loads == Loads::member)
        {
          q0.setZero();
          p0.setZero();
          w.setZero();
          committed_tangent = tangent();
        }

        bool takes_beam_loads() const override { return takes_loads || member_loads; }
        void
        zero_loads() override
        {
          q0.setZero();
          p0.setZero();
          if (member_loads && !w.isZero(0))
            {
              w.setZero();
              member->set_uniform_load(w);
            }
        }
        void
        add_beam_uniform(const double wy, const double wx, const double) override
        {
          if (!member_loads)
            {
              add_uniform_beam_load(member->length(), wy, wx, q0, p0);
              return;
            }
          // the reactions for localForce; the member takes q0's place
          Eigen::Vector3d unused = Eigen::Vector3d::Zero();
          add_uniform_beam_load(member->length(), wy, wx, unused, p0);
          w += MemberLoad<2>(wx, wy);
          member->set_uniform_load(w);
          member->set_load_factor(1);
        }

        unsigned int n_dofs() const override { return 6; }
        bool         rayleigh_damped() const override { return true; }
        bool         costly_trial() const override { return true; }

        bool
        set_trial(const Vector &u, const Vector &) override
        {
          return member->set_trial(BeamColumn<2>::GlobalVector(u));
        }

        Vector
        force() const override
        {
          if (!takes_loads)
            return member->resisting_force();
          // B^T q + P-Delta's p_g are linear in q: q0's share added; p0 in
          // local components at the ends' translations
          const auto &t  = member->transformation();
          const auto &ax = t.local_axes(); // rows: local x, y
          Vector      p  = member->resisting_force() + t.global_force(q0);
          p.segment<2>(0) += p0[0] * ax.row(0).transpose() + p0[1] * ax.row(1).transpose();
          p.segment<2>(3) += p0[2] * ax.row(1).transpose();
          return p;
        }
        Matrix
        tangent() const override
        {
          if (!takes_loads || q0[0] == 0)
            return member->tangent();
          // P-Delta's N/L g g^T of q0's N (zero on a Linear transformation)
          return member->tangent() +
                 member->transformation().global_tangent(q0, CrdTransformation<2>::BasicMatrix::Zero());
        }
        Matrix initial_tangent() const override { return member->initial_tangent(); }
        void   commit() override { member->commit(); }
        void   revert() override { member->revert(); }
        void   reset() override { member->reset(); }
        std::string failure() const override { return member->failure(); }

        std::vector<double> response(const std::vector<std::string> &words) const override;

      private:
        std::unique_ptr<BeamColumn<2>> member;
        bool                           takes_loads, member_loads;
        Eigen::Vector3d                q0, p0; // element loads: basic fixed-end forces, reactions
        MemberLoad<2>                  w;      // the member's load (w_x, w_y)
      };

      template <typename V>
      std::vector<double>
      values_of(const V &v)
      {
        return std::vector<double>(v.data(), v.data() + v.size());
      }

      /// The responses of both dimensions: basicForce (q), basicDeformation,
      /// section i force|deformation; empty for any other words.
      template <int dim, typename Basic>
      std::vector<double>
      member_response(const BeamColumn<dim> &member, const int tag,
                      const std::vector<std::string> &words, const Basic &q)
      {
        const std::string what = words.empty() ? "" : words[0];
        if (words.size() == 1 && (what == "basicForce" || what == "basicForces"))
          return values_of(q);
        if (words.size() == 1 && (what == "basicDeformation" || what == "chordRotation" ||
                                  what == "chordDeformation"))
          return values_of(member.basic_deformation());
        if (words.size() == 3 && what == "section")
          {
            const int i = std::atoi(words[1].c_str());
            if (i < 1 || i > static_cast<int>(member.n_points()))
              throw ScriptError("element " + std::to_string(tag) + " has no section " +
                                words[1] + " (1 to " + std::to_string(member.n_points()) + ")");
            const SectionLaw &s = member.section(i - 1);
            if (words[2] == "force" || words[2] == "forces")
              return section_values(s, s.resultant());
            if (words[2] == "deformation" || words[2] == "deformations")
              return section_values(s, s.deformation());
          }
        return {};
      }

      std::vector<double>
      BeamColumnElement::response(const std::vector<std::string> &words) const
      {
        const std::string what = words.empty() ? "" : words[0];
        const Eigen::Vector3d q = member->basic_force() + q0;
        if (words.size() == 1 && (what == "localForce" || what == "localForces"))
          {
            const double shear = (q[1] + q[2]) / member->length();
            return {-q[0] + p0[0], shear + p0[1], q[1], q[0], -shear + p0[2], q[2]};
          }
        const std::vector<double> shared = member_response(*member, tag, words, q);
        return shared.empty() ? Element::response(words) : shared;
      }

      /// The section of `tag` with the member's resultants (2: plane, 4: space).
      const SectionLaw &
      section_of(const Domain &domain, const int tag, const unsigned int n_resultants)
      {
        const auto it = domain.sections.find(tag);
        if (it == domain.sections.end())
          throw ScriptError("section " + std::to_string(tag) + " does not exist");
        if (it->second->n_resultants() != n_resultants)
          throw ScriptError("section " + std::to_string(tag) + " is not a " +
                            (n_resultants == 2 ? "plane" : "3D") + " section");
        return *it->second;
      }

      /// The member of a beam-column on the domain's integration rule.
      template <int dim>
      std::unique_ptr<BeamColumn<dim>>
      make_member(const Domain &domain, const CrdTransformation<dim> &transf,
                  const BeamColumnKind kind, const IntegrationSpec &integration,
                  const OpenSeesIteration &iteration)
      {
        constexpr unsigned int n_resultants = MemberSize<dim>::resultants;
        BeamIntegration                          rule;
        std::vector<std::unique_ptr<SectionLaw>> sections;
        using Kind = IntegrationSpec::Kind;
        if (integration.kind == Kind::hinge_radau)
          {
            rule = hinge_radau_integration(integration.hinge_length_i,
                                           integration.hinge_length_j, transf.initial_length());
            // OpenSees's HingeRadau: end I's section at xi = 0 only, end J's at
            // xi = 1 only; the points at 8 lp/3 and the interior's take the
            // interior section (OPS_HingeRadauBeamIntegration's secTags)
            const SectionLaw &end_i    = section_of(domain, integration.section_i, n_resultants);
            const SectionLaw &interior = section_of(domain, integration.section, n_resultants);
            const SectionLaw &end_j    = section_of(domain, integration.section_j, n_resultants);
            for (const SectionLaw *s : {&end_i, &interior, &interior, &interior, &interior, &end_j})
              sections.push_back(s->clone());
          }
        else
          {
            rule     = integration.kind == Kind::lobatto ? lobatto_integration(integration.n_points) :
                                                           legendre_integration(integration.n_points);
            sections = sections_along(rule, section_of(domain, integration.section, n_resultants));
          }
        if (kind == BeamColumnKind::displacement_based)
          return std::make_unique<DispBeamColumn<dim>>(transf, rule, std::move(sections));
        auto force_based = std::make_unique<ForceBeamColumn<dim>>(transf, rule, std::move(sections));
        force_based->use_opensees_iteration(iteration);
        return force_based;
      }

      /// A 3D beam-column of poundfe's BeamColumn<3>, its element loads the
      /// member's. Its localForce as OpenSees's ForceBeamColumn3d: (-N, Vy,
      /// -Vz, -T, MyI, MzI, N, -Vy, Vz, T, MyJ, MzJ) with Vy = (MzI + MzJ)/L,
      /// Vz = (MyI + MyJ)/L, and the load's basic reactions p0.
      class BeamColumnElement3d : public Element
      {
      public:
        /// Which of OpenSees's 3D elements it stands for: their initial
        /// stiffness on CorotCrdTransf3d, whose getInitialGlobalStiffMatrix
        /// takes the initial basic stiffness k_b0 through the transformation's
        /// current T: ElasticBeam3d and DispBeamColumn3d at each call,
        /// ForceBeamColumn3d once, at its first call (Ki); their responses
        /// (ElasticBeam3d: no basicDeformation, no sections).
        enum class Kind
        {
          elastic,
          displacement_based,
          force_based
        };

        /// `loads`: whether it takes element loads (not on a corotational
        /// member, BeamColumn's).
        BeamColumnElement3d(const int tag, const std::array<int, 2> nodes,
                            std::unique_ptr<BeamColumn<3>> beam, const Kind element_kind,
                            const bool loads = true)
          : Element(tag, {nodes[0], nodes[1]})
          , member(std::move(beam))
          , kind(element_kind)
          , takes_loads(loads)
          , virgin_basic_tangent(member->basic_tangent())
        {
          w.setZero();
          committed_tangent = tangent();
        }

        bool takes_beam_loads() const override { return takes_loads; }
        void
        zero_loads() override
        {
          if (w.isZero(0))
            return;
          w.setZero();
          member->set_uniform_load(w);
        }
        void
        add_beam_uniform(const double wy, const double wx, const double wz) override
        {
          w += MemberLoad<3>(wx, wy, wz);
          member->set_uniform_load(w);
          member->set_load_factor(1);
        }

        unsigned int n_dofs() const override { return 12; }
        bool         rayleigh_damped() const override { return true; }
        bool         costly_trial() const override { return true; }
        bool
        set_trial(const Vector &u, const Vector &) override
        {
          return member->set_trial(BeamColumn<3>::GlobalVector(u));
        }
        Vector      force() const override { return member->resisting_force(); }
        Matrix      tangent() const override { return member->tangent(); }
        Matrix      initial_tangent() const override;
        void        commit() override { member->commit(); }
        void        revert() override { member->revert(); }
        void        reset() override { member->reset(); }
        std::string failure() const override { return member->failure(); }
        std::vector<double> response(const std::vector<std::string> &words) const override;

      private:
        std::unique_ptr<BeamColumn<3>> member;
        Kind                           kind;
        bool                           takes_loads;
        MemberLoad<3>                  w; // the member's load (w_x, w_y, w_z)
        /// k_b0: the basic tangent of the virgin member (as made)
        BeamColumn<3>::BasicMatrix virgin_basic_tangent;
        /// ForceBeamColumn3d's Ki on CorotCrdTransf3d, from its first use on
        /// (a reset keeps it, as OpenSees's revertToStart does)
        mutable std::optional<Matrix> first_initial_tangent;
      };

      Matrix
      BeamColumnElement3d::initial_tangent() const
      {
        const CrdTransformation<3> &t = member->transformation();
        if (t.kind() != Transformation::corotational)
          return member->initial_tangent();
        if (kind == Kind::force_based && first_initial_tangent)
          return *first_initial_tangent;
        // B^T k_b0 B at the current geometry (no geometric part at q = 0)
        const Matrix k0 =
          t.global_tangent(BeamColumn<3>::BasicVector::Zero(), virgin_basic_tangent);
        if (kind == Kind::force_based)
          first_initial_tangent = k0;
        return k0;
      }

      std::vector<double>
      BeamColumnElement3d::response(const std::vector<std::string> &words) const
      {
        const std::string what = words.empty() ? "" : words[0];
        const auto       &q    = member->basic_force();
        if (words.size() == 1 && (what == "localForce" || what == "localForces"))
          {
            const double L = member->length(), vy = (q[1] + q[2]) / L, vz = (q[3] + q[4]) / L;
            // the basic reactions of the load (ForceBeamColumn3d::getResponse)
            const auto p0 = uniform_load_forces<3>(L, w).p0;
            return {-q[0] + p0[0], vy + p0[1], -vz + p0[3], -q[5], q[3], q[1],
                    q[0],          -vy + p0[2], vz + p0[4], q[5],  q[4], q[2]};
          }
        if (kind == Kind::elastic) // ElasticBeam3d: basicForce, no deformations nor sections
          return words.size() == 1 && (what == "basicForce" || what == "basicForces") ?
                   std::vector<double>(q.data(), q.data() + q.size()) :
                   Element::response(words);
        const std::vector<double> shared = member_response(*member, tag, words, q);
        return shared.empty() ? Element::response(words) : shared;
      }

      /// The member's transformation, made on nodes that may have moved
      /// (displacements_when_made).
      CrdTransformation<2>
      transformation_of(const Domain &domain, const std::array<int, 2> nodes,
                        const Transformation kind, const int tag)
      {
        const auto &a = domain.node(nodes[0]).coordinates, &b = domain.node(nodes[1]).coordinates;
        const CrdTransformation<2>::GlobalVector made = displacements_when_made(domain, nodes, 3);
        const Eigen::Vector2d i(a[0], a[1]), j(b[0], b[1]);
        // the transformation's own length and test (!(L > 0)), to the bit
        if (!(displaced_chord<2>(i, j, made).norm() > 0))
          throw ScriptError("element " + std::to_string(tag) + " has zero length");
        const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
        CrdTransformation<2>  transformation(kind, i, j, zero, zero, Eigen::Vector3d::UnitZ(), made);
        // OpenSees's own tangent: a script's damping on K_t or K_c takes it
        transformation.use_opensees_tangent();
        return transformation;
      }

      /// The member's transformation in space with the geomTransf's vecxz,
      /// made on nodes that may have moved (the chord of the displaced
      /// nodes); ScriptError for a member of zero length or a vecxz along it.
      CrdTransformation<3>
      transformation_3d(const Domain &domain, const std::array<int, 2> nodes,
                        const Transformation kind, const std::array<double, 3> &vecxz,
                        const int tag)
      {
        const auto &a = domain.node(nodes[0]).coordinates, &b = domain.node(nodes[1]).coordinates;
        const CrdTransformation<3>::GlobalVector made = displacements_when_made(domain, nodes, 6);
        const Eigen::Vector3d i(a[0], a[1], a[2]), j(b[0], b[1], b[2]);
        const Eigen::Vector3d chord = displaced_chord<3>(i, j, made);
        if (!(chord.norm() > 0))
          throw ScriptError("element " + std::to_string(tag) + " has zero length");
        const Eigen::Vector3d v(vecxz[0], vecxz[1], vecxz[2]);
        // huge coordinates or vecxz overflow the length or the local z axis
        if (!std::isfinite(chord.norm()) || !std::isfinite(chord.cross(v).norm()))
          throw ScriptError("element " + std::to_string(tag) +
                            ": its geometry is not finite in double precision (the length or "
                            "the product of the axis and the transformation's vecxz overflows)");
        if (!(chord.cross(v).norm() > 0))
          throw ScriptError("element " + std::to_string(tag) +
                            ": the transformation's vecxz is parallel to its axis");
        CrdTransformation<3> transf(kind, i, j, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                    v, made);
        transf.use_opensees_tangent();
        return transf;
      }
    } // namespace

    std::unique_ptr<Element>
    make_beam_column_2d(const Domain &domain, const int tag, const std::array<int, 2> nodes,
                        const BeamColumnKind kind, const Transformation transformation,
                        const IntegrationSpec &integration, const OpenSeesIteration &iteration)
    {
      const CrdTransformation<2> transf = transformation_of(domain, nodes, transformation, tag);
      std::unique_ptr<BeamColumn<2>> beam =
        make_member<2>(domain, transf, kind, integration, iteration);
      // no element loads on a corotational member (BeamColumn's)
      using Loads       = BeamColumnElement::Loads;
      const Loads loads = transformation == Transformation::corotational ? Loads::none :
                          kind == BeamColumnKind::displacement_based     ? Loads::fixed_end_forces :
                                                                           Loads::member;
      return std::make_unique<BeamColumnElement>(tag, nodes, std::move(beam), loads);
    }

    std::unique_ptr<Element>
    make_beam_column_3d(const Domain &domain, const int tag, const std::array<int, 2> nodes,
                        const BeamColumnKind kind, const Transformation transformation,
                        const std::array<double, 3> &vecxz, const IntegrationSpec &integration,
                        const OpenSeesIteration &iteration)
    {
      const CrdTransformation<3> transf =
        transformation_3d(domain, nodes, transformation, vecxz, tag);
      using Kind3d = BeamColumnElement3d::Kind;
      return std::make_unique<BeamColumnElement3d>(
        tag, nodes, make_member<3>(domain, transf, kind, integration, iteration),
        kind == BeamColumnKind::displacement_based ? Kind3d::displacement_based :
                                                     Kind3d::force_based,
        transformation != Transformation::corotational);
    }

    std::unique_ptr<Element>
    make_elastic_corotational_2d(const Domain &domain, const int tag,
                                 const std::array<int, 2> nodes, const double A, const double E,
                                 const double I)
    {
      const CrdTransformation<2> transf =
        transformation_of(domain, nodes, Transformation::corotational, tag);
      const ElasticSection section(E * A, E * I);
      return std::make_unique<BeamColumnElement>(
        tag, nodes, std::make_unique<DispBeamColumn<2>>(transf, section, 2));
    }
    std::unique_ptr<Element>
    make_elastic_corotational_3d(const Domain &domain, const int tag,
                                 const std::array<int, 2> nodes, const ElasticSection3d &section,
                                 const std::array<double, 3> &vecxz)
    {
      const CrdTransformation<3> transf =
        transformation_3d(domain, nodes, Transformation::corotational, vecxz, tag);
      const ElasticSection elastic(section.E * section.A, section.E * section.Iz,
                                   section.E * section.Iy, section.G * section.J);
      return std::make_unique<BeamColumnElement3d>(
        tag, nodes, std::make_unique<DispBeamColumn<3>>(transf, elastic, 2),
        BeamColumnElement3d::Kind::elastic, false);
    }

    std::vector<double>
    section_values(const SectionLaw &section, const SectionVector &v)
    {
      const auto *aggregator = dynamic_cast<const AggregatorSection *>(&section);
      if (!aggregator)
        return std::vector<double>(v.data(), v.data() + v.size());
      std::vector<double> values;
      for (const unsigned int r : aggregator->response_order())
        values.push_back(v[r]);
      return values;
    }
  } // namespace opensees
} // namespace poundfe
