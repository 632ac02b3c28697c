// Probabilistic analyses against independent references:
//   - sample statistics and the type-7 quantile on hand-computed data;
//   - the lognormal maximum-likelihood fit against a brute-force grid search
//     of the same likelihood written here, and its recovery of the curve
//     from exact expected counts;
//   - Subset Simulation on g = beta - sum(u_i)/sqrt(n), n = 100, whose
//     Pf = Phi(-beta) is exact: 20 independent runs each at beta = 3.09 (1e-3)
//     and 4.26 (1e-5); their mean lies within 3 standard errors of Pf and
//     their scatter agrees with the CoV the method reports;
//   - Subset Simulation against the program's own crude Monte Carlo on the
//     linear oscillator of input/subset-drift.prm at Pf near 1e-2;
//   - the Monte Carlo estimator: the scatter of batch estimates against
//     sqrt((1 - Pf)/(N Pf));
//   - the random loading through the integrator: a linear oscillator under
//     base white noise, and under the equivalent force, against the closed-
//     form stationary variance.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/reliability/montecarlo.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/reliability/statistics.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/reliability/subset.h>
#include <poundfe/excitation/stochastic_load.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/input/input_parameters.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>

#include "test_utilities.h"

using namespace poundfe;
using poundfe_test::MpiFixture;
BOOST_GLOBAL_FIXTURE(MpiFixture);

BOOST_AUTO_TEST_CASE(sample_statistics_and_quantiles)
{
  const SampleStatistics s = describe({10, 1, 9, 2, 8, 3, 7, 4, 6, 5});
  BOOST_TEST(s.mean == 5.5);
  BOOST_TEST(s.standard_deviation == std::sqrt(82.5 / 9), boost::test_tools::tolerance(1e-15));
  BOOST_TEST(s.median == 5.5);
  // type 7: h = p (n - 1) = 1.44 -> 2 + 0.44; 7.56 -> 8 + 0.56
  BOOST_TEST(s.percentile_16 == 2.44, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s.percentile_84 == 8.56, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s.min == 1);
  BOOST_TEST(s.max == 10);
  const ProbabilityEstimate p = estimate_probability(25, 1000);
  BOOST_TEST(p.probability == 0.025);
  BOOST_TEST(p.coefficient_of_variation == std::sqrt(0.975 / 25), boost::test_tools::tolerance(1e-14));
  BOOST_TEST(std::isinf(estimate_probability(0, 10).coefficient_of_variation));
  const Histogram h = histogram({0, 0.5, 1, 1.5, 2, 3.9, 4}, 4);
  BOOST_TEST(h.counts == std::vector<unsigned long>({2, 2, 1, 2}), boost::test_tools::per_element());
  double integral = 0;
  for (std::size_t i = 0; i < 4; ++i)
    integral += h.density[i] * (h.edges[i + 1] - h.edges[i]);
  BOOST_TEST(integral == 1.0, boost::test_tools::tolerance(1e-14));
}

