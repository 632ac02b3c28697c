// The bidirectional Bouc-Wen law (Park, Wen & Ang 1986) against independent
// references: the uniaxial law along either axis, the closed-form backbone
// of a radial path, the unit-circle yield surface and the steady lag of a
// circular orbit, central finite differences of its tangent, exact revert.
#include <poundfe/laws/bidirectional_bouc_wen.h>
#include <poundfe/laws/bouc_wen.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;

namespace
{
  BoucWenParameters
  biaxial_axis(const double stiffness, const double yield, const double n = 2)
  {
    BoucWenParameters p;
    p.stiffness         = stiffness;
    p.yield_deformation = yield;
    p.alpha             = 0.1;
    p.n                 = n;
    return p;
  }

  /// u(s) of a test path: a swept sine with growing amplitude, so that the
  /// law loads, yields, unloads and reloads.
  double
  cyclic_path(const double s, const double yield)
  {
    return 4 * yield * s * std::sin(2 * M_PI * 3 * s);
  }
} // namespace

BOOST_AUTO_TEST_SUITE(bidirectional_bouc_wen)

// (a) Motion along one axis only: z_2 stays 0 and the law is Wen's uniaxial
// law with the same parameters, to round-off (1e-12 relative to the yield
// force), along axis 1 and along axis 2 (other stiffness and yield), n = 2
// and n = 3.
BOOST_AUTO_TEST_CASE(reduces_to_uniaxial_along_each_axis)
{
  for (const double n : {2.0, 3.0})
    for (unsigned int axis = 0; axis < 2; ++axis)
      {
        const BoucWenParameters px = biaxial_axis(5e6, 0.01, n), py = biaxial_axis(2e6, 0.02, n);
        const BoucWenParameters &along = axis == 0 ? px : py;
        BidirectionalBoucWen     biaxial(px, py);
        BoucWen                  uniaxial(along);
        const double             scale = along.stiffness * along.yield_deformation;
        double                   worst = 0;
        for (unsigned int i = 1; i <= 600; ++i)
          {
            const double    u = cyclic_path(i / 600.0, along.yield_deformation);
            Eigen::Vector2d d = Eigen::Vector2d::Zero();
            d[axis]           = u;
            BOOST_REQUIRE(biaxial.set_trial(d));
            BOOST_REQUIRE(uniaxial.set_trial(u, 0));
            worst = std::max({worst, std::abs(biaxial.force()[axis] - uniaxial.force()) / scale,
                              std::abs(biaxial.tangent()(axis, axis) - uniaxial.tangent()) /
                                along.stiffness});
            BOOST_CHECK_EQUAL(biaxial.history()[1 - axis], 0.0);
            BOOST_CHECK_EQUAL(biaxial.force()[1 - axis], 0.0);
            biaxial.commit();
            uniaxial.commit();
          }
        BOOST_TEST_MESSAGE("n = " << n << ", axis " << axis + 1 << ": worst relative difference "
                                  << worst);
        BOOST_CHECK_LE(worst, 1e-12);
      }
}

// (b1) A radial path at any angle: z stays parallel to u and |z| follows the
// uniaxial backbone dz/dr = (A - (beta + gamma) |z|^2) / u_y, whose closed
// form for A = beta + gamma = 1 is tanh(r / u_y): the yield surface is a
// circle. Tolerance 1e-5: the trapezoidal rule's O(h^2) error for the
// increment h = u_y / 100 (measured 5.1e-6); z x e to round-off.
BOOST_AUTO_TEST_CASE(radial_path_follows_the_closed_form_backbone)
{
  const double         uy = 0.01;
  BidirectionalBoucWen law(biaxial_axis(5e6, uy), biaxial_axis(5e6, uy));
  for (const double angle : {0.3, 1.1, 2.5})
    {
      law.reset();
      const Eigen::Vector2d e(std::cos(angle), std::sin(angle));
      double                worst = 0, worst_angle = 0;
      for (unsigned int i = 1; i <= 400; ++i)
        {
          const double r = i * uy / 100;
          BOOST_REQUIRE(law.set_trial(r * e));
          law.commit();
          const Eigen::Vector2d z = law.history();
          worst       = std::max(worst, std::abs(z.norm() - std::tanh(r / uy)));
          worst_angle = std::max(worst_angle, std::abs(z[0] * e[1] - z[1] * e[0]));
        }
      BOOST_TEST_MESSAGE("radial path at " << angle << " rad: |z| - tanh " << worst
                                           << ", z x e " << worst_angle);
      BOOST_CHECK_LE(worst, 1e-5);
      BOOST_CHECK_LE(worst_angle, 1e-14);
    }
}

