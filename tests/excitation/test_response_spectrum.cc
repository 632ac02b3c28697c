// Response spectra, intensity measures and the Eurocode 8 spectrum
// (excitation/response_spectrum.h) against references written here:
//   - Newmark average acceleration with fine sub-steps on the same
//     piecewise-linear excitation (a second method for the peaks);
//   - the closed-form response of a damped oscillator to a resonant
//     harmonic base acceleration from rest (transient and steady state) and
//     to a step (overshoot 1 + exp(-zeta pi / sqrt(1 - zeta^2)));
//   - exactness under a varying step (the floor spectra's sub-steps);
//   - Arias intensity, PGV and PGD of a sine, D5-95 of an exponential
//     decay, all in closed form;
//   - EN 1998-1 eq. 3.2-3.5 by hand at the corner periods.
#include <poundfe/excitation/response_spectrum.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace poundfe;

namespace
{
  /// A deterministic broadband motion: five sines under a rise-plateau-decay
  /// envelope, sampled at dt.
  GroundMotion
  broadband_motion(const double dt, const double duration)
  {
    const double        f[] = {0.7, 1.3, 2.9, 5.1, 8.3}, phase[] = {0.3, 1.9, 4.0, 2.2, 5.5};
    std::vector<double> a;
    for (unsigned int k = 0; k * dt <= duration + 1e-12; ++k)
      {
        const double t   = k * dt;
        const double env = std::min(1.0, t / 2) * (t > 6 ? std::exp(-0.5 * (t - 6)) : 1.0);
        double       sum = 0;
        for (unsigned int j = 0; j < 5; ++j)
          sum += std::sin(2 * M_PI * f[j] * t + phase[j]) / (1 + 0.3 * j);
        a.push_back(2.0 * env * sum);
      }
    return GroundMotion(dt, a, "broadband");
  }

  /// Peak |u| of u'' + 2 zeta w u' + w^2 u = -a by Newmark's average
  /// acceleration with n sub-steps per sample (a linear in between), then
  /// `tail` seconds of free vibration.
  double
  newmark_peak(const GroundMotion &motion, const double T, const double zeta, const unsigned int n,
               const double tail)
  {
    const double w = 2 * M_PI / T, c = 2 * zeta * w, k = w * w;
    const double h = motion.time_step() / n;
    const double k_eff = k + 2 * c / h + 4 / (h * h);
    std::vector<double> a = motion.samples();
    double       u = 0, v = 0, acc = -a[0], peak = 0;
    auto         step = [&](const double ag1) {
      const double p  = -ag1 + (4 / (h * h) * u + 4 / h * v + acc) + c * (2 / h * u + v);
      const double u1 = p / k_eff;
      const double v1 = 2 / h * (u1 - u) - v;
      acc             = 4 / (h * h) * (u1 - u) - 4 / h * v - acc;
      u = u1, v = v1;
      peak = std::max(peak, std::abs(u));
    };
    for (std::size_t i = 0; i + 1 < a.size(); ++i)
      for (unsigned int j = 1; j <= n; ++j)
        step(a[i] + (a[i + 1] - a[i]) * double(j) / n);
    acc = -(c * v + k * u); // the record ends: a = 0
    for (unsigned int j = 0; j * h < tail; ++j)
      step(0);
    return peak;
  }
} // namespace

BOOST_AUTO_TEST_CASE(closed_form_and_series_agree)
{
  // The two evaluations of the same exact step, where both are accurate.
  for (const double zeta : {0.0, 0.05, 0.2, 0.7})
    for (const double wh : {0.2, 0.5, 1.0, 2.0})
      {
        const double         omega = 7.0, h = wh / omega;
        const OscillatorStep a = nigam_jennings_closed_form(omega, zeta, h);
        const OscillatorStep b = nigam_jennings_series(omega, zeta, h);
        // natural scales of the entries: A ~ [1, 1/w; w, 1], B ~ [1/w^2; 1/w]
        const double scale_a[] = {1, 1 / omega, omega, 1};
        const double scale_b[] = {1 / (omega * omega), 1 / (omega * omega), 1 / omega, 1 / omega};
        for (unsigned int j = 0; j < 4; ++j)
          {
            BOOST_TEST(std::abs(a.A[j] - b.A[j]) < 1e-12 * scale_a[j]);
            BOOST_TEST(std::abs(a.B[j] - b.B[j]) < 1e-12 * scale_b[j]);
          }
      }
}

