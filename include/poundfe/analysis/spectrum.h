// The `spectrum` command: the elastic response spectrum and intensity
// measures of the input's ground motion (excitation/response_spectrum.h);
// with --realizations N, the mean and standard deviation of the spectra of
// realizations 0..N-1 of its stochastic motion against the Spectrum
// section's target, and the factor on the Kanai-Tajimi (or Clough-Penzien,
// white-noise) intensity S0 that makes the mean pseudo-acceleration equal
// the target at the matching period. The motion is linear in S0^(1/2), so
// every spectral ordinate scales with sqrt(S0): factor = (Se(T1) / mean
// PSA(T1))^2, exact for the ensemble of the same normals.
#ifndef poundfe_analysis_spectrum_h
#define poundfe_analysis_spectrum_h

#include <poundfe/analysis/input_parameters.h>

#include <string>

namespace poundfe
{
  /// Returns the exit status; throws InputError before anything is written.
  int spectrum_command(const InputParameters &input, const std::string &output_directory,
                       unsigned int n_realizations);
} // namespace poundfe

#endif
