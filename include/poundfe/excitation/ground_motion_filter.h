// The filter and the intensity of a generated ground motion as its input
// gives them, shared by the generator (make_motion_generator) and the input's
// bound on the expected peak (GroundMotionParameters::check):
//   filter: Soil's preset (Der Kiureghian & Neuenhofer 1992), or omega_g,
//     zeta_g (and omega_f, zeta_f for Clough-Penzien) when Soil = custom;
//   intensity: S0, or D / pi (the thesis's <w(t) w(t')> = 2 D delta(t - t'),
//     D = pi S0); 0 when neither is given (Target PGA then sets S0).
#ifndef poundfe_excitation_ground_motion_filter_h
#define poundfe_excitation_ground_motion_filter_h

#include <poundfe/excitation/excitation_parameters.h>
#include <poundfe/excitation/stochastic.h>

namespace poundfe
{
  /// The Kanai-Tajimi or Clough-Penzien filter the input selects.
  FilterParameters ground_motion_filter(const GroundMotionParameters &g);

  /// S0 from S0 or D (m^2/s^3); 0 when both are 0.
  double given_spectral_intensity(const GroundMotionParameters &g);
} // namespace poundfe

#endif
