// The Bouc-Wen law against independent references: central finite
// differences of its tangent, the linear limit alpha = 1, the bilinear
// (elastic-perfectly-plastic) limit of large n, the area of a closed loop
// from a Runge-Kutta integration of dz/du written here, and exact revert.
#include <poundfe/laws/bouc_wen.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

using namespace poundfe;

namespace
{
  BoucWenParameters
  storey(const double alpha = 0.1, const double n = 2)
  {
    BoucWenParameters p;
    p.stiffness         = 5e6;
    p.yield_deformation = 0.01;
    p.alpha             = alpha;
    p.n                 = n;
    return p;
  }

  /// Drive the law along u(t) = amplitude sin(2 pi s), s in [0, cycles],
  /// committing every increment; returns the work int F du (trapezoidal).
  double
  drive(BoucWen &law, const double amplitude, const double cycles, const unsigned int per_cycle,
        double start_cycle = 0)
  {
    double work = 0, u_old = law.force() * 0, f_old = law.force();
    u_old = amplitude * std::sin(2 * M_PI * start_cycle);
    const unsigned int n = std::lround(cycles * per_cycle);
    for (unsigned int i = 1; i <= n; ++i)
      {
        const double u = amplitude * std::sin(2 * M_PI * (start_cycle + double(i) / per_cycle));
        BOOST_REQUIRE(law.set_trial(u, 0));
        work += 0.5 * (f_old + law.force()) * (u - u_old);
        law.commit();
        u_old = u;
        f_old = law.force();
      }
    return work;
  }

  /// Classical RK4 in u of dz/du = (A - |z|^n (beta sgn(du z) + gamma)) / u_y
  /// over u(s) = a sin(2 pi s); returns (1 - alpha) k u_y \oint z du over
  /// the last of `cycles` cycles, the energy dissipated per cycle.
  double
  loop_area_by_runge_kutta(const BoucWenParameters &p, const double amplitude,
                           const unsigned int cycles)
  {
    const unsigned int per_cycle = 200000;
    auto               rate      = [&](const double z, const double du_ds) {
      const double s = du_ds > 0 ? 1.0 : -1.0;
      return (p.A - std::pow(std::abs(z), p.n) * (p.beta * s * (z > 0 ? 1 : -1) + p.gamma)) /
             p.yield_deformation * du_ds;
    };
    double       z = 0, area = 0;
    const double h = 1.0 / per_cycle;
    for (unsigned int c = 0; c < cycles; ++c)
      for (unsigned int i = 0; i < per_cycle; ++i)
        {
          const double s     = c + double(i) / per_cycle;
          auto         du_ds = [&](const double x) {
            return amplitude * 2 * M_PI * std::cos(2 * M_PI * x);
          };
          const double k1 = rate(z, du_ds(s));
          const double k2 = rate(z + 0.5 * h * k1, du_ds(s + 0.5 * h));
          const double k3 = rate(z + 0.5 * h * k2, du_ds(s + 0.5 * h));
          const double k4 = rate(z + h * k3, du_ds(s + h));
          const double z_new = z + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
          if (c + 1 == cycles) // Simpson-like: trapezoid with the fine step
            area += 0.5 * (z + z_new) * (amplitude * (std::sin(2 * M_PI * (s + h)) -
                                                      std::sin(2 * M_PI * s)));
          z = z_new;
        }
    return (1 - p.alpha) * p.stiffness * p.yield_deformation * area;
  }
} // namespace

