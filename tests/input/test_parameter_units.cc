// Every declared parameter says its unit (issue 14 item 15): its
// documentation carries one marker 'Unit: <u>.', where <u> is
//   -                  no unit: a name, file, choice, switch or index
//   dimensionless      a pure number (ratio, factor, tolerance)
//   count              a whole number of things
//   per field          a list whose fields' units the text states
//   that of <entry>    the unit of another entry (Sweep/Values)
//   a unit expression  SI symbols and the few others input uses (g, km,
//                      degrees, year(s), 1/year), with ^, / and blanks, alternatives
//                      joined by ' or ', optionally followed by a note
//                      in parentheses, e.g. 'N/m or N/m^1.5', 'm^2/s^3'.
// The walk goes over the parameters as declared (ParameterHandler's JSON
// form, one building), so a new entry without a unit fails here. Entries of
// a Building tagged [frame], [shear], [mesh] use only those tags.
#include <poundfe/input/input_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/test/unit_test.hpp>

#include <regex>
#include <sstream>

using namespace poundfe;

namespace
{
  /// Whether `unit` is one of the marker's forms (above).
  bool
  valid_unit(const std::string &unit)
  {
    static const std::regex symbol_expression(
      "(1|m|s|kg|N|Pa|rad|Hz|g|km|degrees|years?)(\\^[0-9.]+)?"
      "(( |/)(m|s|kg|N|Pa|rad|Hz|g|km|year)(\\^[0-9.]+)?)*");
    static const std::regex note(" \\([^()]*\\)$");
    std::string bare = std::regex_replace(unit, note, "");
    if (bare == "-" || bare == "dimensionless" || bare == "count" || bare == "per field")
      return true;
    if (bare.rfind("that of ", 0) == 0 && bare.size() > 8)
      return true;
    std::size_t start = 0;
    for (std::size_t end; (end = bare.find(" or ", start)) != std::string::npos; start = end + 4)
      if (!std::regex_match(bare.substr(start, end - start), symbol_expression))
        return false;
    return std::regex_match(bare.substr(start), symbol_expression);
  }

  /// The unit of a documentation text: the text after its one 'Unit: ' up
  /// to the '.' that ends the marker ('' if there is none, or two).
  std::string
  unit_of(const std::string &documentation)
  {
    const std::size_t at = documentation.find("Unit: ");
    if (at == std::string::npos || documentation.find("Unit: ", at + 1) != std::string::npos)
      return "";
    const std::size_t end = documentation.find(". ", at);
    std::string unit =
      documentation.substr(at + 6, end == std::string::npos ? std::string::npos : end - at - 6);
    if (end == std::string::npos && !unit.empty() && unit.back() == '.')
      unit.pop_back();
    return unit;
  }

  /// ParameterHandler mangles names in its trees (a blank is "_20").
  std::string
  demangled(const std::string &name)
  {
    std::string out;
    for (std::size_t i = 0; i < name.size(); ++i)
      if (name[i] == '_' && i + 2 < name.size() && std::isxdigit(name[i + 1]) &&
          std::isxdigit(name[i + 2]))
        {
          out += static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
          i += 2;
        }
      else
        out += name[i];
    return out;
  }

  /// Every entry under `tree`: (path, documentation).
  void
  collect(const boost::property_tree::ptree &tree, const std::string &path,
          std::vector<std::pair<std::string, std::string>> &entries)
  {
    for (const auto &[name, child] : tree)
      if (child.count("documentation") > 0 && child.count("value") > 0)
        entries.emplace_back(path + demangled(name), child.get<std::string>("documentation"));
      else if (!child.empty())
        collect(child, path + demangled(name) + "/", entries);
  }

  std::vector<std::pair<std::string, std::string>>
  declared_entries()
  {
    InputParameters parameters;
    parameters.model.buildings.resize(1);
    parameters.sections.sections.resize(1);
    dealii::ParameterHandler prm;
    parameters.declare(prm);
    std::stringstream json;
    prm.print_parameters(json, dealii::ParameterHandler::JSON);
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(json, tree);
    std::vector<std::pair<std::string, std::string>> entries;
    collect(tree, "", entries);
    return entries;
  }
} // namespace

