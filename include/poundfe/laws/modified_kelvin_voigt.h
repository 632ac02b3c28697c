// Modified Kelvin-Voigt contact: damping only while the bodies approach,
//   F = k delta + c delta_dot (delta_dot > 0),  F = k delta (delta_dot <= 0),
// c = 2 xi sqrt(k m_e); no tensile force can arise.
// xi from e: (1 - e^2) / (e (e (pi - 2) + 2)).
// Source: Mahmoud & Jankowski, Advances in Structural Engineering 14 (2011);
// doc/theory.md §4.
#ifndef poundfe_laws_modified_kelvin_voigt_h
#define poundfe_laws_modified_kelvin_voigt_h

#include <poundfe/laws/contact_law.h>

namespace poundfe
{
  class ModifiedKelvinVoigt : public ContactLaw
  {
  public:
    using ContactLaw::ContactLaw;
    Response respond(double penetration, double rate, double approach_velocity) const override;
    double   elastic_energy(double penetration) const override;
  };
} // namespace poundfe

#endif
