#include <poundfe/laws/kelvin_voigt.h>

#include <cmath>

namespace poundfe
{
  ContactLaw::Response
  KelvinVoigt::respond(const double delta, const double rate, double /*approach_velocity*/) const
  {
    const double c = 2 * p.damping * std::sqrt(p.stiffness * p.effective_mass);
    return {p.stiffness * delta + c * rate, p.stiffness, c};
  }

  double
  KelvinVoigt::elastic_energy(const double delta) const
  {
    return 0.5 * p.stiffness * delta * delta;
  }
} // namespace poundfe
