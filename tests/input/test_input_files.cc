// The input files an input names (input/engine_parameters.h:
// named_input_files), which a resumed table is tied to by their digests
// (output/output_directory.h: resume_file). Each section lists its own
// beside its declarations; this checks that the lists together cover every
// declared entry that names a file (every entry called "... file" or "File"
// in print_parameters, and Nodal forces/Tabulated, whose fifth field is
// one), so that an entry added later without its listing fails here, and
// that each name is resolved against the parameter file's directory.
// Reference: print_parameters' own listing.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include <boost/test/unit_test.hpp>

#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace poundfe;

namespace
{
  /// The path of every entry of print_parameters whose name ends in "file"
  /// or "File" ("Building 1/Mesh file", "Ground motion/Record/File", ...).
  std::set<std::string>
  declared_file_entries()
  {
    std::ostringstream listing;
    print_parameters(listing);
    std::istringstream       in(listing.str());
    std::vector<std::string> sections;
    std::set<std::string>    entries;
    for (std::string line; std::getline(in, line);)
      {
        const std::string text = trimmed(line);
        if (text.rfind("subsection ", 0) == 0)
          sections.push_back(trimmed(text.substr(11)));
        else if (text == "end" && !sections.empty())
          sections.pop_back();
        else if (text.rfind("set ", 0) == 0)
          {
            const std::string name = trimmed(text.substr(4, text.find('=') - 4));
            if (name.size() >= 4 && (name.substr(name.size() - 4) == "file" ||
                                     name.substr(name.size() - 4) == "File"))
              {
                std::string path;
                for (const std::string &s : sections)
                  path += s + "/";
                entries.insert(path + name);
              }
          }
      }
    return entries;
  }
} // namespace

BOOST_AUTO_TEST_CASE(every_declared_file_entry_is_listed_and_resolved)
{
  InputParameters input;
  input.file      = "study/pair.prm";
  input.directory = "study";
  input.model.buildings.resize(1);
  input.model.buildings[0].mesh_file         = "frame.msh";
  input.ground_motion.record_file            = "x.at2";
  input.ground_motion.second_record_file     = "y.at2";
  input.ground_motion.third_record_file      = "/records/z.at2";
  input.nodal_forces.tabulated               = {"1 2 0 ux force.csv", "B 1 1 uy ../push.csv"};
  input.site_hazard.catalogue_file           = "catalogue.csv";
  input.site_hazard.fragility_file           = "fragility/summary.json";
  input.separation.hazard.hazard_file        = "hazard_curve.csv";

  std::set<std::string> listed, paths;
  for (const NamedInputFile &f : named_input_files(input))
    {
      BOOST_TEST_MESSAGE(f.entry << ": the " << f.what << " '" << f.name << "' at " << f.path);
      BOOST_TEST(!f.what.empty());
      listed.insert(f.entry);
      paths.insert(f.path);
    }
  std::set<std::string> expected = declared_file_entries();
  BOOST_TEST(expected.size() >= 7u); // Mesh file, File, Second, Third, Catalogue, Fragility, hazard
  expected.insert("Nodal forces/Tabulated");
  BOOST_TEST(listed == expected, boost::test_tools::per_element());
  const std::set<std::string> resolved{"study/frame.msh",      "study/x.at2",
                                       "study/y.at2",          "/records/z.at2",
                                       "study/force.csv",      "push.csv",
                                       "study/catalogue.csv",  "study/fragility/summary.json",
                                       "study/hazard_curve.csv"};
  BOOST_TEST(paths == resolved, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(nothing_named_nothing_listed)
{
  InputParameters input;
  input.model.buildings.resize(2);
  BOOST_TEST(named_input_files(input).empty());
}
