// Bifurcation diagrams (dynamics/bifurcation.h) against independent
// references:
//  - the period classification of constructed sequences (period 1, 2, 3,
//    quasi-periodic);
//  - a linear damped oscillator m x'' + c x' + k x = F sin(w t): its steady
//    state x(t) = X sin(w t - phi), X = F / sqrt((k - m w^2)^2 + (c w)^2),
//    phi = atan2(c w, k - m w^2) (Chopra, Dynamics of Structures, §3.2), so
//    every Poincaré sample is x(k T) = -X sin(phi) and the response is
//    period 1; its largest Lyapunov exponent is the decay rate of free
//    vibration, -zeta w0 = -c / (2 m);
//  - the Duffing oscillator x'' + 0.2 x' + x + x^3 = 20 cos(w t) from rest
//    (input/duffing-bifurcation.prm): period 2 at w = 0.77 and period 1 at
//    w = 0.81, its Poincaré points those of a classical Runge-Kutta
//    integration written here (2000 steps per period);
//  - the SD oscillator with dry friction (input/sd-bifurcation.prm) against
//    an event-driven integration with exact stick written here: RK4 in slip
//    with the sign of the friction force fixed, the instant the slip
//    velocity reaches zero found by bisection, then stick (x frozen, v = 0)
//    while the force that drives the mass stays within mu_s N, its end again
//    found by bisection (the switch model of Leine & Nijmeijer 2004,
//    Dynamics and Bifurcations of Non-Smooth Mechanical Systems, §2.4). The
//    mass stays stuck for f < mu N(0); at f = 1.5 the orbit is period 3.
#include <poundfe/base/exceptions.h>
#include <poundfe/dynamics/bifurcation.h>
#include <poundfe/input/bifurcation_input.h>
#include <poundfe/input/input_parameters.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace poundfe;

namespace
{
  /// Poincaré samples x(k T), k = n_transient + 1 .. n_transient + n_sampled,
  /// of x'' + d x' + x + x^3 = f cos(w t) from rest by classical RK4 with
  /// n_steps steps per period (Hairer, Norsett & Wanner, §II.1).
  std::vector<double>
  duffing_samples(const double d, const double f, const double w, const unsigned int n_steps,
                  const unsigned int n_transient, const unsigned int n_sampled)
  {
    const auto rhs = [&](const double t, const std::array<double, 2> &x) {
      return std::array<double, 2>{{x[1], -d * x[1] - x[0] - x[0] * x[0] * x[0] + f * std::cos(w * t)}};
    };
    const double          h = 2 * M_PI / w / n_steps;
    std::array<double, 2> x{{0, 0}};
    std::vector<double>   samples;
    for (unsigned int k = 1; k <= n_transient + n_sampled; ++k)
      {
        for (unsigned int j = 0; j < n_steps; ++j)
          {
            const double t  = ((k - 1) * n_steps + j) * h;
            const auto   k1 = rhs(t, x);
            const auto   k2 = rhs(t + h / 2, {{x[0] + h / 2 * k1[0], x[1] + h / 2 * k1[1]}});
            const auto   k3 = rhs(t + h / 2, {{x[0] + h / 2 * k2[0], x[1] + h / 2 * k2[1]}});
            const auto   k4 = rhs(t + h, {{x[0] + h * k3[0], x[1] + h * k3[1]}});
            for (unsigned int i = 0; i < 2; ++i)
              x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
          }
        if (k > n_transient)
          samples.push_back(x[0]);
      }
    return samples;
  }

