// Nonlinear viscoelastic contact (Jankowski 2005):
//   F = beta delta^(3/2) + c(delta) delta_dot  while delta_dot > 0 (approach),
//   F = beta delta^(3/2)                       while delta_dot <= 0 (restitution),
//   c(delta) = 2 xi sqrt(beta sqrt(delta) m_e);
// xi from e: 9 sqrt(5) (1 - e^2) / (2 e (e (9 pi - 16) + 16)) (Jankowski,
// Earthquake Eng. Struct. Dyn. 35 (2006) 517).
// Source: R. Jankowski, Earthquake Eng. Struct. Dyn. 34 (2005) 595;
// doc/theory.md §4 and §8 (the thesis's spillway).
#include <poundfe/laws/contact_law.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    class Jankowski : public ContactLaw
    {
    public:
      using ContactLaw::ContactLaw;
      Response respond(double penetration, double rate, double approach_velocity) const override;
      double   elastic_energy(double penetration) const override;
    };
  } // namespace

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

  /// The registry entry (source/laws/contact_law_registry.cc).
  namespace contact_laws
  {
    ContactLawType
    jankowski()
    {
      ContactLawType type;
      type.name    = "jankowski";
      type.formula = "beta d^1.5 + c(d) d' while approaching";
      type.make    = [](const ContactLawParameters &p) { return std::make_unique<Jankowski>(p); };
      type.damping_from_restitution = [](const double e, const std::string &/*variant*/) {
        return 9 * std::sqrt(5.0) * (1 - e * e) / (2 * e * (e * (9 * M_PI - 16) + 16));
      };
      type.linear_impact_duration = false;
      return type;
    }
  } // namespace contact_laws
} // namespace poundfe
