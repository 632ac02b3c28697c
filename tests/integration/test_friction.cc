// Dry friction and the SD oscillator through the whole program (Springs and
// Friction sections -> model -> elements -> Newmark with stick-slip events)
// against independent references: an adaptive Dormand-Prince integration
// written here (the frictionless SD oscillator); Coulomb-damped free
// vibration (amplitude falls 4 mu N/k per cycle, rest in |x| <= mu_s N/k);
// Den Hartog's (1931) steady amplitude of the forced Coulomb-damped
// oscillator in continuous sliding; the belt-driven stick-slip limit cycle in
// closed form (stick at v0, slip arcs of the harmonic oscillator); the energy
// balance with the friction dissipation and the belt's work.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/integration/newmark.h>

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <functional>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  /// m x'' + c x' + k x [+ springs] + friction = p(t), one storey.
  InputParameters
  oscillator(const double m, const double k, const double c)
  {
    InputParameters p = poundfe_test::shear_building_input(1, m, k, 0);
    p.model.buildings[0].storey_damping = {c};
    p.output.n_modes                    = 1;
    return p;
  }

  void
  add_friction(InputParameters &p, const double mu_s, const double mu_k, const double n,
               const double belt = 0)
  {
    p.friction.surfaces                 = {"1 1 0"};
    p.friction.law.static_coefficient   = mu_s;
    p.friction.law.kinetic_coefficient  = mu_k;
    p.friction.law.normal.constant      = n;
    p.friction.law.belt_velocity        = belt;
  }

  struct History
  {
    std::vector<double> t, x, v;
    StickSlipLog        log;
    double              energy_error = 0;
    EnergyBalance       energy;
  };

  /// From (x0, v0) under p(t), steps of dt to `end`.
  History
  simulate(const InputParameters &input, const double x0, const double v0, const double dt,
           const double end, const std::function<double(double)> &force = nullptr)
  {
    const Analysis    analysis = prepare_analysis(input);
    NonlinearElements elements = make_nonlinear_elements(analysis.model);
    NewmarkParameters parameters;
    parameters.time_step = dt;
    NewmarkIntegrator integrator(analysis.system, "eigen-ldlt", parameters, &elements);
    Vector            p = Vector::Zero(1);
    if (force)
      p[0] = force(0);
    integrator.initialize(p, Vector::Constant(1, x0), Vector::Constant(1, v0));
    History h;
    const auto n = std::lround(end / dt);
    for (long i = 0; i <= n; ++i)
      {
        if (i > 0)
          integrator.advance([&](const double t, Vector &load) { load[0] = force ? force(t) : 0; });
        h.t.push_back(integrator.time());
        h.x.push_back(integrator.displacement()[0]);
        h.v.push_back(integrator.velocity()[0]);
      }
    h.log          = integrator.stick_slip_log();
    h.energy_error = integrator.max_energy_error();
    h.energy       = integrator.energy();
    return h;
  }

  /// y' = f(t, y) from t0 to t1 by Dormand-Prince 5(4) with error control
  /// (Hairer, Norsett & Wanner, Solving ODEs I, §II.4-5).
  using State = std::array<double, 2>;
  State
  dormand_prince(const std::function<State(double, const State &)> &f, State y, double t,
                 const double t1, const double tolerance)
  {
    static const double c[7] = {0, 1. / 5, 3. / 10, 4. / 5, 8. / 9, 1, 1};
    static const double a[7][6] = {
      {},
      {1. / 5},
      {3. / 40, 9. / 40},
      {44. / 45, -56. / 15, 32. / 9},
      {19372. / 6561, -25360. / 2187, 64448. / 6561, -212. / 729},
      {9017. / 3168, -355. / 33, 46732. / 5247, 49. / 176, -5103. / 18656},
      {35. / 384, 0, 500. / 1113, 125. / 192, -2187. / 6784, 11. / 84}};
    static const double e[7] = {71. / 57600, 0, -71. / 16695, 71. / 1920, -17253. / 339200,
                                22. / 525, -1. / 40}; // b5 - b4
    double h = 1e-3;
    while (t < t1)
      {
        h = std::min(h, t1 - t);
        State k[7];
        for (int s = 0; s < 7; ++s)
          {
            State ys = y;
            for (int j = 0; j < s; ++j)
              for (int i = 0; i < 2; ++i)
                ys[i] += h * a[s][j] * k[j][i];
            k[s] = f(t + c[s] * h, ys);
          }
        State  next = y;
        double error = 0;
        for (int i = 0; i < 2; ++i)
          {
            double ei = 0;
            for (int s = 0; s < 7; ++s)
              {
                next[i] += h * (s < 6 ? a[6][s] : 0) * k[s][i];
                ei += h * e[s] * k[s][i];
              }
            error = std::max(error, std::abs(ei) / (tolerance * (1 + std::abs(y[i]))));
          }
        if (error <= 1)
          {
            t += h;
            y = next;
          }
        h *= std::clamp(0.9 * std::pow(std::max(error, 1e-10), -0.2), 0.2, 5.0);
      }
    return y;
  }
} // namespace

