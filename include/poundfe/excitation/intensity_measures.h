// Intensity measures of a record or of a horizontal pair, for scaling
// records in an incremental dynamic analysis (assessment/ida.h), on the
// spectrum code (response_spectrum.h):
//   Sa(T, zeta) = omega^2 Sd(T, zeta), the pseudo-spectral acceleration (the
//     spectrum command's PSA column), omega = 2 pi / T;
//   Sa_avg = (prod_i Sa(T_i))^(1/n), the geometric mean over n periods
//     (Eads, Miranda & Lignos 2015: Sa_avg over 0.2 T1 .. 3 T1);
//   PGA = max |a|; PGV = max |v|, v = int a dt, exact for a linear between
//     samples (response_spectrum.h), without baseline correction;
//   Arias intensity, CAV, D5-75 and D5-95 as ground_motion_intensity.
// A horizontal pair (a1, a2): the geometric mean sqrt(IM1 IM2) of the
// as-recorded components, or Boore's (2010) orientation-independent RotDnn:
// for each angle theta = 0, 1, ..., 179 degrees, the peak of the response to
// a1 cos(theta) + a2 sin(theta), which, the oscillator being linear, is
// u1(t) cos(theta) + u2(t) sin(theta) of the components' own histories;
// RotD100 is the largest of the 180 peaks, RotD50 their median (the mean of
// the 90th and 91st in ascending order). The histories are sampled where
// response_spectrum() samples one record (the record's samples, at least
// 200 per period, and one period of free vibration after the end), so that
// each angle's peak is that of response_spectrum() of the rotated record.
// The measures that scale with the record (PGA, PGV, Sa, Sa_avg and their
// pair measures: IM(lambda a) = lambda IM(a)) are those IDA may scale by.
//   Boore, D. M. (2010). Orientation-independent, nongeometric-mean measures
//     of seismic intensity from two horizontal components of motion. BSSA
//     100(4), 1830-1835.
//   Eads, L., Miranda, E. & Lignos, D. G. (2015). Average spectral
//     acceleration as an intensity measure for collapse risk assessment.
//     Earthquake Engng Struct. Dyn. 44, 2057-2073.
#ifndef poundfe_excitation_intensity_measures_h
#define poundfe_excitation_intensity_measures_h

#include <poundfe/base/choices.h>
#include <poundfe/excitation/ground_motion.h>

#include <string>
#include <vector>

namespace poundfe
{
  /// The measures an IDA scales records by (all proportional to the scale).
  enum class IntensityMeasure
  {
    sa,     // Sa(T, zeta), g
    sa_avg, // geometric mean of Sa over a period range, g
    pga,    // g
    pgv     // m/s
  };
  const NameTable<IntensityMeasure> &intensity_measure_names();
  /// "g" or "m/s".
  std::string intensity_unit(IntensityMeasure measure);

  /// How the two components of a pair make one value.
  enum class PairMeasure
  {
    geometric_mean,
    rotd50,
    rotd100
  };
  const NameTable<PairMeasure> &pair_measure_names();

  /// Sa(T, zeta) = omega^2 Sd of one record, m/s^2.
  double pseudo_spectral_acceleration(const GroundMotion &motion, double period, double zeta);

  /// The histories whose peaks give a measure: the oscillator's relative
  /// displacement times omega^2 (Sa), the acceleration (PGA) or the
  /// velocity at the samples (PGV), on the sampling of response_spectrum().
  std::vector<double> response_history(const GroundMotion &motion, IntensityMeasure measure,
                                       double period, double zeta);

  /// The peak of h1 cos(theta) + h2 sin(theta) at theta = 0..179 degrees.
  std::vector<double> rotated_peaks(const std::vector<double> &h1, const std::vector<double> &h2);

  /// RotD50 (median of the 180) or RotD100 (largest) of rotated peaks.
  double rotd(std::vector<double> peaks, PairMeasure measure);

  /// The value of `measure` (measured on each of `periods` for Sa_avg; on
  /// periods[0] for Sa) of a record of one or two components (then combined
  /// by `pair`), in the measure's unit (g or m/s).
  double intensity_of(const std::vector<GroundMotion> &components, IntensityMeasure measure,
                      PairMeasure pair, const std::vector<double> &periods, double zeta);
} // namespace poundfe

#endif
