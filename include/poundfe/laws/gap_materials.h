// The uniaxial materials of OpenSees that pounding scripts put in zero-length
// gap elements, and OpenSees's linear elastic material with a dashpot
// (equations and sources in source/laws/gap_materials.cc). Each is a
// registered material (material_registry.h): "Elastic", "ElasticPPGap",
// "ImpactMaterial", with OpenSees's parameter names.
#ifndef poundfe_laws_gap_materials_h
#define poundfe_laws_gap_materials_h

#include <poundfe/laws/material_registry.h>

namespace poundfe
{
  /// OpenSees Elastic: sigma = E eps + eta eps_dot, E = Epos for eps >= 0,
  /// Eneg below.
  class ElasticUniaxial : public UniaxialLaw
  {
  public:
    ElasticUniaxial(double E, double eta, double Eneg);

    bool   set_trial(double strain, double rate) override;
    double force() const override;
    double tangent() const override { return trial_strain >= 0 ? E : Eneg; }
    double damping_tangent() const override { return eta; }
    double stored_energy() const override;
    double initial_stiffness() const override { return E; }
    void   commit() override {}
    void   revert() override {}
    void   reset() override { trial_strain = trial_rate = 0; }

  private:
    double E, eta, Eneg;
    double trial_strain = 0, trial_rate = 0;
  };

  struct GapMaterialState
  {
    double strain = 0, stress = 0, tangent = 0;
    /// ElasticPPGap: the elastic range [min, max] of strains after this
    /// state is committed (OpenSees's minElasticYieldStrain, maxElasticYieldStrain).
    double min_elastic = 0, max_elastic = 0;
  };

  /// OpenSees ElasticPPGap (EPPGapMaterial): an elastic-perfectly-plastic
  /// spring (with hardening eta E) that engages past a gap; `damage`: the
  /// plastic deformation widens the gap for good.
  class ElasticPPGap : public UniaxialMaterial<GapMaterialState>
  {
  public:
    ElasticPPGap(double E, double Fy, double gap, double eta, bool damage);
    /// 0 for a real gap (Fy and gap of one sign: open at strain 0), as
    /// OpenSees's EPPGapMaterial::getInitialTangent; E otherwise.
    double initial_stiffness() const override
    {
      return (Fy >= 0 && gap > 0) || (Fy < 0 && gap < 0) ? 0 : E;
    }

  private:
    GapMaterialState respond(const GapMaterialState &from, double strain) const override;
    GapMaterialState virgin() const override;
    double           E, Fy, gap, eta;
    bool             damage;
  };

  /// OpenSees ImpactMaterial (Muthukumar and DesRoches 2006): a bilinear
  /// compression-only contact spring, K1 up to the yield deformation
  /// Delta_y, then K2, that engages once the strain is below the (negative)
  /// gap.
  class ImpactMaterial : public UniaxialMaterial<GapMaterialState>
  {
  public:
    ImpactMaterial(double K1, double K2, double Delta_y, double gap);
    double initial_stiffness() const override { return K1; }

  private:
    GapMaterialState respond(const GapMaterialState &from, double strain) const override;
    GapMaterialState virgin() const override;
    double           K1, K2, Delta_y, gap;
  };
} // namespace poundfe

#endif
