// The interface of a history-dependent force-deformation law of one
// deformation measure d (a hinge rotation, a storey drift, a gap closure),
// after OpenSees's UniaxialMaterial (setTrialStrain / getStress / getTangent /
// commitState / revertToLastCommit / revertToStart):
//   set_trial(d, d_dot)  -> force(), tangent() = dF/dd, damping_tangent() = dF/dd_dot
//   commit()             -> the trial state becomes the committed state
//   revert()             -> the trial state is the committed state again, exactly
// A law never changes its committed state except in commit(), so a rejected
// Newton iteration or a cut step costs nothing but a revert().
#ifndef poundfe_laws_uniaxial_law_h
#define poundfe_laws_uniaxial_law_h

#include <string>

namespace poundfe
{
  class UniaxialLaw
  {
  public:
    virtual ~UniaxialLaw() = default;

    /// The time at the end of the step about to be tried (laws driven by a
    /// moving surface need it; set before set_trial).
    virtual void set_trial_time(double) {}
    /// Evaluate the trial state at the end of the step. Returns false when
    /// the law's own iteration fails; failure() then says why, and the
    /// trial state must not be used (revert() or a new set_trial()).
    virtual bool set_trial(double deformation, double rate) = 0;

    virtual double force() const = 0;
    /// dF/dd at the trial state, consistent with the law's integration.
    virtual double tangent() const = 0;
    /// dF/dd_dot at the trial state (rate-dependent laws only).
    virtual double damping_tangent() const { return 0; }
    /// Recoverable energy of the trial state; the work done on the law minus
    /// this is what the law dissipated.
    virtual double stored_energy() const = 0;
    /// Whether the law can dissipate at all: an elastic law (an undamped
    /// contact law) cannot. The energy balance does not use it yet
    /// (element_dissipation, integration/time_stepper.h: the quadrature of
    /// an elastic gap's work would move into the balance error).
    virtual bool dissipates() const { return true; }
    /// Work done on the structure, from the committed to the trial state, by
    /// what drives the law (a moving belt); 0 for passive laws.
    virtual double supplied_work_increment() const { return 0; }
    /// A law-specific internal variable reported in outputs (Bouc-Wen: z).
    virtual double history_variable() const { return 0; }
    /// Deformation at which the law yields (for ductility); 0 if none.
    virtual double yield_deformation() const { return 0; }
    /// Initial stiffness dF/dd at the virgin state.
    virtual double initial_stiffness() const = 0;
    /// Contact laws: whether the trial / committed state carries force.
    /// A change between them within a step is an event the integrator
    /// locates by cutting the step.
    virtual bool is_active() const { return false; }
    virtual bool was_active() const { return false; }
    /// The branch of a piecewise law at the trial / committed state (a gap:
    /// open 0, closed 1; friction: stick 0, slip -1 or +1). A change within
    /// a step is an event the integrator locates by cutting the step.
    virtual int phase() const { return is_active(); }
    /// Contact: how long an impact lasts, for the integrator to resolve it
    /// (see NonlinearElement::contact_duration); 0: not a contact.
    virtual double contact_duration(double /*closing_rate*/) const { return 0; }
    virtual int committed_phase() const { return was_active(); }

    virtual void commit() = 0;
    virtual void revert() = 0;
    /// Back to the virgin state.
    virtual void reset() = 0;

    /// Why set_trial returned false, with the values (a law whose
    /// set_trial can refuse overrides it); empty: the law gave no reason.
    virtual std::string failure() const { return {}; }
  };
} // namespace poundfe

#endif
