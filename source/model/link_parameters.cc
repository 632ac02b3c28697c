#include <poundfe/base/numbers.h>
#include <poundfe/model/link_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  const NameTable<BumperLaw> &
  bumper_law_names()
  {
    static const NameTable<BumperLaw> table({{BumperLaw::none, "none"},
                                             {BumperLaw::linear, "linear"},
                                             {BumperLaw::hertz, "hertz"},
                                             {BumperLaw::table, "table"}});
    return table;
  }

  void
  LinkParameters::declare(dealii::ParameterHandler &prm)
  {
    const std::string where =
      "between the ux of two floor nodes 'building floor node building floor node' (the "
      "building: its number or its Name; floor 1-based; node 0-based from the left), on "
      "d = ux_first - ux_second, separated by ';'. ";
    const auto list = Patterns::List(Patterns::Anything(), 0, 1000, ";");
    prm.add_parameter("Viscous dampers", viscous,
                      "Viscous dampers " + where +
                        "'... c alpha': F = c |v|^alpha sgn(v), 0 < alpha <= 1 (c in "
                        "N (s/m)^alpha). Unit: per field.",
                      list);
    prm.add_parameter("Kelvin-Voigt links", kelvin_voigt,
                      "Viscoelastic links, spring and damper in parallel, " + where +
                        "'... k c alpha': F = k d + c |v|^alpha sgn(v) (k in N/m). Unit: per "
                        "field.",
                      list);
    prm.add_parameter("Maxwell links", maxwell,
                      "Viscoelastic links, spring k (N/m) in series with a linear dashpot c "
                      "(N s/m), " + where + "'... k c'. Unit: per field.",
                      list);
    prm.add_parameter("Elastic-plastic links", elastic_plastic,
                      "Bilinear links with kinematic hardening " + where +
                        "'... k Fy r': stiffness k (N/m), yield force Fy (N), post-yield "
                        "stiffness r k, 0 <= r < 1. Unit: per field.",
                      list);
    prm.add_parameter("Soil coupling", soil_coupling,
                      "Structure-soil-structure interaction, typed in: 'building building k c' "
                      "separated by ';', a spring k (N/m) and a dashpot c (N s/m), both >= 0, "
                      "between the sways of the two buildings' compliant foundations "
                      "(Building <i>/Foundation), on d = u0_first - u0_second; reported among "
                      "the links (doc/theory.md §1.16). Unit: per field.",
                      list);
    prm.add_parameter("Rocking soil coupling", rocking_soil_coupling,
                      "Structure-soil-structure interaction in rocking, typed in: 'building "
                      "building k c' separated by ';', a rotational spring k (N m/rad) and "
                      "dashpot c (N m s/rad), both >= 0, between the rockings of the two "
                      "buildings' compliant foundations in the x-z plane (2D: their rotation; "
                      "3D: about y), on d = theta_first - theta_second; reported among the "
                      "links (doc/theory.md §1.16). Unit: per field.",
                      list);
    prm.add_parameter("Regularization velocity", regularization_velocity,
                      "v_eps of the dampers with alpha < 1: F = c v (v^2 + v_eps^2)^((alpha-1)/2) "
                      "keeps the tangent finite at v = 0 (doc/theory.md §1.14). Unit: m/s.");
  }

  void
  LinkParameters::check(const InputFile &input) const
  {
    input.positive("Links/Regularization velocity", regularization_velocity);
  }

  void
  BumperInputParameters::declare(dealii::ParameterHandler &prm)
  {
    add_choice(prm, "Law", bumper.law,
               "A bumper layer in every gap between buildings and at barriers, touched "
               "before the structure: none; linear (F = k delta); hertz (F = k delta^1.5); "
               "table (piecewise linear through the Table's points). Once crushed to zero "
               "thickness the structure's contact law acts too (doc/theory.md §4.9). Unit: -.",
               bumper_law_names());
    prm.add_parameter("Thickness", bumper.thickness,
                      "t: the bumper is touched at a closure of (gap - t); at most the "
                      "smallest gap. Unit: m.");
    prm.add_parameter("Stiffness", bumper.stiffness,
                      "k of the linear (N/m) or hertz (N/m^1.5) bumper. Unit: N/m or N/m^1.5.");
    prm.add_parameter("Table", table,
                      "'compression force' pairs separated by ';' (m, N), compressions "
                      "increasing from > 0 up to at least the thickness, forces increasing "
                      "(Law = table). Unit: per field.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
  }

  void
  BumperInputParameters::finalize(const InputFile &input, const std::string &contact_law)
  {
    if (bumper.law == BumperLaw::none)
      return;
    if (contact_law == "none")
      input.fail("Bumpers/Law", "a bumper needs gaps: set Contact/Law");
    input.non_negative("Bumpers/Thickness", bumper.thickness);
    if (bumper.law != BumperLaw::table)
      {
        input.positive("Bumpers/Stiffness", bumper.stiffness);
        // the links' bound (model/building_links.cc): Newton squares the force
        input.at_most("Bumpers/Stiffness", bumper.stiffness, largest_model_value, "",
                      "beyond any physical bumper");
        return;
      }
    bumper.table.clear();
    std::array<double, 2> last{{0.0, 0.0}};
    for (const std::string &entry : table)
      {
        if (entry.find_first_not_of(" \t") == std::string::npos)
          continue;
        std::istringstream    in(entry);
        std::array<double, 2> point{{0, 0}};
        std::string           rest;
        if (!read_number(read_number(in, point[0]), point[1]) || (in >> rest))
          input.fail("Bumpers/Table", "'" + entry + "': expected 'compression force'");
        if (!(point[0] > last[0] && point[1] > last[1]) || !std::isfinite(point[0] + point[1]))
          input.fail("Bumpers/Table", "'" + entry + "': compressions and forces must "
                                      "increase from (0, 0) and be finite");
        bumper.table.push_back(point);
        last = point;
      }
    if (bumper.table.empty())
      input.fail("Bumpers/Table", "Law = table needs at least one 'compression force' pair");
    if (last[0] < bumper.thickness)
      input.fail("Bumpers/Table", "the table ends at a compression of " + number_text(last[0]) +
                                    " m, before the thickness " +
                                    number_text(bumper.thickness) + " m");
  }
} // namespace poundfe
