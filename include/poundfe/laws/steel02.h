// Steel02: Giuffré–Menegotto–Pinto steel with Filippou, Popov & Bertero's
// isotropic hardening, as OpenSees's Steel02 (equations in
// source/laws/steel02.cc).
#ifndef poundfe_laws_steel02_h
#define poundfe_laws_steel02_h

#include <poundfe/laws/material_registry.h>

namespace poundfe
{
  namespace internal
  {
    template <class Material, class State>
    class TypedFibreRun;
  } // namespace internal

  struct Steel02Parameters
  {
    double fy  = 0;     // yield stress (Pa), > 0
    double E0  = 0;     // initial elastic modulus (Pa), > 0
    double b   = 0;     // hardening ratio, in [0, 1)
    double R0  = 20;    // curvature of the first transition, > 0
    double cR1 = 0.925; // reduction of R with the plastic excursion, in [0, 1)
    double cR2 = 0.15;  // > 0
    double a1  = 0;     // isotropic hardening as in Steel01
    double a2  = 1;
    double a3  = 0;
    double a4  = 1;
  };

  struct Steel02State
  {
    double strain = 0, stress = 0, tangent = 0;
    double eps_max = 0, eps_min = 0; // largest and smallest strains of reversals
    double eps_pl = 0;               // the far reversal strain (for xi)
    double eps_0 = 0, sig_0 = 0;     // where the two asymptotes meet
    double eps_r = 0, sig_r = 0;     // the last reversal point
    int    direction = 0;            // 1 loading, 2 unloading, 0 virgin
    // the branch's constants, set with eps_0 at a reversal (a trial on the
    // branch then divides once and calls pow twice): R, 1/R and the secant
    // (sig_0 - sig_r) / (eps_0 - eps_r)
    double R = 0, inverse_R = 0, secant = 0;
  };

  class Steel02 final : public UniaxialMaterial<Steel02State>
  {
  public:
    /// InputError naming the parameter unless fy, E0, R0, cR2, a2, a4 > 0,
    /// b and cR1 in [0, 1), a1, a3 >= 0. With `opensees_dead_band`, OpenSees
    /// 3.8's: a virgin state given a strain change below 10 DBL_EPSILON
    /// stays virgin (stress 0, tangent E0) at the trial strain.
    explicit Steel02(const Steel02Parameters &parameters, bool opensees_dead_band = false);

    double initial_stiffness() const override { return p.E0; }
    double yield_deformation() const override { return p.fy / p.E0; }
    const Steel02Parameters &parameters() const { return p; }

    Steel02State virgin() const override;

  private:
    // a section's run of Steel02 fibres (fibre_section.cc) keeps their
    // states itself: it evaluates them by trial_state and words a refused
    // one by failure()
    template <class Material, class State>
    friend class internal::TypedFibreRun;

    Steel02State respond(const Steel02State &from, double strain) const override;
    /// The trial state at `strain` from `from`; the last trial is not read
    /// (Concrete02's signature, for the typed runs).
    Steel02State trial_state(const Steel02State &from, const Steel02State &last,
                             double strain) const;
    /// R, 1/R and the secant of the branch that starts at (eps_r, sig_r).
    void set_branch(Steel02State &s) const;
    /// Whether a virgin state stays virgin after the change `d_strain`.
    bool stays_virgin(double d_strain) const;

    Steel02Parameters p;
    double            eps_y, hardening; // fy / E0, b E0
    bool              opensees_dead_band;
  };
} // namespace poundfe

#endif
