// Linear (elastic spring) contact: F = k delta for delta > 0.
// Source: Maison & Kasai, J. Struct. Eng. 116(4) (1990) 957;
// doc/theory.md §4.
#include <poundfe/laws/contact_law.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    class LinearContact : public ContactLaw
    {
    public:
      using ContactLaw::ContactLaw;
      Response respond(double penetration, double rate, double approach_velocity) const override;
      double   elastic_energy(double penetration) const override;
    };
  } // namespace

  ContactLaw::Response
  LinearContact::respond(const double delta, double /*rate*/, double /*approach_velocity*/) const
  {
    return {p.stiffness * delta, p.stiffness, 0.0};
  }

  double
  LinearContact::elastic_energy(const double delta) const
  {
    return 0.5 * p.stiffness * delta * delta;
  }

  /// The registry entry (source/laws/contact_law_registry.cc).
  namespace contact_laws
  {
    ContactLawType
    linear()
    {
      ContactLawType type;
      type.name    = "linear";
      type.formula = "k d";
      type.make    = [](const ContactLawParameters &p) { return std::make_unique<LinearContact>(p); };
      type.linear_impact_duration = true;
      return type;
    }
  } // namespace contact_laws
} // namespace poundfe
