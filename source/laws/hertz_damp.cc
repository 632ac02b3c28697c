#include <poundfe/laws/hertz_damp.h>

#include <cmath>

namespace poundfe
{
  ContactLaw::Response
  HertzDamp::respond(const double delta, const double rate, const double approach_velocity) const
  {
    const double root = std::sqrt(delta), factor = 1 + p.damping * rate / approach_velocity;
    return {p.stiffness * delta * root * factor, 1.5 * p.stiffness * root * factor,
            p.stiffness * delta * root * p.damping / approach_velocity};
  }

  double
  HertzDamp::elastic_energy(const double delta) const
  {
    return 0.4 * p.stiffness * delta * delta * std::sqrt(delta);
  }
} // namespace poundfe
