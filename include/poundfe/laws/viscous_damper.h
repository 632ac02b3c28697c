// OpenSees 3.8's ViscousDamper (SRC/material/uniaxial/ViscousDamper.cpp, by
// Akcelyan and Lignos, after Kasai and Oohara 2001, "Algorithm and computer
// code to simulate response of nonlinear viscous damper", Passively
// Controlled Structure Symposium, Yokohama): a nonlinear dashpot F = C |v_d|^alpha
// sign(v_d) in series with a spring F = K u_s (the brace), so that the
// force obeys the ordinary differential equation
//     dF/dt = K (v - sign(F) (|F| / C)^(1/alpha)),
// v the strain rate, integrated over OpenSees's time step dt (the `analyze`
// step, OpenSees's global ops_Dt) with v varying linearly from the
// committed rate to the trial rate, by an adaptive method NM: 1
// Dormand-Prince 5(4), 2 Adams-Bashforth-Moulton of order 6, 3 a modified
// Rosenbrock triple; a sub-step h = s dt is accepted when its relative
// error is at most RelTol, its error at most AbsTol, or s = 0.5^MaxHalf,
// and halved otherwise (never doubled again, as in OpenSees). With LGap > 0
// the force is zero while the strain is within LGap of where the force
// last changed sign (a pin's play). Tangent, damping tangent and initial
// tangent are 0, as OpenSees 3.8's, so that a script's Newton iterations
// are OpenSees's.
#ifndef poundfe_laws_viscous_damper_h
#define poundfe_laws_viscous_damper_h

#include <poundfe/laws/uniaxial_law.h>

#include <map>
#include <memory>
#include <string>

namespace poundfe
{
  /// The damper of `values` (OpenSees's names K, C, Alpha, LGap, NM, RelTol,
  /// AbsTol, MaxHalf; the last five OpenSees's defaults when absent),
  /// integrating over `time_step` as it is when a trial is set (the
  /// caller's variable: it must outlive the damper). InputError naming a
  /// value it refuses: K, C or Alpha not > 0 (a negative Alpha is 1, with
  /// OpenSees's warning, before this), NM not 1, 2 or 3, MaxHalf not an
  /// integer from 0 to 30 (more sub-steps than that is a hang).
  std::unique_ptr<UniaxialLaw> make_viscous_damper(const std::map<std::string, double> &values,
                                                   const double                        &time_step);
} // namespace poundfe

#endif
