// Density estimation (reliability/density.h) against independent references:
//   - the binned kernel density of exact N(0, 1) bin probabilities against
//     the N(0, 1 + h^2 + w^2/12) density (the convolution of the Gaussian
//     with the kernel and with the binning's uniform error), to 2e-3 of the peak;
//   - it integrates to the fraction of samples in the range (1e-9);
//   - binned quantiles of uniform counts: linear in p (exact);
//   - Silverman's rule against its formula evaluated by hand;
//   - peaks of a two-Gaussian mixture at +-1.5 (1 % of the peak between
//     grid points), none from noise below the threshold, one of a Gaussian.
#include <poundfe/reliability/density.h>

#include <array>
#include <cmath>

#include <boost/test/unit_test.hpp>

using namespace poundfe;

namespace
{
  double
  normal_pdf(const double x, const double variance)
  {
    return std::exp(-x * x / (2 * variance)) / std::sqrt(2 * M_PI * variance);
  }

  /// N * P(bin) of N(mean, 1) on the grid.
  std::vector<double>
  exact_counts(const BinGrid &grid, const double n, const double mean)
  {
    std::vector<double> counts(grid.n_bins);
    for (unsigned int i = 0; i < grid.n_bins; ++i)
      {
        const double a = grid.low + i * grid.width() - mean, b = a + grid.width();
        counts[i] = n * 0.5 * (std::erf(b / std::sqrt(2.0)) - std::erf(a / std::sqrt(2.0)));
      }
    return counts;
  }
} // namespace

