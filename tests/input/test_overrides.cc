// Parameter overrides (read_parameters(file, overrides)): a value set by
// path lands in the same member the file's value would (the reference: the
// file itself, and the value written into the override), through the same
// patterns and checks; an unknown path or a refused value is one InputError
// naming the path.
#include <poundfe/input/input_parameters.h>
#include <poundfe/input/unknown_path.h>
#include <poundfe/base/exceptions.h>

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace poundfe;

namespace
{
  const std::string two_buildings = "input/two-buildings.prm";
  const std::string sdof          = "input/bouc-wen-sdof.prm";
  const std::string json          = "tests/cli/three-storey-shear.json";
  const std::string sd            = "input/sd-oscillator.prm";
  const std::string duffing       = "input/duffing-bifurcation.prm";

  /// The InputError of reading `file` with one override (an empty error when none).
  InputError
  error_of(const std::string &file, const std::string &path, const std::string &value)
  {
    try
      {
        read_parameters(file, {{path, value}});
      }
    catch (const InputError &e)
      {
        return e;
      }
    BOOST_ERROR("no InputError for " + path + " = " + value);
    return InputError("", 0, "", "");
  }
} // namespace

BOOST_AUTO_TEST_CASE(overrides_set_numeric_entries_in_any_section)
{
  const InputParameters file = read_parameters(two_buildings);
  BOOST_TEST(file.model.separations == std::vector<double>{0.01});
  const InputParameters p = read_parameters(
    two_buildings, {{"Model/Separations", "0.07"},
                    {"Building 2/Floor masses", "19000, 16000"},
                    {"Building 1/Damping/Damping ratio", "0.02"},
                    {"Time integration/Time step", "0.004"}});
  BOOST_TEST(p.model.separations == std::vector<double>{0.07});
  BOOST_TEST(p.model.buildings.at(1).floor_masses == (std::vector<double>{19000, 16000}));
  BOOST_TEST(p.model.buildings.at(0).damping_ratio == 0.02);
  BOOST_TEST(p.time_integration.newmark.time_step == 0.004);
  // everything else is the file's
  BOOST_TEST(p.model.buildings.at(0).floor_masses == file.model.buildings.at(0).floor_masses);
}

BOOST_AUTO_TEST_CASE(overrides_reach_ground_motion_friction_and_springs)
{
  const InputParameters motion =
    read_parameters(two_buildings, {{"Ground motion/Scale factor", "0.5"},
                                    {"Ground motion/Stochastic/S0", "0.02"}});
  BOOST_TEST(motion.ground_motion.scale_factor == 0.5);
  BOOST_TEST(motion.ground_motion.spectral_intensity == 0.02);
  const InputParameters friction =
    read_parameters(sd, {{"Friction/Static coefficient", "0.25"},
                         {"Friction/Kinetic coefficient", "0.2"}});
  BOOST_TEST(friction.friction.law.static_coefficient == 0.25);
  BOOST_TEST(friction.friction.law.kinetic_coefficient == 0.2);
  const InputParameters spring = read_parameters(duffing, {{"Springs/Cubic springs:5", "3"}});
  BOOST_TEST(spring.springs.cubic.at(0) == "1 1 0 1 3");
  // the section's own check: mu_k > mu_s is refused, naming the entry
  const InputError e = error_of(sd, "Friction/Kinetic coefficient", "0.5");
  BOOST_TEST(e.parameter().find("Friction/") == 0u, e.what());
}

BOOST_AUTO_TEST_CASE(overrides_work_for_json_input)
{
  const InputParameters file = read_parameters(json);
  const InputParameters p    = read_parameters(json, {{"Building 1/Floor masses", "12345"}});
  BOOST_TEST(p.model.buildings.at(0).floor_masses == std::vector<double>{12345});
  BOOST_TEST(file.model.buildings.at(0).floor_masses != p.model.buildings.at(0).floor_masses);
}

BOOST_AUTO_TEST_CASE(field_overrides_change_one_field_of_the_first_item)
{
  const InputParameters file = read_parameters(sdof);
  BOOST_TEST(file.nodal_forces.harmonic.at(0) == "1 1 0 ux 40000 35.35533905932738 0");
  const InputParameters amplitude = read_parameters(sdof, {{"Nodal forces/Harmonic:5", "123"}});
  BOOST_TEST(amplitude.nodal_forces.harmonic.at(0) == "1 1 0 ux 123 35.35533905932738 0");
  const InputParameters omega =
    read_parameters(sdof, {{"Nodal forces/Harmonic:6", "20"}, {"Nodal forces/Harmonic:7", "0.5"}});
  BOOST_TEST(omega.nodal_forces.harmonic.at(0) == "1 1 0 ux 40000 20 0.5");
}