// (b2) A circular orbit u = rho u_y (cos phi, sin phi): the state never
// leaves the unit disc (the circular yield surface, n = 2), |z| -> 1, and z
// lags the velocity by psi with sin psi = 1/rho (on |z| = 1 the law moves z
// by the projection of dc on the circle's tangent: dpsi/dphi = 1 - rho sin psi).
BOOST_AUTO_TEST_CASE(circular_orbit_stays_on_the_unit_circle)
{
  const double         uy = 0.01, rho = 20;
  BidirectionalBoucWen law(biaxial_axis(5e6, uy), biaxial_axis(5e6, uy));
  const unsigned int   per_cycle = 4000;
  double               largest = 0, smallest_last = 2, lag_error = 0;
  for (unsigned int i = 1; i <= 200; ++i) // out to the orbit along x in small steps
    {
      BOOST_REQUIRE(law.set_trial(Eigen::Vector2d(rho * uy * i / 200, 0)));
      law.commit();
      largest = std::max(largest, law.history().norm());
    }
  for (unsigned int i = 1; i <= 4 * per_cycle; ++i)
    {
      const double phi = 2 * M_PI * i / per_cycle;
      BOOST_REQUIRE(law.set_trial(rho * uy * Eigen::Vector2d(std::cos(phi), std::sin(phi))));
      law.commit();
      const Eigen::Vector2d z = law.history();
      largest                 = std::max(largest, z.norm());
      if (i > 3 * per_cycle)
        {
          smallest_last = std::min(smallest_last, z.norm());
          // the velocity's direction is phi + pi/2; measure in the first
          // quadrant of both, away from the axes (where z.dc >= 0 per axis)
          const double velocity = phi + M_PI / 2, lag = velocity - std::atan2(z[1], z[0]);
          const double wrapped  = std::remainder(lag, 2 * M_PI);
          const double in_cycle = std::remainder(phi, 2 * M_PI);
          if (in_cycle > -M_PI / 2 + 0.3 && in_cycle < -0.3)
            lag_error = std::max(lag_error, std::abs(wrapped - std::asin(1 / rho)));
        }
    }
  BOOST_TEST_MESSAGE("circular orbit: max |z| " << largest << ", min |z| of the last cycle "
                                                << smallest_last << ", lag error " << lag_error
                                                << " (psi " << std::asin(1 / rho) << ")");
  // the ODE keeps |z| <= 1 exactly; its trapezoidal map only to O(h^2)
  // (measured 1 + 3.1e-7 at h = 2 pi rho u_y / 4000)
  BOOST_CHECK_LE(largest, 1 + 1e-6);
  BOOST_CHECK_GE(smallest_last, 0.99);
  BOOST_CHECK_LE(lag_error, 1e-5); // rad; the step's O(h^2) error, h = 2 pi rho / 4000
}

// (c) The tangent against central differences of the force at trial states
// after a biaxial history, n = 2 and n = 3, with increments in all four
// sign quadrants (the sign of the step's increment fixes the branch).
BOOST_AUTO_TEST_CASE(tangent_matches_finite_differences)
{
  for (const double n : {2.0, 3.0})
    for (const double sx : {1.0, -1.0})
      for (const double sy : {1.0, -1.0})
        {
          BidirectionalBoucWen law(biaxial_axis(5e6, 0.01, n), biaxial_axis(2e6, 0.02, n));
          for (unsigned int i = 1; i <= 50; ++i)
            {
              const double s = i / 50.0;
              BOOST_REQUIRE(law.set_trial(
                Eigen::Vector2d(cyclic_path(s, 0.01), 0.6 * cyclic_path(0.8 * s + 0.1, 0.02))));
              law.commit();
            }
          const Eigen::Vector2d trial =
            law.deformation() + Eigen::Vector2d(sx * 0.004, sy * 0.007);
          BOOST_REQUIRE(law.set_trial(trial));
          const Eigen::Matrix2d k = law.tangent();
          Eigen::Matrix2d       fd;
          for (unsigned int j = 0; j < 2; ++j)
            {
              const double    h = 1e-7;
              Eigen::Vector2d plus = trial, minus = trial;
              plus[j] += h;
              minus[j] -= h;
              BOOST_REQUIRE(law.set_trial(plus));
              const Eigen::Vector2d f_plus = law.force();
              BOOST_REQUIRE(law.set_trial(minus));
              fd.col(j) = (f_plus - law.force()) / (2 * h);
            }
          const double error = (k - fd).norm() / k.norm();
          BOOST_TEST_MESSAGE("n = " << n << ", quadrant " << sx << ", " << sy
                                    << ": tangent relative error " << error);
          BOOST_CHECK_LE(error, 1e-6);
          BOOST_CHECK_GT(std::abs(k(0, 1)) + std::abs(k(1, 0)), 1e-3 * k.norm()); // coupled
        }
}

// (d) revert() restores the committed state exactly: the force, tangent and
// z of the committed state, and a repeated trial gives the same bits.
BOOST_AUTO_TEST_CASE(revert_restores_the_committed_state_exactly)
{
  BidirectionalBoucWen law(biaxial_axis(5e6, 0.01), biaxial_axis(2e6, 0.02));
  BOOST_REQUIRE(law.set_trial(Eigen::Vector2d(0.02, -0.015)));
  law.commit();
  const Eigen::Vector2d f = law.force(), z = law.history();
  const Eigen::Matrix2d k = law.tangent();
  BOOST_REQUIRE(law.set_trial(Eigen::Vector2d(0.013, 0.01)));
  const Eigen::Vector2d f_trial = law.force();
  BOOST_REQUIRE(law.set_trial(Eigen::Vector2d(-0.05, 0.04)));
  law.revert();
  BOOST_CHECK(law.history() == z);
  BOOST_CHECK(law.force() == f);
  BOOST_REQUIRE(law.set_trial(Eigen::Vector2d(0.02, -0.015))); // the committed point
  BOOST_CHECK(law.force() == f);
  BOOST_REQUIRE(law.set_trial(Eigen::Vector2d(0.013, 0.01)));
  BOOST_CHECK(law.force() == f_trial);
  law.revert();
  // the tangent after revert is that of a zero increment from the committed state
  const Eigen::Matrix2d reverted = law.tangent();
  BOOST_REQUIRE(law.set_trial(Eigen::Vector2d(0.02, -0.015)));
  BOOST_CHECK_LE((law.tangent() - reverted).norm(), 1e-15 * reverted.norm());
  BOOST_CHECK_GT((k - reverted).norm(), 0.0); // the step's tangent is the discrete map's
}

BOOST_AUTO_TEST_SUITE_END()
