// The SD and Duffing springs and the dry-friction law on their own: tangents
// against central differences of the force, the SD potential against the
// integral of the force, exact revert, and the return mapping's stick and
// slip branches against Coulomb's law written here.
#include <poundfe/laws/elastic_springs.h>
#include <poundfe/laws/friction.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;

namespace
{
  /// |dF/dd - central difference| / max(|dF/dd|, 1) over a range of d.
  double
  spring_tangent_error(const SpringLawParameters &p)
  {
    double worst = 0;
    for (double x = -2.5; x <= 2.5; x += 0.0137)
      {
        const double h  = 1e-6;
        const double fd = (p.force(x + h) - p.force(x - h)) / (2 * h);
        worst = std::max(worst, std::abs(p.tangent(x) - fd) / std::max(std::abs(fd), 1.0));
      }
    return worst;
  }
} // namespace

BOOST_AUTO_TEST_CASE(sd_spring_tangent_and_potential)
{
  SpringLawParameters sd;
  sd.kind      = SpringKind::sd;
  sd.stiffness = 1.3;
  sd.length    = 1.0;
  sd.height    = 0.4;
  // central differences with h = 1e-6: truncation ~h^2 F''' and round-off ~1e-16/h
  BOOST_TEST(spring_tangent_error(sd) < 1e-8);
  // U(x) = int_0^x F: Simpson's rule with 2000 panels (error ~1e-12)
  const double x = 1.7;
  double       integral = 0;
  const int    n        = 2000;
  for (int i = 0; i <= n; ++i)
    integral += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * sd.force(x * i / n);
  integral *= x / (3 * n);
  BOOST_TEST(sd.energy(x) == integral, boost::test_tools::tolerance(1e-10));
  // the wells of the bistable spring (H < L) at +-sqrt(L^2 - H^2)
  BOOST_TEST(std::abs(sd.force(std::sqrt(1 - 0.16))) < 1e-14);
  // H = 0: F = K (x - L sgn x), the discontinuous limit
  sd.height = 0;
  BOOST_TEST(sd.force(0.3) == 1.3 * (0.3 - 1.0), boost::test_tools::tolerance(1e-15));
  BOOST_TEST(sd.force(-0.3) == 1.3 * (-0.3 + 1.0), boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(cubic_spring_tangent)
{
  SpringLawParameters duffing;
  duffing.kind      = SpringKind::cubic;
  duffing.stiffness = -1;
  duffing.cubic     = 1;
  BOOST_TEST(spring_tangent_error(duffing) < 1e-8);
  BOOST_TEST(duffing.energy(2.0) == -2.0 + 4.0, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(friction_slip_tangent_by_central_differences)
{
  // Slip with a Stribeck curve and N = C0 - K H (1 - L/r) + C1 |x| + C2 |x'|
  // + C3 |x'|^3 (C2 < 0 < C3, the cubic characteristic): every term of dF/dx
  // and dF/dx' is exercised.
  FrictionLawParameters p;
  p.static_coefficient       = 0.4;
  p.kinetic_coefficient      = 0.25;
  p.stribeck_velocity        = 0.05;
  p.stick_stiffness          = 1e4;
  p.normal.constant          = 2;
  p.normal.per_displacement  = 0.3;
  p.normal.per_velocity      = -0.2;
  p.normal.per_velocity_cubed = 0.5;
  p.normal.sd_reaction       = true;
  p.normal.sd_stiffness      = 1;
  p.normal.sd_length         = 1;
  p.normal.sd_height         = 0.4;
  for (const FrictionModel model : {FrictionModel::elastic_plastic, FrictionModel::regularized})
    {
      p.model                  = model;
      p.regularization_velocity = 0.02;
      for (const auto &[x, v] : {std::pair{0.7, 0.08}, std::pair{-1.2, -0.03}, std::pair{0.3, -0.2}})
        {
          Friction law(p);
          law.set_trial_time(1.0);
          BOOST_REQUIRE(law.set_trial(x, v));
          if (model == FrictionModel::elastic_plastic)
            BOOST_REQUIRE(law.is_active()); // 0.7 m from the committed slip: slipping
          const double dk = law.tangent(), dc = law.damping_tangent();
          const double h  = 1e-7;
          auto force      = [&](const double xx, const double vv) {
            law.revert();
            law.set_trial(xx, vv);
            return law.force();
          };
          const double fd_x = (force(x + h, v) - force(x - h, v)) / (2 * h);
          const double fd_v = (force(x, v + h) - force(x, v - h)) / (2 * h);
          BOOST_TEST(std::abs(dk - fd_x) < 1e-6 * std::max(1.0, std::abs(fd_x)));
          BOOST_TEST(std::abs(dc - fd_v) < 1e-6 * std::max(1.0, std::abs(fd_v)));
        }
    }
}

// alpha = 0 (thesis Figs. 3.2 b, 3.3 b): the SD spring lies flat and its
// vertical reaction K H (1 - L/r) vanishes as H -> 0 at every x; at x = 0 the
// formula alone is 0 * inf. The limit, checked against small H, is the
// constant part of N.
BOOST_AUTO_TEST_CASE(sd_normal_force_at_zero_height_is_the_limit_of_small_heights)
{
  NormalForce n;
  n.constant     = 2;
  n.sd_reaction  = true;
  n.sd_stiffness = 1;
  n.sd_length    = 1;
  for (const double x : {0.0, 1e-12, -0.3, 0.7, 2.0})
    {
      n.sd_height              = 0;
      const NormalForce::Value flat = n(x, 0.1);
      BOOST_TEST(std::isfinite(flat.n));
      BOOST_TEST(std::isfinite(flat.dx));
      BOOST_TEST(flat.n == 2.0);
      if (std::abs(x) > 0.1) // away from x = 0 the small-H values converge to it
        {
          n.sd_height = 1e-9;
          BOOST_TEST(std::abs(n(x, 0.1).n - flat.n) < 1e-8);
        }
    }
}

BOOST_AUTO_TEST_CASE(return_mapping_is_coulombs_law_and_reverts_exactly)
{
  FrictionLawParameters p;
  p.static_coefficient  = 0.5;
  p.kinetic_coefficient = 0.3;
  p.stick_stiffness     = 100;
  p.normal.constant     = 10; // mu_s N = 5, mu_k N = 3
  Friction law(p);
  // stick: elastic up to mu_s N / k_s = 0.05
  law.set_trial(0.04, 0.0);
  BOOST_TEST(!law.is_active());
  BOOST_TEST(law.force() == 4.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(law.tangent() == 100.0, boost::test_tools::tolerance(1e-14));
  law.commit();
  // break-away beyond the static limit: the kinetic force, the slip is what
  // the stick spring does not take
  law.set_trial(0.2, 0.5);
  BOOST_TEST(law.is_active());
  BOOST_TEST(law.force() == 3.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(law.history_variable() == 0.2 - 0.03, boost::test_tools::tolerance(1e-14));
  const double force = law.force(), slip = law.history_variable();
  law.commit();
  // a rejected trial leaves the committed state as it was, to the bit
  law.set_trial(-3.0, -2.0);
  law.revert();
  BOOST_TEST(law.force() == force);
  BOOST_TEST(law.history_variable() == slip);
  BOOST_TEST(law.is_active());
  // unloading from slip: elastic again, through the stick spring
  law.set_trial(0.19, -0.1);
  BOOST_TEST(!law.is_active());
  BOOST_TEST(law.force() == 3.0 - 1.0, boost::test_tools::tolerance(1e-12));
  // a moving belt: the stick spring sees x - v0 t
  p.belt_velocity = 0.1;
  Friction belt(p);
  belt.set_trial_time(0.2);
  belt.set_trial(0.0, 0.0);
  BOOST_TEST(belt.force() == -100 * 0.02, boost::test_tools::tolerance(1e-14));
  // the belt's work on the structure over the step: -F v0 dt (trapezoidal)
  BOOST_TEST(belt.supplied_work_increment() == -0.5 * (-2.0) * 0.1 * 0.2,
             boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(cubic_friction_characteristic_in_steady_slip)
{
  // Steady slip at x' against a fixed surface: F = mu_k (C0 + C2 |x'| +
  // C3 |x'|^3) sgn(x') by hand (Popp & Stelter 1990's cubic characteristic,
  // the thesis's Fig. 3.2 c-e). With C2 = -0.45, C3 = 0.5 the force is
  // smallest at |x'| = sqrt(-C2 / (3 C3)) = 0.5477 and rises beyond.
  FrictionLawParameters p;
  p.model                     = FrictionModel::regularized;
  p.regularization_velocity   = 1e-9;
  p.static_coefficient        = 1.0;
  p.kinetic_coefficient       = 0.25;
  p.normal.constant           = 1;
  p.normal.per_velocity       = -0.45;
  p.normal.per_velocity_cubed = 0.5;
  const auto slip_force = [&](const double v) {
    Friction law(p);
    law.set_trial_time(0.0);
    BOOST_REQUIRE(law.set_trial(0.1, v));
    return law.force();
  };
  for (const double v : {0.1, 0.5477225575051661, 1.0, -1.3})
    {
      const double s = std::abs(v);
      BOOST_TEST(slip_force(v) == 0.25 * (1 - 0.45 * s + 0.5 * s * s * s) * (v > 0 ? 1 : -1),
                 boost::test_tools::tolerance(1e-14));
    }
  const double v_min = std::sqrt(0.45 / 1.5);
  BOOST_TEST(slip_force(v_min) < slip_force(0.9 * v_min));
  BOOST_TEST(slip_force(v_min) < slip_force(1.1 * v_min));
}
