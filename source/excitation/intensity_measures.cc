// Intensity measures of records and pairs (intensity_measures.h).
#include <poundfe/excitation/intensity_measures.h>
#include <poundfe/excitation/response_spectrum.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  const NameTable<IntensityMeasure> &
  intensity_measure_names()
  {
    static const NameTable<IntensityMeasure> table({{IntensityMeasure::sa, "Sa"},
                                                    {IntensityMeasure::sa_avg, "Sa_avg"},
                                                    {IntensityMeasure::pga, "PGA"},
                                                    {IntensityMeasure::pgv, "PGV"}});
    return table;
  }

  std::string
  intensity_unit(const IntensityMeasure measure)
  {
    return measure == IntensityMeasure::pgv ? "m/s" : "g";
  }

  const NameTable<PairMeasure> &
  pair_measure_names()
  {
    static const NameTable<PairMeasure> table({{PairMeasure::geometric_mean, "geometric mean"},
                                               {PairMeasure::rotd50, "RotD50"},
                                               {PairMeasure::rotd100, "RotD100"}});
    return table;
  }

  double
  pseudo_spectral_acceleration(const GroundMotion &motion, const double period, const double zeta)
  {
    return response_spectrum(motion, {period}, {zeta}).psa(0, 0);
  }

  namespace
  {
    /// omega^2 u(t) of one oscillator at the points where response_spectrum()
    /// looks for its peaks: each step cut into the sub-steps it cuts it into
    /// (at least spectrum_samples_per_period per period), then one period of
    /// free vibration.
    std::vector<double>
    oscillator_history(const GroundMotion &motion, const double period, const double zeta)
    {
      SpectralOscillators        bank({period}, {zeta});
      const std::vector<double> &a  = motion.samples();
      const double               dt = motion.time_step();
      const double               w2 = std::pow(2 * M_PI / period, 2);
      const unsigned int m = std::max(1u, static_cast<unsigned int>(std::ceil(
                                            dt / period * spectrum_samples_per_period - 1e-9)));
      std::vector<double> history{0.0};
      bank.start(0, a.empty() ? 0 : a[0]);
      const std::size_t n_intervals = motion.is_held() ? a.size() : a.size() - 1;
      for (std::size_t k = 0; k < n_intervals; ++k)
        {
          const double a0 = a[k], a1 = motion.is_held() ? a[k] : a[k + 1];
          for (unsigned int j = 0; j < m; ++j)
            {
              const double b0 = a0 + j * (a1 - a0) / m;
              const double b1 = (j + 1 == m) ? a1 : a0 + (j + 1) * (a1 - a0) / m;
              bank.advance(dt / m, b0, b1);
              history.push_back(w2 * bank.displacement()[0]);
            }
        }
      for (unsigned int j = 0; j < spectrum_samples_per_period; ++j)
        {
          bank.advance(period / spectrum_samples_per_period, 0, 0);
          history.push_back(w2 * bank.displacement()[0]);
        }
      return history;
    }

    /// v(t) = int_0^t a at the samples (trapezoidal: exact for linear a).
    std::vector<double>
    velocity_history(const GroundMotion &motion)
    {
      const std::vector<double> &a = motion.samples();
      std::vector<double>        v{0.0};
      for (std::size_t k = 0; k + 1 < a.size(); ++k)
        v.push_back(v.back() + 0.5 * motion.time_step() *
                                 (a[k] + (motion.is_held() ? a[k] : a[k + 1])));
      return v;
    }

    /// One period's measure of a record of one or two components, m/s^2 or m/s.
    double
    measure_at(const std::vector<GroundMotion> &components, const IntensityMeasure measure,
               const PairMeasure pair, const double period, const double zeta)
    {
      std::vector<double> single;
      for (const GroundMotion &motion : components)
        single.push_back(measure == IntensityMeasure::pga ? motion.peak() :
                         measure == IntensityMeasure::pgv ?
                                                            ground_motion_intensity(motion).pgv :
                                                            pseudo_spectral_acceleration(motion, period, zeta));
      if (components.size() == 1)
        return single[0];
      if (pair == PairMeasure::geometric_mean)
        return std::sqrt(single[0] * single[1]);
      return rotd(rotated_peaks(response_history(components[0], measure, period, zeta),
                                response_history(components[1], measure, period, zeta)),
                  pair);
    }
  } // namespace

  std::vector<double>
  response_history(const GroundMotion &motion, const IntensityMeasure measure, const double period,
                   const double zeta)
  {
    if (measure == IntensityMeasure::pga)
      return motion.samples();
    if (measure == IntensityMeasure::pgv)
      return velocity_history(motion);
    return oscillator_history(motion, period, zeta);
  }

  std::vector<double>
  rotated_peaks(const std::vector<double> &h1, const std::vector<double> &h2)
  {
    AssertDimension(h1.size(), h2.size());
    std::vector<double> peaks;
    for (unsigned int degrees = 0; degrees < 180; ++degrees)
      {
        const double c = std::cos(degrees * M_PI / 180), s = std::sin(degrees * M_PI / 180);
        double       peak = 0;
        for (std::size_t k = 0; k < h1.size(); ++k)
          peak = std::max(peak, std::abs(c * h1[k] + s * h2[k]));
        peaks.push_back(peak);
      }
    return peaks;
  }

  double
  rotd(std::vector<double> peaks, const PairMeasure measure)
  {
    Assert(!peaks.empty(), dealii::ExcMessage("no rotated peaks"));
    std::sort(peaks.begin(), peaks.end());
    if (measure == PairMeasure::rotd100)
      return peaks.back();
    const std::size_t n = peaks.size();
    return n % 2 ? peaks[n / 2] : 0.5 * (peaks[n / 2 - 1] + peaks[n / 2]);
  }

  double
  intensity_of(const std::vector<GroundMotion> &components, const IntensityMeasure measure,
               const PairMeasure pair, const std::vector<double> &periods, const double zeta)
  {
    Assert(components.size() == 1 || components.size() == 2,
           dealii::ExcMessage("one component or a pair"));
    const double unit = measure == IntensityMeasure::pgv ? 1.0 : standard_gravity;
    if (measure != IntensityMeasure::sa_avg)
      return measure_at(components, measure, pair, periods.empty() ? 1.0 : periods[0], zeta) / unit;
    Assert(!periods.empty(), dealii::ExcMessage("Sa_avg needs periods"));
    double log_sum = 0;
    for (const double period : periods)
      log_sum += std::log(measure_at(components, IntensityMeasure::sa, pair, period, zeta));
    return std::exp(log_sum / periods.size()) / unit;
  }
} // namespace poundfe