// Counts (numbers of impacts) get one bin per whole number, centred on it,
// or w whole numbers per bin when the range needs more than max_bins bins.
// Reference: the counts by hand. Exact.
BOOST_AUTO_TEST_CASE(count_histogram_has_bins_centred_on_whole_numbers)
{
  const std::vector<double> counts{0, 0, 1, 3, 3, 3, 7};
  const Histogram           h = count_histogram(counts, 20);
  BOOST_TEST(h.edges.size() == 9u);
  BOOST_TEST(h.edges.front() == -0.5);
  BOOST_TEST(h.edges.back() == 7.5);
  const std::vector<unsigned long> expected{2, 1, 0, 3, 0, 0, 0, 1};
  BOOST_TEST(h.counts == expected, boost::test_tools::per_element());
  BOOST_TEST(std::accumulate(h.density.begin(), h.density.end(), 0.0) == 1.0,
             boost::test_tools::tolerance(1e-15));
  const Histogram w = count_histogram(counts, 3); // 8 whole numbers in 3 bins: w = 3
  const std::vector<double>        edges{-0.5, 2.5, 5.5, 8.5};
  const std::vector<unsigned long> grouped{3, 3, 1};
  BOOST_TEST(w.edges == edges, boost::test_tools::per_element());
  BOOST_TEST(w.counts == grouped, boost::test_tools::per_element());
  BOOST_TEST(w.density[0] == 3.0 / (7 * 3), boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(lognormal_fragility_maximum_likelihood)
{
  const std::vector<double> im{0.1, 0.2, 0.3, 0.4, 0.6, 0.8};
  // exact expected counts of theta = 0.35, beta = 0.45 with 10^6 trials: the
  // MLE of the expected data is the curve itself
  std::vector<unsigned long> trials(im.size(), 1000000), failures;
  for (const double x : im)
    failures.push_back(std::lround(1e6 * standard_normal_cdf(std::log(x / 0.35) / 0.45)));
  const LognormalFragility exact = fit_lognormal_fragility(im, failures, trials);
  BOOST_TEST(exact.fitted);
  BOOST_TEST(exact.theta == 0.35, boost::test_tools::tolerance(1e-4));
  BOOST_TEST(exact.beta == 0.45, boost::test_tools::tolerance(1e-4));

  // small counts: against a grid search of the likelihood written here
  const std::vector<unsigned long> few{0, 2, 5, 6, 9, 10}, ten(im.size(), 10);
  const LognormalFragility         fit = fit_lognormal_fragility(im, few, ten);
  double best = -1e300, best_theta = 0, best_beta = 0;
  for (double theta = 0.2; theta < 0.5; theta += 0.0005)
    for (double beta = 0.1; beta < 1.2; beta += 0.0005)
      {
        double l = 0;
        for (std::size_t j = 0; j < im.size(); ++j)
          {
            const double p = standard_normal_cdf(std::log(im[j] / theta) / beta);
            l += few[j] * std::log(p) + (ten[j] - few[j]) * std::log(1 - p);
          }
        if (l > best)
          best = l, best_theta = theta, best_beta = beta;
      }
  BOOST_TEST_MESSAGE("fit theta " << fit.theta << " beta " << fit.beta << "; grid " << best_theta
                                  << " " << best_beta);
  BOOST_TEST(std::abs(fit.theta - best_theta) < 1e-3); // two grid cells
  BOOST_TEST(std::abs(fit.beta - best_beta) < 1e-3);
  BOOST_TEST(fit.log_likelihood >= best - 1e-9);
  BOOST_TEST(!fit_lognormal_fragility(im, std::vector<unsigned long>(6, 0), ten).fitted);
}

namespace
{
  /// 20 runs of Subset Simulation on the linear limit state; returns
  /// (mean estimate, scatter CoV, mean reported CoV).
  void
  check_linear_limit_state(const double beta, const unsigned int samples_per_level)
  {
    const unsigned int n = 100;
    const auto         y = [n](const std::vector<double> &u) {
      return std::accumulate(u.begin(), u.end(), 0.0) / std::sqrt(double(n));
    };
    const double exact = standard_normal_cdf(-beta);
    const unsigned int runs = 20;
    std::vector<double> estimates;
    double              reported = 0;
    for (unsigned int r = 0; r < runs; ++r)
      {
        SubsetSettings settings;
        settings.samples_per_level = samples_per_level;
        settings.seed              = 100 + r;
        const SubsetResult result  = subset_simulation(y, n, beta, settings, MPI_COMM_WORLD);
        BOOST_TEST(result.reached_threshold);
        estimates.push_back(result.probability);
        reported += result.coefficient_of_variation / runs;
        if (r == 0)
          {
            // N at level 0, then N - p0 N per further level
            const unsigned long expected_runs =
              samples_per_level + (result.levels.size() - 1) * (samples_per_level * 9 / 10);
            BOOST_TEST(result.model_runs <= expected_runs);
            BOOST_TEST(result.model_runs > expected_runs * 9 / 10); // the proposal nearly always moves
          }
      }
    const SampleStatistics s       = describe(estimates);
    const double           scatter = s.standard_deviation / s.mean;
    BOOST_TEST_MESSAGE("beta " << beta << ": Pf exact " << exact << ", mean of " << runs
                               << " estimates " << s.mean << ", scatter CoV " << scatter
                               << ", reported CoV " << reported);
    // the mean within 3 standard errors (the scatter / sqrt(runs)) of the
    // exact Pf, plus the O(1/N) bias of the method (a few %)
    BOOST_TEST(std::abs(s.mean - exact) < 3 * s.standard_deviation / std::sqrt(runs) + 0.05 * exact);
    // the reported CoV (which ignores the correlation between levels) agrees
    // with the observed scatter to a factor of 2
    BOOST_TEST(reported > 0.5 * scatter);
    BOOST_TEST(reported < 2.0 * scatter);
  }
} // namespace

BOOST_AUTO_TEST_CASE(subset_simulation_linear_limit_state_1e3)
{
  check_linear_limit_state(3.09, 1000);
}

BOOST_AUTO_TEST_CASE(subset_simulation_linear_limit_state_1e5)
{
  check_linear_limit_state(4.26, 1000);
}

BOOST_AUTO_TEST_CASE(subset_simulation_against_crude_monte_carlo_on_the_oscillator)
{
  const InputParameters input    = read_parameters("input/subset-drift.prm");
  const Analysis        analysis = prepare_analysis(input);
  RealizationRunner     runner(analysis, time_history_parameters(input));
  const double          threshold = 0.125; // Pf near 1e-2
  const unsigned int    drift     = runner.drift_columns(1)[0];

  // crude Monte Carlo through the program's own driver (realizations.csv in a temporary directory)
  const std::string directory = std::filesystem::temp_directory_path() / "poundfe-test-crude-mc";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  const unsigned long   n_mc  = 6000;
  const MonteCarloTable table = run_monte_carlo(runner, n_mc, 1.0, directory + "/realizations.csv", MPI_COMM_WORLD);
  std::filesystem::remove_all(directory);
  const std::vector<double> peaks = table.completed_values(drift);
  BOOST_TEST(peaks.size() == n_mc);
  const ProbabilityEstimate mc = estimate_probability(
    std::count_if(peaks.begin(), peaks.end(), [&](double x) { return x > threshold; }), n_mc);

  // the Monte Carlo estimator: the scatter of 30 batch estimates of 200
  // against sqrt(p (1 - p) / 200) at the 12 % level (0.1 m)
  {
    const double        b = 0.1;
    std::vector<double> batch;
    for (unsigned int k = 0; k < 30; ++k)
      batch.push_back(std::count_if(peaks.begin() + 200 * k, peaks.begin() + 200 * (k + 1),
                                    [&](double x) { return x > b; }) / 200.0);
    const SampleStatistics s = describe(batch);
    const double predicted   = std::sqrt(s.mean * (1 - s.mean) / 200);
    BOOST_TEST_MESSAGE("MC batches: p " << s.mean << ", scatter " << s.standard_deviation
                                        << ", predicted " << predicted);
    // the sample standard deviation of 30 batches has a relative error of 13 %
    BOOST_TEST(std::abs(s.standard_deviation / predicted - 1) < 0.4);
  }

  std::vector<double> responses;
  const auto          y = [&](const std::vector<double> &xi) {
    runner.run(xi, responses);
    return responses[drift];
  };
  double ss = 0, ss_variance = 0;
  unsigned int runs = 0;
  for (unsigned int r = 0; r < 3; ++r)
    {
      SubsetSettings settings;
      settings.samples_per_level = 1000;
      settings.seed              = 40 + r;
      const SubsetResult result  = subset_simulation(y, runner.n_variables(), threshold, settings, MPI_COMM_WORLD);
      ss += result.probability / 3;
      ss_variance += std::pow(result.coefficient_of_variation * result.probability / 3, 2);
      runs += result.model_runs;
    }
  const double mc_sd = mc.coefficient_of_variation * mc.probability;
  BOOST_TEST_MESSAGE("oscillator: crude MC " << mc.probability << " (CoV "
                                             << mc.coefficient_of_variation << ", " << n_mc
                                             << " runs), Subset Simulation " << ss << " (CoV "
                                             << std::sqrt(ss_variance) / ss << ", " << runs
                                             << " runs)");
  BOOST_TEST(mc.probability > 0.005);
  BOOST_TEST(mc.probability < 0.02);
  BOOST_TEST(std::abs(ss - mc.probability) < 3 * std::sqrt(ss_variance + mc_sd * mc_sd));
}

namespace
{
  /// Mean square of the storey drift over t in [10, 30] s of 400 realizations
  /// of the input's random loading (linear model).
  double
  stationary_mean_square(const InputParameters &input)
  {
    const Analysis       analysis = prepare_analysis(input);
    Excitation           excitation = make_excitation(analysis, input);
    const StochasticLoad load(input.ground_motion, input.time_integration.newmark.time_step,
                              excitation);
    NewmarkIntegrator    integrator(analysis.system, "eigen-ldlt", input.time_integration.newmark);
    const LoadFunction   p = [&](double t, Vector &f) { excitation.load(t, f); };
    std::vector<double>  xi;
    Vector               f(analysis.system.n_equations());
    double               sum = 0, count = 0;
    for (unsigned int r = 0; r < 400; ++r)
      {
        load.standard_normals(r, xi);
        load.apply(xi, excitation);
        excitation.load(0, f);
        integrator.initialize(f);
        for (unsigned int step = 1; step <= 3000; ++step)
          {
            integrator.advance(p);
            if (step > 1000)
              sum += integrator.displacement()[0] * integrator.displacement()[0], count += 1;
          }
      }
    return sum / count;
  }
} // namespace

BOOST_AUTO_TEST_CASE(white_noise_base_and_force_give_the_closed_form_variance)
{
  // One storey, m = 1000 kg, f = 1 Hz, zeta = 0.05 (input/subset-drift.prm),
  // 30 s. Base white noise S0: sigma^2 = pi S0 / (2 zeta w^3); a force of
  // intensity m^2 S0 at the floor is the same load.
  InputParameters base = read_parameters("input/subset-drift.prm");
  base.ground_motion.duration = 30;
  const double w = 2 * M_PI, zeta = 0.05, s0 = base.ground_motion.spectral_intensity;
  const double expected = M_PI * s0 / (2 * zeta * w * w * w);

  InputParameters force       = base;
  force.ground_motion.type    = GroundMotionType::none;
  force.time_integration.end_time              = 30;
  force.nodal_forces.white_noise    = {"1 1 0 ux " + std::to_string(1000.0 * 1000.0 * s0)};
  const double base_variance  = stationary_mean_square(base);
  const double force_variance = stationary_mean_square(force);
  BOOST_TEST_MESSAGE("stationary drift variance: closed form " << expected << ", base white noise "
                                                               << base_variance << ", force "
                                                               << force_variance);
  // 400 x 20 s with a correlation time 1/(zeta w) = 3.2 s: ~2500 independent
  // values, a sampling error of sqrt(2/2500) = 2.8 %; 9 % is 3.2 sigma
  BOOST_TEST(std::abs(base_variance / expected - 1) < 0.09);
  BOOST_TEST(std::abs(force_variance / expected - 1) < 0.09);
  // the same normals drive both: the two loads are one load
  BOOST_TEST(force_variance == base_variance, boost::test_tools::tolerance(1e-9));
}

namespace
{
  /// An in-memory journal: what a killed run left is a prefix of the
  /// records of an uninterrupted one.
  class MemoryJournal : public SubsetJournal
  {
  public:
    std::vector<std::array<double, 3>> records; // level, sample, response, in order
    std::map<std::pair<unsigned int, unsigned int>, double> earlier;
    unsigned int n_found = 0;

    bool find(const unsigned int level, const unsigned int sample, double &y) const override
    {
      const auto at = earlier.find({level, sample});
      if (at == earlier.end())
        return false;
      y = at->second;
      return true;
    }
    void record(const unsigned int level, const unsigned int sample, const double y) override
    {
      BOOST_TEST(!earlier.count({level, sample})); // a journalled sample is never run again
      records.push_back({double(level), double(sample), y});
    }
  };
} // namespace

// Resumability (issue 27): Subset Simulation replayed with the first k
// responses of a run taken from a journal gives the same estimate, levels
// and acceptance rates to the last bit (the algorithm is deterministic
// given the responses), and runs only the samples the journal lacks.
BOOST_AUTO_TEST_CASE(subset_simulation_resumed_from_a_partial_journal_is_bit_identical)
{
  const unsigned int n = 20;
  const auto         y = [n](const std::vector<double> &u) {
    return std::accumulate(u.begin(), u.end(), 0.0) / std::sqrt(double(n));
  };
  SubsetSettings settings;
  settings.samples_per_level       = 300;
  settings.conditional_probability = 0.15; // chains of unequal length
  settings.seed                    = 7;
  MemoryJournal      full;
  const SubsetResult reference = subset_simulation(y, n, 3.0, settings, MPI_COMM_WORLD, &full);
  BOOST_TEST_REQUIRE(reference.levels.size() >= 3u);
  BOOST_TEST(reference.model_runs == full.records.size());
  for (const double fraction : {0.0, 0.1, 0.5, 0.93, 1.0})
    {
      MemoryJournal      partial;
      const std::size_t  k = std::lround(fraction * full.records.size());
      for (std::size_t i = 0; i < k; ++i)
        partial.earlier[{unsigned(full.records[i][0]), unsigned(full.records[i][1])}] =
          full.records[i][2];
      const SubsetResult resumed = subset_simulation(y, n, 3.0, settings, MPI_COMM_WORLD, &partial);
      BOOST_TEST(resumed.probability == reference.probability); // bit-identical
      BOOST_TEST(resumed.coefficient_of_variation == reference.coefficient_of_variation);
      BOOST_TEST_REQUIRE(resumed.levels.size() == reference.levels.size());
      for (std::size_t l = 0; l < resumed.levels.size(); ++l)
        {
          BOOST_TEST(resumed.levels[l].threshold == reference.levels[l].threshold);
          BOOST_TEST(resumed.levels[l].acceptance_rate == reference.levels[l].acceptance_rate);
        }
      BOOST_TEST(resumed.resumed_runs == k);
      BOOST_TEST(resumed.model_runs == full.records.size() - k);
      BOOST_TEST(partial.records.size() == full.records.size() - k);
    }
}
