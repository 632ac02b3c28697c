// ElasticPP: elastic-perfectly-plastic, as OpenSees's ElasticPP (equations
// in source/laws/elastic_pp.cc).
#ifndef poundfe_laws_elastic_pp_h
#define poundfe_laws_elastic_pp_h

#include <poundfe/laws/material_registry.h>

namespace poundfe
{
  struct ElasticPPParameters
  {
    double E     = 0; // elastic modulus (Pa), > 0
    double epsyP = 0; // yield strain in tension, > 0
    double epsyN = 0; // yield strain in compression (its magnitude); 0: -epsyP
    double eps0  = 0; // initial strain
  };

  struct ElasticPPState
  {
    double strain = 0, stress = 0, tangent = 0;
    double plastic_strain = 0;
  };

  class ElasticPP : public UniaxialMaterial<ElasticPPState>
  {
  public:
    explicit ElasticPP(const ElasticPPParameters &parameters);

    double initial_stiffness() const override { return p.E; }
    double yield_deformation() const override { return p.epsyP; }
    double history_variable() const override { return trial.plastic_strain; }

  private:
    ElasticPPState respond(const ElasticPPState &from, double strain) const override;
    ElasticPPState virgin() const override;

    ElasticPPParameters p;
  };
} // namespace poundfe

#endif
