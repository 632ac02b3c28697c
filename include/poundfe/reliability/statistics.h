// Sample statistics and estimators of the probabilistic analyses.
//   Quantiles: linear interpolation between order statistics (Hyndman & Fan
//     1996, type 7, as R and NumPy by default).
//   Monte Carlo: Pf = n_f / N, CoV = sqrt((1 - Pf) / (N Pf)).
//   Wilson score interval of a binomial proportion p = k / n at confidence
//     c, z = Phi^-1((1 + c) / 2): (p + z^2/(2n) -+ z sqrt(p(1 - p)/n +
//     z^2/(4n^2))) / (1 + z^2/n) (Wilson 1927, JASA 22(158); Brown, Cai &
//     DasGupta 2001, Statistical Science 16(2)).
//   Fragility: P(fail | x) = Phi(ln(x / theta) / beta), theta and beta by
//     maximum likelihood over binomial counts (Shinozuka et al. 2000;
//     Baker 2015, Earthquake Spectra 31(1)).
#ifndef poundfe_reliability_statistics_h
#define poundfe_reliability_statistics_h

#include <string>
#include <vector>

namespace poundfe
{
  struct SampleStatistics
  {
    unsigned long n    = 0;
    double        mean = 0, standard_deviation = 0; // unbiased (N - 1)
    double        median = 0, percentile_16 = 0, percentile_84 = 0;
    double        min = 0, max = 0;
  };

  /// Quantile p in [0, 1] of ascending values (type 7).
  double quantile(const std::vector<double> &sorted, double p);

  SampleStatistics describe(std::vector<double> values);

  struct ProbabilityEstimate
  {
    unsigned long n_failures = 0, n = 0;
    double        probability = 0;
    double        coefficient_of_variation = 0; // infinite when no failure was seen
  };

  ProbabilityEstimate estimate_probability(unsigned long n_failures, unsigned long n);

  /// Confidence interval [lower, upper] of a probability.
  struct ProbabilityInterval
  {
    double lower = 0, upper = 1;
  };

  /// Wilson score interval of k successes in n > 0 trials at `confidence` in (0, 1).
  ProbabilityInterval wilson_interval(unsigned long k, unsigned long n, double confidence);

  struct Histogram
  {
    std::vector<double>        edges;   // bins + 1
    std::vector<unsigned long> counts;  // bins
    std::vector<double>        density; // count / (N width): integrates to 1
  };

  /// Equal-width bins over [min, max] (a single value gets a unit-width bin).
  Histogram histogram(const std::vector<double> &values, unsigned int bins);

  /// Bins for whole numbers (counts): each bin holds w consecutive integers,
  /// edges half-way between integers, w = 1 unless the range needs more than
  /// `max_bins` bins.
  Histogram count_histogram(const std::vector<double> &values, unsigned int max_bins);

  struct LognormalFragility
  {
    double theta = 0, beta = 0; // median and logarithmic standard deviation
    double log_likelihood = 0;
    bool   fitted = false;      // false: all or no failures, no finite estimate
    std::string note;
  };

  /// Maximum-likelihood lognormal fragility from n_failures[j] of n_trials[j] at
  /// intensity[j] > 0.
  LognormalFragility fit_lognormal_fragility(const std::vector<double>        &intensity,
                                             const std::vector<unsigned long> &n_failures,
                                             const std::vector<unsigned long> &n_trials);

  /// Fragility value Phi(ln(x / theta) / beta).
  double fragility(const LognormalFragility &curve, double intensity);
} // namespace poundfe

#endif
