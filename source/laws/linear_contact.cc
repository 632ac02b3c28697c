#include <poundfe/laws/linear_contact.h>

#include <cmath>

namespace poundfe
{
  ContactLaw::Response
  LinearContact::respond(const double delta, const double rate, const double approach_velocity) const
  {
    (void)approach_velocity;
    (void)rate;
    return {p.stiffness * delta, p.stiffness, 0.0};
  }

  double
  LinearContact::elastic_energy(const double delta) const
  {
    return 0.5 * p.stiffness * delta * delta;
  }
} // namespace poundfe
