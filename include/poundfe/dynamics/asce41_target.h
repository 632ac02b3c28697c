// The target displacement of ASCE/SEI 41-17's nonlinear static procedure
// (the coefficient method, §7.4.3.3) from a pushover curve (V_i, Delta_i) of
// base shear against the control node's displacement, from (0, 0):
//   delta_t = C0 C1 C2 S_a T_e^2 / (4 pi^2)          (7-28; S_a in m/s^2)
//   bilinear idealisation (§7.4.3.2.4): from the origin with the secant
//     stiffness K_e of the curve at 0.6 V_y to (Delta_y, V_y), Delta_y =
//     V_y / K_e, then to the curve's point (Delta_d, V_d) at the target or
//     at the largest base shear (a plateau's end, within 1e-6 of it),
//     whichever is less; V_y <= the largest base
//     shear; the areas under both equal to Delta_d:
//       V_y Delta_d + V_d (Delta_d - Delta_y) = 2 A(Delta_d)
//     post-yield ratio alpha_1 = (V_d - V_y) / (Delta_d - Delta_y) / K_e
//   T_e = T_i sqrt(K_i / K_e)                             (7-27)
//   mu_strength = S_a / (V_y / W) C_m                     (7-31)
//     (C_m of Table 7-4, 1 when T_e > 1 s)
//   C1 = 1 + (mu_strength - 1) / (a T_e^2), T_e >= 0.2 s used, C1 = 1 for
//     T_e > 1 s; a = 130 (site class A, B), 90 (C), 60 (D, E, F)   (7-29)
//   C2 = 1 + ((mu_strength - 1) / T_e)^2 / 800, C2 = 1 for T_e > 0.7 s (7-30)
//   C0: the first mode's participation factor times its ordinate at the
//     control node (§7.4.3.3.2, first way)
//   strength degradation (§7.4.3.3.2): where the curve falls past
//     (Delta_d, V_d), alpha_2 = the slope to where it degrades to 0.6 V_y
//     (or to its last point) over K_e; mu_max = Delta_d / Delta_y +
//     |alpha_e|^-h / 4, h = 1 + 0.15 ln T_e                (7-32)
//     with alpha_e = alpha_2 (7-33 with lambda = 1: the whole fall counted
//     as strength degradation, P-Delta not told apart); mu_strength >
//     mu_max calls for a nonlinear dynamic procedure.
// delta_t depends on the idealisation through T_e and V_y and the
// idealisation on delta_t through Delta_d: the two are iterated to their
// fixed point. mu_strength < 1 (elastic response): C1 = C2 = 1.
// Source: ASCE/SEI 41-17, Seismic Evaluation and Retrofit of Existing
// Buildings, §7.4.3.2.4 and §7.4.3.3; FEMA 440 (2005) ch. 5 and 10.
#ifndef poundfe_dynamics_asce41_target_h
#define poundfe_dynamics_asce41_target_h

#include <poundfe/base/choices.h>

#include <functional>
#include <limits>
#include <vector>

namespace poundfe
{
  /// The site classes of ASCE 7 (§20.3), which set C1's factor a.
  enum class SiteClass
  {
    A,
    B,
    C,
    D,
    E,
    F
  };

  const NameTable<SiteClass> &site_class_names();

  /// C1's factor a of the site class (7-29).
  double asce41_site_factor(SiteClass site_class);

  /// The bilinear idealisation of §7.4.3.2.4 to (Delta_d, V_d).
  struct Asce41Bilinear
  {
    double yield_force         = 0; // V_y, N
    double yield_displacement  = 0; // Delta_y, m
    double effective_stiffness = 0; // K_e = V_y / Delta_y, N/m
    double end_displacement    = 0; // Delta_d, m
    double end_force           = 0; // V_d, N
    double post_yield_ratio    = 0; // alpha_1
    /// The curve is straight to Delta_d: it has no yield point there and
    /// V_y = V_d, Delta_y = Delta_d.
    bool elastic = false;
  };

  /// The idealisation of the curve (d_i, V_i), d_0 = V_0 = 0, d ascending,
  /// to `end_displacement` (0 < Delta_d <= d.back()), the areas by the
  /// trapezoidal rule.
  Asce41Bilinear asce41_bilinear(const std::vector<double> &d, const std::vector<double> &V,
                                 double end_displacement);

  /// C1 and C2 of mu_strength at the effective period (7-29, 7-30).
  struct Asce41Coefficients
  {
    double c1 = 1, c2 = 1;
  };
  Asce41Coefficients asce41_coefficients(double strength_ratio, double effective_period,
                                         SiteClass site_class);

  /// What the coefficient method takes besides the curve.
  struct Asce41Building
  {
    double    initial_period = 0; // T_i, s: the first mode's
    double    c0             = 1; // the first mode's participation at the control node
    double    mass           = 0; // W / g, kg
    double    mass_factor    = 1; // C_m (Table 7-4)
    SiteClass site_class     = SiteClass::D;
  };

  struct Asce41Target
  {
    Asce41Bilinear bilinear;
    double initial_stiffness     = 0; // K_i, N/m: the curve's first segment
    double effective_period      = 0; // T_e, s
    double spectral_acceleration = 0; // S_a(T_e), m/s^2
    double mass_factor           = 1; // C_m as applied (1 when T_e > 1 s)
    double strength_ratio        = 0; // mu_strength
    double c0 = 1, c1 = 1, c2 = 1;
    double target = 0; // delta_t, m
    unsigned int iterations = 0;
    bool         converged  = false;
    /// delta_t beyond the curve's last point: the push stopped short of it.
    bool beyond_curve = false;
    /// Strength degradation: alpha_2 (= alpha_e) and mu_max, NaN where the
    /// curve does not fall past (Delta_d, V_d).
    double degrading_slope_ratio = std::numeric_limits<double>::quiet_NaN();
    double max_strength_ratio    = std::numeric_limits<double>::quiet_NaN();
    bool   exceeds_strength_limit = false; // mu_strength > mu_max
  };

  /// The target displacement of the curve (d_i, V_i) (as asce41_bilinear)
  /// under the 5 %-damped spectrum `spectrum` (T -> S_a, m/s^2).
  Asce41Target asce41_target(const std::vector<double> &d, const std::vector<double> &V,
                             const Asce41Building &building,
                             const std::function<double(double)> &spectrum);
} // namespace poundfe

#endif