BOOST_AUTO_TEST_CASE(binned_kernel_density_of_a_gaussian)
{
  const BinGrid             grid{-8, 8, 160};
  const double              h      = 0.3;
  const std::vector<double> counts = exact_counts(grid, 1e6, 0);
  const std::vector<double> f      = kernel_density(grid, counts, 1e6, h);
  const double              var    = 1 + h * h + grid.width() * grid.width() / 12;
  double                    worst = 0, integral = 0;
  for (unsigned int i = 0; i < grid.n_bins; ++i)
    {
      worst = std::max(worst, std::abs(f[i] - normal_pdf(grid.center(i), var)));
      integral += f[i] * grid.width();
    }
  BOOST_TEST(worst < 2e-3 * normal_pdf(0, var));
  BOOST_TEST(integral == 1.0, boost::test_tools::tolerance(1e-9));
  const std::vector<double> p = histogram_density(grid, counts, 1e6);
  BOOST_TEST(p[80] * grid.width() * 1e6 == counts[80], boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(binned_quantiles_and_silverman)
{
  const BinGrid             grid{0, 10, 10};
  const std::vector<double> counts(10, 5.0);
  for (const double p : {0.1, 0.25, 0.5, 0.73})
    BOOST_TEST(binned_quantile(grid, counts, 0, 50, p) == 10 * p,
               boost::test_tools::tolerance(1e-12));
  // 10 below the grid: p = 0.5 of 60 is the 30th, 20 into the grid
  BOOST_TEST(binned_quantile(grid, counts, 10, 60, 0.5) == 4.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(silverman_bandwidth(2.0, 1.34, 100000) == 0.9 * 1.0 * 0.1,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(silverman_bandwidth(1.0, 2.68, 32) == 0.9 * 0.5, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(peaks_of_a_mixture_and_of_noise)
{
  const BinGrid       grid{-5, 5, 201};
  std::vector<double> f(grid.n_bins);
  for (unsigned int i = 0; i < grid.n_bins; ++i)
    {
      const double x = grid.center(i);
      // 4 % ripple: local maxima too small to count at a 5 % threshold
      f[i] = 0.5 * normal_pdf(x - 1.5, 0.25) + 0.5 * normal_pdf(x + 1.5, 0.25) +
             0.04 * 0.4 * (1 + std::cos(25 * x)) / 2;
    }
  const std::vector<Peak> peaks = find_peaks(grid, f, 0.05);
  BOOST_TEST_REQUIRE(peaks.size() == 2U);
  BOOST_TEST(std::abs(peaks[0].location + 1.5) <= grid.width());
  BOOST_TEST(std::abs(peaks[1].location - 1.5) <= grid.width());
  BOOST_TEST(find_peaks(grid, f, 0.01).size() > 2U); // the ripple counts at 1 %
  std::vector<double> g(grid.n_bins);
  for (unsigned int i = 0; i < grid.n_bins; ++i)
    g[i] = normal_pdf(grid.center(i), 1);
  BOOST_TEST(find_peaks(grid, g, 0.05).size() == 1U);
  BOOST_TEST(grid.bin(-5.1) == -1);
  BOOST_TEST(grid.bin(5.0) == 201);
  BOOST_TEST(grid.bin(0.0) == 100);
}

BOOST_AUTO_TEST_CASE(peaks_are_located_between_grid_points)
{
  // N(1.037, 0.5^2) on a grid of width 0.1 (centres at 0.05 + 0.1 k): the
  // nearest centre is 0.13 widths off the mode; the parabola through the
  // three highest points puts it within 0.005 widths (measured 1.2e-3; the
  // vertex of a parabola fitted to a Gaussian errs by O(w^3 / sigma^2)) and
  // its height within 1e-4 of the mode's density.
  const BinGrid       grid{-4, 6, 100};
  const double        mean = 1.037, variance = 0.25;
  std::vector<double> f(grid.n_bins);
  for (unsigned int i = 0; i < grid.n_bins; ++i)
    f[i] = normal_pdf(grid.center(i) - mean, variance);
  const std::vector<Peak> peaks = find_peaks(grid, f, 0.05);
  BOOST_TEST_REQUIRE(peaks.size() == 1U);
  BOOST_TEST(std::abs(grid.center(peaks[0].index) - mean) > 0.1 * grid.width());
  BOOST_TEST(std::abs(peaks[0].location - mean) < 0.005 * grid.width());
  BOOST_TEST(std::abs(peaks[0].height - normal_pdf(0, variance)) < 1e-4 * normal_pdf(0, variance));
}

namespace
{
  /// The AMISE-optimal Gaussian-kernel bandwidth [R(K) / (N psi4)]^(1/5) of
  /// a normal mixture (weight, mean, sigma), psi4 = int f''^2 in closed form:
  /// sum_ij w_i w_j phi4_{s_i^2 + s_j^2}(mu_i - mu_j) (Marron & Wand 1992,
  /// Ann. Statist. 20, 712-736, Theorem 4.1; Wand & Jones 1995, §2.6).
  double
  amise_bandwidth(const std::vector<std::array<double, 3>> &mixture, const double n)
  {
    double psi4 = 0;
    for (const auto &[wi, mi, si] : mixture)
      for (const auto &[wj, mj, sj] : mixture)
        {
          const double v = si * si + sj * sj, x = mi - mj;
          psi4 += wi * wj * (x * x * x * x / (v * v * v * v) - 6 * x * x / (v * v * v) + 3 / (v * v)) *
                  normal_pdf(x, v);
        }
    return std::pow(1 / (2 * std::sqrt(M_PI)) / (n * psi4), 0.2);
  }

  /// N times each bin's probability under the mixture.
  std::vector<double>
  mixture_counts(const BinGrid &grid, const std::vector<std::array<double, 3>> &mixture,
                 const double n)
  {
    std::vector<double> counts(grid.n_bins, 0.0);
    for (unsigned int i = 0; i < grid.n_bins; ++i)
      for (const auto &[w, m, s] : mixture)
        {
          const double a = (grid.low + i * grid.width() - m) / (s * std::sqrt(2.0));
          const double b = a + grid.width() / (s * std::sqrt(2.0));
          counts[i] += n * w * 0.5 * (std::erf(b) - std::erf(a));
        }
    return counts;
  }
} // namespace

BOOST_AUTO_TEST_CASE(sheather_jones_finds_the_amise_bandwidth_of_a_bimodal_density)
{
  // Two well separated modes, 0.5 N(-1.5, 0.25) + 0.5 N(1.5, 0.25), as the
  // exact bin probabilities of N = 1e6 samples on 400 bins. Reference: the
  // AMISE-optimal bandwidth in closed form (above). Sheather-Jones's
  // relative error falls as N^(-5/14) (Sheather & Jones 1991, §4; 7e-3 at
  // N = 1e6 times a constant of order 1, plus the pilots' bias): tolerance
  // 3 % (measured 1.7 %). Silverman's rule sees one wide normal and is 2.3
  // times too wide, which merges the modes of smaller samples; a single
  // N(0, 1) checks the plug-in against its normal reference 1.06 N^(-1/5).
  const BinGrid                           grid{-5, 5, 400};
  const double                            n = 1e6;
  const std::vector<std::array<double, 3>> bimodal{{{0.5, -1.5, 0.5}}, {{0.5, 1.5, 0.5}}};
  const std::vector<double>               counts = mixture_counts(grid, bimodal, n);
  const double iqr = binned_quantile(grid, counts, 0, n, 0.75) - binned_quantile(grid, counts, 0, n, 0.25);
  const double h   = sheather_jones_bandwidth(grid, counts, iqr);
  const double h_opt = amise_bandwidth(bimodal, n);
  BOOST_TEST_MESSAGE("Sheather-Jones " << h << ", AMISE-optimal " << h_opt);
  BOOST_TEST(std::abs(h / h_opt - 1) < 0.03);
  const double sigma = std::sqrt(0.25 + 1.5 * 1.5);
  BOOST_TEST(silverman_bandwidth(sigma, iqr, n) > 2 * h_opt);

  const std::vector<std::array<double, 3>> normal{{{1.0, 0.0, 1.0}}};
  const std::vector<double>                single = mixture_counts(grid, normal, n);
  const double iqr1 = binned_quantile(grid, single, 0, n, 0.75) - binned_quantile(grid, single, 0, n, 0.25);
  BOOST_TEST(std::abs(sheather_jones_bandwidth(grid, single, iqr1) / amise_bandwidth(normal, n) - 1) < 0.03);
  // too few samples, or no spread: no bandwidth
  BOOST_TEST(std::isnan(sheather_jones_bandwidth(grid, std::vector<double>(400, 0.0), 1.0)));
  BOOST_TEST(std::isnan(sheather_jones_bandwidth(grid, counts, 0.0)));
}

// The support of the kernel density of a uniform density on two blocks
// against its closed form: f(b + d) = f_0 Φ(-d/h) outside a block's end b
// (f_0 = 1/2 inside each block of [0, 1] ∪ [2, 3]; the other block, 20 h
// away, adds < 1e-80), so with threshold 1e-3 the support ends at
// b ± h Φ⁻¹(0.999), Φ⁻¹(0.999) = 3.090232306167813 (published tables).
// The counts are exact (bin edges on the blocks' ends). Tolerance 0.1 bin
// widths: the ends are interpolated linearly between bin centres on the
// Gaussian tail, whose curvature over one bin (w/h = 0.1) moves them by a
// few hundredths of a bin (measured 0.024). Blocks 0.2 apart
// (2 h from the gap's middle, where f = Φ(-2) = 0.023 > 5e-4) give one
// interval; with a threshold of 0.6 (above f_0/2, f at a block's end) each
// interval lies inside its block, ending h Φ⁻¹(0.6) = 0.2533471031357997 h
// inside it.
BOOST_AUTO_TEST_CASE(support_of_two_uniform_blocks)
{
  const BinGrid grid{-1, 4, 1000};
  const double  h = 0.05, n = 1e6, z = 3.090232306167813;
  const auto    blocks = [&](const double second) {
    std::vector<double> counts(grid.n_bins, 0.0);
    for (unsigned int i = 0; i < grid.n_bins; ++i)
      {
        const double x = grid.center(i);
        if ((x > 0 && x < 1) || (x > second && x < second + 1))
          counts[i] = n * 0.5 * grid.width();
      }
    return kernel_density(grid, counts, n, h);
  };
  const std::vector<SupportInterval> apart = density_support(grid, blocks(2), 1e-3);
  BOOST_TEST_REQUIRE(apart.size() == 2u);
  const std::array<double, 4> want{{-h * z, 1 + h * z, 2 - h * z, 3 + h * z}};
  const std::array<double, 4> got{{apart[0].low, apart[0].high, apart[1].low, apart[1].high}};
  for (unsigned int k = 0; k < 4; ++k)
    BOOST_TEST(std::abs(got[k] - want[k]) < 0.1 * grid.width(), "end " << k << ": " << got[k]
                                                                     << " against " << want[k]);
  BOOST_TEST(density_support(grid, blocks(1.2), 1e-3).size() == 1u);
  const std::vector<SupportInterval> core = density_support(grid, blocks(2), 0.6);
  BOOST_TEST_REQUIRE(core.size() == 2u);
  const double inside = 0.2533471031357997 * h;
  BOOST_TEST(std::abs(core[0].low - inside) < 0.1 * grid.width());
  BOOST_TEST(std::abs(core[1].high - (3 - inside)) < 0.1 * grid.width());
  // nothing above a threshold of a density that is zero everywhere
  BOOST_TEST(density_support(grid, std::vector<double>(grid.n_bins, 0.0), 1e-3).empty());
}