BOOST_AUTO_TEST_CASE(peaks_match_newmark)
{
  // Newmark (gamma 1/2, beta 1/4) at h = dt/40 = 2.5e-4 s: its period error
  // (omega h)^2/12 is below 3e-5 at T = 0.1 s, and its peaks are sampled
  // 400 times per period or more; the spectrum's peaks are sampled at least
  // 200 times per period (at most 1.2e-4 low). Tolerance 1e-3: the Newmark
  // period error accumulates into phase over the 14 s (measured: 1.5e-4 at most).
  const GroundMotion        motion = broadband_motion(0.01, 12);
  const std::vector<double> periods{0.1, 0.5, 1.0, 2.0};
  const std::vector<double> zetas{0.02, 0.05};
  const ResponseSpectrum    spectrum = response_spectrum(motion, periods, zetas);
  for (unsigned int d = 0; d < zetas.size(); ++d)
    for (unsigned int i = 0; i < periods.size(); ++i)
      {
        const double reference = newmark_peak(motion, periods[i], zetas[d], 40, 2.0);
        BOOST_TEST_MESSAGE("T = " << periods[i] << " s, zeta = " << zetas[d] << ": Sd "
                                  << spectrum.sd(d, i) << " m, Newmark " << reference << " m");
        BOOST_TEST(spectrum.sd(d, i) == reference, boost::test_tools::tolerance(1e-3));
        BOOST_TEST(spectrum.psa(d, i) == std::pow(2 * M_PI / periods[i], 2) * spectrum.sd(d, i),
                   boost::test_tools::tolerance(1e-14));
      }
}

BOOST_AUTO_TEST_CASE(resonant_harmonic_closed_form)
{
  // a = A sin(w t) at the oscillator's own w, from rest:
  //   u(t) = C [cos w t - e^(-zeta w t) (cos wd t + zeta/sqrt(1-zeta^2) sin wd t)],
  //   C = A / (2 zeta w^2), then free vibration from (u, u') at the end.
  // The peak of the closed form is found on a grid of T/4000 (error < 3e-7).
  // Tolerance 5e-4: the record's linear interpolation of the sine
  // ((w dt)^2/12 = 8e-5 at dt = T/200) and the spectrum's sampling of the
  // peak (1 - cos(pi/200) = 1.2e-4).
  const double A = 1.0, T = 1.0, zeta = 0.05, w = 2 * M_PI / T, dt = T / 200;
  const double root = std::sqrt(1 - zeta * zeta), wd = w * root, C = A / (2 * zeta * w * w);
  auto         u_forced = [&](const double t) {
    return C * (std::cos(w * t) -
                std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta / root * std::sin(wd * t)));
  };
  for (const double duration : {3.0, 30.0})
    {
      std::vector<double> a;
      for (unsigned int k = 0; k * dt <= duration + 1e-9; ++k)
        a.push_back(A * std::sin(w * k * dt));
      const ResponseSpectrum spectrum =
        response_spectrum(GroundMotion(dt, a, "sine"), {T}, {zeta});
      double       peak = 0;
      const double fine = T / 4000;
      for (double t = 0; t <= duration; t += fine)
        peak = std::max(peak, std::abs(u_forced(t)));
      // free vibration after the end, from u and u' (central difference of the closed form)
      const double u_end = u_forced(duration);
      const double v_end = (u_forced(duration + 1e-6) - u_forced(duration - 1e-6)) / 2e-6;
      for (double s = 0; s <= T; s += fine)
        peak = std::max(peak, std::abs(std::exp(-zeta * w * s) *
                                       (u_end * std::cos(wd * s) +
                                        (v_end + zeta * w * u_end) / wd * std::sin(wd * s))));
      BOOST_TEST_MESSAGE("resonance, " << duration << " s: Sd " << spectrum.sd(0, 0)
                                       << " m, closed form " << peak << " m, steady " << C);
      BOOST_TEST(spectrum.sd(0, 0) == peak, boost::test_tools::tolerance(5e-4));
      if (duration > 10) // e^(-zeta w t) = 8e-5: the steady amplitude, PSA = A / (2 zeta)
        BOOST_TEST(spectrum.psa(0, 0) == A / (2 * zeta), boost::test_tools::tolerance(5e-4));
    }
}

