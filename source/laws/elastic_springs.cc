#include <poundfe/base/numbers.h>
#include <poundfe/laws/elastic_springs.h>

#include <cmath>
#include <string>

namespace poundfe
{
  double
  SpringLawParameters::force(const double x) const
  {
    if (kind == SpringKind::cubic)
      return stiffness * x + cubic * x * x * x;
    if (height == 0) // the discontinuous limit; F(0) = 0 by symmetry
      return stiffness * (x - length * ((x > 0) - (x < 0)));
    return stiffness * x * (1 - length / std::hypot(x, height));
  }

  double
  SpringLawParameters::tangent(const double x) const
  {
    if (kind == SpringKind::cubic)
      return stiffness + 3 * cubic * x * x;
    if (height == 0)
      return stiffness;
    const double r = std::hypot(x, height);
    return stiffness * (1 - length * height * height / (r * r * r));
  }

  double
  SpringLawParameters::energy(const double x) const
  {
    if (kind == SpringKind::cubic)
      return 0.5 * stiffness * x * x + 0.25 * cubic * x * x * x * x;
    return stiffness * (0.5 * x * x - length * (std::hypot(x, height) - height));
  }

  ElasticSpring::ElasticSpring(const SpringLawParameters &parameters)
    : p(parameters)
    , discontinuous(parameters.kind == SpringKind::sd && parameters.height == 0)
  {
    reset();
  }

  bool
  ElasticSpring::set_trial(const double deformation, double)
  {
    trial_deformation = deformation;
    trial_force       = p.force(deformation);
    trial_tangent     = p.tangent(deformation);
    return std::isfinite(trial_force);
  }

  std::string
  ElasticSpring::failure() const
  {
    return "the spring force is not finite at a deformation of " +
           number_text(trial_deformation) + " m";
  }

  void
  ElasticSpring::commit()
  {
    committed_deformation = trial_deformation;
  }

  void
  ElasticSpring::revert()
  {
    set_trial(committed_deformation, 0);
  }

  void
  ElasticSpring::reset()
  {
    committed_deformation = 0;
    set_trial(0, 0);
  }
} // namespace poundfe
