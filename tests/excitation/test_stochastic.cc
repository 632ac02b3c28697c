// The generators against their target spectra (doc/theory.md §5), with the
// estimates written here, independently of the library:
//   - ensemble PSD: averaged periodogram at the DFT frequencies (Eigen's FFT),
//     averaged over bands, against the analytic Kanai-Tajimi
//     and Clough-Penzien spectra; for filtered white noise the exact target is
//     S(w) sinc^2(w dt / 2), because the noise is held over dt;
//   - variance against the band-limited integral of S (adaptive quadrature);
//   - Gaussian marginals: skewness, excess kurtosis and the Kolmogorov-Smirnov
//     distance of thinned (nearly independent) samples.
#include <poundfe/excitation/excitation.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/input/input_parameters.h>

#include <boost/test/unit_test.hpp>

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <vector>

using namespace poundfe;

namespace
{
  /// Adaptive Simpson on [a, b].
  double
  integrate(const std::function<double(double)> &f, const double a, const double b,
            const double tolerance = 1e-10)
  {
    const std::function<double(double, double, double, double, double, int)> step =
      [&](double x0, double x1, double f0, double fm, double f1, int depth) {
        const double m = (x0 + x1) / 2, l = (x0 + m) / 2, r = (m + x1) / 2;
        const double fl = f(l), fr = f(r);
        const double whole = (x1 - x0) / 6 * (f0 + 4 * fm + f1);
        const double halves = (m - x0) / 6 * (f0 + 4 * fl + fm) + (x1 - m) / 6 * (fm + 4 * fr + f1);
        if (depth > 40 || std::abs(halves - whole) < 15 * tolerance * (std::abs(halves) + 1e-300))
          return halves;
        return step(x0, m, f0, fl, fm, depth + 1) + step(m, x1, fm, fr, f1, depth + 1);
      };
    return step(a, b, f(a), f((a + b) / 2), f(b), 0);
  }

  StochasticMotion
  stationary_motion(const bool clough_penzien, const StochasticMethod method)
  {
    StochasticMotion m;
    m.method             = method;
    m.filter             = soil_preset(Soil::medium, clough_penzien);
    m.spectral_intensity = 0.02;
    m.duration           = 50;
    m.cutoff_frequency   = 100; // spectral representation: N = 100 * 50 / pi = 1592 frequencies
    m.sample_interval    = 0.01;
    m.envelope.kind      = EnvelopeKind::none;
    m.seed               = 11;
    return m;
  }

  /// Samples of realizations 0..n-1, from t = skip on.
  std::vector<std::vector<double>>
  ensemble(const MotionGenerator &generator, const unsigned int n, const double skip)
  {
    std::vector<std::vector<double>> samples(n);
    std::vector<double>              xi(generator.n_variables()), values;
    const unsigned int first = std::lround(skip / generator.motion().sample_interval);
    for (unsigned int r = 0; r < n; ++r)
      {
        standard_normals(generator.motion().seed, r, xi);
        generator.generate(xi.data(), values);
        samples[r].assign(values.begin() + first, values.end());
      }
    return samples;
  }

  double
  held_noise_psd(const MotionGenerator &g, const double w)
  {
    const double x = w * g.motion().sample_interval / 2;
    const double sinc = x == 0 ? 1 : std::sin(x) / x;
    return g.motion().method == StochasticMethod::filtered_white_noise ?
             g.target_psd(w) * sinc * sinc :
             g.target_psd(w);
  }

  void
  check_ensemble_psd(const bool clough_penzien, const StochasticMethod method)
  {
    const MotionGenerator generator(stationary_motion(clough_penzien, method));
    // 10 s of start-up transient dropped (e^{-zeta w_g 10} = 4e-18); 40 s kept
    const auto         samples = ensemble(generator, 100, 10);
    const double       dt      = generator.motion().sample_interval;
    const unsigned int n       = samples[0].size();
    const double       dw      = 2 * M_PI / (n * dt);
    std::vector<double> periodogram(n / 2 + 1, 0.0);
    Eigen::FFT<double>  fft;
    std::vector<std::complex<double>> spectrum;
    for (const auto &a : samples)
      {
        fft.fwd(spectrum, a);
        for (unsigned int k = 0; k <= n / 2; ++k)
          periodogram[k] += std::norm(spectrum[k]) * dt / (2 * M_PI * n) / samples.size();
      }
    // 8 bands between 2 and 40 rad/s
    const unsigned int k_first = std::ceil(2 / dw), k_last = std::floor(40 / dw);
    const unsigned int per_band = (k_last - k_first) / 8;
    double             worst    = 0;
    for (unsigned int band = 0; band < 8; ++band)
      {
        double estimate = 0, target = 0;
        for (unsigned int k = k_first + band * per_band; k < k_first + (band + 1) * per_band; ++k)
          {
            estimate += periodogram[k];
            target += held_noise_psd(generator, k * dw);
          }
        worst = std::max(worst, std::abs(estimate / target - 1));
      }
    BOOST_TEST_MESSAGE((clough_penzien ? "CP" : "KT")
                       << (method == StochasticMethod::spectral_representation ? " spectral" :
                                                                                  " filtered")
                       << ": largest band deviation of the ensemble PSD " << worst);
    // each band averages 100 x 30 periodogram ordinates, whose relative
    // standard deviation is 1/sqrt(3000) = 1.8 %; 6 % is 3.3 sigma
    BOOST_TEST(worst < 0.06);
  }
} // namespace

