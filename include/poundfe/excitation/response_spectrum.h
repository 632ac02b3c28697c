// Elastic response spectra and intensity measures of an acceleration history.
//
// Spectral oscillator (relative displacement u of a unit mass on the ground):
//   u'' + 2 zeta omega u' + omega^2 u = -a(t),   omega = 2 pi / T,  0 <= zeta < 1,
// with a(t) linear between samples (a "piecewise-linear" excitation). Over a
// step h from (u0, v0) under a0 -> a1 the solution is exact (Nigam &
// Jennings 1969, eq. 8-9):
//   [u1; v1] = A(omega, zeta, h) [u0; v0] + B(omega, zeta, h) [a0; a1],
//   A = exp(Z), Z = h [[0, 1], [-omega^2, -2 zeta omega]],
//   B = -h [ (phi1(Z) - phi2(Z)) e, phi2(Z) e ],  e = [0; 1],
//   phi1(Z) = sum_k Z^k / (k + 1)!,  phi2(Z) = sum_k Z^k / (k + 2)!.
// A and B are evaluated by Nigam & Jennings's closed forms (e^(-zeta omega h),
// sin and cos of omega_d h, omega_d = omega sqrt(1 - zeta^2)) when
// omega h >= 0.2, and by the series above when omega h < 0.2, where the
// closed forms lose digits to cancellation (their terms grow like
// 1/(omega h)^3 while B shrinks like h^2: a sub-step of a contact, h = 1e-6 s,
// would leave no correct digit).
// Peaks are taken at the samples and at least 200 times per period T (a step
// longer than T/200 is cut into equal sub-steps, still exact since a(t) stays
// linear), so a sampled peak is at most 1 - cos(pi/200) = 1.2e-4 below the
// true one. After the record ends the oscillator keeps vibrating freely:
// response_spectrum() follows it for one more longest period (a(t) = 0).
//   Sd = max_t |u|,  PSV = omega Sd,  PSA = omega^2 Sd,
//   Sv = max_t |u'| (relative velocity),
//   Sa = max_t |u'' + a| = max_t |2 zeta omega u' + omega^2 u| (absolute).
//
// Intensity measures (a in m/s^2, linear between samples, or held over each
// interval for white noise):
//   PGA = max |a|;  v(t) = int_0^t a,  d(t) = int_0^t v, both exact for the
//   piecewise-linear a (v: the trapezoidal rule; d_{i+1} = d_i + h v_i +
//   h^2 (2 a_i + a_{i+1}) / 6); PGV = max |v|, PGD = max |d|, exact: the
//   extrema inside a step (where a = 0, where v = 0) included; with NO
//   baseline correction (a record's PGD then includes the drift of its
//   baseline; a generated motion's that of its random walk).
//   Arias intensity I_A = pi / (2 g) int_0^T a^2 dt (Arias 1970), m/s;
//   significant durations D5-75 = t75 - t5 and D5-95 = t95 - t5, the times
//   at which the Husid curve int_0^t a^2 reaches 5 %, 75 % and 95 % of its
//   final value (Trifunac & Brady 1975), located exactly inside the step;
//   cumulative absolute velocity CAV = int_0^T |a| dt (EPRI 1988), exact for
//   the piecewise-linear a (a step whose ends differ in sign: its two
//   triangles, h (a0^2 + a1^2) / (2 (|a0| + |a1|))).
//
// Design spectrum: Eurocode 8 (EN 1998-1:2004, section 3.2.2.2, eq. 3.2-3.6),
// horizontal elastic spectrum of type 1 (Table 3.2) or type 2 (Table 3.3):
//   0 <= T <= TB:  Se = ag S (1 + T/TB (2.5 eta - 1))
//   TB <= T <= TC: Se = 2.5 ag S eta
//   TC <= T <= TD: Se = 2.5 ag S eta TC / T
//   TD <= T:       Se = 2.5 ag S eta TC TD / T^2   (defined to 4 s; continued)
//   eta = sqrt(10 / (5 + xi)) >= 0.55, xi the viscous damping ratio in percent.
//
// References
//   Nigam, N. C. & Jennings, P. C. (1969). Calculation of response spectra
//     from strong-motion earthquake records. Bulletin of the Seismological
//     Society of America 59(2), 909-922.
//   Arias, A. (1970). A measure of earthquake intensity. In R. J. Hansen (ed.),
//     Seismic Design for Nuclear Power Plants, MIT Press, 438-483.
//   Trifunac, M. D. & Brady, A. G. (1975). A study on the duration of strong
//     earthquake ground motion. Bulletin of the Seismological Society of
//     America 65(3), 581-626.
//   EPRI (1988). A criterion for determining exceedance of the operating
//     basis earthquake. Report NP-5930, Electric Power Research Institute.
//   Husid, R. (1969). Caracteristicas de terremotos. Analisis general. Revista
//     del IDIEM 8, 21-42.
//   CEN (2004). EN 1998-1:2004 Eurocode 8: Design of structures for earthquake
//     resistance. Part 1: General rules, seismic actions and rules for
//     buildings. Section 3.2.2.2, Tables 3.2 and 3.3.
#ifndef poundfe_excitation_response_spectrum_h
#define poundfe_excitation_response_spectrum_h

