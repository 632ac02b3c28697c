#include <poundfe/reliability/statistics.h>
#include <poundfe/excitation/stochastic.h>

#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>

namespace poundfe
{
  double
  quantile(const std::vector<double> &sorted, const double p)
  {
    if (sorted.empty())
      return std::numeric_limits<double>::quiet_NaN();
    const double      h = p * (sorted.size() - 1);
    const std::size_t i = static_cast<std::size_t>(std::floor(h));
    if (i + 1 >= sorted.size())
      return sorted.back();
    return sorted[i] + (h - i) * (sorted[i + 1] - sorted[i]);
  }

  ProbabilityInterval
  wilson_interval(const unsigned long k, const unsigned long n, const double confidence)
  {
    if (n == 0)
      return {0, 1};
    const double z      = boost::math::quantile(boost::math::normal(), 0.5 * (1 + confidence));
    const double p      = double(k) / n;
    const double z2n    = z * z / n;
    const double centre = (p + z2n / 2) / (1 + z2n);
    const double half   = z * std::sqrt(p * (1 - p) / n + z2n / (4 * n)) / (1 + z2n);
    // exact at the ends: k = 0 (k = n) puts the lower (upper) limit at 0 (1),
    // which centre -/+ half reaches only to round-off (2.8e-17 was printed)
    return {k == 0 ? 0.0 : std::max(0.0, centre - half), k == n ? 1.0 : std::min(1.0, centre + half)};
  }

  SampleStatistics
  describe(std::vector<double> values)
  {
    SampleStatistics s;
    s.n = values.size();
    if (values.empty())
      return s;
    std::sort(values.begin(), values.end());
    s.mean = std::accumulate(values.begin(), values.end(), 0.0) / s.n;
    double sum = 0;
    for (const double x : values)
      sum += (x - s.mean) * (x - s.mean);
    s.standard_deviation = s.n > 1 ? std::sqrt(sum / (s.n - 1)) : 0;
    s.median             = quantile(values, 0.5);
    s.percentile_16      = quantile(values, 0.16);
    s.percentile_84      = quantile(values, 0.84);
    s.min                = values.front();
    s.max                = values.back();
    return s;
  }

  ProbabilityEstimate
  estimate_probability(const unsigned long n_failures, const unsigned long n)
  {
    ProbabilityEstimate e;
    e.n_failures  = n_failures;
    e.n           = n;
    e.probability = n > 0 ? static_cast<double>(n_failures) / n : 0;
    e.coefficient_of_variation =
      n_failures > 0 ? std::sqrt((1 - e.probability) / (n * e.probability)) :
                       std::numeric_limits<double>::infinity();
    return e;
  }

  Histogram
  histogram(const std::vector<double> &values, const unsigned int bins)
  {
    Histogram h;
    if (values.empty() || bins == 0)
      return h;
    const auto [lo_it, hi_it] = std::minmax_element(values.begin(), values.end());
    double     lo = *lo_it, hi = *hi_it;
    if (!(hi > lo))
      lo -= 0.5, hi += 0.5;
    const double width = (hi - lo) / bins;
    h.edges.resize(bins + 1);
    for (unsigned int i = 0; i <= bins; ++i)
      h.edges[i] = lo + i * width;
    h.counts.assign(bins, 0);
    for (const double x : values)
      ++h.counts[std::min<unsigned int>(bins - 1, static_cast<unsigned int>((x - lo) / width))];
    h.density.resize(bins);
    for (unsigned int i = 0; i < bins; ++i)
      h.density[i] = h.counts[i] / (values.size() * width);
    return h;
  }

  Histogram
  count_histogram(const std::vector<double> &values, const unsigned int max_bins)
  {
    Histogram h;
    if (values.empty() || max_bins == 0)
      return h;
    const auto [lo_it, hi_it] = std::minmax_element(values.begin(), values.end());
    const double lo = std::round(*lo_it), hi = std::round(*hi_it);
    const double width = std::max(1.0, std::ceil((hi - lo + 1) / max_bins));
    const auto   bins  = static_cast<unsigned int>(std::ceil((hi - lo + 1) / width));
    for (unsigned int i = 0; i <= bins; ++i)
      h.edges.push_back(lo - 0.5 + i * width);
    h.counts.assign(bins, 0);
    for (const double x : values)
      ++h.counts[std::min<unsigned int>(bins - 1, (std::round(x) - lo) / width)];
    for (const unsigned long count : h.counts)
      h.density.push_back(count / (values.size() * width));
    return h;
  }

  double
  fragility(const LognormalFragility &curve, const double intensity)
  {
    return standard_normal_cdf(std::log(intensity / curve.theta) / curve.beta);
  }

