// Equations and sources: include/poundfe/reliability/distribution.h.
#include <poundfe/base/numbers.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/reliability/distribution.h>

#include <deal.II/base/exceptions.h>

#include <boost/math/distributions/extreme_value.hpp>
#include <boost/math/distributions/lognormal.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/uniform.hpp>
#include <boost/math/distributions/weibull.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <stdexcept>

namespace poundfe
{
  namespace
  {
    const std::vector<std::pair<DistributionType, std::string>> names = {
      {DistributionType::normal, "normal"},
      {DistributionType::lognormal, "lognormal"},
      {DistributionType::uniform, "uniform"},
      {DistributionType::truncated_normal, "truncated normal"},
      {DistributionType::gumbel, "Gumbel"},
      {DistributionType::weibull, "Weibull"}};

    /// |u| beyond which Phi(u) rounds to 0 or 1 in double precision.
    constexpr double u_limit = 37.5;

    const boost::math::normal standard_normal;

    /// Weibull COV of shape k: sqrt(Gamma(1 + 2/k)/Gamma(1 + 1/k)^2 - 1).
    double
    weibull_cov(const double k)
    {
      const double g1 = std::tgamma(1 + 1 / k);
      return std::sqrt(std::tgamma(1 + 2 / k) / (g1 * g1) - 1);
    }

    /// Shape of the Weibull distribution with coefficient of variation `cov`
    /// (decreasing in k: bisection in ln k over [0.02, 500], COV 0.002..~5e2).
    double
    weibull_shape(const double cov)
    {
      double lo = std::log(0.02), hi = std::log(500.0);
      if (!(cov < weibull_cov(std::exp(lo)) && cov > weibull_cov(std::exp(hi))))
        throw std::invalid_argument("a Weibull COV must lie in (" +
                                    std::to_string(weibull_cov(std::exp(hi))) + ", " +
                                    std::to_string(weibull_cov(std::exp(lo))) + ")");
      for (int i = 0; i < 200 && hi - lo > 1e-15; ++i)
        {
          const double mid = 0.5 * (lo + hi);
          (weibull_cov(std::exp(mid)) > cov ? lo : hi) = mid;
        }
      return std::exp(0.5 * (lo + hi));
    }

    void
    require(const bool condition, const std::string &problem)
    {
      if (!condition)
        throw std::invalid_argument(problem);
    }
  } // namespace

  const std::string &
  distribution_name(const DistributionType type)
  {
    for (const auto &[t, name] : names)
      if (t == type)
        return name;
    throw std::logic_error("a distribution without a name");
  }

  DistributionType
  distribution_type(const std::string &name)
  {
    std::string choices;
    for (const auto &[t, n] : names)
      {
        if (n == name)
          return t;
        choices += (choices.empty() ? "'" : ", '") + n + "'";
      }
    throw std::invalid_argument("unknown distribution '" + name + "' (one of " + choices + ")");
  }

  double
  standard_normal_quantile(const double p)
  {
    if (p <= 0)
      return -u_limit;
    if (p >= 1)
      return u_limit;
    return boost::math::quantile(standard_normal, p);
  }

  Distribution::Distribution(const DistributionType type, std::vector<double> parameters)
    : kind(type)
    , native(std::move(parameters))
  {}

  Distribution
  Distribution::from_native(const DistributionType type, const std::vector<double> &p)
  {
    const std::size_t n_parameters = type == DistributionType::truncated_normal ? 4 : 2;
    require(p.size() == n_parameters, distribution_name(type) + " takes " +
                                        std::to_string(n_parameters) + " parameters");
    for (const double x : p)
      require(std::isfinite(x), "a parameter is not a finite number");
    switch (type)
      {
        case DistributionType::normal:
          require(p[1] > 0, "the standard deviation sigma must be > 0");
          break;
        case DistributionType::lognormal:
          require(p[1] > 0, "zeta (the standard deviation of ln X) must be > 0");
          break;
        case DistributionType::uniform:
          require(p[0] < p[1], "the lower bound must be below the upper bound");
          break;
        case DistributionType::truncated_normal:
          require(p[1] > 0, "the parent's standard deviation sigma must be > 0");
          require(p[2] < p[3], "the lower bound must be below the upper bound");
          require(standard_normal_cdf((p[3] - p[0]) / p[1]) -
                      standard_normal_cdf((p[2] - p[0]) / p[1]) > 1e-300,
                  "the bounds hold no probability of the parent normal");
          break;
        case DistributionType::gumbel:
        case DistributionType::weibull:
          require(p[1] > 0, "the scale must be > 0");
          if (type == DistributionType::weibull)
            require(p[0] > 0, "the shape must be > 0");
          break;
      }
    return Distribution(type, p);
  }