#include <poundfe/excitation/ground_motion.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  /// The exact step of one oscillator: [u1; v1] = A [u0; v0] + B [a0; a1],
  /// row-major (A = {a00, a01, a10, a11}).
  struct OscillatorStep
  {
    std::array<double, 4> A{}, B{};
  };

  /// The step of h for omega > 0, 0 <= zeta < 1, h > 0: the closed form for
  /// omega h >= 0.2, the series below.
  OscillatorStep nigam_jennings_step(double omega, double zeta, double h);
  /// The two evaluations on their own (for the tests of their agreement).
  OscillatorStep nigam_jennings_closed_form(double omega, double zeta, double h);
  OscillatorStep nigam_jennings_series(double omega, double zeta, double h);

  /// Samples per period at which peaks are looked for (at least).
  constexpr unsigned int spectrum_samples_per_period = 200;

  /// A bank of spectral oscillators (every period for every damping ratio)
  /// driven by one acceleration history that arrives a sample at a time, at
  /// any (varying) step: a record, or a floor's absolute acceleration seen
  /// by a step observer (contact sub-steps included). Nothing is stored but
  /// the oscillators' states and peaks.
  class SpectralOscillators
  {
  public:
    SpectralOscillators(std::vector<double> periods, std::vector<double> damping_ratios);

    /// At rest at time t under acceleration a; peaks forgotten.
    void start(double t, double a);
    /// Advance from the last sample to (t, a), a linear in between. A
    /// sample at (within 1e-12 s of) the last time only replaces its value.
    void advance_to(double t, double a);
    /// Advance by h under a0 -> a1 (linear); the last sample becomes (t + h, a1).
    void advance(double h, double a0, double a1);
    /// Free vibration (a = 0) for one longest period: the peaks after a
    /// record that has ended.
    void add_free_vibration();

    const std::vector<double> &periods() const { return period; }
    const std::vector<double> &damping_ratios() const { return damping; }
    /// Peaks of oscillator (damping d, period i), index d * n_periods + i.
    unsigned int index(unsigned int d, unsigned int i) const { return d * period.size() + i; }
    const std::vector<double> &peak_displacement() const { return max_u; }
    const std::vector<double> &peak_velocity() const { return max_v; }
    const std::vector<double> &peak_absolute_acceleration() const { return max_a; }
    double last_time() const { return time; }
    /// The oscillators' present relative displacement and velocity.
    const std::vector<double> &displacement() const { return u; }
    const std::vector<double> &velocity() const { return v; }

  private:
    /// Coefficients (and sub-steps) of every oscillator for a step h.
    void prepare(double h);

    std::vector<double>         period, damping;
    std::vector<double>         omega, zeta; // per oscillator
    std::vector<OscillatorStep> steps;       // for h / n_substeps, per oscillator
    std::vector<unsigned int>   n_substeps;
    double                      prepared_h = -1;
    std::vector<double>         u, v, max_u, max_v, max_a;
    double                      time = 0, last_a = 0;
  };

  struct ResponseSpectrum
  {
    std::vector<double> periods;        // s
    std::vector<double> damping_ratios; // fractions of critical
    /// Per damping ratio d, per period i (index d * n_periods + i).
    std::vector<double> displacement;   // Sd, m
    std::vector<double> relative_velocity;     // Sv, m/s
    std::vector<double> absolute_acceleration; // Sa, m/s^2

    unsigned int n_periods() const { return periods.size(); }
    double sd(unsigned int d, unsigned int i) const { return displacement[d * periods.size() + i]; }
    double omega(unsigned int i) const;
    double psv(unsigned int d, unsigned int i) const { return omega(i) * sd(d, i); }
    double psa(unsigned int d, unsigned int i) const { return omega(i) * omega(i) * sd(d, i); }
  };

  /// The spectrum of a ground motion (linear between samples, or held when
  /// the motion is), free vibration after its end included.
  ResponseSpectrum response_spectrum(const GroundMotion &motion, const std::vector<double> &periods,
                                     const std::vector<double> &damping_ratios);

  struct GroundMotionIntensity
  {
    double pga = 0, pgv = 0, pgd = 0; // m/s^2, m/s, m (no baseline correction)
    double arias_intensity = 0;       // m/s
    double cumulative_absolute_velocity = 0; // CAV, m/s
    double t5 = 0, t75 = 0, t95 = 0;  // s, 5, 75 and 95 % of the Husid curve
    double significant_duration = 0;  // D5-95, s
    double significant_duration_5_75 = 0; // D5-75, s
    double duration = 0;              // of the record, s
  };

  GroundMotionIntensity ground_motion_intensity(const GroundMotion &motion);

  enum class DesignSpectrum
  {
    none,
    ec8_type_1,
    ec8_type_2
  };

  enum class GroundType
  {
    A,
    B,
    C,
    D,
    E
  };

  /// Soil factor S and corner periods TB, TC, TD (s) of EN 1998-1 Table 3.2
  /// (type 1) or 3.3 (type 2).
  struct Ec8GroundParameters
  {
    double S = 1, TB = 0, TC = 0, TD = 0;
  };
  Ec8GroundParameters ec8_ground_parameters(DesignSpectrum type, GroundType ground);

  /// eta = sqrt(10 / (5 + 100 zeta)), not below 0.55.
  double ec8_damping_correction(double zeta);

  /// Se(T) of EN 1998-1 eq. 3.2-3.5 in the units of ag (e.g. m/s^2).
  double ec8_elastic_spectrum(DesignSpectrum type, GroundType ground, double ag, double zeta,
                              double period);

  /// "5pct" for zeta = 0.05: the suffix of a damping ratio's columns.
  std::string damping_label(double zeta);

  /// n periods from t_min to t_max, logarithmically or evenly spaced.
  std::vector<double> period_grid(double t_min, double t_max, unsigned int n, bool logarithmic);
} // namespace poundfe

#endif