BOOST_AUTO_TEST_CASE(frictionless_sd_oscillator_against_dormand_prince)
{
  // x'' + c x' + x (1 - 1/sqrt(x^2 + alpha^2)) = f cos(Omega t), the thesis's
  // c = 0.048, alpha = 0.4, f = 0.85, Omega = 1/3, from (0.5, 0).
  const double    c = 0.048, alpha = 0.4, f = 0.85, omega = 1. / 3;
  InputParameters p = oscillator(1, 0, c);
  p.springs.sd      = {"1 1 0 1 1 0.4"};
  const double end  = 60;
  // Newmark's average acceleration is second order: dt = 1e-3 -> ~1e-6 x
  const History h = simulate(p, 0.5, 0, 1e-3, end, [&](double t) { return f * std::cos(omega * t); });
  auto rhs = [&](const double t, const State &y) -> State {
    return {{y[1], f * std::cos(omega * t) - c * y[1] -
                     y[0] * (1 - 1 / std::sqrt(y[0] * y[0] + alpha * alpha))}};
  };
  double worst = 0;
  State  y     = {{0.5, 0}};
  for (std::size_t i = 1000; i < h.t.size(); i += 1000) // every second
    {
      y     = dormand_prince(rhs, y, h.t[i - 1000], h.t[i], 1e-11);
      worst = std::max(worst, std::abs(h.x[i] - y[0]));
    }
  BOOST_TEST_MESSAGE("SD oscillator: largest |x - x_DP| over 60 s: " << worst);
  BOOST_TEST(worst < 2e-4); // the response is O(1); Newmark's phase error grows ~ t dt^2
  // Newton's residual tolerance 1e-8 on the work sums
  BOOST_TEST(h.energy_error < 1e-6);
}

BOOST_AUTO_TEST_CASE(coulomb_free_vibration_decays_linearly_and_stops_in_the_band)
{
  // m = 1, k = (2 pi)^2, mu N = 0.5: each half cycle the amplitude falls by
  // 2 mu N/k; the mass stops at the first extreme with |x| <= mu_s N/k.
  const double    k = 4 * M_PI * M_PI, mu = 0.05, n = 10, x0 = 0.2;
  InputParameters p = oscillator(1, k, 0);
  add_friction(p, mu, mu, n);
  const History h    = simulate(p, x0, 0, 1e-3, 6);
  const double  drop = 2 * mu * n / k; // per half cycle
  // the extremes: where the velocity changes sign
  std::vector<double> extremes{x0};
  for (std::size_t i = 1; i + 1 < h.t.size(); ++i)
    if (h.v[i] * h.v[i + 1] < 0 || (h.v[i] != 0 && h.v[i + 1] == 0))
      extremes.push_back(h.x[i + (std::abs(h.v[i + 1]) < std::abs(h.v[i]))]);
  double expected = x0;
  unsigned int half_cycles = 0;
  while (std::abs(expected) > mu * n / k)
    {
      expected = -(expected - (expected > 0 ? drop : -drop));
      ++half_cycles;
      BOOST_REQUIRE(half_cycles < extremes.size());
      // sampled at dt = T/1000: the extreme is found to ~(2 pi 1e-3)^2/2 x0
      BOOST_TEST(std::abs(extremes[half_cycles] - expected) < 1e-4);
    }
  BOOST_TEST_MESSAGE("Coulomb free vibration: " << half_cycles << " half cycles, rest at "
                                                 << h.x.back() << " (closed form " << expected
                                                 << ")");
  // at rest, inside the band, where the closed form says (to the stick
  // spring's deflection mu N/k_s = 1.3e-6 and the sampling)
  BOOST_TEST(std::abs(h.x.back()) <= mu * n / k);
  BOOST_TEST(std::abs(h.x.back() - expected) < 1e-4);
  BOOST_TEST(std::abs(h.v.back()) < 1e-6);
  BOOST_TEST(h.energy_error < 1e-6);
}

