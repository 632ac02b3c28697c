// The capacity curve of a pushover as an equivalent single-degree-of-freedom
// system and the N2 method's target displacement (EN 1998-1:2004 Annex B):
//   Gamma = m* / sum m_i Phi_i^2, m* = sum m_i Phi_i (Phi_n = 1 at the
//   control node), F* = F_b / Gamma, d* = d_n / Gamma            (B.1-B.3)
//   elastic-perfectly plastic idealisation of equal energy: F_y* = the
//   largest F* up to d_m* (the mechanism), E_m* the area under the curve to
//   d_m*, d_y* = 2 (d_m* - E_m* / F_y*)                            (B.6)
//   T* = 2 pi sqrt(m* d_y* / F_y*)                                 (B.7)
//   d_et* = S_e(T*) (T* / 2 pi)^2                                  (B.8)
//   T* < T_C: d_t* = d_et* when F_y* / m* >= S_e(T*), else
//     d_t* = d_et* / q_u (1 + (q_u - 1) T_C / T*) >= d_et*,
//     q_u = S_e(T*) m* / F_y*                                       (B.10-B.11)
//   T* >= T_C: d_t* = d_et*                                         (B.9)
//   d_t = Gamma d_t*.
// Source: CEN (2004), EN 1998-1:2004, Annex B; Fajfar, Earthquake Spectra
// 16 (2000) 573-592.
#ifndef poundfe_dynamics_capacity_curve_h
#define poundfe_dynamics_capacity_curve_h

#include <functional>
#include <vector>

namespace poundfe
{
  /// The elastic-perfectly plastic curve of equal energy (B.6).
  struct BilinearCurve
  {
    double yield_force            = 0; // F_y*
    double yield_displacement     = 0; // d_y*
    double ultimate_displacement  = 0; // d_m*
    double energy                 = 0; // E_m*, the area under the curve to d_m*
  };

  /// The idealisation of the curve (d_i, F_i), starting at (0, 0), up to its
  /// last point (d_m = d.back()). The area is the trapezoidal rule's, which
  /// the idealisation keeps exactly.
  BilinearCurve ec8_bilinear(const std::vector<double> &d, const std::vector<double> &F);

  /// The N2 target displacement of the equivalent system.
  struct N2Target
  {
    double period                = 0; // T*
    double spectral_acceleration = 0; // S_e(T*), m/s^2
    double elastic_displacement  = 0; // d_et*
    double reduction             = 1; // q_u (1: the elastic range)
    double target_sdof           = 0; // d_t*
    double target                = 0; // d_t = Gamma d_t*
  };

  /// B.7-B.11 for the idealised curve `sdof` of an equivalent system of
  /// mass `equivalent_mass` (m*) and factor `gamma`, under the elastic
  /// spectrum `spectrum` (T -> S_e, m/s^2) of corner period `tc`.
  N2Target ec8_n2_target(const BilinearCurve &sdof, double equivalent_mass, double gamma,
                         const std::function<double(double)> &spectrum, double tc);
} // namespace poundfe

#endif
