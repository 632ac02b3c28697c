// Hertz-damp contact: F = k_h delta^(3/2) (1 + xi_bar delta_dot / v0), v0 the
// approach velocity at first contact; clipped at zero during restitution.
// xi_bar from e: 3 (1 - e^2)/4 (Muthukumar & DesRoches, Earthquake Eng.
// Struct. Dyn. 35 (2006) 811) or 8 (1 - e)/(5 e) (Ye, Li & Zhu, Earthquake
// Eng. Struct. Dyn. 38 (2009) 1135); doc/theory.md §4.
#include <poundfe/laws/contact_law.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    class HertzDamp : public ContactLaw
    {
    public:
      using ContactLaw::ContactLaw;
      Response respond(double penetration, double rate, double approach_velocity) const override;
      double   elastic_energy(double penetration) const override;
    };
  } // namespace

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

  /// The registry entry (source/laws/contact_law_registry.cc).
  namespace contact_laws
  {
    ContactLawType
    hertz_damp()
    {
      ContactLawType type;
      type.name    = "hertz-damp";
      type.formula = "k d^1.5 (1 + xi d'/v0)";
      type.make    = [](const ContactLawParameters &p) { return std::make_unique<HertzDamp>(p); };
      type.damping_from_restitution = [](const double e, const std::string &variant) {
        return variant == "ye-li-zhu" ? 8 * (1 - e) / (5 * e) : 3 * (1 - e * e) / 4;
      };
      type.linear_impact_duration = false;
      return type;
    }
  } // namespace contact_laws
} // namespace poundfe
