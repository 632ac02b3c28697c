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
//   Spectral representation (Shinozuka & Deodatis 1991):
//     a(t) = sum_k 2 sqrt(S(w_k) dw) cos(w_k t + phi_k), w_k = (k + 1/2) dw,
//     k < N, N dw = w_u, phases uniform on [0, 2 pi); its variance is the
//     band-limited integral of S over [-w_u, w_u].
//   Plain white noise: w_k = sqrt(2 pi S0 / dt) N(0,1) held over the sample
//     interval (the thesis's intensity D = pi S0).
//   Envelopes: Jennings/Amin-Ang, Saragoni-Hart, Shinozuka-Sato, peak 1.
//   Every sample is a function of a vector of independent standard normals
//   (the phases are phi = 2 pi Phi(xi)), which is what Monte Carlo draws from
//   (seed, realization) and what Subset Simulation moves by Markov chains.
// Sources: Kanai (1957), Tajimi (1960), Clough & Penzien (1975); Der Kiureghian
// & Neuenhofer (1992) for soil presets; Jennings et al. (1968).
#ifndef poundfe_excitation_stochastic_h
#define poundfe_excitation_stochastic_h

#include <poundfe/base/standard_normal.h>
#include <poundfe/excitation/ground_motion.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

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

  enum class Soil
  {
    firm,
    medium,
    soft,
    custom // omega_g, zeta_g given
  };

  /// Preset of Der Kiureghian & Neuenhofer (1992): firm, medium, soft.
  FilterParameters soil_preset(Soil soil, bool clough_penzien);

  /// Two-sided PSD at circular frequency omega for unit S0.
  double filter_psd(const FilterParameters &filter, double omega);

  /// Stationary variance of the filtered motion for unit S0 (exact, from the
  /// Lyapunov equation of the filter's state-space form).
  double stationary_variance_per_unit_s0(const FilterParameters &filter);

  enum class EnvelopeKind
  {
    none,
    jennings,
    saragoni_hart,
    shinozuka_sato
  };

  struct Envelope
  {
    EnvelopeKind kind = EnvelopeKind::none;
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

  enum class StochasticMethod
  {
    filtered_white_noise,
    spectral_representation,
    white_noise
  };

  struct StochasticMotion
  {
    StochasticMethod method = StochasticMethod::filtered_white_noise;
    FilterParameters filter;
    double           spectral_intensity = 0; // S0, m^2/s^3
    double           duration           = 20;
    double           sample_interval    = 0.01;
    double           cutoff_frequency   = 0; // spectral representation, rad/s; 0: default
    unsigned int     n_frequencies      = 0; // spectral representation; 0: default
    Envelope         envelope;
    std::uint64_t    seed        = 1;
    std::uint64_t    realization = 0;
  };

  /// Samples of a motion of `duration` on a grid of `interval`, both ends included.
  unsigned int n_samples(double duration, double interval);

  /// xi.size() standard normals of realization `realization`.
  void standard_normals(std::uint64_t seed, std::uint64_t realization, std::vector<double> &xi);

  /// Turns standard normals into samples of one stochastic motion. Set up
  /// once (filter propagator, frequencies); generate() allocates nothing.
  class MotionGenerator
  {
  public:
    explicit MotionGenerator(const StochasticMotion &motion);

    unsigned int n_variables() const { return n_random; }
    unsigned int n_samples() const { return n_points; }
    /// Held (piecewise constant) rather than linear between samples.
    bool held() const { return settings.method == StochasticMethod::white_noise; }
    /// Two-sided PSD of the stationary (unmodulated) process, m^2/s^3.
    double target_psd(double omega) const;
    /// Highest frequency represented (spectral representation: the cutoff;
    /// otherwise the Nyquist frequency pi / dt).
    double cutoff_frequency() const { return cutoff; }
    const StochasticMotion &motion() const { return settings; }
    std::string description() const;

    /// values (resized to n_samples()) from n_variables() normals.
    void generate(const double *normals, std::vector<double> &values) const;
    /// The sample of (seed, realization) of the settings.
    GroundMotion ground_motion() const;

  private:
    StochasticMotion       settings;
    unsigned int           n_points = 0, n_random = 0;
    double                 cutoff   = 0;
    double                 noise_scale = 0;
    std::array<double, 16> propagator{};   // filter state over one interval
    std::array<double, 4>  noise_gain{};   // response to a held unit input
    std::array<double, 4>  output{};       // a = output . state
    unsigned int           n_states = 2;
    std::vector<double>    omegas, amplitudes, envelope_values;
  };

  struct EnsemblePsd
  {
    std::vector<double> omega;    // rad/s, 0 .. cutoff
    std::vector<double> estimate; // two-sided, m^2/s^3
    std::vector<double> target;   // S(omega) of the generator
  };

  /// Averaged periodogram S(w_k) = dt / (2 pi n) |sum_j a_j e^(-i w_k t_j)|^2
  /// of realizations 0..n_realizations-1, divided by the mean square of the
  /// envelope (so a slowly varying envelope leaves the stationary PSD), and
  /// averaged over `band` neighbouring frequencies, up to max_omega.
  EnsemblePsd ensemble_psd(const MotionGenerator &generator, unsigned int n_realizations,
                           unsigned int band, double max_omega);

  /// Realizations 0..n-1 of a generator's motion, each sample times `scale`.
  struct MotionSamples
  {
    std::vector<std::vector<double>> realizations; // [r][k], m/s^2
    double mean_square = 0; // over every sample of every realization, m^2/s^4
  };

  /// The samples of realizations 0..n_realizations-1 (the standard normals
  /// of (seed, r)), times `scale`. Stops between realizations on SIGINT/SIGTERM.
  MotionSamples sample_realizations(const MotionGenerator &generator,
                                    unsigned int n_realizations, double scale);

  /// One sample of the motion (all methods), modulated by the envelope.
  GroundMotion generate_ground_motion(const StochasticMotion &motion);

  /// S0 giving the target PGA with peak factor p: PGA^2 / (p^2 sigma^2(S0=1)).
  double intensity_from_pga(const FilterParameters &filter, double pga, double peak_factor);
} // namespace poundfe

#endif
