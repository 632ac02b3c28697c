// Amplitude scaling and selection of records to a target spectrum.
//
// Scaling to an intensity: s = x_target / IM(record) for a measure that
// scales with the record (excitation/intensity_measures.h), so that the
// scaled record's measure is x_target.
//
// Selection by least squares on ln Sa (as the PEER ground-motion database's
// tool): at periods T_1..T_m, record r's spectrum Sa_r and the target's
// median S, the scale factor minimising sum_i (ln(s Sa_r(T_i)) - ln S(T_i))^2
// is ln s_r = (1/m) sum_i ln(S(T_i) / Sa_r(T_i)); a record whose s_r lies
// outside the scale limits is not a candidate (scaling it to a limit would
// not be its best fit); its misfit is the root mean square
// e_r = sqrt((1/m) sum_i (ln(s_r Sa_r(T_i)) - ln S(T_i))^2), and the N
// candidates of least misfit are selected (ties: suite order). The selected
// set's spectrum: the geometric mean exp(mean_r ln(s_r Sa_r)) and the
// standard deviation of ln(s_r Sa_r) over the set (n - 1), against the
// target's median and, for a conditional mean spectrum, its conditional
// standard deviation.
#ifndef poundfe_assessment_record_selection_h
#define poundfe_assessment_record_selection_h

#include <string>
#include <vector>

namespace poundfe
{
  /// The target: its periods (s), median Sa (g) and log standard deviation
  /// (0 where it has none).
  struct TargetSpectrum
  {
    std::vector<double> periods, median, sigma;
  };

  struct SelectedRecord
  {
    unsigned int index = 0; // in the candidates
    double       scale = 1, misfit = 0;
  };

  struct RecordSelection
  {
    std::vector<SelectedRecord> records;      // by ascending misfit
    unsigned int                n_within = 0; // candidates whose scale is within the limits
    std::vector<double>         mean, sigma;  // of the scaled set at the target's periods
    double max_mean_misfit = 0; // max_i |ln(mean(T_i) / S(T_i))|
  };

  /// The least-squares scale factor of `spectrum` to `target` (both > 0).
  double least_squares_scale(const std::vector<double> &spectrum, const std::vector<double> &target);
  /// e_r (above) of `spectrum` scaled by `scale`.
  double log_misfit(const std::vector<double> &spectrum, double scale,
                    const std::vector<double> &target);

  /// Selects `n` of the candidates (their spectra at the target's periods);
  /// `scales`: each candidate's scale factor (empty: least squares). Fewer
  /// than n selected when fewer are within [min_scale, max_scale].
  RecordSelection select_records(const std::vector<std::vector<double>> &spectra,
                                 const TargetSpectrum &target, unsigned int n, double min_scale,
                                 double max_scale, const std::vector<double> &scales = {});
} // namespace poundfe

#endif
