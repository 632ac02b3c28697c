// Hertz-damp contact: F = k_h delta^(3/2) (1 + xi_bar delta_dot / v0), v0 the
// approach velocity at first contact; clipped at zero during restitution.
// xi_bar from e: 3 (1 - e^2)/4 (Muthukumar & DesRoches, Earthquake Eng.
// Struct. Dyn. 35 (2006) 811) or 8 (1 - e)/(5 e) (Ye, Li & Zhu, Earthquake
// Eng. Struct. Dyn. 38 (2009) 1089); doc/theory.md §4.
#ifndef poundfe_laws_hertz_damp_h
#define poundfe_laws_hertz_damp_h

#include <poundfe/laws/contact_law.h>

namespace poundfe
{
  class HertzDamp : public ContactLaw
  {
  public:
    using ContactLaw::ContactLaw;
    Response respond(double penetration, double rate, double approach_velocity) const override;
    double   elastic_energy(double penetration) const override;
  };
} // namespace poundfe

#endif
