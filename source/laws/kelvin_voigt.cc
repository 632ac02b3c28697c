// Kelvin-Voigt (linear viscoelastic) contact: F = k delta + c delta_dot,
// c = 2 xi sqrt(k m_e), clipped at zero during restitution.
// xi from e: -ln e / sqrt(pi^2 + ln^2 e).
// Source: Anagnostopoulos, Earthquake Eng. Struct. Dyn. 16 (1988) 443;
// doc/theory.md §4.
#include <poundfe/laws/contact_law.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    class KelvinVoigt : public ContactLaw
    {
    public:
      using ContactLaw::ContactLaw;
      Response respond(double penetration, double rate, double approach_velocity) const override;
      double   elastic_energy(double penetration) const override;
    };
  } // namespace

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

  /// The registry entry (source/laws/contact_law_registry.cc).
  namespace contact_laws
  {
    ContactLawType
    kelvin_voigt()
    {
      ContactLawType type;
      type.name    = "kelvin-voigt";
      type.formula = "k d + c d'";
      type.make    = [](const ContactLawParameters &p) { return std::make_unique<KelvinVoigt>(p); };
      type.damping_from_restitution = [](const double e, const std::string &/*variant*/) {
        return -std::log(e) / std::sqrt(M_PI * M_PI + std::log(e) * std::log(e));
      };
      type.linear_impact_duration = true;
      return type;
    }
  } // namespace contact_laws
} // namespace poundfe
