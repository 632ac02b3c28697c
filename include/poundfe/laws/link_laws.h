// Laws of the links between adjacent buildings (dampers and connectors at a
// pair of floors), on the relative displacement d = u_left - u_right and
// its rate v = d_dot:
//   viscous damper   F = c |v|^alpha sgn(v), 0 < alpha <= 1, regularised as
//                    F = c v (v^2 + v_eps^2)^((alpha - 1)/2)   (alpha < 1)
//                    so that dF/dv = c (alpha v^2 + v_eps^2)(v^2 + v_eps^2)^((alpha-3)/2)
//                    stays finite (c v_eps^(alpha-1) at v = 0) and Newton
//                    converges; alpha = 1 is exactly F = c v;
//   Kelvin-Voigt     F = k d + c |v|^alpha sgn(v) (spring and damper in parallel);
//   Maxwell          spring k in series with a linear dashpot c: F = k (d - z)
//                    = c z_dot, the dashpot stroke z integrated by the
//                    trapezoidal rule z1 = z0 + dt/(2c) (F0 + F1), so
//                    F1 = (k (d1 - z0) - a F0) / (1 + a), a = k dt/(2c),
//                    dF1/dd1 = k / (1 + a);
//   elastic-plastic  bilinear with kinematic hardening (post-yield stiffness
//                    r k), by return mapping.
// Sources: C. Christopoulos & A. Filiatrault, Principles of Passive
// Supplemental Damping and Seismic Isolation, IUSS Press 2006, ch. 5
// (F = c|v|^alpha sgn v, the energy per cycle); J.C. Simo & T.J.R. Hughes,
// Computational Inelasticity, Springer 1998, §1.4 (return mapping with
// kinematic hardening) and §10.3 (the Maxwell element by the generalised
// midpoint rule). The regularisation is this program's choice: the smooth
// form |v| -> sqrt(v^2 + v_eps^2) under the power, which changes the force
// by a relative (1 - alpha) v_eps^2 / (2 v^2) for |v| >> v_eps; OpenSees's
// Viscous material instead keeps the exact force and bounds the tangent at a
// minimum velocity (OpenSees command manual, uniaxialMaterial Viscous).
// doc/theory.md §1.14.
#ifndef poundfe_laws_link_laws_h
#define poundfe_laws_link_laws_h

#include <poundfe/laws/uniaxial_law.h>

#include <memory>
#include <string>

namespace poundfe
{
  enum class LinkKind
  {
    viscous,
    kelvin_voigt,
    maxwell,
    elastic_plastic
  };

  /// The input's name of a link kind (also its label suffix).
  std::string link_kind_name(LinkKind kind);

  struct LinkLawParameters
  {
    LinkKind kind      = LinkKind::viscous;
    double   stiffness = 0; // k, N/m (Kelvin-Voigt, Maxwell, elastic-plastic)
    double   damping   = 0; // c, N (s/m)^alpha (viscous, Kelvin-Voigt, Maxwell)
    double   exponent  = 1; // alpha in (0, 1] (viscous, Kelvin-Voigt)
    double   yield_force = 0; // F_y, N (elastic-plastic)
    double   hardening   = 0; // r in [0, 1): post-yield stiffness r k (elastic-plastic)
    /// v_eps of the regularised damper (alpha < 1), m/s.
    double   regularization_velocity = 1e-6;
  };

  /// The regularised damper force c v (v^2 + v_eps^2)^((alpha-1)/2) and
  /// its derivative dF/dv (exactly c v and c for alpha = 1).
  struct DamperResponse
  {
    double force, damping_tangent;
  };
  DamperResponse damper_response(const LinkLawParameters &p, double velocity);

  /// The law of a link (UniaxialLaw: trial / commit / revert).
  std::unique_ptr<UniaxialLaw> make_link_law(const LinkLawParameters &parameters);
} // namespace poundfe

#endif
