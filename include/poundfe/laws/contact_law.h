// Contact (gap) laws: a force that pushes two bodies apart once their
// closure d exceeds the initial gap g. Penetration delta = d - g, its rate
// delta_dot > 0 while the bodies approach. The force is zero for delta <= 0
// and is never tensile: a damped law whose force would turn negative during
// restitution is clipped to zero (Anagnostopoulos 1988 and later).
// Each law lives in its own file and implements respond(delta, delta_dot):
// force, dF/d delta and dF/d delta_dot of the unclipped law for delta > 0.
// The damping parameter is given, or derived from a coefficient of
// restitution e by the law's literature formula (doc/theory.md §4) or by an
// exact calibration: the value for which a single impact of the effective
// mass on a rigid wall, simulated with this very law, returns e.
#ifndef poundfe_laws_contact_law_h
#define poundfe_laws_contact_law_h

#include <poundfe/laws/uniaxial_law.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  struct ContactLawParameters
  {
    std::string law = "hertz-damp"; // linear|kelvin-voigt|modified-kelvin-voigt|hertz|hertz-damp|jankowski
    double      stiffness      = 0; // k (N/m) or k_h, beta (N/m^1.5)
    double      damping        = 0; // xi (Kelvin-Voigt, Jankowski) or xi_bar (Hertz-damp)
    double      effective_mass = 0; // m_e, kg (Kelvin-Voigt, Jankowski)
    double      initial_gap    = 0; // m
  };

  class ContactLaw : public UniaxialLaw
  {
  public:
    explicit ContactLaw(const ContactLawParameters &parameters);

    bool   set_trial(double closure, double rate) final;
    double force() const final { return trial.force; }
    double tangent() const final { return trial.stiffness; }
    double damping_tangent() const final { return trial.damping; }
    double stored_energy() const final;
    /// Penetration beyond the initial gap (negative: open).
    double history_variable() const override { return trial.penetration; }
    double initial_stiffness() const override { return 0; }
    bool   is_active() const override { return trial.force > 0; }
    bool   was_active() const override { return committed.force > 0; }
    void   commit() override { committed = trial; }
    void   revert() override { trial = committed; }
    void   reset() override;

    const ContactLawParameters &parameters() const { return p; }

    struct Response
    {
      double force, stiffness, damping;
    };
    /// The unclipped law for penetration > 0; `approach_velocity` is the
    /// rate with which this contact began (Hertz-damp needs it).
    virtual Response respond(double penetration, double rate,
                             double approach_velocity) const = 0;
    /// Recoverable (elastic) energy at a penetration.
    virtual double elastic_energy(double penetration) const = 0;

  protected:
    ContactLawParameters p;

  private:
    struct State
    {
      double penetration = 0, rate = 0, force = 0, stiffness = 0, damping = 0;
      double approach_velocity = 0;
    };
    State committed, trial;
  };

  /// Law names accepted by make_contact_law.
  std::vector<std::string> contact_law_names();

  std::unique_ptr<ContactLaw> make_contact_law(const ContactLawParameters &parameters);

  /// Whether the law has a damping parameter (linear and Hertz have none).
  bool contact_law_is_damped(const std::string &law);

  /// The literature formula for the damping parameter from e (doc/theory.md
  /// §4): Kelvin-Voigt xi = -ln e / sqrt(pi^2 + ln^2 e) (Anagnostopoulos);
  /// modified Kelvin-Voigt xi = (1 - e^2) / (e (e (pi - 2) + 2)) (Mahmoud &
  /// Jankowski 2011); Hertz-damp xi_bar = 3 (1 - e^2) / 4 (Muthukumar &
  /// DesRoches 2006) or 8 (1 - e) / (5 e) (Ye, Li & Zhu 2009, variant
  /// "ye-li-zhu"); Jankowski xi = 9 sqrt(5) (1 - e^2) / (2 e (e (9 pi - 16)
  /// + 16)) (Jankowski 2005).
  double damping_from_restitution_formula(const std::string &law, double e,
                                          const std::string &variant = "");

  /// e of one impact of mass m_e, approaching a rigid wall at v0, with the
  /// law of `parameters` (its gap is ignored): |separation / approach
  /// velocity|, from a fine fourth-order Runge-Kutta integration.
  double simulate_restitution(const ContactLawParameters &parameters, double approach_velocity);

  /// The damping parameter for which simulate_restitution returns e
  /// (bisection on the monotone e(damping), to 1e-8 in e).
  double calibrate_damping(ContactLawParameters parameters, double e, double approach_velocity);
} // namespace poundfe

#endif
