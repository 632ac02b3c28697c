#include <poundfe/laws/modified_kelvin_voigt.h>

#include <cmath>

namespace poundfe
{
  ContactLaw::Response
  ModifiedKelvinVoigt::respond(const double delta, const double rate, double /*approach_velocity*/) const
  {
    const double c = 2 * p.damping * std::sqrt(p.stiffness * p.effective_mass);
    if (rate > 0)
      return {p.stiffness * delta + c * rate, p.stiffness, c};
    return {p.stiffness * delta, p.stiffness, 0.0};
  }

  double
  ModifiedKelvinVoigt::elastic_energy(const double delta) const
  {
    return 0.5 * p.stiffness * delta * delta;
  }
} // namespace poundfe
