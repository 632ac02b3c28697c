// The first period of each building on its compliant foundation against the
// same building on a fixed base, and the approximate lengthening of ASCE
// 7-16 §19.2.1.1 (NEHRP; Veletsos & Meek 1974):
//   T~ / T = sqrt(1 + k / K_x (1 + K_x h^2 / K_θ)),
// k = 4 π² M* / T² the fixed-base building's stiffness in its first mode
// (M* its effective modal mass), h = Σ m_i φ_i h_i / Σ m_i φ_i its
// effective height (the code's 0.7 W and 0.7 h approximate M* and h; the
// exact first-mode values are used here). For one storey on a massless
// foundation the formula is exact: three springs in series. doc/theory.md
// §1.16.
#ifndef poundfe_dynamics_foundation_periods_h
#define poundfe_dynamics_foundation_periods_h

#include <poundfe/model/model.h>

#include <vector>

namespace poundfe
{
  struct FoundationPeriods
  {
    unsigned int building = 0;
    double fixed_base_period    = 0; // s, the first mode
    double flexible_base_period = 0; // s, the first mode on the foundation
    double effective_stiffness  = 0; // k, N/m
    double effective_height     = 0; // h, m above the base
    double code_ratio           = 0; // T~/T of ASCE 7-16 §19.2.1.1

    double ratio() const { return flexible_base_period / fixed_base_period; }
  };

  /// The same model on fixed bases: every foundation's base node clamped,
  /// the storeys no longer rocked, the foundations gone.
  Model fixed_base_model(const Model &model);

  /// For each foundation of `model` (in order): the periods and the code's
  /// lengthening. Throws NumericalError if a building is a mechanism.
  std::vector<FoundationPeriods> foundation_periods(const Model &model);
} // namespace poundfe

#endif
