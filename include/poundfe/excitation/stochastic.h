// Stochastic ground motion.
//   Kanai-Tajimi PSD (two-sided): S(w) = S0 (wg^4 + 4 zg^2 wg^2 w^2) /
//     ((wg^2 - w^2)^2 + 4 zg^2 wg^2 w^2); Clough-Penzien multiplies by
//     w^4 / ((wf^2 - w^2)^2 + 4 zf^2 wf^2 w^2).
//   Samples by filtered white noise: xf'' + 2 zg wg xf' + wg^2 xf = -w(t),
//     a = -(2 zg wg xf' + wg^2 xf) (KT); CP passes a through
//     xh'' + 2 zf wf xh' + wf^2 xh = a and returns xh''.
//   White noise <w(t) w(t')> = 2 pi S0 delta(t - t'), sampled as
//     w_k = sqrt(2 pi S0 / dt) N(0,1), held over each sample interval; the
//     filter is advanced exactly over each interval (matrix exponential).
//   S0 from a target PGA: PGA = p sigma with sigma^2 the stationary variance
//     (Lyapunov equation of the filter; for KT pi S0 wg (1 + 4 zg^2)/(2 zg)).
//   Envelopes: Jennings/Amin-Ang, Saragoni-Hart, Shinozuka-Sato, peak 1.
// Sources: Kanai (1957), Tajimi (1960), Clough & Penzien (1975); Der Kiureghian
// & Neuenhofer (1992) for soil presets; Jennings et al. (1968).
#ifndef poundfe_excitation_stochastic_h
#define poundfe_excitation_stochastic_h

#include <poundfe/excitation/ground_motion.h>

#include <cstdint>
#include <string>

namespace poundfe
{
  struct FilterParameters
  {
    bool   clough_penzien = false;
    double omega_g        = 10;
    double zeta_g         = 0.4;
    double omega_f        = 1;
    double zeta_f         = 0.6;
  };

  /// Preset of Der Kiureghian & Neuenhofer (1992): "firm", "medium", "soft".
  FilterParameters soil_preset(const std::string &soil, bool clough_penzien);

  /// Two-sided PSD at circular frequency omega for unit S0.
  double filter_psd(const FilterParameters &filter, double omega);

  /// Stationary variance of the filtered motion for unit S0 (exact, from the
  /// Lyapunov equation of the filter's state-space form).
  double stationary_variance_per_unit_s0(const FilterParameters &filter);

  struct Envelope
  {
    std::string kind = "none"; // none | jennings | saragoni-hart | shinozuka-sato
    double      rise_end = 2, plateau_end = 10, decay = 0.3; // Jennings
    double      b = 2, c = 0.5;                                // Saragoni-Hart
    double      alpha = 0.2, beta = 0.6;                        // Shinozuka-Sato

    double operator()(double t) const;
  };

  /// Reproducible standard normal stream for (seed, realization): the same
  /// numbers on every platform (SplitMix64 + xoshiro256**, Box-Muller).
  class NormalStream
  {
  public:
    NormalStream(std::uint64_t seed, std::uint64_t realization);
    double next();

  private:
    std::uint64_t uniform_bits();
    std::uint64_t state[4];
    bool          has_spare = false;
    double        spare     = 0;
  };

  struct StochasticMotion
  {
    FilterParameters filter;
    double           spectral_intensity = 0; // S0, m^2/s^3
    double           duration           = 20;
    double           sample_interval    = 0.01;
    Envelope         envelope;
    std::uint64_t    seed        = 1;
    std::uint64_t    realization = 0;
  };

  /// One sample of filtered white noise, modulated by the envelope.
  GroundMotion generate_ground_motion(const StochasticMotion &motion);

  /// S0 giving the target PGA with peak factor p: PGA^2 / (p^2 sigma^2(S0=1)).
  double intensity_from_pga(const FilterParameters &filter, double pga, double peak_factor);
} // namespace poundfe

#endif