  Distribution
  Distribution::from_moments(const DistributionType type, const double mean, const double sd)
  {
    require(std::isfinite(mean) && std::isfinite(sd), "the mean and the standard deviation must "
                                                      "be finite numbers");
    // the mean first: a COV times a mean of 0 gives sd = 0, whose message
    // would blame the standard deviation for the mean
    if (type == DistributionType::lognormal || type == DistributionType::weibull)
      require(mean > 0, std::string("a ") +
                          (type == DistributionType::lognormal ? "lognormal" : "Weibull") +
                          " mean must be > 0 (its values are positive), got " +
                          number_text(mean));
    require(sd > 0, "the standard deviation must be > 0");
    switch (type)
      {
        case DistributionType::normal:
          return from_native(type, {mean, sd});
          case DistributionType::lognormal: {
            require(mean > 0, "a lognormal mean must be > 0");
            const double zeta2 = std::log1p((sd / mean) * (sd / mean));
            return from_native(type, {std::log(mean) - 0.5 * zeta2, std::sqrt(zeta2)});
          }
        case DistributionType::uniform:
          return from_native(type, {mean - std::sqrt(3.0) * sd, mean + std::sqrt(3.0) * sd});
        case DistributionType::truncated_normal:
          throw std::invalid_argument("a truncated normal takes its native parameters "
                                      "(mu, sigma, lower, upper), not a mean and a COV");
          case DistributionType::gumbel: {
            const double scale = sd * std::sqrt(6.0) / M_PI;
            return from_native(type, {mean - boost::math::constants::euler<double>() * scale, scale});
          }
          case DistributionType::weibull: {
            require(mean > 0, "a Weibull mean must be > 0");
            const double k = weibull_shape(sd / mean);
            return from_native(type, {k, mean / std::tgamma(1 + 1 / k)});
          }
      }
    throw std::logic_error("unknown distribution type");
  }

  double
  Distribution::mean() const
  {
    const std::vector<double> &p = native;
    switch (kind)
      {
        case DistributionType::normal:
          return p[0];
        case DistributionType::lognormal:
          return std::exp(p[0] + 0.5 * p[1] * p[1]);
        case DistributionType::uniform:
          return 0.5 * (p[0] + p[1]);
          case DistributionType::truncated_normal: {
            const double a = (p[2] - p[0]) / p[1], b = (p[3] - p[0]) / p[1];
            const double z = standard_normal_cdf(b) - standard_normal_cdf(a);
            return p[0] + p[1] * (standard_normal_pdf(a) - standard_normal_pdf(b)) / z;
          }
        case DistributionType::gumbel:
          return p[0] + boost::math::constants::euler<double>() * p[1];
        case DistributionType::weibull:
          return p[1] * std::tgamma(1 + 1 / p[0]);
      }
    return 0;
  }

  double
  Distribution::standard_deviation() const
  {
    const std::vector<double> &p = native;
    switch (kind)
      {
        case DistributionType::normal:
          return p[1];
        case DistributionType::lognormal:
          return mean() * std::sqrt(std::expm1(p[1] * p[1]));
        case DistributionType::uniform:
          return (p[1] - p[0]) / std::sqrt(12.0);
          case DistributionType::truncated_normal: {
            const double a = (p[2] - p[0]) / p[1], b = (p[3] - p[0]) / p[1];
            const double z  = standard_normal_cdf(b) - standard_normal_cdf(a);
            const double fa = standard_normal_pdf(a), fb = standard_normal_pdf(b);
            // a phi(a) with a = -inf is 0, not NaN
            const double afa = std::isfinite(a) ? a * fa : 0, bfb = std::isfinite(b) ? b * fb : 0;
            const double r   = (fa - fb) / z;
            return p[1] * std::sqrt(1 + (afa - bfb) / z - r * r);
          }
        case DistributionType::gumbel:
          return M_PI * p[1] / std::sqrt(6.0);
        case DistributionType::weibull:
          return mean() * weibull_cov(p[0]);
      }
    return 0;
  }

  double
  Distribution::pdf(const double x) const
  {
    const std::vector<double> &p = native;
    switch (kind)
      {
        case DistributionType::normal:
          return standard_normal_pdf((x - p[0]) / p[1]) / p[1];
        case DistributionType::lognormal:
          return x > 0 ? boost::math::pdf(boost::math::lognormal(p[0], p[1]), x) : 0;
        case DistributionType::uniform:
          return x >= p[0] && x <= p[1] ? 1 / (p[1] - p[0]) : 0;
          case DistributionType::truncated_normal: {
            if (x < p[2] || x > p[3])
              return 0;
            const double z = standard_normal_cdf((p[3] - p[0]) / p[1]) -
                             standard_normal_cdf((p[2] - p[0]) / p[1]);
            return standard_normal_pdf((x - p[0]) / p[1]) / (p[1] * z);
          }
        case DistributionType::gumbel:
          return boost::math::pdf(boost::math::extreme_value(p[0], p[1]), x);
        case DistributionType::weibull:
          return x >= 0 ? boost::math::pdf(boost::math::weibull(p[0], p[1]), x) : 0;
      }
    return 0;
  }

