#include <poundfe/base/numbers.h>
#include <poundfe/model/link_parameters.h>
#include <poundfe/separation/mitigation_parameters.h>

#include <deal.II/base/parameter_handler.h>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  void
  MitigationParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Mitigation");
    prm.add_parameter("Damper locations", damper_locations,
                      "The viscous dampers of the study, 'building floor node building floor "
                      "node' as in Links/Viscous dampers without the law's numbers, separated "
                      "by ';'; every one takes each of the Damper coefficients in turn. "
                      "Unit: per field.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
    prm.add_parameter("Damper coefficients", damper_coefficients,
                      "c of the dampers, one case each, >= 0: F = c |v|^alpha sgn(v); 0 is a "
                      "damper without force, which equals the bare pair; at most 1e150 as every link's. Unit: N s/m (with alpha = 1; in general N s^alpha/m^alpha).",
                      Patterns::List(Patterns::Double(), 0));
    prm.add_parameter("Damper exponent", damper_exponent,
                      "alpha of every damper of the study, in (0, 1]. Unit: dimensionless.",
                      Patterns::Double());
    add_choice(prm, "Bumper law", bumper_law_names().name(bumper_law),
               "The stiffness law of the study's bumpers (Bumpers/Law): linear (F = k delta) "
               "or hertz (F = k delta^1.5). Unit: -.",
               {"linear", "hertz"},
               [this](const std::string &s) { bumper_law = bumper_law_names().value(s); });
    prm.add_parameter("Bumper thicknesses", bumper_thicknesses,
                      "One bumper case per thickness t >= 0 (Bumpers/Thickness), in every gap; "
                      "each at most the gap. Unit: m.",
                      Patterns::List(Patterns::Double(), 0));
    prm.add_parameter("Bumper stiffnesses", bumper_stiffnesses,
                      "k of the bumpers (Bumpers/Stiffness): one for all thicknesses or one per "
                      "thickness; at most 1e150 as Bumpers/Stiffness. Unit: N/m or N/m^1.5.",
                      Patterns::List(Patterns::Double(), 0));
    prm.leave_subsection();
  }

  void
  MitigationParameters::check(const InputFile &input) const
  {
    const std::string s = "Mitigation/";
    for (const double c : damper_coefficients) // the bounds of Links and Bumpers
      {
        input.non_negative(s + "Damper coefficients", c);
        input.at_most(s + "Damper coefficients", c, largest_model_value, "",
                      "beyond any physical link");
      }
    input.distinct(s + "Damper coefficients", damper_coefficients);
    if (!(damper_exponent > 0 && damper_exponent <= 1))
      input.fail(s + "Damper exponent",
                 "alpha must lie in (0, 1], got " + number_text(damper_exponent));
    if (!damper_coefficients.empty() && damper_locations.empty())
      input.fail(s + "Damper locations", "the Damper coefficients need dampers: give their "
                                         "'building floor node building floor node'");
    if (!damper_locations.empty() && damper_coefficients.empty())
      input.fail(s + "Damper coefficients", "is empty: give the c of each case (0: no force)");
    for (const double t : bumper_thicknesses)
      input.non_negative(s + "Bumper thicknesses", t);
    input.distinct(s + "Bumper thicknesses", bumper_thicknesses);
    if (bumper_thicknesses.empty() && !bumper_stiffnesses.empty())
      input.fail(s + "Bumper thicknesses", "is empty: give a thickness for each bumper case");
    if (!bumper_thicknesses.empty())
      input.list(s + "Bumper stiffnesses", bumper_stiffnesses, bumper_thicknesses.size(), false,
                 "one per thickness");
    for (const double k : bumper_stiffnesses)
      input.at_most(s + "Bumper stiffnesses", k, largest_model_value, "",
                    "beyond any physical contact");
  }

  void
  MitigationParameters::require(const InputFile &input) const
  {
    if (damper_coefficients.empty() && bumper_thicknesses.empty())
      input.fail("Mitigation/Damper coefficients",
                 "the mitigation study needs something to compare with the bare pair: "
                 "Damper coefficients (with Damper locations) or Bumper thicknesses");
  }

  BumperParameters
  MitigationParameters::bumper(const unsigned int k) const
  {
    BumperParameters b;
    b.law       = bumper_law;
    b.thickness = bumper_thicknesses.at(k);
    b.stiffness = bumper_stiffnesses.size() == 1 ? bumper_stiffnesses[0] : bumper_stiffnesses.at(k);
    return b;
  }

  std::vector<std::string>
  MitigationParameters::damper_entries(const double c) const
  {
    std::vector<std::string> entries;
    for (const std::string &location : damper_locations)
      entries.push_back(location + " " + number_text(c) + " " + number_text(damper_exponent));
    return entries;
  }
} // namespace poundfe
