// Site hazard from a catalogue of historical earthquakes, as the thesis does
// it for a site with a thin record (the Memve'ele dam, southern Cameroon):
//
//   epicentral distance   Delta = R c, c the central angle by the haversine
//                         formula on a sphere of R = 6371.0 km (Sinnott 1984,
//                         Sky & Telescope 68(2) 159); r = sqrt(Delta^2 + h^2)
//                         with a focal depth h (0: the epicentral distance);
//   site intensity        I = 8.0 + 1.5 M - 2.5 ln r, r in km (Cornell 1968,
//                         "Engineering seismic risk analysis", BSSA 58(5)
//                         1583-1606);
//   site acceleration     log10 A_h = 0.014 + 0.30 I, A_h in cm/s^2 (Trifunac
//                         & Brady 1975, "On the correlation of seismic
//                         intensity scales with the peaks of recorded strong
//                         ground motion", BSSA 65(1) 139-162);
//   annual maxima         Gumbel type I, F(x) = exp(-exp(-(x - u)/s)) (Gumbel
//                         1958, Statistics of Extremes, Columbia University
//                         Press), u and s by maximum likelihood, the years
//                         without an event above the minimum intensity
//                         censored at it; annual rate of exceedance
//                         lambda(x) = -ln F(x), return period 1/(1 - F(x));
//   Poisson recurrence    lambda(x) = nu0 exp(-b (x - x0)) above the minimum
//                         intensity x0 (a Gutenberg-Richter law in intensity),
//                         b by maximum likelihood, b = 1/(mean(x) - x0) (Aki
//                         1965, Bull. Earthquake Res. Inst. 43, 237-239),
//                         return period 1/lambda;
//   fragility x hazard    lambda_F = int P(F | a) |d lambda/da| da (Cornell,
//                         Jalayer, Hamburger & Foutch 2002, J. Struct. Eng.
//                         128(4) 526-533), P(F | a) = Phi(ln(a/theta)/beta).
#ifndef poundfe_hazard_site_hazard_h
#define poundfe_hazard_site_hazard_h

#include <functional>
#include <string>
#include <vector>

namespace poundfe
{
  /// The mean Earth radius (IUGG), km.
  constexpr double earth_radius_km = 6371.0;

  struct GeographicPoint
  {
    double latitude  = 0; // degrees north
    double longitude = 0; // degrees east
  };

  /// Central angle between two points on a sphere (haversine), rad.
  double central_angle(const GeographicPoint &a, const GeographicPoint &b);

  /// Great-circle distance on the sphere of radius earth_radius_km, km.
  double great_circle_distance_km(const GeographicPoint &a, const GeographicPoint &b);

  /// Cornell's site intensity of magnitude M at distance r (km, r > 0).
  double cornell_intensity(double magnitude, double distance_km);

  /// Trifunac-Brady peak horizontal acceleration of intensity I, cm/s^2.
  double trifunac_brady_acceleration(double intensity);

  /// The intensity whose Trifunac-Brady acceleration is a (cm/s^2, a > 0).
  double trifunac_brady_intensity(double acceleration_cm_s2);

  /// Gumbel type I: location u, scale s, and their asymptotic standard errors
  /// (inverse of the observed information).
  struct GumbelFit
  {
    double       location = 0, scale = 0;
    double       location_standard_error = 0, scale_standard_error = 0;
    double       log_likelihood = 0;
    unsigned int n_observed = 0, n_censored = 0;
  };

  /// Maximum likelihood of the annual maxima `maxima`, with `n_censored`
  /// more years whose maximum is below `censoring_level` (none: 0). Needs
  /// two distinct maxima; throws std::invalid_argument otherwise.
  GumbelFit fit_gumbel(const std::vector<double> &maxima, unsigned int n_censored = 0,
                       double censoring_level = 0);

  double gumbel_cdf(const GumbelFit &fit, double x);

  /// Exponential recurrence of the values above a threshold x0 over an
  /// observation period: lambda(x) = nu0 exp(-b (x - x0)), x >= x0.
  struct ExponentialRecurrence
  {
    double       threshold = 0;          // x0
    double       rate_above_threshold = 0; // nu0, 1/year
    double       b = 0, b_standard_error = 0;
    unsigned int n_events = 0;
  };

  /// Aki's maximum-likelihood b of the values >= threshold observed over
  /// `years`. Needs one value above the threshold; throws
  /// std::invalid_argument otherwise.
  ExponentialRecurrence fit_exponential_recurrence(const std::vector<double> &values,
                                                   double threshold, double years);

  /// The fitted annual hazard of the site intensity.
  struct IntensityHazard
  {
    enum class Model
    {
      gumbel,
      poisson
    };
    Model                 model = Model::gumbel;
    GumbelFit             gumbel{};
    ExponentialRecurrence poisson{};

    /// Annual rate of exceeding intensity x (Gumbel: -ln F(x)).
    double annual_rate(double intensity) const;
    /// Probability of exceeding x in one year (Gumbel: 1 - F; Poisson: 1 - exp(-rate)).
    double annual_exceedance_probability(double intensity) const;
    /// Return period of x, years (Gumbel: 1/(1 - F); Poisson: 1/rate).
    double return_period(double intensity) const;
    /// The intensity of return period T > 1 year (the inverse of return_period).
    double intensity_for_return_period(double years) const;
  };

  /// The Trifunac-Brady PGA of intensity I, g.
  double trifunac_brady_pga_g(double intensity);

  /// The hazard in PGA: the annual rate of exceeding a (g), lambda(a) =
  /// lambda_I(I(a)), I(a) the Trifunac-Brady inverse.
  double annual_rate_of_pga(const IntensityHazard &hazard, double pga_g);

  /// Lognormal fragility P(F | a) = Phi(ln(a/theta)/beta), theta in g.
  struct LognormalCurve
  {
    double theta = 0, beta = 0;
  };

  /// lambda_F = int_{a_min}^inf P(F | a) |d lambda/da| da for a hazard curve
  /// lambda(a) (annual rate of exceeding PGA a, in the fragility's unit) that
  /// decreases; the events below a_min are not counted. Integrated by parts
  /// in z = ln(a/theta)/beta, P(a_min) lambda(a_min) + int lambda phi(z) dz,
  /// so only lambda is needed: adaptive Gauss-Kronrod on unit panels of z,
  /// right for any beta (1e-12 to 10 are tested against the closed form);
  /// beta = 0 is the step, lambda(max(a_min, theta)). Throws NumericalError
  /// if lambda grows so fast below theta that the integral does not converge.
  double annual_failure_rate(const std::function<double(double)> &annual_rate_of_pga,
                             double minimum_pga, const LognormalCurve &fragility);

  /// P(at least one failure in `years`) = 1 - exp(-years lambda_F).
  double probability_in_years(double annual_rate, double years);
} // namespace poundfe

#endif
