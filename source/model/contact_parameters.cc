#include <poundfe/base/numbers.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/model/contact_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <tuple>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  const NameTable<ContactDampingFrom> &
  contact_damping_from_names()
  {
    static const NameTable<ContactDampingFrom> table({{ContactDampingFrom::given, "given"},
                                                      {ContactDampingFrom::formula, "formula"},
                                                      {ContactDampingFrom::calibrated, "calibrated"}});
    return table;
  }

  const NameTable<HertzDampFormula> &
  hertz_damp_formula_names()
  {
    static const NameTable<HertzDampFormula> table(
      {{HertzDampFormula::muthukumar_desroches, "muthukumar-desroches"},
       {HertzDampFormula::ye_li_zhu, "ye-li-zhu"}});
    return table;
  }

  void
  ContactParameters::declare(dealii::ParameterHandler &prm)
  {
    // every registered law, with its formula (laws/contact_law.h)
    std::vector<std::string> laws{"none"};
    std::string              formulas;
    for (const std::string &name : contact_law_names())
      {
        laws.push_back(name);
        formulas += ", " + name + " (" + contact_law_type(name).formula + ")";
      }
    add_choice(prm, "Law", law,
               "Gap elements between neighbouring buildings (and at barriers): none" + formulas +
                 ". Unit: -.",
               laws);
    prm.add_parameter("Stiffness", stiffness,
                      "k in N/m (linear laws) or k_h, beta in N/m^1.5 (Hertz laws, "
                      "Jankowski; concrete ~2.75e9). Unit: N/m or N/m^1.5.");
    add_choice(prm, "Damping from", damping_from,
               "given: the value of Damping; formula: the law's literature formula "
               "from the coefficient of restitution; calibrated: the value for "
               "which one impact of the effective mass on a rigid wall returns "
               "exactly that coefficient. Unit: -.",
               contact_damping_from_names());
    prm.add_parameter("Damping", damping,
                      "xi (Kelvin-Voigt laws, Jankowski) or xi_bar (Hertz-damp) when given. "
                      "Unit: dimensionless.");
    prm.add_parameter("Coefficient of restitution", restitution,
                      "e in (0, 1] for the penalty laws, in [0, 1] with Model = nonsmooth; "
                      "concrete ~0.65. Unit: dimensionless.");
    add_choice(prm, "Hertz-damp formula", hertz_damp_formula,
               "xi_bar from e: 3(1 - e^2)/4 (Muthukumar & DesRoches) or "
               "8(1 - e)/(5e) (Ye, Li & Zhu). Unit: -.",
               hertz_damp_formula_names());
    prm.add_parameter("Effective mass", effective_mass,
                      "m_e; 0: m1 m2/(m1 + m2) of the colliding floor masses (the "
                      "floor mass against a barrier); at most 1e150 kg, the largest mass of a "
                      "model. Unit: kg.");
    prm.add_parameter("Calibration velocity", calibration_velocity,
                      "Approach velocity of the calibration impact. Unit: m/s.");
    prm.add_parameter("Between buildings", between_buildings,
                      "Gap elements between neighbouring buildings at every floor level "
                      "the lower one has (initial gap: Model/Separations). Unit: -.");
    prm.add_parameter("Floor to column", floor_to_column,
                      "Where a floor of one building has no floor of its neighbour at "
                      "the same level, the contact point is on the neighbour's facing "
                      "column at that height (frames). Unit: -.");
    prm.add_parameter("Floor to column in plan", floor_to_column_in_plan,
                      "Dimension = 3: a slab also touches the facing perimeter columns of a "
                      "3D frame neighbour where it is between two of the neighbour's floors "
                      "(buildings with different storey heights); the force acts at the "
                      "column's point at the slab's height. Off by default: 3D models made "
                      "before give the same numbers. Unit: -.");
    prm.add_parameter("Barriers", barriers,
                      "Rigid barriers 'building floor side gap' separated by ';', e.g. "
                      "'1 2 right 0.015; B 3 left 0.02': the floor's facing joint touches "
                      "a barrier on the left or right side once it has moved by gap (m) "
                      "towards it. The building: its number (1-based) or its Name; the "
                      "floor 1-based. Unit: per field.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
  }

  void
  ContactParameters::check(const InputFile &input) const
  {
    if (law == "none")
      return;
    input.positive("Contact/Stiffness", stiffness);
    // the links' bound (model/building_links.cc): Newton squares the force
    input.at_most("Contact/Stiffness", stiffness, largest_model_value, "",
                  "beyond any physical contact");
    input.at_most("Contact/Damping", damping, largest_model_value, "",
                  "beyond any physical contact");
    if (!(restitution > 0 && restitution <= 1))
      input.fail("Contact/Coefficient of restitution",
                 "must lie in (0, 1], got " + number_text(restitution));
    input.non_negative("Contact/Damping", damping);
    input.non_negative("Contact/Effective mass", effective_mass);
    input.at_most("Contact/Effective mass", effective_mass, largest_model_value, "kg",
                  "the largest mass of a model");
    input.positive("Contact/Calibration velocity", calibration_velocity);
  }

  std::vector<std::string>
  ContactParameters::entries_without_effect(const InputFile &input) const
  {
    const bool none   = law == "none";
    const bool damped = !none && contact_law_is_damped(law);
    const bool given  = damping_from == ContactDampingFrom::given;
    const bool formula = damping_from == ContactDampingFrom::formula;
    const std::string law_is = "Contact/Law = " + law;
    // an entry, whether it has no effect, and why
    const std::vector<std::tuple<const char *, bool, std::string>> entries{
      {"Stiffness", none, law_is + " makes no gap element"},
      {"Damping from", none || !damped, law_is + (none ? " makes no gap element" : " has no damping")},
      {"Damping", none || !damped || !given,
       none ? law_is + " makes no gap element" :
       !damped ? law_is + " has no damping" :
                 "Damping from = " + contact_damping_from_names().name(damping_from) +
                   " derives the damping from the Coefficient of restitution"},
      {"Coefficient of restitution", none || !damped || given,
       none ? law_is + " makes no gap element" :
       !damped ? law_is + " has no damping: its impacts are elastic" :
                 std::string("Damping from = given uses Damping")},
      {"Hertz-damp formula", law != "hertz-damp" || !formula,
       law != "hertz-damp" ? law_is + ": the formula is Hertz-damp's" :
                             std::string("only Damping from = formula uses it")},
      {"Calibration velocity", none || !damped || damping_from != ContactDampingFrom::calibrated,
       "only Damping from = calibrated (a damped law) uses it"}};
    std::vector<std::string> warnings;
    for (const auto &[entry, without_effect, why] : entries)
      if (without_effect && input.line_of("Contact/" + std::string(entry)) > 0)
        warnings.push_back(input.warning("Contact/" + std::string(entry), "has no effect: " + why));
    return warnings;
  }

  double
  contact_law_damping(const ContactParameters &contact, const ContactLawParameters &law)
  {
    if (!contact_law_is_damped(contact.law))
      return 0;
    if (contact.damping_from == ContactDampingFrom::given)
      return contact.damping;
    if (contact.damping_from == ContactDampingFrom::formula)
      return damping_from_restitution_formula(
        contact.law, contact.restitution,
        hertz_damp_formula_names().name(contact.hertz_damp_formula));
    // the damping parameters are dimensionless: one calibration serves every gap
    return calibrate_damping(law, contact.restitution, contact.calibration_velocity);
  }
} // namespace poundfe