BOOST_AUTO_TEST_CASE(tangent_matches_central_differences)
{
  // States on the virgin curve, near saturation, just after reversal, with
  // degradation, for both integration rules: dF/du from the law against
  // [F(u + h) - F(u - h)] / 2h from the same committed state.
  for (const double theta : {0.5, 1.0})
    for (const double degradation : {0.0, 0.4})
      {
        BoucWenParameters p = storey(0.1, 2.5);
        p.theta             = theta;
        p.delta_A           = 0.5 * degradation;
        p.delta_nu          = degradation;
        p.delta_eta         = degradation;
        BoucWen law(p);
        // a committed path: load to 2.5 u_y, unload to 0.5 u_y
        const std::vector<double> path{0.004, 0.012, 0.025, 0.018, 0.005};
        for (const double u : path)
          {
            BOOST_REQUIRE(law.set_trial(u, 0));
            law.commit();
            for (const double step : {-3e-3, -4e-4, 2e-4, 1e-3, 6e-3})
              {
                const double u_trial = u + step;
                const double h       = 1e-7 * std::max(std::abs(step), 1e-3);
                BOOST_REQUIRE(law.set_trial(u_trial + h, 0));
                const double f_plus = law.force();
                BOOST_REQUIRE(law.set_trial(u_trial - h, 0));
                const double f_minus = law.force();
                BOOST_REQUIRE(law.set_trial(u_trial, 0));
                const double fd = (f_plus - f_minus) / (2 * h);
                // central differences: O(h^2) truncation + round-off ~1e-9 k
                BOOST_TEST(law.tangent() == fd, boost::test_tools::tolerance(1e-6));
                law.revert();
              }
          }
      }
}