BOOST_AUTO_TEST_CASE(the_unit_marker_is_recognised_strictly)
{
  // the checker itself: it must be able to fail
  BOOST_TEST(unit_of("Length of the sample, s.") == "");
  BOOST_TEST(unit_of("Duration. Unit: s.") == "s");
  BOOST_TEST(unit_of("Soil. Unit: -. Allowed: firm, soft.") == "-");
  BOOST_TEST(unit_of("Unit: s. Unit: m.") == "");
  for (const char *good : {"-", "dimensionless", "count", "per field", "m/s^2", "N s/m",
                           "N m/rad", "m^2/s^3", "1/s", "1/year", "N/m or N/m^1.5", "year", "degrees",
                           "that of Parameter", "dimensionless (a macroseismic intensity)"})
    BOOST_TEST(valid_unit(good), good);
  for (const char *bad : {"", "meters", "m/", "s s s.", "unitless", "N/mm", "kN", "per"})
    BOOST_TEST(!valid_unit(bad), bad);
}

BOOST_AUTO_TEST_CASE(every_declared_entry_says_its_unit)
{
  const auto entries = declared_entries();
  BOOST_TEST_MESSAGE(entries.size() << " declared entries");
  BOOST_TEST(entries.size() > 200u); // the walk reached every section
  for (const auto &[path, documentation] : entries)
    BOOST_TEST(valid_unit(unit_of(documentation)),
               path << ": no valid 'Unit: <u>.' in '" << documentation << "'");
}

BOOST_AUTO_TEST_CASE(building_entries_use_the_type_tags)
{
  unsigned int n_tagged = 0;
  for (const auto &[path, documentation] : declared_entries())
    if (!documentation.empty() && documentation.front() == '[')
      {
        const std::string tag = documentation.substr(0, documentation.find(']') + 1);
        // a cross-section's entries are tagged by the section types that read them
        if (path.rfind("Sections/Section 1/", 0) == 0)
          {
            BOOST_TEST((tag == "[RC rectangle]" || tag == "[RC circle]" || tag == "[RC]" ||
                        tag == "[steel I]" || tag == "[RC rectangle, steel I]" ||
                        tag == "[RC, steel I]" || tag == "[fibres]"),
                       path << ": tag " << tag);
            continue;
          }
        BOOST_TEST((tag == "[frame]" || tag == "[shear]" || tag == "[mesh]" ||
                    tag == "[frame, shear]" || tag == "[frame, mesh]" || tag == "[3D]" ||
                    tag == "[3D shear]" || tag == "[3D frame]" || tag == "[3D mesh]" ||
                    tag == "[3D frame, mesh]" || tag == "[frame, fibre]" ||
                    tag == "[frame, mesh, fibre]" || tag == "[mesh, fibre]"),
                   path << ": tag " << tag);
        BOOST_TEST(path.rfind("Building 1/", 0) == 0u, path << " is tagged outside a building");
        ++n_tagged;
      }
  BOOST_TEST(n_tagged > 25u);
}

namespace
{
  /// Whether the text before 'Unit: u.' names the unit again, as "in u",
  /// ", u", "(u)" or "u:" — e.g. "Clear distance in m ... Unit: m." (issue 27:
  /// help texts without doubled units). Only plain units: '-', counts and
  /// dimensionless numbers cannot double.
  bool
  says_its_unit_twice(const std::string &documentation)
  {
    const std::string unit = unit_of(documentation);
    if (unit.empty() || unit == "-" || unit == "dimensionless" || unit == "count" ||
        unit.find(' ') != std::string::npos)
      return false;
    const std::string text = documentation.substr(0, documentation.find("Unit: "));
    for (const std::string &form : {" in " + unit + " ", " in " + unit + ":", ", " + unit + " ",
                                    ", " + unit + ";", ", " + unit + ",", "(" + unit + ")",
                                    " " + unit + ": "})
      if (text.find(form) != std::string::npos)
        return true;
    return false;
  }
} // namespace

BOOST_AUTO_TEST_CASE(no_entry_says_its_unit_twice)
{
  // the checker itself
  BOOST_TEST(says_its_unit_twice("Clear distance in m between buildings. Unit: m."));
  BOOST_TEST(says_its_unit_twice("Interval of rows, s (0: every step). Unit: s."));
  BOOST_TEST(!says_its_unit_twice("Clear distance between buildings. Unit: m."));
  BOOST_TEST(!says_its_unit_twice("Scale the record (in g when Units = g). Unit: dimensionless."));
  for (const auto &[path, documentation] : declared_entries())
    BOOST_TEST(!says_its_unit_twice(documentation), path << ": '" << documentation << "'");
}
