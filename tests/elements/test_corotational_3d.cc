// The corotational transformation in space (elements/corotational_3d.h):
// a large rigid rotation strains nothing; the tangent against central
// differences of the resisting force, each perturbation a spin of one
// rotation DOF from the trial state (the triads' update), at a committed
// state with large rotations, elastic and past yield. The tangent is
// OpenSees's CorotCrdTransf3d's (Newton's iterates of the corpus's
// corotational_3d.tcl are OpenSees's to six digits): exact in the
// translations' columns, within 0.4 % of its geometric part in the
// rotations' (Crisfield's K_sigma as OpenSees writes them).
#include <poundfe/elements/beam_column.h>
#include <poundfe/laws/material_registry.h>
#include <poundfe/sections/aggregator_section.h>
#include <poundfe/sections/elastic_section.h>

#include <boost/test/unit_test.hpp>

#include <Eigen/Geometry>

#include <array>

using namespace poundfe;

namespace
{
  constexpr double corot3d_EA = 2e9, corot3d_EI = 2e7, corot3d_GJ = 1e7, corot3d_My = 1e5;
  using Vector12 = BeamColumn<3>::GlobalVector;

  const Eigen::Vector3d corot3d_a(0.3, -0.2, 0.1), corot3d_b(2.1, 1.1, 1.7),
    corot3d_orientation(0.3, 0.2, 1.0);

  CrdTransformation<3>
  corot3d_transformation()
  {
    CrdTransformation<3> t(Transformation::corotational, corot3d_a, corot3d_b,
                           Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                           corot3d_orientation);
    t.use_opensees_tangent();
    return t;
  }

  AggregatorSection
  corot3d_yielding_section()
  {
    SectionVector rigidities(4);
    rigidities << corot3d_EA, corot3d_EI, 0.5 * corot3d_EI, corot3d_GJ;
    AggregatorSection section(rigidities);
    for (unsigned int r = 1; r < 3; ++r)
      section.set_law(r, [r] {
        return make_material({"Steel01",
                              {{"fy", corot3d_My},
                               {"E0", (r == 1 ? 1 : 0.5) * corot3d_EI},
                               {"b", 0.03}}});
      });
    return section;
  }

  /// The ends' displacements of a rigid rotation theta (a rotation vector)
  /// of the member about end I, and a translation c.
  Vector12
  rigid_motion(const Eigen::Vector3d &theta, const Eigen::Vector3d &c)
  {
    const Eigen::Matrix3d q = Eigen::AngleAxisd(theta.norm(), theta.normalized()).toRotationMatrix();
    Vector12              u;
    u << c, theta, c + (q - Eigen::Matrix3d::Identity()) * (corot3d_b - corot3d_a), theta;
    return u;
  }

  /// The errors of the tangent at the trial u, committed at u_c, against
  /// central differences K_fd (column j: each side from the trial state at u,
  /// a revert, the trial u, then u + h e_j: one spin onto its triads): on the
  /// translation columns relative to max |K|, on the rotation columns
  /// relative to the geometric part's max |K - B^T k_b B|, and that part's
  /// size relative to max |K|.
  std::array<double, 3>
  corot3d_tangent_errors(BeamColumn<3> &e, const Vector12 &u_c, const Vector12 &u, const double h)
  {
    e.reset();
    BOOST_REQUIRE(e.set_trial(u_c));
    e.commit();
    BOOST_REQUIRE(e.set_trial(u));
    const BeamColumn<3>::GlobalMatrix k = e.tangent();
    const auto                       &b = e.transformation().compatibility();
    const BeamColumn<3>::GlobalMatrix geometric = k - b.transpose() * e.basic_tangent() * b;
    BeamColumn<3>::GlobalMatrix       fd;
    for (int j = 0; j < 12; ++j)
      {
        Vector12 side[2];
        for (const int s : {0, 1})
          {
            e.revert();
            BOOST_REQUIRE(e.set_trial(u));
            Vector12 perturbed = u;
            perturbed[j] += s == 0 ? h : -h;
            BOOST_REQUIRE(e.set_trial(perturbed));
            side[s] = e.resisting_force();
          }
        fd.col(j) = (side[0] - side[1]) / (2 * h);
      }
    const double scale = k.cwiseAbs().maxCoeff(), geometric_scale = geometric.cwiseAbs().maxCoeff();
    double       translations = 0, rotations = 0;
    for (int j = 0; j < 12; ++j)
      ((j % 6) < 3 ? translations : rotations) =
        std::max((j % 6) < 3 ? translations : rotations, (k - fd).col(j).cwiseAbs().maxCoeff());
    return {{translations / scale, rotations / geometric_scale, geometric_scale / scale}};
  }
} // namespace

