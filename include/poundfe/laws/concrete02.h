// Concrete02: Concrete01's Kent–Scott–Park compression envelope with
// Yassin's (1994) unloading rule and linear tension softening, as
// OpenSees's Concrete02 (equations in source/laws/concrete02.cc).
#ifndef poundfe_laws_concrete02_h
#define poundfe_laws_concrete02_h

#include <poundfe/laws/concrete01.h>

namespace poundfe
{
  namespace internal
  {
    template <class Material, class State>
    class TypedFibreRun;
  } // namespace internal

  struct Concrete02Parameters
  {
    Concrete01Parameters compression;
    double               lambda = 0.1; // unloading slope at epscu over Ec0, in [0, 1)
    double               ft     = 0;   // tensile strength (Pa), >= 0
    double               Ets    = 0;   // tension softening modulus (Pa), > 0
  };

  struct Concrete02State
  {
    double strain = 0, stress = 0, tangent = 0;
    double min_strain = 0;     // the largest compression reached
    double tension_strain = 0; // the largest tensile strain beyond the zero-stress strain
    // functions of min_strain alone, set with it (an unloading or reloading
    // trial, the most frequent, then evaluates no envelope and no division):
    double min_stress = 0;     // sigma_m, the envelope's stress at min_strain
    double reload_slope = 0;   // Er
    double zero_strain = 0;    // eps_t, where the unloading curve reaches zero stress
  };

  class Concrete02 final : public UniaxialMaterial<Concrete02State>
  {
  public:
    /// With `opensees_dead_band`, OpenSees 3.8's: a strain within DBL_EPSILON
    /// of the committed one keeps the committed history and the last trial's
    /// stress and tangent.
    explicit Concrete02(const Concrete02Parameters &parameters, bool opensees_dead_band = false);

    double initial_stiffness() const override { return envelope.initial_modulus(); }
    double history_variable() const override { return trial.min_strain; }
    /// The tension envelope: Ec0 eps to ft, then ft - Ets (eps - ft/Ec0) down to 0.
    StressPoint tension_envelope(double strain) const;

    Concrete02State virgin() const override;

  private:
    // a section's run of Concrete02 fibres (fibre_section.cc) keeps their
    // states itself: it evaluates them by trial_state and words a refused
    // one by failure()
    template <class Material, class State>
    friend class internal::TypedFibreRun;

    Concrete02State respond(const Concrete02State &from, double strain) const override;
    /// The trial state at `strain` from `from`, `last` the last trial (the
    /// dead band keeps its stress and tangent).
    Concrete02State trial_state(const Concrete02State &from, const Concrete02State &last,
                                double strain) const;
    /// Between the largest compression and the tension side.
    Concrete02State unload_or_reload(const Concrete02State &from, double strain) const;
    /// Sets min_strain = strain on the envelope and what follows from it.
    void set_min_strain(Concrete02State &s, double strain, const StressPoint &on_envelope) const;
    /// The trial in the dead band (OpenSees's): the committed history at
    /// `strain` with the stress and tangent of the last trial.
    Concrete02State in_dead_band(const Concrete02State &from, const Concrete02State &last,
                                 double strain) const;

    KentScottParkEnvelope envelope;
    double                lambda, ft, Ets;
    // constants of the law, computed once: Ec0, eps_R, and the tension
    // envelope's cracking and zero-stress strains
    double Ec0, eps_R, crack_strain, tension_end;
    bool   opensees_dead_band;
  };
} // namespace poundfe

#endif
