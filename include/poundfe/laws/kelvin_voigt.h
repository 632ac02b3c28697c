// Kelvin-Voigt (linear viscoelastic) contact: F = k delta + c delta_dot,
// c = 2 xi sqrt(k m_e), clipped at zero during restitution.
// xi from e: -ln e / sqrt(pi^2 + ln^2 e).
// Source: Anagnostopoulos, Earthquake Eng. Struct. Dyn. 16 (1988) 443;
// doc/theory.md §4.
#ifndef poundfe_laws_kelvin_voigt_h
#define poundfe_laws_kelvin_voigt_h

#include <poundfe/laws/contact_law.h>

namespace poundfe
{
  class KelvinVoigt : public ContactLaw
  {
  public:
    using ContactLaw::ContactLaw;
    Response respond(double penetration, double rate, double approach_velocity) const override;
    double   elastic_energy(double penetration) const override;
  };
} // namespace poundfe

#endif
