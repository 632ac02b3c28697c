// Concrete02: Concrete01's Kent–Scott–Park compression envelope with
// Yassin's (1994) unloading rule and linear tension softening, as
// OpenSees's Concrete02 (equations in source/laws/concrete02.cc).
#ifndef poundfe_laws_concrete02_h
#define poundfe_laws_concrete02_h

#include <poundfe/laws/concrete01.h>

namespace poundfe
{
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
  };

  class Concrete02 : public UniaxialMaterial<Concrete02State>
  {
  public:
    explicit Concrete02(const Concrete02Parameters &parameters);

    double initial_stiffness() const override { return envelope.initial_modulus(); }
    double history_variable() const override { return trial.min_strain; }
    /// The tension envelope: Ec0 eps to ft, then ft - Ets (eps - ft/Ec0) down to 0.
    StressPoint tension_envelope(double strain) const;

  private:
    Concrete02State respond(const Concrete02State &from, double strain) const override;
    Concrete02State virgin() const override;
    /// Between the largest compression and the tension side.
    Concrete02State unload_or_reload(const Concrete02State &from, double strain) const;

    KentScottParkEnvelope envelope;
    double                lambda, ft, Ets;
  };
} // namespace poundfe

#endif