BOOST_AUTO_TEST_CASE(held_step_overshoot)
{
  // A constant acceleration a0 held for 20 periods: the step response peaks
  // at (a0 / w^2) (1 + exp(-zeta pi / sqrt(1 - zeta^2))). The held samples
  // take the same path as white noise. Tolerance 2e-4: the peak is sampled
  // 200 times per period at least (1 - cos(pi/200) = 1.2e-4).
  const double        a0 = 0.8, T = 0.5, zeta = 0.1, w = 2 * M_PI / T;
  std::vector<double> a(int(20 * T / 0.05), a0);
  const ResponseSpectrum spectrum =
    response_spectrum(GroundMotion(0.05, a, "step", true), {T}, {zeta});
  const double expected = a0 / (w * w) * (1 + std::exp(-zeta * M_PI / std::sqrt(1 - zeta * zeta)));
  BOOST_TEST(spectrum.sd(0, 0) == expected, boost::test_tools::tolerance(2e-4));
}

BOOST_AUTO_TEST_CASE(varying_step_is_exact)
{
  // The floor spectra see a varying step (contact sub-steps down to dt/2^k,
  // and the end of a sub-step again at the step). Feeding the samples of a
  // piecewise-linear motion with points inserted on its lines (at fractions
  // 1/2, 1/4, ..., 2^-20 of a step) and repeated must leave the state exact:
  // the same displacement and velocity to round-off.
  const GroundMotion        motion = broadband_motion(0.01, 4);
  const std::vector<double> periods{0.02, 0.3, 3.0};
  const std::vector<double> zetas{0.05};
  SpectralOscillators       uniform(periods, zetas), varying(periods, zetas);
  const std::vector<double> &a  = motion.samples();
  const double               dt = motion.time_step();
  uniform.start(0, a[0]);
  varying.start(0, a[0]);
  for (std::size_t k = 0; k + 1 < a.size(); ++k)
    {
      uniform.advance_to((k + 1) * dt, a[k + 1]);
      if (k % 7 == 3)
        for (const int level : {20, 16, 12, 8, 4, 3, 2, 1})
          {
            const double f = std::ldexp(1.0, -level); // 2^-level of the step
            varying.advance_to((k + f) * dt, a[k] + f * (a[k + 1] - a[k]));
          }
      varying.advance_to((k + 1) * dt, a[k + 1]);
      varying.advance_to((k + 1) * dt, a[k + 1]); // seen again
    }
  for (unsigned int i = 0; i < periods.size(); ++i)
    {
      const double w = 2 * M_PI / periods[i];
      BOOST_TEST(std::abs(uniform.displacement()[i] - varying.displacement()[i]) <
                 1e-9 * uniform.peak_displacement()[i]);
      BOOST_TEST(std::abs(uniform.velocity()[i] - varying.velocity()[i]) <
                 1e-9 * w * uniform.peak_displacement()[i]);
    }
}

BOOST_AUTO_TEST_CASE(short_period_tends_to_pga)
{
  // A rigid oscillator follows the ground: PSA -> PGA as T -> 0. The motion's
  // highest frequency is 8.3 Hz; at T = 0.004 s (250 Hz) the quasi-static
  // amplification 1 / (1 - (f/fn)^2) is 1.001: tolerance 0.5 %.
  const GroundMotion     motion   = broadband_motion(0.01, 12);
  const ResponseSpectrum spectrum = response_spectrum(motion, {0.004}, {0.05});
  BOOST_TEST(spectrum.psa(0, 0) == motion.peak(), boost::test_tools::tolerance(5e-3));
}