BOOST_AUTO_TEST_CASE(a_rigid_rotation_in_space_strains_nothing)
{
  // 1.4 rad about a skew axis and a translation, in one update and in ten:
  // the triads turn with the chord, v stays at round-off of the chord's
  // length (the ten updates compose spins about one axis: exp(a) exp(b) =
  // exp(a + b))
  const ElasticSection  section(corot3d_EA, corot3d_EI, 0.5 * corot3d_EI, corot3d_GJ);
  const Eigen::Vector3d theta = 1.4 * Eigen::Vector3d(0.2, -0.7, 0.5).normalized();
  const Eigen::Vector3d c(0.4, -0.1, 0.3);
  for (const unsigned int steps : {1u, 10u})
    {
      DispBeamColumn<3> e(corot3d_transformation(), section, 2);
      for (unsigned int s = 1; s <= steps; ++s)
        {
          BOOST_REQUIRE(e.set_trial(rigid_motion(theta * s / steps, c * s / steps)));
          e.commit();
        }
      BOOST_TEST_MESSAGE("rigid rotation in " << steps << ": |v| "
                                              << e.basic_deformation().norm());
      BOOST_TEST(e.basic_deformation().norm() <= 1e-14);
      BOOST_TEST(e.resisting_force().norm() <= 1e-14 * corot3d_EA);
    }
}

BOOST_AUTO_TEST_CASE(a_corotational_tangent_in_space_is_the_derivative_of_the_forces)
{
  // committed after a large rigid rotation (0.9 rad) with bending, then a
  // trial that bends and twists it further; elastic, and past yield
  Vector12 bend;
  bend << 0.002, -0.003, 0.001, 0.02, -0.03, 0.01, 0.004, 0.006, -0.005, -0.01, 0.02, 0.015;
  const Vector12 u_c = rigid_motion(0.9 * Eigen::Vector3d(0.3, 0.8, -0.5).normalized(),
                                    Eigen::Vector3d(0.1, 0.2, -0.1)) +
                       bend;
  const Vector12          u       = u_c + 0.5 * bend;
  const ElasticSection    elastic(corot3d_EA, corot3d_EI, 0.5 * corot3d_EI, corot3d_GJ);
  const AggregatorSection yielding = corot3d_yielding_section();
  for (const SectionLaw *section : {static_cast<const SectionLaw *>(&elastic),
                                    static_cast<const SectionLaw *>(&yielding)})
    {
      ForceBeamColumn<3> fb(corot3d_transformation(), *section, 4);
      DispBeamColumn<3>  db(corot3d_transformation(), *section, 3);
      for (BeamColumn<3> *e : std::initializer_list<BeamColumn<3> *>{&fb, &db})
        {
          const auto error = corot3d_tangent_errors(*e, u_c, u, 1e-7);
          BOOST_TEST_MESSAGE("corotational 3D tangent: translations "
                             << error[0] << ", rotations " << error[1] << " of the geometric part "
                             << error[2]);
          BOOST_TEST(error[0] < 1e-8);
          BOOST_TEST(error[1] < 1e-2);
          BOOST_TEST(error[2] > 1e-4);
        }
    }
  // past yield indeed
  DispBeamColumn<3> db(corot3d_transformation(), yielding, 3);
  BOOST_REQUIRE(db.set_trial(u));
  BOOST_TEST(std::abs(db.section(0).resultant()[1]) > corot3d_My);
}