BOOST_AUTO_TEST_CASE(forced_coulomb_oscillator_has_den_hartogs_amplitude)
{
  // m x'' + k x + F sgn(x') = P0 cos(w t), continuous sliding (F/P0 = 0.2):
  // X = (P0/k) sqrt(1/(1 - r^2)^2 - (F/P0)^2 (U/r)^2), U = sin(pi/r)/(1 + cos(pi/r)).
  const double k = 4 * M_PI * M_PI, P0 = 1, F = 0.2;
  for (const double r : {0.6, 1.5})
    {
      InputParameters p = oscillator(1, k, 0);
      add_friction(p, F / 10, F / 10, 10);
      // a velocity reversal passes through the stick spring in pi sqrt(m/k_s):
      // 1e8 k keeps it 1e-4 of the period
      p.friction.law.stick_stiffness = 1e8 * k;
      const double w = r * 2 * M_PI, period = 2 * M_PI / w;
      // the reversals are located to dt/16 and the amplitude converges to
      // first order in dt (1.3e-3 at T/2000, 2.6e-5 at T/8000 for r = 1.5)
      const History h = simulate(p, 0, 0, period / 8000, 60 * period,
                                 [&](double t) { return P0 * std::cos(w * t); });
      double amplitude = 0;
      for (std::size_t i = 0; i < h.t.size(); ++i)
        if (h.t[i] > 50 * period)
          amplitude = std::max(amplitude, std::abs(h.x[i]));
      const double U = std::sin(M_PI / r) / (1 + std::cos(M_PI / r));
      const double X = P0 / k * std::sqrt(1 / std::pow(1 - r * r, 2) - std::pow(F / P0 * U / r, 2));
      BOOST_TEST_MESSAGE("Den Hartog r = " << r << ": " << amplitude << " against " << X);
      BOOST_TEST(amplitude == X, boost::test_tools::tolerance(2e-4));
    }
}

BOOST_AUTO_TEST_CASE(belt_driven_stick_slip_limit_cycle_in_closed_form)
{
  // m = k = N = 1, mu_s = 0.4, mu_k = 0.2, belt v0 = 0.1. Stick carries the
  // mass with the belt to x_s = mu_s N/k; slip is x_k + D cos(t) + v0 sin(t)
  // (x_k = mu_k N/k, D = x_s - x_k) until x' = v0 again, at
  // theta = 2 (pi - atan(D/v0)); then stick from x_e = x(theta) to x_s.
  const double    v0 = 0.1, xs = 0.4, xk = 0.2, D = xs - xk;
  InputParameters p = oscillator(1, 1, 0);
  add_friction(p, 0.4, 0.2, 1, v0);
  p.friction.law.stick_stiffness = 1e6;
  const History h     = simulate(p, 0, 0, 1e-3, 60, [](double) { return 0.0; });
  const double  theta = 2 * (M_PI - std::atan(D / v0));
  const double  xe    = xk + D * std::cos(theta) + v0 * std::sin(theta);
  const double  slip  = theta, stick = (xs - xe) / v0;
  const StickSlipStatistics s = stick_slip_statistics(h.log, 0, 60);
  BOOST_REQUIRE(s.stick_durations.size() >= 5u);
  // after the first stick the cycle repeats exactly: every later episode;
  // switches are located within dt/2^4 = 6e-5 s
  for (std::size_t i = 1; i < s.stick_durations.size(); ++i)
    BOOST_TEST(std::abs(s.stick_durations[i] - stick) < 2e-4);
  for (std::size_t i = 1; i < s.slip_durations.size(); ++i)
    BOOST_TEST(std::abs(s.slip_durations[i] - slip) < 2e-4);
  double lowest = 1, highest = -1;
  for (std::size_t i = 0; i < h.t.size(); ++i)
    if (h.t[i] > 20)
      {
        lowest  = std::min(lowest, h.x[i]);
        highest = std::max(highest, h.x[i]);
      }
  BOOST_TEST_MESSAGE("stick-slip: stick " << s.stick_durations.back() << " s (" << stick
                                          << "), slip " << s.slip_durations.back() << " s ("
                                          << slip << "), x in [" << lowest << ", " << highest << "]");
  // the slip arc x_k + A cos(t - phi), A = sqrt(D^2 + v0^2), passes both extremes
  const double A = std::hypot(D, v0);
  BOOST_TEST(std::abs(lowest - (xk - A)) < 1e-5);
  BOOST_TEST(std::abs(highest - (xk + A)) < 1e-5);
  BOOST_TEST(std::abs(xe) < 1e-12); // the closed form's end of slip, here at x = 0
  // the belt does work on the structure and friction dissipates it
  BOOST_TEST(h.energy.belt > 0);
  BOOST_TEST(h.energy.friction > 0);
  BOOST_TEST(h.energy_error < 1e-6);
}