BOOST_AUTO_TEST_CASE(overrides_change_the_number_of_buildings_first)
{
  // the number of buildings shapes the declarations: it is set in the first pass
  const InputParameters p = read_parameters(sdof, {{"Model/Number of buildings", "2"},
                                                   {"Building 2/Floor masses", "500"}});
  BOOST_TEST(p.model.buildings.size() == 2u);
  BOOST_TEST(p.model.buildings.at(1).floor_masses == std::vector<double>{500});
}

BOOST_AUTO_TEST_CASE(bad_overrides_are_input_errors_naming_the_path)
{
  struct Case
  {
    std::string file, path, value, problem;
  };
  for (const Case &c : std::vector<Case>{
         {two_buildings, "Model/Separations", "-0.1", "must be zero or positive"},
         {two_buildings, "Model/Separations", "wide", "is not allowed"},
         {two_buildings, "Model/Spacing", "0.1", "No entry with name <Spacing> in 'Model'"},
         {two_buildings, "Building 3/Floor masses", "1",
          "'Building 3' is given, but Model/Number of buildings is 2"},
         {two_buildings, "Buildin 1/Floor masses", "1",
          "There is no such subsection to be entered: Buildin 1 (did you mean 'Building 1' or "
          "'Building 2'?)"},
         {two_buildings, "Separations", "0.1", "a path is"},
         {json, "Building 1/Floor masses", "-5", "positive"},
         {sdof, "Nodal forces/Harmonic:8", "1", "has 7 fields, not 8"},
         {sdof, "Nodal forces/Harmonic:0", "1", "fields count from 1"},
         {sdof, "Nodal forces/Harmonc:2", "1",
          "No entry with name <Harmonc> in 'Nodal forces' (did you mean 'Harmonic'?)"},
         {sdof, "Time integration/Time step", "0", "positive"}})
    {
      const InputError e = error_of(c.file, c.path, c.value);
      BOOST_TEST(e.parameter().find(c.path.substr(0, c.path.rfind(':'))) == 0u, c.path);
      BOOST_TEST(std::string(e.what()).find(c.problem) != std::string::npos,
                 c.path << " = " << c.value << ": " << e.what());
      BOOST_TEST(e.file() == c.file);
    }
}

BOOST_AUTO_TEST_CASE(an_unknown_path_is_refused_in_the_same_words_by_the_file_and_an_override)
{
  // the reference: the same misspelt path written into the file
  struct Case
  {
    std::string block, path, problem;
  };
  for (const Case &c : std::vector<Case>{
         {"subsection Time integration\n  set Tim step = 0.01\nend\n", "Time integration/Tim step",
          "No entry with name <Tim step> in 'Time integration' (did you mean 'Time step'?)"},
         {"subsection Time integraton\n  set Time step = 0.01\nend\n", "Time integraton/Time step",
          "There is no such subsection to be entered: Time integraton (did you mean 'Time "
          "integration'?)"},
         {"subsection Building 1\n  subsection Dampng\n    set Type = none\n  end\nend\n",
          "Building 1/Dampng/Type",
          "There is no such subsection to be entered: Building 1/Dampng (did you mean 'Damping'?)"},
         {"subsection Model\n  set Time step = 0.01\nend\n", "Model/Time step",
          "No entry with name <Time step> in 'Model' (did you mean 'Ground motion/Record/Time "
          "step' or 'Time integration/Time step'?)"}})
    {
      // a file of no other section (a section may be entered only once)
      const std::string base = "subsection Output\n  set Plots = false\nend\n";
      const std::filesystem::path directory = std::filesystem::temp_directory_path();
      const std::string file = (directory / "poundfe-test-unknown-path.prm").string();
      const std::string plain = (directory / "poundfe-test-known-paths.prm").string();
      std::ofstream(file) << base << c.block;
      std::ofstream(plain) << base;
      std::string from_file;
      try
        {
          read_parameters(file);
          BOOST_ERROR("no InputError for " + c.path + " in the file");
        }
      catch (const InputError &e)
        {
          from_file = e.problem();
          BOOST_TEST(e.line() > 0, c.path);
        }
      const InputError from_override = error_of(plain, c.path, "0.01");
      std::filesystem::remove(file);
      std::filesystem::remove(plain);
      BOOST_TEST(from_file == c.problem);
      BOOST_TEST(from_override.problem() == c.problem);
      BOOST_TEST(from_override.parameter() == c.path);
      BOOST_TEST(from_override.file() == plain);
    }
  // a JSON file: deal.II's JSON reader names the entry alone; the reader
  // finds its path among the file's keys
  for (const Case &c : std::vector<Case>{
         {R"({"Time integration": {"Tim step": "0.01"}})", "Time integration/Tim step",
          "No entry with name <Tim step> in 'Time integration' (did you mean 'Time step'?)"},
         {R"({"Building 1": {"Dampng": {"Type": "none"}}})", "Building 1/Dampng/Type",
          "There is no such subsection to be entered: Building 1/Dampng (did you mean 'Damping'?)"}})
    {
      const std::string file =
        (std::filesystem::temp_directory_path() / "poundfe-test-unknown-path.json").string();
      std::ofstream(file) << c.block;
      try
        {
          read_parameters(file);
          BOOST_ERROR("no InputError for " + c.path + " in the JSON file");
        }
      catch (const InputError &e)
        {
          BOOST_TEST(e.parameter() == c.path);
          BOOST_TEST(e.problem() == c.problem);
        }
      std::filesystem::remove(file);
    }
}

