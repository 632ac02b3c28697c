// Dry friction between a mass and a surface moving at the belt velocity v0
// (v0 = 0: the fixed ground), on the relative displacement r = x - v0 t and
// the slip velocity r' = x' - v0:
//   normal force      N(x, x') = max(0, C0(x) + C1 |x| + C2 |x'| + C3 |x'|^3),
//                     C0(x) = C0 - K H (1 - L / sqrt(x^2 + H^2)) when N takes
//                     the vertical reaction of an SD spring (K, L, H) into
//                     account (the thesis's eq. 2.7; elastic_springs.h);
//                     C2 < 0 < C3 makes mu N fall and rise again with the
//                     speed: the cubic friction characteristic of Popp &
//                     Stelter (1990), the thesis's C2, C3 of Fig. 3.2 (c-e);
//   coefficient       mu(r') = mu_k + (mu_s - mu_k) exp(-|r'| / v_s)
//                     (Stribeck curve; v_s = 0: mu_k in slip, mu_s to break
//                     away from stick);
//   Coulomb's law     |F| <= mu_s N in stick (r' = 0), F = mu(r') N sgn(r') in slip.
// Stick is set-valued; two treatments:
//   elastic-plastic   (return mapping, as OpenSees's flat and friction-pendulum
//                     bearings): a stiff stick spring k_s in series with a
//                     rigid-plastic slider at slip s,
//                        F_trial = k_s (r - s_n) + c_s r',
//                        stick if |F_trial| <= mu_lim N (mu_lim = mu_s from
//                        stick, mu(r') from slip): F = F_trial, dF/dx = k_s,
//                        dF/dx' = c_s;
//                        slip otherwise: F = mu(r') N sgn(F_trial),
//                        s = r - F/k_s, dF/dx = mu sgn dN/dx,
//                        dF/dx' = sgn (mu' N + mu dN/dx').
//                     The dashpot c_s = 2 sqrt(k_s m) (critical for the
//                     node's mass m on the stick spring) damps the ringing
//                     of the mass on the stick spring that an undamped one
//                     would keep after every switch to stick: without it
//                     the force in stick oscillates about the true reaction
//                     by up to the jump at the switch (mu_k N - k x), and
//                     breaks away early;
//   regularized       the thesis's smooth sgn: F = mu(r') N tanh(r'/eps),
//                     no state ("stuck" when |r'| <= eps, for statistics).
// A change between stick and slip is an event the integrator locates by
// cutting the step (is_active(): slipping). Work: the structure does
// int F x' dt on the element; the belt does -int F v0 dt on the structure
// (supplied_work_increment); what friction dissipates is
// int F r' dt = work - stored + supplied >= 0.
// Sources: C.A. Coulomb 1785; R. Stribeck 1902; J.C. Simo & T.J.R. Hughes,
// Computational Inelasticity, Springer 1998, §1.2-1.4 (return mapping of the
// frictional slider); OpenSees FlatSliderBearing / Coulomb frictionModel;
// D. Karnopp, J. Dyn. Syst. Meas. Control 107 (1985) 100; K. Popp & P. Stelter,
// Phil. Trans. R. Soc. Lond. A 332 (1990) 89-105 (the cubic characteristic);
// doc/theory.md §8.2.
#ifndef poundfe_laws_friction_h
#define poundfe_laws_friction_h

#include <poundfe/laws/uniaxial_law.h>

namespace poundfe
{
  enum class FrictionModel
  {
    elastic_plastic,
    regularized
  };

  /// N(x, x') and its partial derivatives.
  struct NormalForce
  {
    double constant           = 1; // C0, N
    double per_displacement   = 0; // C1, N/m
    double per_velocity       = 0; // C2, N s/m
    double per_velocity_cubed = 0; // C3, N s^3/m^3
    bool   sd_reaction        = false; // subtract K H (1 - L/sqrt(x^2 + H^2))
    double sd_stiffness       = 0, sd_length = 0, sd_height = 0;

    struct Value
    {
      double n = 0, dx = 0, dv = 0;
    };
    Value operator()(double x, double v) const;
  };

  struct FrictionLawParameters
  {
    FrictionModel model                   = FrictionModel::elastic_plastic;
    double        static_coefficient      = 0.3; // mu_s
    double        kinetic_coefficient     = 0.3; // mu_k
    double        stribeck_velocity       = 0;   // v_s, m/s; 0: no Stribeck curve
    double        belt_velocity           = 0;   // v0, m/s
    double        stick_stiffness         = 0;   // k_s, N/m (elastic-plastic)
    double        stick_damping           = 0;   // c_s, N s/m (elastic-plastic)
    double        regularization_velocity = 1e-3; // eps, m/s (regularized)
    NormalForce   normal;
  };

  class Friction final : public UniaxialLaw
  {
  public:
    explicit Friction(const FrictionLawParameters &parameters);

    void   set_trial_time(double time) override { trial_time = time; }
    bool   set_trial(double deformation, double rate) override;
    double force() const override { return trial.force; }
    double tangent() const override { return trial.tangent; }
    double damping_tangent() const override { return trial.damping_tangent; }
    double stored_energy() const override;
    double supplied_work_increment() const override;
    /// Why set_trial refused its state: the force or tangent not finite, with
    /// the deformation, rate and normal force.
    std::string failure() const override;
    /// The slip s (the slider's position relative to the belt), m.
    double history_variable() const override { return trial.slip; }
    double initial_stiffness() const override { return p.stick_stiffness; }
    /// Slipping.
    bool is_active() const override { return trial.slipping; }
    bool was_active() const override { return committed.slipping; }
    /// Stick 0; slip in the direction of the force, -1 or +1: a reversal
    /// of the slip is an event too.
    int phase() const override { return phase_of(trial); }
    int committed_phase() const override { return phase_of(committed); }

    void commit() override;
    void revert() override;
    void reset() override;

    /// mu(r') in slip and its derivative d mu / d r'.
    double coefficient(double slip_velocity, double &derivative) const;

  private:
    struct State
    {
      double force = 0, tangent = 0, damping_tangent = 0, slip = 0;
      double spring_force = 0; // k_s (r - s), of the stick spring alone
      bool   slipping = false;
    };
    static int phase_of(const State &s)
    {
      return s.slipping ? (s.force > 0) - (s.force < 0) : 0;
    }
    void elastic_plastic(double relative, double slip_velocity, const NormalForce::Value &n);
    void regularized(double slip_velocity, const NormalForce::Value &n);

    FrictionLawParameters p;
    State                 trial, committed;
    double                trial_time = 0, committed_time = 0;
    /// set_trial's arguments and normal force, for failure()
    double trial_deformation = 0, trial_rate = 0, trial_normal = 0;
  };
} // namespace poundfe

#endif
