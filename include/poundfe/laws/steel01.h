// Steel01: bilinear steel with kinematic hardening and optional isotropic
// hardening, as OpenSees's Steel01 (equations in source/laws/steel01.cc).
#ifndef poundfe_laws_steel01_h
#define poundfe_laws_steel01_h

#include <poundfe/laws/material_registry.h>

namespace poundfe
{
  struct Steel01Parameters
  {
    double fy = 0; // yield stress (Pa), > 0
    double E0 = 0; // initial elastic modulus (Pa), > 0
    double b  = 0; // hardening ratio E_sh / E0, in [0, 1)
    double a1 = 0; // growth of the compression yield stress ...
    double a2 = 1; // ... per plastic excursion of a2 (2 fy / E0)
    double a3 = 0; // the same for tension
    double a4 = 1;
  };

  struct Steel01State
  {
    double strain = 0, stress = 0, tangent = 0;
    double min_strain = 0, max_strain = 0; // strains at the last reversals
    double shift_p = 1, shift_n = 1;       // isotropic growth of the two asymptotes
    int    loading = 0;                    // +1 loading, -1 unloading, 0 virgin
  };

  class Steel01 : public UniaxialMaterial<Steel01State>
  {
  public:
    /// InputError naming the parameter unless fy, E0 > 0, 0 <= b < 1,
    /// a2, a4 > 0 and a1, a3 >= 0.
    explicit Steel01(const Steel01Parameters &parameters);

    double initial_stiffness() const override { return p.E0; }
    double yield_deformation() const override { return p.fy / p.E0; }
    const Steel01Parameters &parameters() const { return p; }

  private:
    Steel01State respond(const Steel01State &from, double strain) const override;
    Steel01State virgin() const override;

    Steel01Parameters p;
  };
} // namespace poundfe

#endif
