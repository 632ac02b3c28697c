// The earthquake coefficient of a site study (formulas and sources in
// hazard/site_study.h).
#include <poundfe/hazard/site_study.h>
#include <poundfe/hazard/site_hazard.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace poundfe
{
  double
  intensity_scale_minimum(const IntensityScale scale)
  {
    return scale == IntensityScale::isc ? 1.0 : 0.0;
  }

  double
  intensity_scale_maximum(const IntensityScale scale)
  {
    return scale == IntensityScale::isc ? 12.0 : 7.0;
  }

  double
  jma_acceleration_gal(const double jma_intensity)
  {
    return 0.45 * std::pow(10.0, jma_intensity / 2);
  }

  double
  intensity_acceleration_gal(const IntensityScale scale, const double intensity)
  {
    return scale == IntensityScale::isc ? trifunac_brady_acceleration(intensity) :
                                          jma_acceleration_gal(intensity);
  }

  double
  return_period_of_exceedance(const double service_life, const double probability)
  {
    Assert(service_life > 0 && probability > 0 && probability < 1,
           dealii::ExcMessage("a positive life and a probability in (0, 1)"));
    return -service_life / std::log1p(-probability);
  }

  double
  IntensityFrequencyRelation::intensity_for_return_period(const double years) const
  {
    Assert(b > 0 && years > 0, dealii::ExcMessage("b > 0 and a positive return period"));
    return (a + std::log10(years)) / b;
  }

  double
  rounded_to_decimals(const double value, const int decimals)
  {
    if (decimals < 0)
      return value;
    const double scale = std::pow(10.0, decimals);
    // a printed decimal is rounded half away from zero; the 1e-12 guards a
    // value such as 0.0335 stored as 0.03349999...
    return std::round(value * scale * (1 + 1e-12)) / scale;
  }

  SiteStudyResult
  site_study(const std::vector<SiteStudyEntry> &entries, const SiteStudySettings &settings)
  {
    SiteStudyResult               result;
    std::map<double, double>      largest; // return period -> largest k
    for (const SiteStudyEntry &e : entries)
      {
        SiteStudyRow row{e, intensity_acceleration_gal(e.scale, e.intensity), 0};
        row.coefficient = row.acceleration_gal / (100 * settings.gravity); // gal = cm/s^2
        result.rows.push_back(row);
        auto it    = largest.emplace(e.return_period, row.coefficient).first;
        it->second = std::max(it->second, row.coefficient);
      }
    for (const auto &[T, k] : largest)
      result.coefficients.push_back({T, k, rounded_to_decimals(k, settings.coefficient_decimals)});

    DesignEarthquakes &design = result.design;
    design.service_life_return_period =
      return_period_of_exceedance(settings.service_life, settings.exceedance_probability);
    design.obe_return_period = settings.obe_return_period > 0 ? settings.obe_return_period :
                                                                design.service_life_return_period;
    const auto obe = std::find_if(result.coefficients.begin(), result.coefficients.end(),
                                  [&](const DesignCoefficient &c) {
                                    return std::abs(c.return_period - design.obe_return_period) <=
                                           1e-9 * design.obe_return_period;
                                  });
    Assert(obe != result.coefficients.end(),
           dealii::ExcMessage("the OBE return period has no entry"));
    design.obe_g = obe->rounded;
    design.mce_g = settings.mce_factor * design.obe_g;
    return result;
  }
} // namespace poundfe
