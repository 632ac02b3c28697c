// Hertz (elastic, nonlinear) contact: F = k_h delta^(3/2).
// Elastic impact of m on a rigid wall at v0: delta_max = (5 m v0^2/(4 k_h))^(2/5),
// F_max = k_h delta_max^(3/2), contact time 2.9432 delta_max / v0.
// Source: Goldsmith, Impact (1960); Davis, J. Struct. Eng. 118 (1992);
// doc/theory.md §4.
#ifndef poundfe_laws_hertz_h
#define poundfe_laws_hertz_h

#include <poundfe/laws/contact_law.h>

namespace poundfe
{
  class Hertz : public ContactLaw
  {
  public:
    using ContactLaw::ContactLaw;
    Response respond(double penetration, double rate, double approach_velocity) const override;
    double   elastic_energy(double penetration) const override;
  };
} // namespace poundfe

#endif
