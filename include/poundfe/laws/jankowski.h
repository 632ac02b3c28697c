// Nonlinear viscoelastic contact (Jankowski 2005):
//   F = beta delta^(3/2) + c(delta) delta_dot  while delta_dot > 0 (approach),
//   F = beta delta^(3/2)                       while delta_dot <= 0 (restitution),
//   c(delta) = 2 xi sqrt(beta sqrt(delta) m_e);
// xi from e: 9 sqrt(5) (1 - e^2) / (2 e (e (9 pi - 16) + 16)).
// Source: R. Jankowski, Earthquake Eng. Struct. Dyn. 34 (2005) 595;
// doc/theory.md §4 and §8 (the thesis's spillway).
#ifndef poundfe_laws_jankowski_h
#define poundfe_laws_jankowski_h

#include <poundfe/laws/contact_law.h>

namespace poundfe
{
  class Jankowski : public ContactLaw
  {
  public:
    using ContactLaw::ContactLaw;
    Response respond(double penetration, double rate, double approach_velocity) const override;
    double   elastic_energy(double penetration) const override;
  };
} // namespace poundfe

#endif
