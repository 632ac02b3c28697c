// Contact (gap) laws: a force that pushes two bodies apart once their
// closure d exceeds the initial gap g. Penetration delta = d - g, its rate
// delta_dot > 0 while the bodies approach. The force is zero for delta <= 0
// and is never tensile: a damped law whose force would turn negative during
// restitution is clipped to zero (Anagnostopoulos 1988 and later).
// Each law lives in its own file, source/laws/<law>.cc, and implements
// respond(delta, delta_dot): force, dF/d delta and dF/d delta_dot of the
// unclipped law for delta > 0; that file also defines the law's registry
// entry (ContactLawType below).
// The damping parameter is given, or derived from a coefficient of
// restitution e by the law's literature formula (doc/theory.md §4) or by an
// exact calibration: the value for which a single impact of the effective
// mass on a rigid wall, simulated with this very law, returns e.
#ifndef poundfe_laws_contact_law_h
#define poundfe_laws_contact_law_h

#include <poundfe/laws/uniaxial_law.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace poundfe
{
  struct ContactLawParameters
  {
    std::string law = "hertz-damp"; // a registered name: contact_law_names()
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
    /// Only with a damping parameter: the contact laws' springs are elastic.
    bool   dissipates() const override { return p.damping > 0; }
    /// Why set_trial refused its state: the closure, its rate or the force
    /// not finite, with the values.
    std::string failure() const final;
    /// Penetration beyond the initial gap (negative: open).
    double history_variable() const override { return trial.penetration; }
    double initial_stiffness() const override { return 0; }
    bool   is_active() const override { return trial.force > 0; }
    bool   was_active() const override { return committed.force > 0; }
    /// elastic_impact_duration at the approach velocity of the committed
    /// contact, or at `closing_rate` when open.
    double contact_duration(double closing_rate) const override;
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
      /// set_trial's arguments, for failure()
      double closure = 0;
    };
    State committed, trial;
    /// Whether the registry says impacts last pi sqrt(m/k); -1: not looked up yet.
    mutable int linear_impact = -1;
  };

  /// A contact law as the program knows it: the registry holds one per
  /// name. A law is one file, source/laws/<law>.cc, that defines its class
  /// and its type; built-in laws are listed in source/laws/contact_law_registry.cc,
  /// others (tests, extensions) register through a ContactLawRegistrar.
  struct ContactLawType
  {
    std::string name;
    /// The force, for the input documentation ("k d^1.5").
    std::string formula;
    std::function<std::unique_ptr<ContactLaw>(const ContactLawParameters &)> make;
    /// The damping parameter from a coefficient of restitution e by the
    /// law's literature formula (`variant`: Contact/Hertz-damp formula);
    /// empty for a law without damping.
    std::function<double(double e, const std::string &variant)> damping_from_restitution;
    /// Whether an elastic impact lasts pi sqrt(m/k) (a linear spring)
    /// rather than 2.94 delta_max / v0 (Hertz): simulate_restitution's scale.
    bool linear_impact_duration = false;
  };

  /// The duration of an elastic impact of the effective mass m on the law's
  /// spring at approach velocity v0: pi sqrt(m / k) for a linear law, and
  /// for a Hertz law (k delta^1.5) 2.9432 delta_max / v0 with delta_max =
  /// (5 m v0^2 / (4 k))^(2/5) (Goldsmith 1960, Impact, §4.2). 0 if v0 <= 0
  /// for a Hertz law.
  double elastic_impact_duration(const ContactLawParameters &parameters, double v0);

  /// Add a law to the registry; a name can be registered once.
  void register_contact_law(ContactLawType type);

  /// Registers a law at static initialisation: one object per law, e.g.
  ///   const ContactLawRegistrar quadratic({"quadratic", "k d^2", make, {}, false});
  struct ContactLawRegistrar
  {
    explicit ContactLawRegistrar(ContactLawType type) { register_contact_law(std::move(type)); }
  };

  /// The registered law of that name; std::invalid_argument if none.
  const ContactLawType &contact_law_type(const std::string &name);

  /// Registered law names: the built-in laws, then the others in the order
  /// they were registered.
  std::vector<std::string> contact_law_names();

  std::unique_ptr<ContactLaw> make_contact_law(const ContactLawParameters &parameters);

  /// Whether the law has a damping parameter (linear and Hertz have none).
  bool contact_law_is_damped(const std::string &law);

  /// The law's literature formula for the damping parameter from e
  /// (doc/theory.md §4; each law's file names its source); 0 for a law
  /// without damping.
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
