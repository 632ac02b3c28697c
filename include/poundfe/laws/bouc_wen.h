// Bouc-Wen hysteresis (Wen 1976) with Baber-Noori degradation (Baber & Noori
// 1985), for a hinge moment-rotation or a storey force-drift:
//   F      = alpha k u + (1 - alpha) k u_y z
//   dz/du  = ( A - nu |z|^n (beta sgn(du z) + gamma) ) / (eta u_y)
//   A = A0 - dA eps,  nu = 1 + dnu eps,  eta = 1 + deta eps,
//   eps    = int z du / u_y   (hysteretic energy over (1 - alpha) k u_y^2).
// The rate-independent ODE in u is integrated over the step by the
// generalised midpoint rule (theta = 1 backward Euler, 1/2 trapezoidal):
//   z1 = z0 + (du/u_y) [ (1 - theta) g(z0, eps0) + theta g(z1, eps1) ],
//   eps1 = eps0 + du (z0 + z1) / (2 u_y),  g = dz/du u_y,
// solved by a local Newton iteration started from the committed z0 (never
// from an arbitrary guess), safeguarded by backtracking. The tangent dF/du
// is the exact derivative of that discrete map (implicit function theorem),
// so the global Newton iteration converges quadratically.
// Sources: doc/theory.md §2; Y.K. Wen, J. Eng. Mech. Div. ASCE 102 (1976) 249;
// T.T. Baber & M.N. Noori, J. Eng. Mech. 111 (1985) 1010.
#ifndef poundfe_laws_bouc_wen_h
#define poundfe_laws_bouc_wen_h

#include <poundfe/laws/uniaxial_law.h>

namespace poundfe
{
  struct BoucWenParameters
  {
    double       stiffness         = 0; // k: initial stiffness (N/m or N m/rad)
    double       yield_deformation = 0; // u_y (m or rad)
    double       alpha             = 0.1;
    double       A                 = 1.0;
    double       beta              = 0.5;
    double       gamma             = 0.5;
    double       n                 = 2.0;
    double       delta_A           = 0.0;
    double       delta_nu          = 0.0;
    double       delta_eta         = 0.0;
    double       theta             = 0.5; // 1: backward Euler, 1/2: trapezoidal
    double       tolerance         = 1e-12; // on the residual of z (dimensionless)
    unsigned int max_iterations    = 30;
  };

  class BoucWen : public UniaxialLaw
  {
  public:
    explicit BoucWen(const BoucWenParameters &parameters);

    bool   set_trial(double deformation, double rate) override;
    double force() const override { return trial_force; }
    double tangent() const override { return trial_tangent; }
    double stored_energy() const override;
    double history_variable() const override { return trial.z; }
    double yield_deformation() const override { return p.yield_deformation; }
    double initial_stiffness() const override { return p.stiffness; }
    void   commit() override;
    void   revert() override;
    void   reset() override;
    std::string failure() const override { return failure_message; }

    /// Normalised dissipated energy eps of the trial state.
    double normalised_energy() const { return trial.epsilon; }
    const BoucWenParameters &parameters() const { return p; }

  private:
    struct State
    {
      double deformation = 0;
      double z           = 0;
      double epsilon     = 0;
      double direction   = 1; // sign of the last nonzero increment
    };
    /// g = u_y dz/du and its partial derivatives in z and eps.
    struct Rate
    {
      double g, g_z, g_epsilon;
    };
    Rate   rate_of(double z, double epsilon, double direction) const;
    double force_of(double deformation, double z) const;

    BoucWenParameters p;
    State             committed, trial;
    double            trial_force   = 0;
    double            trial_tangent = 0;
    std::string       failure_message;
  };
} // namespace poundfe

#endif
