// The help of every choice lists its allowed values, and each enum's name
// table parses back what it prints (summary.json and messages use it).
#include <poundfe/base/input_file.h>
#include <poundfe/input/input_parameters.h>

#include "test_utilities.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <sstream>

using namespace poundfe;

namespace
{
  template <typename Enum>
  void
  check_round_trip(const NameTable<Enum> &table)
  {
    for (const std::string &name : table.names())
      BOOST_TEST(table.name(table.value(name)) == name);
  }
} // namespace

BOOST_AUTO_TEST_CASE(help_lists_the_allowed_values)
{
  std::ostringstream out;
  print_parameters(out);
  std::string help;
  for (const char c : out.str()) // PRM output wraps comments: join the lines
    if (c != '\n' && c != '#')
      help += c;
  help.erase(std::unique(help.begin(), help.end(),
                         [](char a, char b) { return a == ' ' && b == ' '; }),
             help.end());
  for (const char *allowed :
       {"Allowed: none, modes, coefficients, modal, bands.", "Allowed: fixed, pinned.",
        "Allowed: kanai-tajimi, clough-penzien, white-noise, record, none.",
        "Allowed: none, jennings, saragoni-hart, shinozuka-sato.", "Allowed: g, m/s^2.",
        "Allowed: eigen-ldlt, umfpack, band-lu, petsc, trilinos, petsc-mumps, petsc-cg-boomeramg, "
        "trilinos-cg-ml.",
        "Allowed: peak drift ratio, peak roof displacement, peak contact force, limit state.",
        "Allowed: auto, woodbury, refactorize, hybrid.", "up to a total rank of Woodbury columns"})
    BOOST_TEST(help.find(allowed) != std::string::npos, allowed);
}

BOOST_AUTO_TEST_CASE(name_tables_round_trip)
{
  check_round_trip(building_type_names());
  check_round_trip(base_fixity_names());
  check_round_trip(damping_type_names());
  check_round_trip(mass_matrix_names());
  check_round_trip(contact_damping_from_names());
  check_round_trip(hertz_damp_formula_names());
  check_round_trip(ground_motion_type_names());
  check_round_trip(stochastic_method_names());
  check_round_trip(envelope_names());
  check_round_trip(soil_names());
  check_round_trip(record_format_names());
  check_round_trip(record_units_names());
  check_round_trip(tangent_update_names());
  check_round_trip(hysteresis_integration_names());
  check_round_trip(subset_response_names());
}

BOOST_AUTO_TEST_CASE(choices_are_enums_after_parsing)
{
  const InputParameters input = read_parameters("tests/cli/three-storey-shear.json");
  BOOST_TEST(building_type_names().name(input.model.buildings.at(0).type) == "shear");
}

// An item of a ';' list that holds only a vertical tab or a form feed is
// empty (trimmed skips what `>>` skips): before, it passed as an item with no
// words, and its first word was read out of an empty list (a crash from a
// parameter file: "x normal mean 0 sd 1;\v;\v").
BOOST_AUTO_TEST_CASE(an_item_of_blanks_only_is_no_item)
{
  BOOST_TEST(trimmed("\v x \f") == "x");
  BOOST_TEST(trimmed("\v\f\n").empty());
  const std::string file = poundfe_test::temporary_file(
    "blank_items.prm", "subsection Reliability\n"
                       "  set Random variables = x normal mean 0 sd 1;\v;\f\n"
                       "  set Constants = R 3;\v\n"
                       "  set Limit states = g: R - x\n"
                       "end\n");
  const InputParameters input = read_parameters(file);
  BOOST_TEST(input.reliability.variable_names.size() == 1u);
  BOOST_TEST(input.reliability.constants.size() == 1u);
}