  /// The SD oscillator with Coulomb friction of input/sd-bifurcation.prm,
  ///   x'' + c x' + x (1 - 1/sqrt(x^2 + a^2)) + mu N(x) sgn(x') = f cos(w t),
  ///   N(x) = g1 - a (1 - 1/sqrt(x^2 + a^2)),
  /// from rest with exact stick (an event-driven switch, see the file's
  /// head): Poincaré samples x(k T) as duffing_samples.
  std::vector<double>
  sd_exact_stick_samples(const double f, const unsigned int n_steps, const unsigned int n_transient,
                         const unsigned int n_sampled)
  {
    constexpr double c = 0.048, a = 0.4, g1 = 2, mu = 0.1, w = 1.0 / 3;
    struct State
    {
      double x, v;
    };
    const auto normal  = [&](const double x) { return g1 - a * (1 - 1 / std::sqrt(x * x + a * a)); };
    const auto driving = [&](const double t, const double x) { // all but damping and friction
      return f * std::cos(w * t) - x * (1 - 1 / std::sqrt(x * x + a * a));
    };
    // One RK4 step of length h in slip with sgn(v) = s.
    const auto slip = [&](const double t, const State &y, const double h, const double s) {
      const auto rhs = [&](const double tt, const State &z) {
        return State{z.v, driving(tt, z.x) - c * z.v - mu * normal(z.x) * s};
      };
      const State k1 = rhs(t, y);
      const State k2 = rhs(t + h / 2, {y.x + h / 2 * k1.x, y.v + h / 2 * k1.v});
      const State k3 = rhs(t + h / 2, {y.x + h / 2 * k2.x, y.v + h / 2 * k2.v});
      const State k4 = rhs(t + h, {y.x + h * k3.x, y.v + h * k3.v});
      return State{y.x + h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
                   y.v + h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v)};
    };
    // Bisection for the first root in (0, h] of a quantity positive at 0.
    const auto first_root = [](const auto &positive, double h) {
      double low = 0;
      for (unsigned int i = 0; i < 200 && h - low > 1e-15 * (1 + h); ++i)
        {
          const double mid = (low + h) / 2;
          (positive(mid) ? low : h) = mid;
        }
      return h;
    };
    const double        T = 2 * M_PI / w, h = T / n_steps;
    State               y{0, 0};
    double              s = 0; // 0: stuck, +-1: slipping that way
    std::vector<double> samples;
    for (unsigned int k = 1; k <= n_transient + n_sampled; ++k)
      for (unsigned int j = 0; j < n_steps; ++j)
        {
          double t = ((k - 1) * n_steps + j) * h;
          for (double left = h; left > 0;)
            if (s == 0)
              {
                const auto stuck = [&](const double d) {
                  return std::abs(driving(t + d, y.x)) <= mu * normal(y.x);
                };
                const double d = stuck(left) ? left : first_root(stuck, left);
                t += d, left -= d;
                if (!stuck(0)) // breaks away, in the direction of the driving force
                  s = driving(t, y.x) > 0 ? 1 : -1;
              }
            else
              {
                const auto moving = [&](const double d) { return s * slip(t, y, d, s).v > 0; };
                const double d = moving(left) ? left : first_root(moving, left);
                y = slip(t, y, d, s);
                t += d, left -= d;
                if (s * y.v <= 0) // the slip velocity reached zero: stick or reverse
                  {
                    y.v = 0;
                    const double drive = driving(t, y.x);
                    s = std::abs(drive) <= mu * normal(y.x) ? 0 : (drive > 0 ? 1 : -1);
                  }
              }
          if (j + 1 == n_steps && k > n_transient)
            samples.push_back(y.x);
        }
    return samples;
  }

  /// The first n samples, sorted (a period-n orbit's points, whatever its phase).
  std::vector<double>
  orbit(const std::vector<double> &samples, const unsigned int n)
  {
    std::vector<double> points(samples.begin(), samples.begin() + n);
    std::sort(points.begin(), points.end());
    return points;
  }
} // namespace

BOOST_AUTO_TEST_CASE(poincare_period_of_constructed_sequences)
{
  std::vector<double> one(40, 0.3), two, three, quasi;
  for (unsigned int k = 0; k < 40; ++k)
    {
      two.push_back(k % 2 ? 1.0 : -0.5);
      three.push_back(std::vector<double>{0.1, 0.7, -0.2}[k % 3]);
      quasi.push_back(std::sin(k * std::sqrt(2.0))); // never repeats
    }
  BOOST_TEST(poincare_period(one, 0) == 1u);
  BOOST_TEST(poincare_period(two, 1e-12) == 2u);
  BOOST_TEST(poincare_period(three, 1e-12) == 3u);
  BOOST_TEST(poincare_period(quasi, 1e-6) == 0u);
  // a perturbation above the tolerance breaks the period, below it does not
  two[31] += 2e-6;
  BOOST_TEST(poincare_period(two, 1e-6) == 0u);
  BOOST_TEST(poincare_period(two, 1e-5) == 2u);
  // period n needs 2 n samples
  BOOST_TEST(poincare_period(std::vector<double>(three.begin(), three.begin() + 5), 1e-12) == 0u);
}

