// The earthquake coefficient of a site study (thesis §2.3.1, Table 2.3): the
// site intensity of each return period by several methods, its acceleration,
// the seismic coefficient and the design earthquakes:
//
//   ISC (Modified Mercalli-type) scale  log10 A = 0.014 + 0.30 I, A in gal
//                         (Trifunac & Brady 1975, BSSA 65(1) 139-162; the
//                         thesis's relation (i));
//   JMA scale             a = 0.45 10^(S/2), a in gal (Kawasumi 1951, "Measures
//                         of earthquake danger and expectancy of maximum
//                         intensity throughout Japan", Bull. Earthquake Res.
//                         Inst. 29, 469-482; the thesis's relation (ii));
//   intensity-frequency   log10 N_c(I) = a - b I, N_c the annual number of site
//                         events of intensity >= I (a Gutenberg-Richter law in
//                         intensity); the intensity of return period T solves
//                         N_c(I) = 1/T: I_T = (a + log10 T)/b;
//   earthquake coefficient k = A/g (the thesis: k = gal/980, g = 9.80 m/s^2);
//   OBE                   50 % probability of exceedance in the service life L
//                         (USACE ER 1110-2-1806, 1995): with Poisson
//                         occurrences T = -L/ln(1 - p), 144.3 years for L = 100;
//   MCE                   a multiple of the OBE (the thesis: 2).
#ifndef poundfe_hazard_site_study_h
#define poundfe_hazard_site_study_h

#include <string>
#include <vector>

namespace poundfe
{
  /// The intensity scales of the site study and their ranges.
  enum class IntensityScale
  {
    isc, // Modified Mercalli-type, I to XII
    jma  // Japan Meteorological Agency, 0 to 7
  };

  /// Smallest and largest intensity of a scale.
  double intensity_scale_minimum(IntensityScale scale);
  double intensity_scale_maximum(IntensityScale scale);

  /// Kawasumi's acceleration of JMA intensity S, gal (cm/s^2).
  double jma_acceleration_gal(double jma_intensity);

  /// The acceleration (gal) of intensity I on `scale` (ISC: Trifunac-Brady).
  double intensity_acceleration_gal(IntensityScale scale, double intensity);

  /// The return period whose Poisson probability of exceedance in
  /// `service_life` years is `probability` (0 < p < 1): -L / ln(1 - p).
  double return_period_of_exceedance(double service_life, double probability);

  /// log10 N_c(I) = a - b I per year (b > 0).
  struct IntensityFrequencyRelation
  {
    double a = 0, b = 0;
    /// The intensity with N_c = 1/T.
    double intensity_for_return_period(double years) const;
  };

  /// `value` rounded to `decimals` decimals (decimals < 0: unchanged).
  double rounded_to_decimals(double value, int decimals);

  /// One method's site intensity for one return period.
  struct SiteStudyEntry
  {
    std::string    method; // a label: ISC, JMA, M.R., N_c relation, ...
    IntensityScale scale         = IntensityScale::isc;
    double         return_period = 0; // years
    double         intensity     = 0;
  };

  /// An entry with its acceleration and coefficient.
  struct SiteStudyRow
  {
    SiteStudyEntry entry;
    double         acceleration_gal = 0;
    double         coefficient      = 0; // k = A/g
  };

  /// The design coefficient of a return period: the largest of its rows'.
  struct DesignCoefficient
  {
    double return_period = 0;
    double coefficient   = 0; // largest k of the rows
    double rounded       = 0; // to the study's decimals
  };

  /// The OBE and MCE.
  struct DesignEarthquakes
  {
    double service_life_return_period = 0; // T of p in L years
    double obe_return_period          = 0; // the one the OBE is taken at
    double obe_g = 0, mce_g = 0;           // rounded coefficients times the factor
  };

  struct SiteStudyResult
  {
    std::vector<SiteStudyRow>      rows;
    std::vector<DesignCoefficient> coefficients; // by return period, ascending
    DesignEarthquakes              design;
  };

  /// The settings of a study (the parameters' values, without the file).
  struct SiteStudySettings
  {
    double gravity                = 9.80665; // m/s^2
    int    coefficient_decimals   = 2;  // < 0: no rounding
    double service_life           = 100; // years
    double exceedance_probability = 0.5;
    double obe_return_period      = 0;  // 0: the service life's
    double mce_factor             = 2;
  };

  /// Rows, design coefficients and design earthquakes of the entries. The
  /// OBE return period must be one of the entries' (Assert).
  SiteStudyResult site_study(const std::vector<SiteStudyEntry> &entries,
                             const SiteStudySettings         &settings);
} // namespace poundfe

#endif