BOOST_AUTO_TEST_CASE(suggestions_for_an_unknown_path)
{
  // Levenshtein's classic pair (Wagner & Fischer 1974): 3 edits, case ignored
  BOOST_TEST(edit_distance("kitten", "SITTING") == 3u);
  BOOST_TEST(edit_distance("", "abc") == 3u);
  const std::vector<std::string> declared{"Alpha/Speed", "Alpha/Spread", "Alpha/Beta/Speed",
                                          "Gamma/Seed", "Gamma/Duration"};
  // one edit from both: in their order of declaration
  BOOST_TEST(unknown_path_problem(declared, "Alpha/Spead", false) ==
             "No entry with name <Spead> in 'Alpha' (did you mean 'Speed' or 'Spread'?)");
  BOOST_TEST(unknown_path_problem(declared, "Alpha/Sped", false) ==
             "No entry with name <Sped> in 'Alpha' (did you mean 'Speed'?)");
  BOOST_TEST(unknown_path_problem(declared, "Gamma/Colour", false) ==
             "No entry with name <Colour> in 'Gamma'");
  // the same name in another subsection
  BOOST_TEST(unknown_path_problem(declared, "Alpha/duration", false) ==
             "No entry with name <duration> in 'Alpha' (did you mean 'Gamma/Duration'?)");
  BOOST_TEST(unknown_path_problem(declared, "Delta/Seed", false) ==
             "There is no such subsection to be entered: Delta");
  // names are case-sensitive; the suggestions are not
  BOOST_TEST(unknown_path_problem(declared, "Alpha/beta/Speed", false) ==
             "There is no such subsection to be entered: Alpha/beta (did you mean 'Beta'?)");
  BOOST_TEST(unknown_path_problem(declared, "Alpha/Beta/Gamma", true) ==
             "There is no such subsection to be entered: Alpha/Beta/Gamma");
}

BOOST_AUTO_TEST_CASE(sweep_values_and_one_input_per_value)
{
  SweepParameters sweep;
  sweep.values_text = "linspace 0.01 0.05 5";
  const std::vector<double> v = sweep.values();
  BOOST_TEST_REQUIRE(v.size() == 5u);
  for (unsigned int i = 0; i < 5; ++i) // a + i (b - a) / (n - 1), rounded to 15 digits
    BOOST_TEST(v[i] == 0.01 + i * 0.01, boost::test_tools::tolerance(1e-15));
  sweep.values_text = "linspace 0.70 0.84 29"; // the decimal values, not their sums
  BOOST_TEST(sweep.values().at(15) == 0.775);
  BOOST_TEST(sweep.values().at(28) == 0.84);
  sweep.values_text = " 3, -1.5e-2 ,7";
  BOOST_TEST(sweep.values() == (std::vector<double>{3, -1.5e-2, 7}));

  sweep.parameter = "Model/Separations";
  BOOST_TEST(sweep.column_name() == "Model_Separations");
  const InputParameters p = sweep_input(sweep, two_buildings, 0.0625);
  BOOST_TEST(p.model.separations == std::vector<double>{0.0625});
  // a value the entry's check refuses is the override's InputError
  BOOST_CHECK_THROW(sweep_input(sweep, two_buildings, -1), InputError);
}

BOOST_AUTO_TEST_CASE(bad_sweep_values_are_input_errors)
{
  InputFile file;
  file.file = "sweep.prm";
  for (const char *text : {"linspace 0 1", "linspace 0 1 2.5", "linspace 0 1 0", "linspace 0 1 1",
                           "1, two, 3", "1,,2", "linspace 0 1 3 4", "1e999"})
    {
      SweepParameters sweep;
      sweep.values_text = text;
      BOOST_CHECK_THROW(sweep.check(file), InputError);
    }
  SweepParameters sweep;
  sweep.values_text = "1, 2";
  BOOST_CHECK_THROW(sweep.require(file), InputError); // no parameter
}