BOOST_AUTO_TEST_CASE(linear_oscillator_is_period_one_at_its_steady_state)
{
  // input/linear-bifurcation.prm: the oscillator and the force
  const double m = 1000, k = 1e5, c = 1000, F = 1000;
  const std::string     file  = "input/linear-bifurcation.prm";
  const InputParameters input = read_parameters(file, {{"Bifurcation/Sampled periods", "128"}});
  const BuildingParameters &b = input.model.buildings.at(0);
  BOOST_TEST_REQUIRE(b.floor_masses == std::vector<double>{m});
  BOOST_TEST_REQUIRE(b.storey_stiffnesses == std::vector<double>{k});
  BOOST_TEST_REQUIRE(b.storey_damping == std::vector<double>{c});
  BOOST_TEST_REQUIRE(input.nodal_forces.harmonic.at(0).find("1 1 0 ux 1000 ") == 0u);
  BOOST_TEST_REQUIRE(input.bifurcation.sweep.parameter == "Nodal forces/Harmonic:6");

  const double w0 = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m));
  for (const double w : {5.0, 9.5, 10.0, 12.0, 15.0})
    {
      const BifurcationPoint point = bifurcation_point(input, w);
      const double X   = F / std::hypot(k - m * w * w, c * w);
      const double phi = std::atan2(c * w, k - m * w * w);
      // Newmark's (trapezoidal) frequency error (w dt)^2 / 12 at the larger
      // of w and w0, amplified at most 1 / (2 zeta) near resonance; twice that.
      const double dt = point.time_step, w_max = std::max(w, w0);
      const double tolerance = 2 * (w_max * dt) * (w_max * dt) / 12 / (2 * zeta) * X;
      BOOST_TEST(point.completed);
      BOOST_TEST(point.forcing_period == 2 * M_PI / w, boost::test_tools::tolerance(1e-14));
      BOOST_TEST(std::abs(point.forcing_period / dt - std::round(point.forcing_period / dt)) < 1e-9);
      BOOST_TEST(point.period == 1u, "w = " << w);
      BOOST_TEST_REQUIRE(point.samples.size() == 128u);
      for (const double x : point.samples)
        BOOST_TEST(std::abs(x - (-X * std::sin(phi))) <= tolerance,
                   "w = " << w << ": " << x << " against " << -X * std::sin(phi));
      // the range of x(t) over the sampled periods is 2 X
      BOOST_TEST(std::abs(point.response_range - 2 * X) <= 2 * tolerance + 0.01 * X);
      // Benettin's estimate over 128 periods: 3 %
      BOOST_TEST(point.lyapunov_exponent == -zeta * w0, boost::test_tools::tolerance(0.03));
    }
}

BOOST_AUTO_TEST_CASE(continuation_starts_from_the_previous_final_state)
{
  // Without a transient, the second of two equal values continued from the
  // first goes on along the same trajectory: its samples are samples
  // K+1..2K of one run of 2K periods from rest (the reference). Without
  // continuation it starts again from rest: its samples are the first
  // run's. Tolerance: round-off over 2K periods (the restart at t = 0
  // instead of K T changes sin(w t) by ~1e-15 and recomputes a from
  // equilibrium, which linear Newmark satisfies at every step).
  const std::string file = "input/linear-bifurcation.prm";
  const unsigned int K = 16;
  const InputParameters twice = read_parameters(
    file, {{"Bifurcation/Values", "8, 8"}, {"Bifurcation/Transient periods", "0"},
           {"Bifurcation/Sampled periods", std::to_string(K)},
           {"Bifurcation/Lyapunov exponent", "false"}, {"Bifurcation/Continuation", "true"}});
  const std::vector<BifurcationPoint> continued = bifurcation_points(twice);
  const BifurcationPoint long_run = bifurcation_point(
    read_parameters(file, {{"Bifurcation/Transient periods", "0"},
                           {"Bifurcation/Sampled periods", std::to_string(2 * K)},
                           {"Bifurcation/Lyapunov exponent", "false"}}),
    8);
  BOOST_TEST_REQUIRE(continued.size() == 2u);
  BOOST_TEST_REQUIRE(long_run.samples.size() == 2 * K);
  const double scale = *std::max_element(long_run.samples.begin(), long_run.samples.end());
  for (unsigned int k = 0; k < K; ++k)
    {
      BOOST_TEST(std::abs(continued[0].samples[k] - long_run.samples[k]) <= 1e-12 * scale);
      BOOST_TEST(std::abs(continued[1].samples[k] - long_run.samples[K + k]) <= 1e-10 * scale);
    }
  // the transient is still decaying: the continued samples differ from the first run's
  BOOST_TEST(std::abs(continued[1].samples[0] - continued[0].samples[0]) > 1e-6 * scale);

  // Without continuation a value twice is refused (the same point twice,
  // issue 28 class 8), so the second of two different values from rest is
  // compared with that value alone: the same run, bit for bit.
  std::vector<ParameterOverride> overrides = twice.overrides;
  overrides.push_back({"Bifurcation/Continuation", "false"});
  BOOST_CHECK_THROW(read_parameters(file, overrides), poundfe::InputError);
  overrides.push_back({"Bifurcation/Values", "8, 9"});
  const std::vector<BifurcationPoint> from_rest = bifurcation_points(read_parameters(file, overrides));
  const BifurcationPoint              alone     = bifurcation_point(
    read_parameters(file, {{"Bifurcation/Transient periods", "0"},
                           {"Bifurcation/Sampled periods", std::to_string(K)},
                           {"Bifurcation/Lyapunov exponent", "false"}}),
    9);
  BOOST_TEST_REQUIRE(from_rest.size() == 2u);
  BOOST_TEST_REQUIRE(alone.samples.size() == K);
  for (unsigned int k = 0; k < K; ++k)
    BOOST_TEST(from_rest[1].samples[k] == alone.samples[k]);
}

