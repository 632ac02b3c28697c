// Modified Kelvin-Voigt contact: damping only while the bodies approach,
//   F = k delta + c delta_dot (delta_dot > 0),  F = k delta (delta_dot <= 0),
// c = 2 xi sqrt(k m_e); no tensile force can arise.
// xi from e: (1 - e^2) / (e (e (pi - 2) + 2)).
// Source: Mahmoud & Jankowski (2011), see doc/theory.md §11;
// doc/theory.md §4.
#include <poundfe/laws/contact_law.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    class ModifiedKelvinVoigt : public ContactLaw
    {
    public:
      using ContactLaw::ContactLaw;
      Response respond(double penetration, double rate, double approach_velocity) const override;
      double   elastic_energy(double penetration) const override;
    };
  } // namespace

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

  /// The registry entry (source/laws/contact_law_registry.cc).
  namespace contact_laws
  {
    ContactLawType
    modified_kelvin_voigt()
    {
      ContactLawType type;
      type.name    = "modified-kelvin-voigt";
      type.formula = "k d + c d' while approaching";
      type.make    = [](const ContactLawParameters &p) { return std::make_unique<ModifiedKelvinVoigt>(p); };
      type.damping_from_restitution = [](const double e, const std::string &/*variant*/) {
        return (1 - e * e) / (e * (e * (M_PI - 2) + 2));
      };
      type.linear_impact_duration = true;
      return type;
    }
  } // namespace contact_laws
} // namespace poundfe