  double
  Distribution::cdf(const double x) const
  {
    const std::vector<double> &p = native;
    switch (kind)
      {
        case DistributionType::normal:
          return standard_normal_cdf((x - p[0]) / p[1]);
        case DistributionType::lognormal:
          return x > 0 ? standard_normal_cdf((std::log(x) - p[0]) / p[1]) : 0;
        case DistributionType::uniform:
          return std::min(1.0, std::max(0.0, (x - p[0]) / (p[1] - p[0])));
          case DistributionType::truncated_normal: {
            const double fa = standard_normal_cdf((p[2] - p[0]) / p[1]);
            const double fb = standard_normal_cdf((p[3] - p[0]) / p[1]);
            const double fx = standard_normal_cdf((std::min(std::max(x, p[2]), p[3]) - p[0]) / p[1]);
            return (fx - fa) / (fb - fa);
          }
        case DistributionType::gumbel:
          return std::exp(-std::exp(-(x - p[0]) / p[1]));
        case DistributionType::weibull:
          return x > 0 ? -std::expm1(-std::pow(x / p[1], p[0])) : 0;
      }
    return 0;
  }

  double
  Distribution::complementary_cdf(const double x) const
  {
    const std::vector<double> &p = native;
    switch (kind)
      {
        case DistributionType::normal:
          return standard_normal_cdf(-(x - p[0]) / p[1]);
        case DistributionType::lognormal:
          return x > 0 ? standard_normal_cdf(-(std::log(x) - p[0]) / p[1]) : 1;
          case DistributionType::truncated_normal: {
            const double qa = standard_normal_cdf(-(p[2] - p[0]) / p[1]);
            const double qb = standard_normal_cdf(-(p[3] - p[0]) / p[1]);
            const double qx =
              standard_normal_cdf(-(std::min(std::max(x, p[2]), p[3]) - p[0]) / p[1]);
            return (qx - qb) / (qa - qb);
          }
        case DistributionType::gumbel:
          return -std::expm1(-std::exp(-(x - p[0]) / p[1]));
        case DistributionType::weibull:
          return x > 0 ? std::exp(-std::pow(x / p[1], p[0])) : 1;
        case DistributionType::uniform:
          return 1 - cdf(x);
      }
    return 0;
  }

  double
  Distribution::quantile(const double q) const
  {
    Assert(q > 0 && q < 1, dealii::ExcMessage("a probability in (0, 1)"));
    const std::vector<double> &p = native;
    switch (kind)
      {
        case DistributionType::normal:
          return p[0] + p[1] * standard_normal_quantile(q);
        case DistributionType::lognormal:
          return std::exp(p[0] + p[1] * standard_normal_quantile(q));
        case DistributionType::uniform:
          return p[0] + q * (p[1] - p[0]);
          case DistributionType::truncated_normal: {
            const double fa = standard_normal_cdf((p[2] - p[0]) / p[1]);
            const double fb = standard_normal_cdf((p[3] - p[0]) / p[1]);
            const double x  = p[0] + p[1] * standard_normal_quantile(fa + q * (fb - fa));
            return std::min(std::max(x, p[2]), p[3]);
          }
        case DistributionType::gumbel:
          return p[0] - p[1] * std::log(-std::log(q));
        case DistributionType::weibull:
          return p[1] * std::pow(-std::log1p(-q), 1 / p[0]);
      }
    return 0;
  }

  double
  Distribution::complementary_quantile(const double q) const
  {
    const std::vector<double> &p = native;
    switch (kind)
      {
        case DistributionType::normal:
          return p[0] - p[1] * standard_normal_quantile(q);
        case DistributionType::lognormal:
          return std::exp(p[0] - p[1] * standard_normal_quantile(q));
          case DistributionType::truncated_normal: {
            const double qa = standard_normal_cdf(-(p[2] - p[0]) / p[1]);
            const double qb = standard_normal_cdf(-(p[3] - p[0]) / p[1]);
            const double x  = p[0] - p[1] * standard_normal_quantile(qb + q * (qa - qb));
            return std::min(std::max(x, p[2]), p[3]);
          }
        case DistributionType::gumbel:
          return p[0] - p[1] * std::log(-std::log1p(-q));
        case DistributionType::weibull:
          return p[1] * std::pow(-std::log(q), 1 / p[0]);
        case DistributionType::uniform:
          return quantile(1 - q);
      }
    return 0;
  }

  double
  Distribution::to_standard_normal(const double x) const
  {
    if (kind == DistributionType::normal)
      return (x - native[0]) / native[1];
    if (kind == DistributionType::lognormal && x > 0)
      return (std::log(x) - native[0]) / native[1];
    // the smaller of F and 1 - F carries the precision
    const double F = cdf(x);
    if (F <= 0.5)
      return standard_normal_quantile(F);
    return -standard_normal_quantile(complementary_cdf(x));
  }

  double
  Distribution::from_standard_normal(const double u) const
  {
    const double v = std::min(std::max(u, -u_limit), u_limit);
    if (kind == DistributionType::normal)
      return native[0] + native[1] * v;
    if (kind == DistributionType::lognormal)
      return std::exp(native[0] + native[1] * v);
    if (v <= 0)
      return quantile(std::max(standard_normal_cdf(v), 1e-300));
    return complementary_quantile(std::max(standard_normal_cdf(-v), 1e-300));
  }
} // namespace poundfe