  namespace
  {
    /// Negative log-likelihood at (ln theta, ln beta).
    double
    negative_log_likelihood(const std::array<double, 2>      &x,
                            const std::vector<double>        &intensity,
                            const std::vector<unsigned long> &n_failures,
                            const std::vector<unsigned long> &n_trials)
    {
      const double beta = std::exp(x[1]);
      double       sum  = 0;
      for (std::size_t j = 0; j < intensity.size(); ++j)
        {
          const double z = (std::log(intensity[j]) - x[0]) / beta;
          // log Phi(z) and log Phi(-z) from erfc keep their precision in the tails
          const double log_p = std::log(0.5 * std::erfc(-z / std::sqrt(2.0)));
          const double log_q = std::log(0.5 * std::erfc(z / std::sqrt(2.0)));
          if (n_failures[j] > 0)
            sum += n_failures[j] * log_p;
          if (n_trials[j] > n_failures[j])
            sum += (n_trials[j] - n_failures[j]) * log_q;
        }
      return std::isfinite(sum) ? -sum : std::numeric_limits<double>::max();
    }

    using Point2D = std::array<double, 2>;

    /// The minimum of a smooth unimodal `f` of two variables by Nelder-Mead
    /// (reflection -1, expansion -2, contraction ±0.5, shrink 0.5) from a
    /// simplex of sides 0.5 at `start`: the point and f there.
    template <typename Function>
    std::pair<Point2D, double>
    nelder_mead_minimum(const Function &f, const Point2D &start)
    {
      // a + t (b - a)
      auto between = [](const Point2D &a, const Point2D &b, const double t) {
        return Point2D{{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])}};
      };
      std::array<Point2D, 3> simplex{
        {start, {{start[0] + 0.5, start[1]}}, {{start[0], start[1] + 0.5}}}};
      std::array<double, 3> value{{f(simplex[0]), f(simplex[1]), f(simplex[2])}};
      for (unsigned int iteration = 0; iteration < 2000; ++iteration)
        {
          std::array<int, 3> order{{0, 1, 2}};
          std::sort(order.begin(), order.end(), [&](int a, int b) { return value[a] < value[b]; });
          const int best = order[0], middle = order[1], worst = order[2];
          if (std::abs(value[worst] - value[best]) < 1e-12 * (1 + std::abs(value[best])) &&
              std::abs(simplex[worst][0] - simplex[best][0]) +
                  std::abs(simplex[worst][1] - simplex[best][1]) <
                1e-10)
            break;
          const Point2D centroid = between(simplex[best], simplex[middle], 0.5);
          auto along = [&](const double t) { return between(centroid, simplex[worst], t); };
          const Point2D reflected = along(-1);
          const double  fr        = f(reflected);
          if (fr < value[best])
            {
              const Point2D expanded = along(-2);
              const double  fe       = f(expanded);
              simplex[worst] = fe < fr ? expanded : reflected;
              value[worst]   = std::min(fe, fr);
            }
          else if (fr < value[middle])
            simplex[worst] = reflected, value[worst] = fr;
          else
            {
              const Point2D contracted = fr < value[worst] ? along(-0.5) : along(0.5);
              const double  fc         = f(contracted);
              if (fc < std::min(fr, value[worst]))
                simplex[worst] = contracted, value[worst] = fc;
              else
                for (const int i : {middle, worst}) // shrink towards the best
                  {
                    simplex[i] = between(simplex[i], simplex[best], 0.5);
                    value[i]   = f(simplex[i]);
                  }
            }
        }
      const int best = std::min_element(value.begin(), value.end()) - value.begin();
      return {simplex[best], value[best]};
    }
  } // namespace

  LognormalFragility
  fit_lognormal_fragility(const std::vector<double>        &intensity,
                          const std::vector<unsigned long> &n_failures,
                          const std::vector<unsigned long> &n_trials)
  {
    LognormalFragility  curve;
    const unsigned long failures = std::accumulate(n_failures.begin(), n_failures.end(), 0UL);
    const unsigned long trials   = std::accumulate(n_trials.begin(), n_trials.end(), 0UL);
    if (failures == 0 || failures == trials)
      {
        curve.note = failures == 0 ? "no failure at any level" : "failure at every level";
        return curve;
      }
    // one level fixes only Phi(ln(a/theta)/beta) there: theta and beta trade
    // along a ridge and the optimiser would stop anywhere on it
    if (std::set<double>(intensity.begin(), intensity.end()).size() < 2)
      {
        curve.note = "one PGA level: theta and beta need two or more distinct levels";
        return curve;
      }
    // Start: the median at the geometric mean of the levels, beta = 0.5.
    double log_mean = 0;
    for (const double x : intensity)
      log_mean += std::log(x) / intensity.size();
    const auto [x, value] = nelder_mead_minimum(
      [&](const Point2D &p) { return negative_log_likelihood(p, intensity, n_failures, n_trials); },
      {{log_mean, std::log(0.5)}});
    curve.theta          = std::exp(x[0]);
    curve.beta           = std::exp(x[1]);
    curve.log_likelihood = -value;
    curve.fitted         = true;
    if (curve.beta < 1e-3)
      curve.note = "the levels separate failures from survivals: beta tends to zero";
    return curve;
  }
} // namespace poundfe
