// Concrete01: Kent–Scott–Park compression envelope, no tension, linear
// unloading and reloading with Karsan–Jirsa's degraded stiffness, as
// OpenSees's Concrete01 (equations in source/laws/concrete01.cc). The
// envelope is shared with Concrete02.
#ifndef poundfe_laws_concrete01_h
#define poundfe_laws_concrete01_h

#include <poundfe/laws/material_registry.h>

namespace poundfe
{
  /// Compression negative, as in OpenSees; a positive value given for a
  /// compressive quantity is taken as its magnitude (OpenSees does the same).
  struct Concrete01Parameters
  {
    double fpc   = 0; // compressive strength (Pa)
    double epsc0 = 0; // strain at fpc
    double fpcu  = 0; // crushing (residual) strength, |fpcu| <= |fpc|
    double epscu = 0; // strain at fpcu, |epscu| > |epsc0|
  };

  /// Stress and tangent of a point of a curve.
  struct StressPoint
  {
    double stress, tangent;
  };

  /// The Kent–Scott–Park envelope in compression (all values negative):
  /// a parabola to (epsc0, fpc), a line to (epscu, fpcu), then fpcu.
  /// Checks the parameters (InputError naming the parameter) and makes
  /// them negative.
  struct KentScottParkEnvelope
  {
    KentScottParkEnvelope(const char *material, const Concrete01Parameters &parameters);
    StressPoint at(double strain) const;
    /// Ec0 = 2 fpc / epsc0, the initial tangent.
    double initial_modulus() const { return 2 * fpc / epsc0; }

    double fpc, epsc0, fpcu, epscu;
  };

  struct Concrete01State
  {
    double strain = 0, stress = 0, tangent = 0;
    double min_strain = 0;   // the largest compression reached
    double end_strain = 0;   // where the unloading line meets zero stress
    double unload_slope = 0; // that line's slope
  };

  class Concrete01 : public UniaxialMaterial<Concrete01State>
  {
  public:
    /// With `opensees_dead_band`, OpenSees 3.8's: a strain within
    /// DBL_EPSILON of the committed one keeps the committed state.
    explicit Concrete01(const Concrete01Parameters &parameters, bool opensees_dead_band = false);

    double initial_stiffness() const override { return envelope.initial_modulus(); }
    double stored_energy() const override;
    /// The largest compressive strain reached (negative).
    double history_variable() const override { return trial.min_strain; }
    const KentScottParkEnvelope &compression_envelope() const { return envelope; }

  private:
    Concrete01State respond(const Concrete01State &from, double strain) const override;
    Concrete01State virgin() const override;
    /// A new largest compression: the envelope point and the unloading line from it.
    Concrete01State on_envelope(double strain) const;
    /// Whether `strain` lies in the dead band around the committed strain.
    bool in_dead_band(const Concrete01State &from, double strain) const;

    KentScottParkEnvelope envelope;
    bool                  opensees_dead_band;
  };
} // namespace poundfe

#endif
