#include <poundfe/laws/jankowski.h>

#include <cmath>

namespace poundfe
{
  ContactLaw::Response
  Jankowski::respond(const double delta, const double rate, double /*approach_velocity*/) const
  {
    const double root = std::sqrt(delta), elastic = p.stiffness * delta * root;
    if (!(rate > 0))
      return {elastic, 1.5 * p.stiffness * root, 0.0};
    const double a = 2 * p.damping * std::sqrt(p.stiffness * p.effective_mass);
    const double quarter = std::sqrt(root); // delta^(1/4)
    return {elastic + a * quarter * rate, 1.5 * p.stiffness * root + 0.25 * a * rate / (quarter * root),
            a * quarter};
  }

  double
  Jankowski::elastic_energy(const double delta) const
  {
    return 0.4 * p.stiffness * delta * delta * std::sqrt(delta);
  }
} // namespace poundfe
