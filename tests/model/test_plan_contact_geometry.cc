// The gap between two slab outlines in plan (model/plan_contact_geometry.h):
// its gradient and Hessian against central differences of the gap itself,
// for both kinds of end (a corner of floor 1 on edge 2, a corner of floor 2
// on edge 1), and the rest gap against the distance by hand.
#include <poundfe/model/plan_contact_geometry.h>

#include <boost/test/unit_test.hpp>

#include <random>

using namespace poundfe;

namespace
{
  /// Floor 1's east edge x = 5 (y from -4 to 4, counter-clockwise: upwards)
  /// facing floor 2's west edge x = 5.3 (y from 3 down to -6), centres apart.
  PlanContactGeometry
  facing_slabs(const unsigned int end)
  {
    PlanContactGeometry g;
    g.edges   = {{{{{5, -4}, {5, 4}}}, {{{5.3, 3}, {5.3, -6}}}}};
    g.centres = {{{0.5, 0.2}, {9.0, -1.0}}};
    g.end     = end;
    return g;
  }

  /// The largest error of the analytical gradient and Hessian against
  /// central differences (h = 1e-6: the error is O(h^2) ~ 1e-12 of the
  /// unit-size derivatives, round-off ~ 1e-16 / h = 1e-10).
  std::array<double, 2>
  derivative_errors(const PlanContactGeometry &g, const Vector6 &q)
  {
    const PlanContactState s = plan_contact_state(g, q);
    BOOST_REQUIRE(s.defined);
    const double h = 1e-6;
    double       gradient_error = 0, hessian_error = 0;
    for (unsigned int j = 0; j < 6; ++j)
      {
        Vector6 qp = q, qm = q;
        qp[j] += h;
        qm[j] -= h;
        const PlanContactState sp = plan_contact_state(g, qp), sm = plan_contact_state(g, qm);
        gradient_error = std::max(gradient_error,
                                  std::abs((sp.gap - sm.gap) / (2 * h) - s.gradient[j]));
        hessian_error  = std::max(hessian_error, ((sp.gradient - sm.gradient) / (2 * h) -
                                                  s.hessian.col(j)).cwiseAbs().maxCoeff());
      }
    return {{gradient_error, hessian_error}};
  }
} // namespace

BOOST_AUTO_TEST_SUITE(plan_contact_geometry)

BOOST_AUTO_TEST_CASE(rest_gap_and_contact_point)
{
  // end 0: floor 2's edge starts at y = 3 inside floor 1's edge (-4..4):
  // floor 2's corner (5.3, 3) against floor 1's edge, gap 0.3
  const PlanContactState low = plan_contact_state(facing_slabs(0), Vector6::Zero());
  BOOST_TEST(low.gap == 0.3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(low.point.y == 3.0, boost::test_tools::tolerance(1e-12));
  // end 1: floor 1's corner (5, -4) against floor 2's edge (down to -6)
  const PlanContactState high = plan_contact_state(facing_slabs(1), Vector6::Zero());
  BOOST_TEST(high.gap == 0.3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(high.point.x == 5.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(high.point.y == -4.0, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(rotation_closes_the_gap_at_the_corner)
{
  // floor 1 turned by θ about its centre (0.5, 0.2): its corner (5, -4)
  // moves to C + R (X - C); the gap is the x distance to x = 5.3
  const double theta = 0.01;
  Vector6      q     = Vector6::Zero();
  q[2]               = theta;
  const double x     = 0.5 + std::cos(theta) * 4.5 - std::sin(theta) * (-4.2);
  const PlanContactState s = plan_contact_state(facing_slabs(1), q);
  BOOST_TEST(s.gap == 5.3 - x, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(derivatives_match_central_differences)
{
  std::mt19937                     random(7);
  std::uniform_real_distribution<> u(-0.05, 0.05), theta(-0.02, 0.02);
  for (unsigned int trial = 0; trial < 20; ++trial)
    for (const unsigned int end : {0u, 1u})
      {
        const Vector6 q(u(random), u(random), theta(random), u(random), u(random), theta(random));
        const auto    errors = derivative_errors(facing_slabs(end), q);
        BOOST_TEST(errors[0] < 1e-8);
        BOOST_TEST(errors[1] < 1e-7);
      }
}

BOOST_AUTO_TEST_SUITE_END()
