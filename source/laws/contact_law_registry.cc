// The contact law registry: every law the input may name, with its factory,
// its damping formula and its impact time scale (ContactLawType).
// Adding a built-in law: its file source/laws/<law>.cc, which defines the
// class and contact_laws::<law>() (its ContactLawType), and LAW(<law>) in
// the one list below. (Built-in laws are listed rather than registered by
// static objects in their own files because the core is a static library:
// the linker drops an object file that nothing refers to, registrar and all.)
#include <poundfe/laws/contact_law.h>

#include <algorithm>
#include <stdexcept>

namespace poundfe
{
// The built-in laws, in the order the input's documentation lists them.
#define POUNDFE_BUILT_IN_CONTACT_LAWS(LAW)                                                    \
  LAW(linear) LAW(kelvin_voigt) LAW(modified_kelvin_voigt) LAW(hertz) LAW(hertz_damp)        \
    LAW(jankowski)

  namespace contact_laws
  {
#define POUNDFE_DECLARE_CONTACT_LAW(law) ContactLawType law();
    POUNDFE_BUILT_IN_CONTACT_LAWS(POUNDFE_DECLARE_CONTACT_LAW)
#undef POUNDFE_DECLARE_CONTACT_LAW
  } // namespace contact_laws

  namespace
  {
    std::vector<ContactLawType> &
    registry()
    {
      // built on first use, so registrars in other files may run in any order
#define POUNDFE_CONTACT_LAW_TYPE(law) contact_laws::law(),
      static std::vector<ContactLawType> types{
        POUNDFE_BUILT_IN_CONTACT_LAWS(POUNDFE_CONTACT_LAW_TYPE)};
#undef POUNDFE_CONTACT_LAW_TYPE
      return types;
    }

    const ContactLawType *
    find(const std::string &name)
    {
      const auto &types = registry();
      const auto  it    = std::find_if(types.begin(), types.end(),
                                   [&](const ContactLawType &t) { return t.name == name; });
      return it == types.end() ? nullptr : &*it;
    }
  } // namespace

  void
  register_contact_law(ContactLawType type)
  {
    if (type.name.empty() || type.name == "none" || !type.make)
      throw std::logic_error("a contact law needs a name (not 'none') and a factory");
    if (find(type.name))
      throw std::logic_error("contact law '" + type.name + "' is registered twice");
    registry().push_back(std::move(type));
  }

  const ContactLawType &
  contact_law_type(const std::string &name)
  {
    if (const ContactLawType *type = find(name))
      return *type;
    throw std::invalid_argument("unknown contact law '" + name + "'");
  }

  std::vector<std::string>
  contact_law_names()
  {
    std::vector<std::string> names;
    for (const ContactLawType &type : registry())
      names.push_back(type.name);
    return names;
  }

  std::unique_ptr<ContactLaw>
  make_contact_law(const ContactLawParameters &parameters)
  {
    return contact_law_type(parameters.law).make(parameters);
  }

  bool
  contact_law_is_damped(const std::string &law)
  {
    // "none" (Contact/Law: no contact) is no registered law and has no damping
    return law != "none" && bool(contact_law_type(law).damping_from_restitution);
  }

  double
  damping_from_restitution_formula(const std::string &law, const double e,
                                   const std::string &variant)
  {
    const ContactLawType &type = contact_law_type(law);
    return type.damping_from_restitution ? type.damping_from_restitution(e, variant) : 0.0;
  }
} // namespace poundfe
