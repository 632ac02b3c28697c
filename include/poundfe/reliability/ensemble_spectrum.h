// The response spectra of an ensemble of stochastic ground motions: the
// PSA of realizations 0..N-1 at each period and damping ratio (Nigam-Jennings,
// excitation/response_spectrum.h), their mean and standard deviation, and
// the intensity measures' (PGA, PGV, PGD, Arias intensity, D5-95); and the
// factor on S0 that brings the mean PSA to a design spectrum at a period
// T1: PSA is proportional to sqrt(S0), so the factor is (target / mean)^2.
#ifndef poundfe_reliability_ensemble_spectrum_h
#define poundfe_reliability_ensemble_spectrum_h

#include <poundfe/excitation/spectrum_parameters.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/reliability/statistics.h>

#include <string>
#include <vector>

namespace poundfe
{
  /// The spectra and intensity measures of realizations 0..N-1.
  struct EnsembleSpectrum
  {
    std::vector<double>           periods; // the grid, then T1 when matching
    unsigned int                  n_grid = 0;
    std::vector<SampleStatistics> psa;      // index d * periods.size() + i
    std::vector<SampleStatistics> measures; // PGA, PGV, PGD, Arias, D5-95

    const SampleStatistics &at(const unsigned int d, const unsigned int i) const
    {
      return psa[d * periods.size() + i];
    }
  };

  /// The PSA of realizations 0..n_realizations-1 of `generator` (each
  /// scaled by `scale_factor`) at `periods` and `damping_ratios`, and their
  /// intensity measures. Stops between realizations on SIGINT/SIGTERM.
  EnsembleSpectrum compute_ensemble_spectrum(const MotionGenerator &generator, double scale_factor,
                            std::vector<double> periods, const std::vector<double> &damping_ratios,
                            unsigned int n_realizations);

  /// The factor on S0 that brings the mean PSA (first damping ratio) to the target at T1.
  struct SpectrumMatching
  {
    double      period = 0, damping_ratio = 0;
    std::string source;
    double      target_psa = 0, mean_psa = 0, std_psa = 0;
    double      s0_factor = 0;
  };

  /// The matching at T1 = `t1` (the period after the grid in `ensemble`),
  /// `source` saying where T1 came from.
  SpectrumMatching match_target(const EnsembleSpectrum &ensemble, const SpectrumParameters &s, double t1,
                        const std::string &source);
} // namespace poundfe

#endif
