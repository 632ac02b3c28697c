// Hunt and fill, the collapse fragility and the fractiles of an IDA
// (ida.h); the runner and the rounds over the ranks are in ida_runner.cc.
#include <poundfe/assessment/ida.h>
#include <poundfe/base/standard_normal.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace poundfe
{
  HuntFill::HuntFill(const Settings &settings)
    : settings(settings)
  {
    Assert(settings.initial_step > 0 && settings.upper > settings.initial_step &&
             settings.tolerance > 0,
           dealii::ExcMessage("bad hunt-and-fill settings"));
  }

  void
  HuntFill::record(const double intensity, const bool has_collapsed)
  {
    intensities.push_back(intensity);
    collapsed.push_back(has_collapsed);
  }

  std::optional<double>
  HuntFill::collapse_intensity() const
  {
    std::optional<double> lowest;
    for (std::size_t i = 0; i < intensities.size(); ++i)
      if (collapsed[i] && (!lowest || intensities[i] < *lowest))
        lowest = intensities[i];
    return lowest;
  }

  double
  HuntFill::highest_survived() const
  {
    const std::optional<double> top = collapse_intensity();
    double                      highest = 0;
    for (std::size_t i = 0; i < intensities.size(); ++i)
      if (!collapsed[i] && (!top || intensities[i] < *top))
        highest = std::max(highest, intensities[i]);
    return highest;
  }

  std::optional<double>
  HuntFill::next() const
  {
    const std::optional<double> top = collapse_intensity();
    if (!top)
      {
        const unsigned int n = intensities.size();
        if (n > 0 && intensities.back() >= settings.upper)
          return fill(); // no collapse below the upper intensity
        // x_{n+1} = (n + 1) s0 + ds n (n + 1) / 2: the steps s0 + k ds, k = 0..n
        const double x = (n + 1) * settings.initial_step + settings.step_increment * n * (n + 1) / 2;
        return std::min(x, settings.upper);
      }
    const double lowest = highest_survived();
    if (*top - lowest > settings.tolerance)
      return 0.5 * (lowest + *top);
    return fill();
  }

  std::optional<double>
  HuntFill::fill() const
  {
    if (intensities.size() >= settings.max_runs)
      return {};
    const std::optional<double> top = collapse_intensity();
    std::vector<double>         points{0.0};
    for (const double x : intensities)
      if (!top || x <= *top)
        points.push_back(x);
    std::sort(points.begin(), points.end());
    double widest = 0, from = 0;
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
      if (points[i + 1] - points[i] > widest)
        {
          widest = points[i + 1] - points[i];
          from   = points[i];
        }
    if (widest <= settings.tolerance)
      return {};
    return from + 0.5 * widest;
  }

  namespace
  {
    /// The censored lognormal log-likelihood of mu = ln theta, beta.
    double
    censored_log_likelihood(const std::vector<double> &logs, const unsigned int n_censored,
                            const double log_upper, const double mu, const double beta)
    {
      double sum = 0;
      for (const double y : logs)
        {
          const double z = (y - mu) / beta;
          sum += -0.5 * z * z - std::log(beta);
        }
      if (n_censored > 0)
        sum += n_censored * std::log(std::max(1e-300, 1 - standard_normal_cdf((log_upper - mu) / beta)));
      return sum;
    }

    /// The maximum of a unimodal f over [a, b] by golden sections: its abscissa.
    template <typename F>
    double
    golden_maximum(const F &f, double a, double b)
    {
      const double r = 0.5 * (std::sqrt(5.0) - 1);
      double       c = b - r * (b - a), d = a + r * (b - a);
      double       fc = f(c), fd = f(d);
      for (unsigned int i = 0; i < 100 && b - a > 1e-12 * (1 + std::abs(a)); ++i)
        if (fc >= fd)
          {
            b = d, d = c, fd = fc;
            c  = b - r * (b - a);
            fc = f(c);
          }
        else
          {
            a = c, c = d, fc = fd;
            d  = a + r * (b - a);
            fd = f(d);
          }
      return 0.5 * (a + b);
    }
  } // namespace

  CollapseFragility
  fit_collapse_fragility(const std::vector<double> &collapse, const unsigned int n_censored,
                         const double upper)
  {
    CollapseFragility fit;
    fit.n_collapsed = collapse.size();
    fit.n_censored  = n_censored;
    if (collapse.size() < 2)
      {
        fit.note = "fewer than two records collapsed: no fit";
        return fit;
      }
    std::vector<double> logs;
    double              mean = 0;
    for (const double x : collapse)
      logs.push_back(std::log(x)), mean += logs.back() / collapse.size();
    double variance = 0;
    for (const double y : logs)
      variance += (y - mean) * (y - mean) / logs.size();
    fit.theta  = std::exp(mean);
    fit.beta   = std::sqrt(variance);
    fit.fitted = fit.beta > 0;
    if (!fit.fitted)
      fit.note = "every collapse intensity is the same: no dispersion";
    if (n_censored == 0 || !fit.fitted)
      return fit;
    const double log_upper = std::log(upper);
    double       best_mu   = mean;
    auto         profile   = [&](const double log_beta) {
      const double beta = std::exp(log_beta);
      auto         in_mu = [&](const double mu) {
        return censored_log_likelihood(logs, n_censored, log_upper, mu, beta);
      };
      best_mu = golden_maximum(in_mu, mean - 10 * fit.beta - 10, log_upper + 10 * fit.beta + 10);
      return in_mu(best_mu);
    };
    const double log_beta = golden_maximum(profile, std::log(fit.beta) - 5, std::log(fit.beta) + 5);
    profile(log_beta);
    fit.theta = std::exp(best_mu);
    fit.beta  = std::exp(log_beta);
    fit.note  = std::to_string(n_censored) + " record(s) censored at the upper intensity";
    return fit;
  }

  double
  empirical_quantile(std::vector<double> values, const double p)
  {
    Assert(!values.empty() && p >= 0 && p <= 1, dealii::ExcMessage("bad quantile"));
    std::sort(values.begin(), values.end());
    const double      h = (values.size() - 1) * p;
    const std::size_t i = static_cast<std::size_t>(std::floor(h));
    if (i + 1 >= values.size())
      return values.back();
    if (h == i)
      return values[i];
    if (std::isinf(values[i + 1]))
      return std::numeric_limits<double>::infinity();
    return values[i] + (h - i) * (values[i + 1] - values[i]);
  }
} // namespace poundfe