BOOST_AUTO_TEST_CASE(arias_pgv_pgd_of_a_sine)
{
  // a = A sin(w t) over n whole periods P:
  //   int a^2 = A^2 n P / 2, so I_A = pi / (2 g) A^2 n P / 2;
  //   v = (A / w)(1 - cos w t): PGV = 2 A / w;  d = (A / w)(t - sin(w t) / w):
  //   PGD = A n P / w at the end.
  // Sampled at P/400, the piecewise-linear interpolant's integrals differ by
  // O((w dt)^2) ~ 2.5e-4 at most: tolerance 5e-4.
  const double        A = 3.0, P = 0.8, w = 2 * M_PI / P, dt = P / 400;
  const unsigned int  n = 5;
  std::vector<double> a;
  for (unsigned int k = 0; k <= 400 * n; ++k)
    a.push_back(A * std::sin(w * k * dt));
  const GroundMotionIntensity m = ground_motion_intensity(GroundMotion(dt, a, "sine"));
  BOOST_TEST(m.arias_intensity == M_PI / (2 * standard_gravity) * A * A * n * P / 2,
             boost::test_tools::tolerance(5e-4));
  BOOST_TEST(m.pgv == 2 * A / w, boost::test_tools::tolerance(5e-4));
  BOOST_TEST(m.pgd == A * n * P / w, boost::test_tools::tolerance(5e-4));
  BOOST_TEST(m.pga == A, boost::test_tools::tolerance(1e-4));
  BOOST_TEST(m.duration == n * P, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(significant_duration_of_exponential_decay)
{
  // a = A e^(-t / tau) on [0, L]: the Husid fraction is
  //   F(t) = (1 - e^(-2t/tau)) / (1 - e^(-2L/tau)),  t_p = -tau/2 ln(1 - p (1 - e^(-2L/tau))).
  // Sampled at tau/500: the interpolant's energy differs by O((dt/tau)^2) ~ 1e-6.
  const double        A = 2.0, tau = 1.5, L = 6.0, dt = tau / 500;
  std::vector<double> a;
  for (unsigned int k = 0; k * dt <= L + 1e-12; ++k)
    a.push_back(A * std::exp(-double(k) * dt / tau));
  const GroundMotionIntensity m     = ground_motion_intensity(GroundMotion(dt, a, "decay"));
  const double                whole = 1 - std::exp(-2.0 * double(a.size() - 1) * dt / tau);
  auto t_p = [&](const double p) { return -tau / 2 * std::log(1 - p * whole); };
  BOOST_TEST(m.t5 == t_p(0.05), boost::test_tools::tolerance(1e-4));
  BOOST_TEST(m.t95 == t_p(0.95), boost::test_tools::tolerance(1e-4));
  BOOST_TEST(m.significant_duration == t_p(0.95) - t_p(0.05), boost::test_tools::tolerance(1e-4));
  BOOST_TEST(m.arias_intensity == M_PI / (2 * standard_gravity) * A * A * tau / 2 * whole,
             boost::test_tools::tolerance(1e-5));
}

BOOST_AUTO_TEST_CASE(eurocode_8_corner_values)
{
  // EN 1998-1 Table 3.2, type 1, ground C: S = 1.15, TB = 0.2, TC = 0.6,
  // TD = 2; a_g = 0.3 g, 5 % (eta = 1): by hand, in g:
  //   Se(0) = 0.3 * 1.15 = 0.345; Se(TB) = Se(TC) = 2.5 * 0.345 = 0.8625;
  //   Se(1.2) = 0.8625 * 0.6 / 1.2 = 0.43125; Se(TD) = 0.8625 * 0.6 / 2 = 0.25875;
  //   Se(4) = 0.8625 * 0.6 * 2 / 16 = 0.0646875; Se(0.1) = 0.345 (1 + 0.5 * 1.5) = 0.60375.
  const auto   type_1 = DesignSpectrum::ec8_type_1;
  const double ag     = 0.3;
  const std::pair<double, double> values[] = {{0, 0.345},     {0.1, 0.60375},   {0.2, 0.8625},
                                               {0.6, 0.8625},  {1.2, 0.43125},   {2.0, 0.25875},
                                               {4.0, 0.0646875}};
  for (const auto &[T, Se] : values)
    BOOST_TEST(ec8_elastic_spectrum(type_1, GroundType::C, ag, 0.05, T) == Se,
               boost::test_tools::tolerance(1e-12));
  // Table 3.3, type 2, ground D: S = 1.8, TB = 0.1, TC = 0.3, TD = 1.2;
  // 10 % damping: eta = sqrt(10/15); plateau 2.5 * 0.3 * 1.8 * eta.
  const double eta = std::sqrt(10.0 / 15.0);
  BOOST_TEST(ec8_damping_correction(0.10) == eta, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(ec8_damping_correction(0.30) == 0.55); // sqrt(10/35) = 0.53 < 0.55
  const auto type_2 = DesignSpectrum::ec8_type_2;
  BOOST_TEST(ec8_elastic_spectrum(type_2, GroundType::D, ag, 0.1, 0.2) == 1.35 * eta,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(ec8_elastic_spectrum(type_2, GroundType::D, ag, 0.1, 2.4) ==
               1.35 * eta * 0.3 * 1.2 / (2.4 * 2.4),
             boost::test_tools::tolerance(1e-12));
  // every ground type's row of both tables
  const double S1[] = {1.0, 1.2, 1.15, 1.35, 1.4}, TC1[] = {0.4, 0.5, 0.6, 0.8, 0.5};
  const double S2[] = {1.0, 1.35, 1.5, 1.8, 1.6}, TC2[] = {0.25, 0.25, 0.25, 0.30, 0.25};
  for (unsigned int g = 0; g < 5; ++g)
    {
      const Ec8GroundParameters p1 = ec8_ground_parameters(type_1, GroundType(g));
      const Ec8GroundParameters p2 = ec8_ground_parameters(type_2, GroundType(g));
      BOOST_TEST(p1.S == S1[g]);
      BOOST_TEST(p1.TC == TC1[g]);
      BOOST_TEST(p1.TD == 2.0);
      BOOST_TEST(p2.S == S2[g]);
      BOOST_TEST(p2.TC == TC2[g]);
      BOOST_TEST(p2.TD == 1.2);
    }
}

BOOST_AUTO_TEST_CASE(velocity_and_displacement_peaks_inside_a_step)
{
  // a = 1 -> -1 over one step of 1 s, then 0 -> ... : v(s) = s - s^2 peaks at
  // s = 1/2 with 1/4 (v is 0 at both samples); then a = -1 -> 1 over the next
  // step: v(s) = -s + s^2 (from 0) and d(s) = 1/6 - s^2/2 + s^3/3 reaches 0
  // at s = 1 while v = 0 at s = 0 and 1 only. By hand: PGV = 1/4, PGD = 1/6.
  const GroundMotionIntensity m = ground_motion_intensity(GroundMotion(1.0, {1, -1, 1}, "pulse"));
  BOOST_TEST(m.pgv == 0.25, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(m.pgd == 1.0 / 6, boost::test_tools::tolerance(1e-14));
  // held: a = 2 for 1 s then -2 for 1 s: v = 2s then 2 - 2s; d peaks at the
  // end, 1 + (2 s - s^2) at s = 1: 2
  const GroundMotionIntensity held = ground_motion_intensity(GroundMotion(1.0, {2, -2}, "held", true));
  BOOST_TEST(held.pgv == 2.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(held.pgd == 2.0, boost::test_tools::tolerance(1e-14));
  // a = -1 -> 1 from v0 = 0.5 (a = 1 held, then this): v = 0 inside, d's peak inside
  const GroundMotionIntensity inside = ground_motion_intensity(GroundMotion(1.0, {0.5, -1.5}, "ramp"));
  // v(s) = 0.5 s - s^2, zero at s = 0.5, d(s) = 0.25 s^2 - s^3/3: d(0.5) = 1/48
  // is a maximum, d(1) = -1/12 the larger |d|
  BOOST_TEST(inside.pgv == 0.5, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(inside.pgd == 1.0 / 12, boost::test_tools::tolerance(1e-14));
}
