#include <poundfe/laws/linear_contact.h>

#include <cmath>

namespace poundfe
{
  ContactLaw::Response
  LinearContact::respond(const double delta, double /*rate*/, double /*approach_velocity*/) const
  {
    return {p.stiffness * delta, p.stiffness, 0.0};
  }

  double
  LinearContact::elastic_energy(const double delta) const
  {
    return 0.5 * p.stiffness * delta * delta;
  }
} // namespace poundfe
