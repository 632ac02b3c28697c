// Linear (elastic spring) contact: F = k delta for delta > 0.
// Source: Maison & Kasai, Earthquake Eng. Struct. Dyn. 19 (1990) 1035;
// doc/theory.md §4.
#ifndef poundfe_laws_linear_contact_h
#define poundfe_laws_linear_contact_h

#include <poundfe/laws/contact_law.h>

namespace poundfe
{
  class LinearContact : public ContactLaw
  {
  public:
    using ContactLaw::ContactLaw;
    Response respond(double penetration, double rate, double approach_velocity) const override;
    double   elastic_energy(double penetration) const override;
  };
} // namespace poundfe

#endif
