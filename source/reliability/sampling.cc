// Equations and sources: include/poundfe/reliability/sampling.h.
#include <poundfe/base/interruption.h>
#include <poundfe/base/numbers.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/reliability/sampling.h>

#include <cmath>
#include <limits>

namespace poundfe
{
  namespace
  {
    /// Sums of the sample values y_i (indicator times weight) and of y_i^2.
    struct Moments
    {
      double sum = 0, sum_squares = 0;
      unsigned long n = 0, n_failures = 0;

      void add(const bool failed, const double weight)
      {
        ++n;
        if (failed)
          {
            ++n_failures;
            sum += weight;
            sum_squares += weight * weight;
          }
      }
      double mean() const { return n > 0 ? sum / n : 0; }
      /// COV of the mean: s/(sqrt(n) mean), s the sample standard deviation.
      double cov() const
      {
        if (n_failures == 0)
          return std::numeric_limits<double>::infinity();
        const double m = mean(), variance = (sum_squares / n - m * m) * n / std::max(n - 1.0, 1.0);
        return std::sqrt(std::max(variance, 0.0) / n) / m;
      }
      bool done(const SamplingSettings &s) const
      {
        return s.target_cov > 0 && n % 1000 == 0 && n_failures > 0 && cov() <= s.target_cov;
      }
    };

    SamplingResult
    result_of(const Moments &m, const StandardSpaceLimitStates &G, const bool interrupted)
    {
      return {m.mean(), m.cov(), m.n, m.n_failures, G.n_evaluations(), interrupted};
    }
  } // namespace

  SamplingResult
  monte_carlo(const ReliabilityProblem &problem, const SamplingSettings &settings)
  {
    const StandardSpaceLimitStates G(problem);
    NormalStream                   random(settings.seed, 0);
    std::vector<double>            u(G.n_variables());
    Moments                        m;
    bool                           interrupted = false;
    while (m.n < settings.max_samples && !m.done(settings))
      {
        if (m.n % 4096 == 0 && (interrupted = interruption_requested()))
          break;
        for (double &x : u)
          x = random.next();
        m.add(G.system_value(u) <= 0, 1.0);
      }
    SamplingResult result = result_of(m, G, interrupted);
    // the binomial form, exact for the indicator: sqrt((1 - p)/(N p))
    if (m.n_failures > 0)
      result.coefficient_of_variation =
        std::sqrt((1 - result.probability) / (m.n * result.probability));
    return result;
  }

  SamplingResult
  importance_sampling(const ReliabilityProblem              &problem,
                      const std::vector<std::vector<double>> &design_points,
                      const SamplingSettings                 &settings)
  {
    const StandardSpaceLimitStates G(problem);
    NormalStream                   random(settings.seed, 1);
    const std::size_t              n_centres = design_points.size();
    std::vector<double>            u(G.n_variables()), half_norm2(n_centres);
    for (std::size_t k = 0; k < n_centres; ++k)
      half_norm2[k] = 0.5 * dot(design_points[k], design_points[k]);
    Moments m;
    bool    interrupted = false;
    while (m.n < settings.max_samples && !m.done(settings))
      {
        if (m.n % 4096 == 0 && (interrupted = interruption_requested()))
          break;
        const std::vector<double> &centre = design_points[m.n % n_centres];
        for (std::size_t i = 0; i < u.size(); ++i)
          u[i] = centre[i] + random.next();
        const bool failed = G.system_value(u) <= 0;
        double     weight = 0;
        if (failed)
          {
            double mixture = 0;
            for (std::size_t k = 0; k < n_centres; ++k)
              mixture += std::exp(dot(u, design_points[k]) - half_norm2[k]);
            weight = n_centres / mixture;
          }
        m.add(failed, weight);
      }
    return result_of(m, G, interrupted);
  }

  std::string
  form_disagreement(const double form_probability, const SamplingResult &is)
  {
    const std::string samples = std::to_string(is.n_samples) + " samples around the design point";
    if (is.n_failures == 0)
      return "importance sampling found no failure in " + samples + ": FORM's Pf = " +
             number_text(form_probability) + " is not confirmed (the design point may be "
             "wrong or one of several)";
    const double error = is.coefficient_of_variation * is.probability;
    if (std::abs(form_probability - is.probability) <= 3 * error)
      return "";
    return "FORM's Pf = " + number_text(form_probability) + " and importance sampling's Pf = " +
           number_text(is.probability) + " (CoV " + number_text(is.coefficient_of_variation) +
           ", " + samples + ") differ by more than three standard errors: the limit state is "
           "too nonlinear near the design point for FORM (or the design point is one of "
           "several); the sampling estimate is the one to trust";
  }
} // namespace poundfe
