#include <poundfe/laws/hertz.h>

#include <cmath>

namespace poundfe
{
  ContactLaw::Response
  Hertz::respond(const double delta, double /*rate*/, double /*approach_velocity*/) const
  {
    const double root = std::sqrt(delta);
    return {p.stiffness * delta * root, 1.5 * p.stiffness * root, 0.0};
  }

  double
  Hertz::elastic_energy(const double delta) const
  {
    return 0.4 * p.stiffness * delta * delta * std::sqrt(delta);
  }
} // namespace poundfe
