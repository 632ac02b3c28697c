// Hertz (elastic, nonlinear) contact: F = k_h delta^(3/2).
// Elastic impact of m on a rigid wall at v0: delta_max = (5 m v0^2/(4 k_h))^(2/5),
// F_max = k_h delta_max^(3/2), contact time 2.9432 delta_max / v0.
// Source: Goldsmith, Impact (1960); Davis, Earthquake Eng. Struct. Dyn. 21(3) (1992) 253;
// doc/theory.md §4.
#include <poundfe/laws/contact_law.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    class Hertz : public ContactLaw
    {
    public:
      using ContactLaw::ContactLaw;
      Response respond(double penetration, double rate, double approach_velocity) const override;
      double   elastic_energy(double penetration) const override;
    };
  } // namespace

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

  /// The registry entry (source/laws/contact_law_registry.cc).
  namespace contact_laws
  {
    ContactLawType
    hertz()
    {
      ContactLawType type;
      type.name    = "hertz";
      type.formula = "k d^1.5";
      type.make    = [](const ContactLawParameters &p) { return std::make_unique<Hertz>(p); };
      type.linear_impact_duration = false;
      return type;
    }
  } // namespace contact_laws
} // namespace poundfe