BOOST_AUTO_TEST_CASE(duffing_period_two_window_against_runge_kutta)
{
  // Tolerance of a Poincaré point: the Newmark error estimated by Richardson
  // extrapolation from a run at half the step (second order: the error of
  // the run at dt is about 4/3 of its difference from the run at dt/2),
  // three times, plus the RK4 error (1e-8, from its own halving below).
  const std::string     file  = "input/duffing-bifurcation.prm";
  const InputParameters input = read_parameters(file, {{"Bifurcation/Lyapunov exponent", "false"}});
  const InputParameters fine  = read_parameters(
    file, {{"Bifurcation/Lyapunov exponent", "false"}, {"Time integration/Time step", "0.01"}});
  BOOST_TEST_REQUIRE(input.model.buildings.at(0).storey_damping == std::vector<double>{0.2});
  BOOST_TEST_REQUIRE(input.nodal_forces.harmonic.at(0).find("1 1 0 ux 20 ") == 0u);
  const unsigned int n_transient = input.bifurcation.transient_periods;
  const unsigned int n_sampled   = input.bifurcation.sampled_periods;
  for (const auto &[w, period] : std::vector<std::pair<double, unsigned int>>{{0.77, 2}, {0.81, 1}})
    {
      const std::vector<double> rk = duffing_samples(0.2, 20, w, 2000, n_transient, n_sampled);
      const std::vector<double> rk_fine = duffing_samples(0.2, 20, w, 4000, n_transient, n_sampled);
      BOOST_TEST_REQUIRE(poincare_period(rk, 1e-6) == period); // the reference's own period
      const BifurcationPoint coarse = bifurcation_point(input, w);
      const BifurcationPoint halved = bifurcation_point(fine, w);
      BOOST_TEST(coarse.period == period, "w = " << w);
      BOOST_TEST(halved.period == period, "w = " << w);
      const std::vector<double> reference = orbit(rk, period), points = orbit(coarse.samples, period),
                                points_fine = orbit(halved.samples, period), check = orbit(rk_fine, period);
      for (unsigned int i = 0; i < period; ++i)
        {
          BOOST_TEST(std::abs(check[i] - reference[i]) < 1e-8); // RK4 converged
          const double tolerance = 3 * 4.0 / 3 * std::abs(points[i] - points_fine[i]) + 1e-8;
          BOOST_TEST_MESSAGE("w = " << w << ": point " << points[i] << ", reference "
                                    << reference[i] << ", tolerance " << tolerance);
          BOOST_TEST(std::abs(points[i] - reference[i]) <= tolerance,
                     "w = " << w << ": point " << points[i] << " against " << reference[i]
                            << " (tolerance " << tolerance << ")");
        }
      if (period == 2) // two distinct points, far beyond the tolerance
        BOOST_TEST(reference[1] - reference[0] > 0.01);
    }
}