BOOST_AUTO_TEST_CASE(alpha_one_is_linear_elastic)
{
  BoucWen law(storey(1.0));
  for (const double u : {0.003, 0.05, -0.08, 0.02})
    {
      BOOST_REQUIRE(law.set_trial(u, 0));
      BOOST_TEST(law.force() == 5e6 * u, boost::test_tools::tolerance(1e-14));
      BOOST_TEST(law.tangent() == 5e6, boost::test_tools::tolerance(1e-14));
      law.commit();
    }
  BOOST_TEST(law.stored_energy() == 0.5 * 5e6 * 0.02 * 0.02, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(large_n_tends_to_the_bilinear_law)
{
  // A = 1, beta + gamma = 1, n = 60: elastic k up to u_y, then alpha k.
  for (const double alpha : {0.0, 0.1})
    {
      BoucWenParameters p = storey(alpha, 60);
      p.theta             = 1.0; // backward Euler: no overshoot at large n
      BoucWen      law(p);
      const double k = p.stiffness, uy = p.yield_deformation;
      for (unsigned int i = 1; i <= 400; ++i)
        {
          const double u = 4 * uy * i / 400;
          BOOST_REQUIRE(law.set_trial(u, 0));
          law.commit();
          const double bilinear = u <= uy ? k * u : k * uy + alpha * k * (u - uy);
          // away from the knee, within 1 % of k u_y
          if (std::abs(u - uy) > 0.2 * uy)
            BOOST_TEST(std::abs(law.force() - bilinear) < 0.01 * k * uy);
        }
      // unloading is elastic again: slope k (1 - alpha) + alpha k = k
      BOOST_REQUIRE(law.set_trial(4 * uy - 0.5 * uy, 0));
      const double f_unloaded = law.force();
      BOOST_TEST(std::abs((k * uy + alpha * k * 3 * uy) - f_unloaded - 0.5 * k * uy) <
                 0.01 * k * uy);
    }
}

BOOST_AUTO_TEST_CASE(elastic_perfectly_plastic_loop_area)
{
  // alpha = 0, n large: the loop of a cycle +-u_m has area 4 F_y (u_m - u_y).
  BoucWenParameters p = storey(0.0, 60);
  p.theta             = 1.0;
  BoucWen      law(p);
  const double um = 3 * p.yield_deformation;
  drive(law, um, 1.0, 4000);
  const double area  = drive(law, um, 1.0, 4000, 1.0);
  const double exact = 4 * p.stiffness * p.yield_deformation * (um - p.yield_deformation);
  BOOST_TEST(area == exact, boost::test_tools::tolerance(0.02));
}

BOOST_AUTO_TEST_CASE(cycle_closes_and_dissipation_equals_loop_area)
{
  BoucWenParameters p = storey(0.1, 2);
  BoucWen           law(p);
  const double      um = 2.5 * p.yield_deformation;
  drive(law, um, 2.0, 4000); // two cycles: the loop is stationary
  const double z_start = law.history_variable(), f_start = law.force();
  const double e_start = law.normalised_energy();
  const double work    = drive(law, um, 1.0, 4000, 2.0);
  // back at u = 0 with the same z: the loop closes
  BOOST_TEST(law.history_variable() == z_start, boost::test_tools::tolerance(1e-8));
  BOOST_TEST(law.force() == f_start, boost::test_tools::tolerance(1e-8));
  // over a closed cycle the work is all dissipated; the law's own
  // bookkeeping (eps = int z du / u_y) agrees with it ...
  const double dissipated = (law.normalised_energy() - e_start) * (1 - p.alpha) *
                            p.stiffness * p.yield_deformation * p.yield_deformation;
  BOOST_TEST(dissipated == work, boost::test_tools::tolerance(1e-5));
  // ... and with the area of the loop from an RK4 integration of dz/du.
  const double area = loop_area_by_runge_kutta(p, um, 3);
  BOOST_TEST(work == area, boost::test_tools::tolerance(2e-4));
}

BOOST_AUTO_TEST_CASE(revert_restores_the_committed_state_exactly)
{
  BoucWenParameters p = storey(0.1, 2);
  p.delta_eta         = 0.3;
  BoucWen law(p);
  for (const double u : {0.006, 0.021, 0.011})
    {
      BOOST_REQUIRE(law.set_trial(u, 0));
      law.commit();
    }
  BoucWen reference(law); // a copy in the committed state
  BOOST_REQUIRE(reference.set_trial(0.015, 0));
  const double f = reference.force(), k = reference.tangent(), z = reference.history_variable();
  // excursions that are rejected
  for (const double u : {0.05, -0.03, 0.0111})
    BOOST_REQUIRE(law.set_trial(u, 0));
  law.revert();
  BOOST_REQUIRE(law.set_trial(0.015, 0));
  BOOST_TEST(law.force() == f); // bitwise
  BOOST_TEST(law.tangent() == k);
  BOOST_TEST(law.history_variable() == z);
}

BOOST_AUTO_TEST_CASE(local_failure_is_reported)
{
  BoucWenParameters p = storey(0.1, 2);
  p.max_iterations    = 1;
  p.tolerance         = 1e-300;
  BoucWen law(p);
  BOOST_TEST(!law.set_trial(0.05, 0));
  BOOST_TEST(law.failure().find("did not converge") != std::string::npos);
}

namespace
{
  /// The discrete map of the law written here with every term of the
  /// degradation (A = A0 - dA eps, nu = 1 + dnu eps, eta = 1 + deta eps and
  /// the divisions by eta), the local Newton iteration and its backtracking
  /// as bouc_wen.h states them: the law's z, force and tangent must be these
  /// to the bit, without degradation too, where the law leaves the terms of
  /// eps out.
  struct GeneralMap
  {
    BoucWenParameters p;
    double            u0 = 0, z0 = 0, e0 = 0, direction = 1;
    double            z = 0, e = 0, force = 0, tangent = 0, s = 1;

    void
    rate(const double zz, const double eps, const double dir, double &g, double &g_z,
         double &g_e) const
    {
      const double a    = std::abs(zz);
      const double sz   = (zz > 0) - (zz < 0);
      const double a_n1 = (a == 0) ? 0.0 : (p.n == 2) ? a : (p.n == 1) ? 1.0 : std::pow(a, p.n - 1);
      const double a_n  = a_n1 * a;
      const double psi  = p.beta * dir * sz + p.gamma;
      const double A    = p.A - p.delta_A * eps;
      const double nu   = 1 + p.delta_nu * eps;
      const double eta  = 1 + p.delta_eta * eps;
      const double phi  = A - nu * a_n * psi;
      g   = phi / eta;
      g_z = -nu * p.n * a_n1 * sz * psi / eta;
      g_e = (-p.delta_A - p.delta_nu * a_n * psi) / eta - phi * p.delta_eta / (eta * eta);
    }

    void
    set_trial(const double u)
    {
      const double uy = p.yield_deformation, th = p.theta, du = u - u0, c = du / uy;
      s = du > 0 ? 1.0 : (du < 0 ? -1.0 : direction);
      double g0, gz0, ge0;
      rate(z0, e0, s, g0, gz0, ge0);
      double g = 0, g_z = 0, g_e = 0;
      const auto residual = [&](const double z1, double &e1, double &r, double &rz, double &re) {
        e1 = e0 + 0.5 * c * (z0 + z1);
        rate(z1, e1, s, r, rz, re);
        return z1 - z0 - c * ((1 - th) * g0 + th * r);
      };
      z       = z0;
      double R = residual(z, e, g, g_z, g_e);
      bool converged = du == 0;
      for (unsigned int it = 0; it < p.max_iterations && !converged; ++it)
        {
          const double dR = 1 - c * th * (g_z + 0.5 * c * g_e);
          double       step = -R / dR;
          for (unsigned int half = 0; half < 30; ++half)
            {
              double       e_try, r, rz, re;
              const double R_try = residual(z + step, e_try, r, rz, re);
              if (std::abs(R_try) < std::abs(R) || half == 29)
                {
                  z = z + step, R = R_try, g = r, g_z = rz, g_e = re, e = e_try;
                  break;
                }
              step *= 0.5;
            }
          converged = std::abs(R) <= p.tolerance;
        }
      const double dR    = 1 - c * th * (g_z + 0.5 * c * g_e);
      const double dR_c  = -((1 - th) * g0 + th * g) - c * th * g_e * 0.5 * (z0 + z);
      const double dz_du = -dR_c / dR / uy;
      const double k     = p.stiffness;
      force   = p.alpha * k * u + (1 - p.alpha) * k * uy * z;
      tangent = p.alpha * k + (1 - p.alpha) * k * uy * dz_du;
      u_trial = u;
    }

    void
    commit()
    {
      direction = (u_trial != u0) ? s : direction;
      u0 = u_trial, z0 = z, e0 = e;
    }

    double u_trial = 0;
  };
} // namespace

BOOST_AUTO_TEST_CASE(the_law_is_the_general_map_to_the_bit)
{
  // random increments up to 3 u_y, with reversals and repeated points
  // (du = 0), committed after every other trial; tolerance: none
  for (const double n : {2.0, 1.0, 1.5})
    for (const double delta : {0.0, 0.05})
      {
        BoucWenParameters p = storey(0.1, n);
        p.delta_A = p.delta_nu = p.delta_eta = delta;
        BoucWen    law(p);
        GeneralMap reference{p};
        unsigned int state = 12345, differing = 0;
        double       u     = 0;
        for (unsigned int i = 0; i < 2000; ++i)
          {
            state = state * 1103515245u + 12345u;
            const double r = double(state >> 8) / double(1u << 24) - 0.5;
            u += (i % 7 == 3) ? 0.0 : 6 * r * p.yield_deformation * (i % 50 == 0 ? 1 : 0.1);
            BOOST_REQUIRE(law.set_trial(u, 0));
            reference.set_trial(u);
            differing += law.force() != reference.force || law.tangent() != reference.tangent ||
                         law.history_variable() != reference.z ||
                         law.normalised_energy() != reference.e;
            if (i % 2 == 0)
              {
                law.commit();
                reference.commit();
              }
          }
        BOOST_TEST_INFO("n = " << n << ", delta = " << delta);
        BOOST_TEST(differing == 0u);
      }
}