BOOST_AUTO_TEST_CASE(ensemble_psd_kanai_tajimi_filtered_white_noise)
{
  check_ensemble_psd(false, StochasticMethod::filtered_white_noise);
}

BOOST_AUTO_TEST_CASE(ensemble_psd_clough_penzien_filtered_white_noise)
{
  check_ensemble_psd(true, StochasticMethod::filtered_white_noise);
}

BOOST_AUTO_TEST_CASE(ensemble_psd_kanai_tajimi_spectral_representation)
{
  check_ensemble_psd(false, StochasticMethod::spectral_representation);
}

BOOST_AUTO_TEST_CASE(ensemble_psd_clough_penzien_spectral_representation)
{
  check_ensemble_psd(true, StochasticMethod::spectral_representation);
}

BOOST_AUTO_TEST_CASE(variance_against_the_band_limited_integral)
{
  for (const bool cp : {false, true})
    for (const StochasticMethod method :
         {StochasticMethod::filtered_white_noise, StochasticMethod::spectral_representation})
      {
        const MotionGenerator generator(stationary_motion(cp, method));
        const double          wu = generator.cutoff_frequency();
        // two-sided: twice the integral over [0, w_u]; filtered white noise
        // has no cutoff, its spectrum is S sinc^2 (integrated to 200 pi / dt,
        // where the remaining tail is below 1e-6 of the total)
        const double upper = method == StochasticMethod::spectral_representation ?
                               wu :
                               200 * M_PI / generator.motion().sample_interval;
        const double expected =
          2 * integrate([&](double w) { return held_noise_psd(generator, w); }, 0, upper, 1e-12);
        const auto samples = ensemble(generator, 60, 10);
        double     sum = 0, count = 0;
        for (const auto &a : samples)
          for (const double x : a)
            sum += x * x, count += 1;
        const double variance = sum / count;
        BOOST_TEST_MESSAGE((cp ? "CP" : "KT") << " method " << int(method) << ": variance "
                                              << variance << ", band-limited integral "
                                              << expected);
        // 60 x 40 s, correlation time ~ 1/(zeta_g w_g) = 0.25 s: ~10000
        // independent values, sampling error sqrt(2/10000) = 1.4 %; 4 %
        BOOST_TEST(std::abs(variance / expected - 1) < 0.04);
      }
}

BOOST_AUTO_TEST_CASE(spectral_representation_sum_is_the_band_limited_integral)
{
  // The amplitudes alone: sum_k 4 S(w_k) dw / 2 = the midpoint rule of the
  // integral; with N = 4000 frequencies it is within 1e-5 of the quadrature.
  StochasticMotion m = stationary_motion(false, StochasticMethod::spectral_representation);
  m.n_frequencies    = 4000;
  const MotionGenerator g(m);
  const double          dw = g.cutoff_frequency() / 4000;
  double                sum = 0;
  for (unsigned int k = 0; k < 4000; ++k)
    sum += 2 * g.target_psd((k + 0.5) * dw) * dw;
  const double integral =
    2 * integrate([&](double w) { return g.target_psd(w); }, 0, g.cutoff_frequency(), 1e-12);
  BOOST_TEST(sum == integral, boost::test_tools::tolerance(1e-5));
}

BOOST_AUTO_TEST_CASE(gaussian_marginals)
{
  for (const StochasticMethod method :
       {StochasticMethod::filtered_white_noise, StochasticMethod::spectral_representation,
        StochasticMethod::white_noise})
    {
      const MotionGenerator generator(stationary_motion(false, method));
      const auto            samples = ensemble(generator, 60, 10);
      // every 50th value (0.5 s apart: nearly independent)
      std::vector<double> x;
      double              m2 = 0;
      for (const auto &a : samples)
        for (std::size_t j = 0; j < a.size(); j += 50)
          x.push_back(a[j]);
      for (const double v : x)
        m2 += v * v / x.size();
      double m3 = 0, m4 = 0;
      for (double &v : x)
        {
          v /= std::sqrt(m2);
          m3 += v * v * v / x.size();
          m4 += v * v * v * v / x.size();
        }
      std::sort(x.begin(), x.end());
      double ks = 0;
      for (std::size_t i = 0; i < x.size(); ++i)
        {
          const double F = standard_normal_cdf(x[i]);
          ks = std::max({ks, std::abs(F - double(i) / x.size()), std::abs(F - double(i + 1) / x.size())});
        }
      const double n = x.size();
      BOOST_TEST_MESSAGE("method " << int(method) << ": n " << n << " skewness " << m3
                                   << " excess kurtosis " << m4 - 3 << " KS " << ks);
      // standard errors sqrt(6/n) and sqrt(24/n); KS critical value at 1 %: 1.63/sqrt(n)
      BOOST_TEST(std::abs(m3) < 4 * std::sqrt(6 / n));
      BOOST_TEST(std::abs(m4 - 3) < 4 * std::sqrt(24 / n));
      BOOST_TEST(ks < 1.63 / std::sqrt(n));
    }
}