BOOST_AUTO_TEST_CASE(sd_oscillator_with_friction_against_exact_stick)
{
  // What separates poundfe from exact stick is the elastic-plastic slider's
  // compliance, not the time step: at every breakaway and reversal the
  // friction force takes about 2 sqrt(m / k_s) = 0.02 s (k_s = 1e4 K, the
  // default) to build up, an impulse error of order mu N sqrt(m / k_s) =
  // 2.6e-3 per transition against the orbit's 1.5. The points differ from
  // exact stick by 1.5e-4 .. 8e-4 at dt = 0.02 and by at most 1.1e-3 at
  // dt = 0.01 (they do not converge to it as dt falls); tolerance 2e-3.
  // The reference's own error is its change when its step is halved (< 1e-6).
  const std::string                    file = "input/sd-bifurcation.prm";
  const std::vector<ParameterOverride> common{{"Bifurcation/Lyapunov exponent", "false"},
                                              {"Bifurcation/Continuation", "false"}};
  std::vector<ParameterOverride> halved_step = common;
  halved_step.push_back({"Time integration/Time step", "0.01"});
  const InputParameters input = read_parameters(file, common);
  const InputParameters fine  = read_parameters(file, halved_step);
  BOOST_TEST_REQUIRE(input.model.buildings.at(0).storey_damping == std::vector<double>{0.048});
  BOOST_TEST_REQUIRE(input.friction.law.static_coefficient == 0.1);
  const unsigned int n_transient = input.bifurcation.transient_periods;
  const unsigned int n_sampled   = input.bifurcation.sampled_periods;

  // Stuck for good below mu N(0) = 0.1 (2 + 0.4 (1/0.4 - 1)) = 0.26: the
  // reference does not move; poundfe's samples are the stick spring's
  // deflection, |x| <= f / (k_s + k_t), k_t = 1 - 1/0.4 the SD spring's
  // tangent at 0.
  const std::vector<double> stuck = sd_exact_stick_samples(0.2, 1000, 5, 8);
  BOOST_TEST(*std::max_element(stuck.begin(), stuck.end()) == 0);
  BOOST_TEST(*std::min_element(stuck.begin(), stuck.end()) == 0);
  const BifurcationPoint held = bifurcation_point(input, 0.2);
  BOOST_TEST(held.period == 1u);
  for (const double x : held.samples)
    BOOST_TEST(std::abs(x) <= 0.2 / (1e4 - 1.5));

  const double              f         = 1.5;
  const std::vector<double> reference = sd_exact_stick_samples(f, 4000, n_transient, n_sampled);
  const std::vector<double> check     = sd_exact_stick_samples(f, 8000, n_transient, n_sampled);
  BOOST_TEST_REQUIRE(poincare_period(reference, 1e-6) == 3u);
  const std::vector<double> exact = orbit(reference, 3), exact_fine = orbit(check, 3);
  for (const InputParameters *run : {&input, &fine})
    {
      const BifurcationPoint point = bifurcation_point(*run, f);
      BOOST_TEST(point.period == 3u);
      const std::vector<double> points = orbit(point.samples, 3);
      for (unsigned int i = 0; i < 3; ++i)
        {
          BOOST_TEST(std::abs(exact_fine[i] - exact[i]) < 1e-6);
          BOOST_TEST_MESSAGE("f = " << f << ", dt = " << run->time_integration.newmark.time_step
                                    << ": point " << points[i] << ", exact stick " << exact[i]);
          BOOST_TEST(std::abs(points[i] - exact[i]) <= 2e-3,
                     "point " << points[i] << " against " << exact[i]);
        }
    }
  BOOST_TEST(exact[2] - exact[0] > 1); // three distinct points, far apart
}

BOOST_AUTO_TEST_CASE(stuck_oscillator_has_a_finite_negative_lyapunov_exponent)
{
  // The thesis's Fig. 3.2 (a) oscillator from rest at f = 0.05, below the
  // static friction force 1: the mass sticks, both trajectories of
  // Benettin's estimate can stop at the same point, and ln(d / d0) would be
  // -inf (the run then failed with a non-finite output). The estimate
  // counts such a period as contracted to round-off: finite, negative, and
  // not below ln(eps) / T per period (T = 2 pi / Omega = 18.85 s).
  const std::vector<ParameterOverride> from_rest{{"Initial conditions/State", ""},
                                                 {"Bifurcation/Transient periods", "5"},
                                                 {"Bifurcation/Sampled periods", "8"}};
  const InputParameters  input = read_parameters("input/thesis/fig-3.2a.prm", from_rest);
  const BifurcationPoint point = bifurcation_point(input, 0.05);
  const double           floor = std::log(std::numeric_limits<double>::epsilon()) / (6 * M_PI);
  BOOST_TEST(std::isfinite(point.lyapunov_exponent));
  BOOST_TEST(point.lyapunov_exponent < 0);
  BOOST_TEST(point.lyapunov_exponent >= floor * (1 + 1e-12));
}
