#include <poundfe/hazard/site_hazard.h>
#include <poundfe/excitation/ground_motion.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/standard_normal.h>

#include <deal.II/base/exceptions.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace poundfe
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    double
    radians(const double degrees)
    {
      return degrees * pi / 180.0;
    }

    /// The Gumbel sample: observed maxima and the censored years.
    struct GumbelSample
    {
      const std::vector<double> &maxima;
      unsigned int               n_censored;
      double                     censoring_level;

      double
      log_likelihood(const double u, const double s) const
      {
        double l = 0;
        for (const double x : maxima)
          {
            const double z = (x - u) / s;
            l += -std::log(s) - z - std::exp(-z);
          }
        if (n_censored > 0)
          l -= n_censored * std::exp(-(censoring_level - u) / s);
        return l;
      }

      /// The location that maximises the likelihood at scale s:
      /// n_obs = sum exp(-(x_i - u)/s) + n_c exp(-(x_c - u)/s), solved for u
      /// with the exponents shifted by the smallest value (no overflow).
      double
      best_location(const double s) const
      {
        double smallest = *std::min_element(maxima.begin(), maxima.end());
        if (n_censored > 0)
          smallest = std::min(smallest, censoring_level);
        double sum = 0;
        for (const double x : maxima)
          sum += std::exp(-(x - smallest) / s);
        if (n_censored > 0)
          sum += n_censored * std::exp(-(censoring_level - smallest) / s);
        return smallest + s * std::log(maxima.size() / sum);
      }
    };
  } // namespace

  double
  central_angle(const GeographicPoint &a, const GeographicPoint &b)
  {
    // haversine: well conditioned for small angles, unlike the cosine rule
    const double dlat = radians(b.latitude - a.latitude);
    const double dlon = radians(b.longitude - a.longitude);
    const double h    = std::pow(std::sin(dlat / 2), 2) + std::cos(radians(a.latitude)) *
                                                            std::cos(radians(b.latitude)) *
                                                            std::pow(std::sin(dlon / 2), 2);
    return 2 * std::asin(std::min(1.0, std::sqrt(h)));
  }

  double
  great_circle_distance_km(const GeographicPoint &a, const GeographicPoint &b)
  {
    return earth_radius_km * central_angle(a, b);
  }

  double
  cornell_intensity(const double magnitude, const double distance_km)
  {
    return 8.0 + 1.5 * magnitude - 2.5 * std::log(distance_km);
  }

  double
  trifunac_brady_acceleration(const double intensity)
  {
    return std::pow(10.0, 0.014 + 0.30 * intensity);
  }

  double
  trifunac_brady_intensity(const double acceleration_cm_s2)
  {
    return (std::log10(acceleration_cm_s2) - 0.014) / 0.30;
  }

  GumbelFit
  fit_gumbel(const std::vector<double> &maxima, const unsigned int n_censored,
             const double censoring_level)
  {
    if (maxima.size() < 2)
      throw std::invalid_argument("a Gumbel fit needs at least two annual maxima, got " +
                                  std::to_string(maxima.size()));
    const auto [low, high] = std::minmax_element(maxima.begin(), maxima.end());
    const double spread    = *high - *low;
    if (!(spread > 0))
      throw std::invalid_argument("a Gumbel fit needs annual maxima that differ");
    const GumbelSample sample{maxima, n_censored, censoring_level};
    // The profile likelihood over ln s, maximised by Brent's method; its
    // maximum lies well inside [spread/1000, 100 spread] for any sample whose
    // maxima differ (s ~ spread / ln n).
    const auto negative_profile = [&sample](const double log_s) {
      const double s = std::exp(log_s);
      return -sample.log_likelihood(sample.best_location(s), s);
    };
    const double lower = std::log(spread * 1e-3), upper = std::log(spread * 1e2);
    const auto   best  = boost::math::tools::brent_find_minima(negative_profile, lower, upper, 40);
    if (best.first - lower < 1e-6 || upper - best.first < 1e-6)
      throw std::invalid_argument("the Gumbel likelihood has no maximum for these maxima");
    GumbelFit fit;
    fit.scale          = std::exp(best.first);
    fit.location       = sample.best_location(fit.scale);
    fit.log_likelihood = sample.log_likelihood(fit.location, fit.scale);
    fit.n_observed     = maxima.size();
    fit.n_censored     = n_censored;

    // Observed information: minus the Hessian of the log-likelihood at the
    // maximum (central differences), inverted for the covariance.
    const double h = 1e-4 * fit.scale;
    const auto   l = [&](const double du, const double ds) {
      return sample.log_likelihood(fit.location + du, fit.scale + ds);
    };
    const double l0  = l(0, 0);
    const double luu = (l(h, 0) - 2 * l0 + l(-h, 0)) / (h * h);
    const double lss = (l(0, h) - 2 * l0 + l(0, -h)) / (h * h);
    const double lus = (l(h, h) - l(h, -h) - l(-h, h) + l(-h, -h)) / (4 * h * h);
    const double det = luu * lss - lus * lus;
    fit.location_standard_error = std::sqrt(std::max(0.0, -lss / det));
    fit.scale_standard_error    = std::sqrt(std::max(0.0, -luu / det));
    return fit;
  }

  double
  gumbel_cdf(const GumbelFit &fit, const double x)
  {
    return std::exp(-std::exp(-(x - fit.location) / fit.scale));
  }

  ExponentialRecurrence
  fit_exponential_recurrence(const std::vector<double> &values, const double threshold,
                             const double years)
  {
    ExponentialRecurrence fit;
    fit.threshold = threshold;
    double excess = 0;
    for (const double x : values)
      if (x >= threshold)
        {
          excess += x - threshold;
          ++fit.n_events;
        }
    if (!(excess > 0))
      throw std::invalid_argument("a Poisson recurrence needs an intensity above the minimum");
    fit.rate_above_threshold = fit.n_events / years;
    fit.b                    = fit.n_events / excess;
    fit.b_standard_error     = fit.b / std::sqrt(double(fit.n_events));
    return fit;
  }

  double
  IntensityHazard::annual_rate(const double intensity) const
  {
    if (model == Model::gumbel)
      return std::exp(-(intensity - gumbel.location) / gumbel.scale);
    return poisson.rate_above_threshold * std::exp(-poisson.b * (intensity - poisson.threshold));
  }

  double
  IntensityHazard::annual_exceedance_probability(const double intensity) const
  {
    // Gumbel: 1 - F = 1 - exp(-rate); Poisson: P(N >= 1) = 1 - exp(-rate)
    return -std::expm1(-annual_rate(intensity));
  }

  double
  IntensityHazard::return_period(const double intensity) const
  {
    if (model == Model::gumbel)
      return 1.0 / annual_exceedance_probability(intensity);
    return 1.0 / annual_rate(intensity);
  }

  double
  IntensityHazard::intensity_for_return_period(const double years) const
  {
    if (model == Model::gumbel)
      return gumbel.location - gumbel.scale * std::log(-std::log1p(-1.0 / years));
    return poisson.threshold +
           std::log(poisson.rate_above_threshold * years) / poisson.b;
  }

  double
  trifunac_brady_pga_g(const double intensity)
  {
    return trifunac_brady_acceleration(intensity) / 100.0 / standard_gravity;
  }

  double
  annual_rate_of_pga(const IntensityHazard &hazard, const double pga_g)
  {
    return hazard.annual_rate(trifunac_brady_intensity(pga_g * standard_gravity * 100));
  }

  namespace
  {
    /// The Gaussian of z beyond which nothing counts: phi(40) ~ 1e-349 is
    /// zero in double precision.
    constexpr double z_beyond = 40;

    /// J = int_{z_min}^inf lambda(theta e^(beta z)) phi(z) dz over unit panels
    /// from z_beyond down (Gauss-Kronrod 31, bisected where its error estimate
    /// asks: a tabulated hazard has kinks). lambda decreases, so the
    /// integrand's peak is at z <= 0 (at z = -k beta for a power law); the
    /// panels stop at z_min or, below 0 and past the peak, once a panel adds
    /// less than 1e-18 of the sum. The panels are in z, not in ln a: their
    /// width follows the fragility's spread whatever beta is (a grid in ln a
    /// of a fixed number of steps misses a narrow lognormal).
    double
    hazard_times_fragility_density(const std::function<double(double)> &annual_rate_of_pga,
                                   const double z_min, const LognormalCurve &fragility)
    {
      const auto integrand = [&](const double z) {
        const double density = standard_normal_pdf(z);
        // lambda may overflow where phi is already 0 (inf * 0)
        return density > 0 ? annual_rate_of_pga(fragility.theta * std::exp(fragility.beta * z)) *
                               density :
                             0.0;
      };
      using Rule                    = boost::math::quadrature::gauss_kronrod<double, 31>;
      const unsigned int max_panels = 100000; // down to z = -99960: any hazard has peaked
      double             sum        = 0;
      for (unsigned int i = 0; i < max_panels; ++i)
        {
          const double top = z_beyond - i, bottom = std::max(z_min, top - 1);
          const double panel = Rule::integrate(integrand, bottom, top, 12, 1e-13);
          sum += panel;
          if (!std::isfinite(sum))
            throw NumericalError("the hazard x fragility integral overflows: the annual rate "
                                 "exceeds the largest double within the fragility's spread "
                                 "(theta " + std::to_string(fragility.theta) + " g, beta " +
                                 std::to_string(fragility.beta) + ")");
          if (bottom <= z_min)
            return sum;
          const bool past_the_peak = bottom < 0 && integrand(bottom) < integrand(top);
          if (past_the_peak && sum > 0 && panel < 1e-18 * sum)
            return sum;
          if (sum == 0 && bottom <= -z_beyond) // lambda is 0 (underflow) where phi is not
            return 0;
        }
      throw NumericalError("the hazard x fragility integral has not converged " +
                           std::to_string(max_panels) + " standard deviations below the "
                           "fragility's median: the hazard grows faster than a lognormal "
                           "decays");
    }
  } // namespace

  double
  annual_failure_rate(const std::function<double(double)> &annual_rate_of_pga,
                      const double minimum_pga, const LognormalCurve &fragility)
  {
    Assert(minimum_pga > 0 && fragility.theta >= 0 && fragility.beta >= 0,
           dealii::ExcMessage("a positive minimum PGA, a median and a beta >= 0"));
    // beta = 0: failure exactly above theta, the limit of beta -> 0
    if (!(fragility.beta > 0))
      return annual_rate_of_pga(std::max(minimum_pga, fragility.theta));
    // by parts in z = ln(a/theta)/beta: int_{a_min}^inf P(F | a) |d lambda| =
    // P(a_min) lambda(a_min) + int_{z_min}^inf lambda(theta e^(beta z)) phi(z) dz
    const double z_min =
      (std::log(minimum_pga) - std::log(fragility.theta)) / fragility.beta;
    const double below = standard_normal_cdf(z_min); // P(F | a_min)
    const double total = below > 0 ? below * annual_rate_of_pga(minimum_pga) : 0.0;
    if (z_min >= z_beyond)
      return total;
    return total + hazard_times_fragility_density(annual_rate_of_pga, z_min, fragility);
  }

  double
  probability_in_years(const double annual_rate, const double years)
  {
    return -std::expm1(-years * annual_rate);
  }
} // namespace poundfe
