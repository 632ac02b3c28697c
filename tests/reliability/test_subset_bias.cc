// Subset Simulation over many seeds against a closed-form failure
// probability: Y = sum(u_i)/sqrt(n) of n = 10 standard normals is itself a
// standard normal, so Pf = P(Y > beta) = Phi(-beta) exactly (beta = 3.2:
// Pf = 6.87e-4). At p0 = 0.1, 0.15, 0.3 and 1/3 with N = 2000 samples per
// level (N/round(p0 N) = 10, 6.67, 3.33 and 2.999: chains of unequal length
// in three cases, p0 N not whole at p0 = 1/3), 200 runs each (seeds 1..200):
//   - the mean estimate lies within two standard errors (the runs' scatter
//     / sqrt(200)) of Phi(-beta): no bias from the chains of unequal length
//     (N = 2000 keeps the method's own O(1/N) bias, from the correlation of
//     the levels' estimates, near 1 %, below the standard error of 1.3 %);
//   - the runs' scatter (their CoV) lies between the mean reported lower
//     bound (levels uncorrelated) and upper bound (levels fully correlated),
//     each widened by three standard errors of a sample standard deviation
//     of 200 runs (from the runs' kurtosis).
#include <poundfe/base/standard_normal.h>
#include <poundfe/reliability/subset.h>

#include <cmath>
#include <numeric>
#include <vector>

#include <boost/test/unit_test.hpp>

using namespace poundfe;

namespace
{
  struct SubsetCampaign
  {
    double mean = 0, standard_error = 0; // of the estimates
    double scatter = 0;                  // their CoV
    double scatter_error = 0;            // relative standard error of `scatter`
    double lower = 0, upper = 0;         // mean reported CoV bounds
  };

  SubsetCampaign
  subset_campaign(const double p0, const unsigned int samples_per_level, const double beta,
                  const unsigned int runs)
  {
    const unsigned int n = 10;
    const auto         y = [](const std::vector<double> &u) {
      return std::accumulate(u.begin(), u.end(), 0.0) / std::sqrt(double(n));
    };
    std::vector<double> estimates;
    SubsetCampaign      c;
    for (unsigned int r = 1; r <= runs; ++r)
      {
        SubsetSettings settings;
        settings.samples_per_level       = samples_per_level;
        settings.conditional_probability = p0;
        settings.max_levels              = 20;
        settings.seed                    = r;
        const SubsetResult result = subset_simulation(y, n, beta, settings, MPI_COMM_WORLD);
        BOOST_TEST_REQUIRE(result.reached_threshold);
        estimates.push_back(result.probability);
        c.lower += result.coefficient_of_variation / runs;
        c.upper += result.coefficient_of_variation_upper_bound / runs;
      }
    double m2 = 0, m4 = 0;
    c.mean = std::accumulate(estimates.begin(), estimates.end(), 0.0) / runs;
    for (const double p : estimates)
      m2 += std::pow(p - c.mean, 2) / runs, m4 += std::pow(p - c.mean, 4) / runs;
    const double sd = std::sqrt(m2 * runs / (runs - 1));
    c.standard_error = sd / std::sqrt(double(runs));
    c.scatter        = sd / c.mean;
    // Var(s^2) = (m4 - s^4)/runs, so s has the relative error sqrt((m4/s^4 - 1)/(4 runs))
    c.scatter_error = std::sqrt((m4 / (m2 * m2) - 1) / (4.0 * runs));
    return c;
  }

  void
  check_subset_campaign(const double p0)
  {
    const double         beta = 3.2, exact = standard_normal_cdf(-beta);
    const unsigned int   runs = 200;
    const SubsetCampaign c    = subset_campaign(p0, 2000, beta, runs);
    const double         margin = 3 * c.scatter_error;
    BOOST_TEST_MESSAGE("p0 " << p0 << ", N 2000, " << runs << " runs: mean/exact " << c.mean / exact
                             << " (2 standard errors " << 2 * c.standard_error / exact
                             << "), scatter CoV " << c.scatter << " (+-" << margin
                             << "), reported CoV bounds " << c.lower << " .. " << c.upper);
    BOOST_TEST(std::abs(c.mean - exact) <= 2 * c.standard_error);
    BOOST_TEST(c.scatter >= c.lower * (1 - margin));
    BOOST_TEST(c.scatter <= c.upper * (1 + margin));
  }
} // namespace

BOOST_AUTO_TEST_CASE(subset_simulation_unbiased_at_p0_0_1)
{
  check_subset_campaign(0.1);
}

BOOST_AUTO_TEST_CASE(subset_simulation_unbiased_at_p0_0_15)
{
  check_subset_campaign(0.15);
}

BOOST_AUTO_TEST_CASE(subset_simulation_unbiased_at_p0_0_3)
{
  check_subset_campaign(0.3);
}

BOOST_AUTO_TEST_CASE(subset_simulation_unbiased_at_p0_one_third)
{
  check_subset_campaign(1.0 / 3);
}
