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