BOOST_AUTO_TEST_CASE(white_noise_is_held_and_has_intensity_s0)
{
  StochasticMotion m   = stationary_motion(false, StochasticMethod::white_noise);
  m.sample_interval    = 0.02;
  const GroundMotion g = generate_ground_motion(m);
  BOOST_TEST(g.is_held());
  // held over each interval, also where t = k dt is rounded below k dt
  for (unsigned int k = 0; k + 1 < 100; ++k)
    {
      BOOST_TEST(g.value(k * 0.02) == g.samples()[k]);
      BOOST_TEST(g.value((k + 0.7) * 0.02) == g.samples()[k]);
      BOOST_TEST(g.value(3 * (k * 0.02 / 3)) == g.samples()[k]);
    }
  // the discrete variance 2 pi S0 / dt: a flat PSD S0 up to pi / dt
  double sum = 0;
  for (const double a : g.samples())
    sum += a * a / g.samples().size();
  const double expected = 2 * M_PI * m.spectral_intensity / m.sample_interval;
  BOOST_TEST(std::abs(sum / expected - 1) < 4 * std::sqrt(2.0 / g.samples().size()));
  // the library's ensemble estimate (used by ground-motion --realizations) is flat at S0
  const EnsemblePsd psd = ensemble_psd(MotionGenerator(m), 40, 20, 1e9);
  for (std::size_t i = 0; i < psd.omega.size(); ++i)
    BOOST_TEST(std::abs(psd.estimate[i] / m.spectral_intensity - 1) < 0.15); // 800 ordinates a point: 4 sigma
}

BOOST_AUTO_TEST_CASE(white_noise_intensity_d_is_pi_s0)
{
  InputParameters input;
  input.ground_motion.type              = GroundMotionType::white_noise;
  input.ground_motion.noise_intensity_d = 0.3;
  input.ground_motion.envelope          = EnvelopeKind::none;
  input.time_integration.newmark.time_step                       = 0.01;
  const MotionGenerator g = make_motion_generator(input.ground_motion, input.time_integration.newmark.time_step);
  BOOST_TEST(g.motion().spectral_intensity == 0.3 / M_PI, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(g.held());
  BOOST_TEST(g.n_variables() == g.n_samples());
}

BOOST_AUTO_TEST_CASE(every_method_is_reproducible_from_seed_and_realization)
{
  for (const StochasticMethod method :
       {StochasticMethod::filtered_white_noise, StochasticMethod::spectral_representation,
        StochasticMethod::white_noise})
    {
      StochasticMotion m = stationary_motion(true, method);
      m.duration         = 5;
      m.realization      = 7;
      const auto a       = generate_ground_motion(m).samples();
      const auto b       = generate_ground_motion(m).samples();
      m.realization      = 8;
      const auto c       = generate_ground_motion(m).samples();
      BOOST_TEST(a == b);
      BOOST_TEST(a != c);
    }
}

BOOST_AUTO_TEST_CASE(sample_realizations_are_the_scaled_realizations_and_their_mean_square)
{
  // `ground-motion --realizations N`'s samples: realization r is the
  // generator's sample of the normals of (seed, r) (the test's own loop,
  // ensemble() above) times the scale factor, exactly (one product each);
  // the mean square is that of every sample, summed here in long double:
  // 3 x 501 terms, relative 1e-12 covers the library's double sum.
  StochasticMotion m = stationary_motion(false, StochasticMethod::filtered_white_noise);
  m.duration         = 5;
  const MotionGenerator generator(m);
  const double          scale   = 2.5;
  const MotionSamples   samples = sample_realizations(generator, 3, scale);
  const auto            plain   = ensemble(generator, 3, 0);
  BOOST_TEST_REQUIRE(samples.realizations.size() == 3u);
  long double sum = 0;
  std::size_t n   = 0;
  for (unsigned int r = 0; r < 3; ++r)
    {
      BOOST_TEST_REQUIRE(samples.realizations[r].size() == plain[r].size());
      for (std::size_t k = 0; k < plain[r].size(); ++k)
        {
          BOOST_TEST(samples.realizations[r][k] == plain[r][k] * scale);
          sum += (long double)(plain[r][k] * scale) * (plain[r][k] * scale);
          ++n;
        }
    }
  BOOST_TEST(samples.mean_square == double(sum / n), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(samples.realizations[0] != samples.realizations[1]);
}
