// Hysteretic: OpenSees's Hysteretic material, a trilinear envelope in each
// direction with pinching, damage and degraded unloading stiffness
// (equations in source/laws/hysteretic.cc).
#ifndef poundfe_laws_hysteretic_h
#define poundfe_laws_hysteretic_h

#include <poundfe/laws/material_registry.h>

#include <map>
#include <string>

namespace poundfe
{
  /// One direction's envelope: (e1, s1), (e2, s2), (e3, s3), strains
  /// increasing in magnitude, all of that direction's sign.
  struct HystereticEnvelope
  {
    double s1 = 0, e1 = 0, s2 = 0, e2 = 0, s3 = 0, e3 = 0;
  };

  /// The envelope of one side ("p" or "n") from Hysteretic's parameters by
  /// OpenSees's names (s1p, e1p, ...). Two points (s3, e3 absent or both 0):
  /// the second becomes the third and the middle one lies halfway, as
  /// OpenSees's two-point constructor puts it.
  HystereticEnvelope hysteretic_envelope(const std::map<std::string, double> &values,
                                         const std::string                   &side);

  struct HystereticParameters
  {
    HystereticEnvelope positive, negative;
    double             pinchX  = 1; // pinching in strain, in [0, 1]
    double             pinchY  = 1; // pinching in stress, in [0, 1]
    double             damage1 = 0; // damage from ductility, >= 0
    double             damage2 = 0; // damage from energy, >= 0
    double             beta    = 0; // unloading stiffness k = (mu)^-beta, >= 0
  };

  struct HystereticState
  {
    double strain = 0, stress = 0, tangent = 0;
    double max_strain = 0, min_strain = 0; // largest excursions (grown by damage)
    double zero_p = 0, zero_n = 0;         // zero-stress strains of the last unloadings
    double energy = 0;                     // dissipated energy
    int    loading = 0;                    // 1 positive, 2 negative increments, 0 virgin
  };

  class Hysteretic : public UniaxialMaterial<HystereticState>
  {
  public:
    /// InputError naming the parameter unless each envelope's strains grow
    /// in magnitude with the right sign, pinchX and pinchY lie in [0, 1]
    /// and damage1, damage2, beta >= 0. With `opensees_dead_band`, OpenSees
    /// 3.8's (in_dead_band).
    explicit Hysteretic(const HystereticParameters &parameters, bool opensees_dead_band = false);

    double initial_stiffness() const override { return p.positive.s1 / p.positive.e1; }
    double yield_deformation() const override { return p.positive.e1; }

  private:
    /// The two envelopes as seen from one direction: `ahead` is the
    /// envelope of the increment's direction, `behind` the other one, both
    /// with positive strains and stresses. A negative increment is the
    /// positive one of the mirrored state (strain, stress -> -strain,
    /// -stress), so the rules are written once.
    struct Sides
    {
      HystereticEnvelope ahead, behind;
      double             E_ahead, E_behind; // unloading moduli
    };
    HystereticState respond(const HystereticState &from, double strain) const override;
    /// respond's rules once the dead band has let the strain through.
    HystereticState respond_outside_band(const HystereticState &from, double strain) const;
    HystereticState virgin() const override;
    HystereticState positive_increment(const HystereticState &from, double strain,
                                       const Sides &sides) const;
    /// OpenSees 3.8's HystereticMaterial::setTrialStrain: at strain 0 with
    /// the last trial still virgin, the last trial as it is; a change below
    /// DBL_EPSILON from the committed strain keeps the committed history and
    /// energy, takes the strain and keeps the last trial's stress, tangent
    /// and loading direction, the tangent even after a revert. False outside
    /// the band (and without it).
    bool in_dead_band(const HystereticState &from, double strain, HystereticState &s) const;

    HystereticParameters p;
    Sides                forward, mirrored;
    double               energy_A; // the envelopes' area to e3 (damage scale)
    bool                 opensees_dead_band;
    /// OpenSees's Ttangent: the tangent of the last trial outside the band
    /// (or the virgin one), which its revertToLastCommit leaves as it is.
    mutable double opensees_tangent = 0;
  };
} // namespace poundfe

#endif
