// Drift limits (output/drift_limits.h): the code tables (ASCE 7-16 Table
// 12.12-1, Eurocode 8 4.4.3.2) as printed in the codes, the user's limits
// as ratios or percentages, bad limits named with their line, and the
// pass/fail of a building against hand-made peak drift ratios.
#include <poundfe/input/input_parameters.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/output/drift_limits.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace poundfe;

namespace
{
  /// The drift limits of a parameter file with `section` as its only section.
  DriftLimitParameters
  read_limits(const std::string &section)
  {
    const std::string file =
      (std::filesystem::temp_directory_path() / "poundfe_drift_limits.prm").string();
    // a parameter outside the section too: a file that sets nothing is refused
    std::ofstream(file) << "subsection Drift limits\n"
                        << section << "end\nsubsection Time integration\n"
                        << "  set Time step = 0.01\nend\n";
    try
      {
        const InputParameters input = read_parameters(file);
        std::remove(file.c_str());
        return input.drift_limits;
      }
    catch (...)
      {
        std::remove(file.c_str());
        throw;
      }
  }
} // namespace

BOOST_AUTO_TEST_CASE(code_drift_limits)
{
  // ASCE 7-16 Table 12.12-1, "all other structures": 0.020 h_sx (I, II),
  // 0.015 h_sx (III), 0.010 h_sx (IV)
  BOOST_TEST(code_drift_limit(DriftCode::asce7, "I", "", 1).drift_ratio == 0.020);
  BOOST_TEST(code_drift_limit(DriftCode::asce7, "II", "", 1).drift_ratio == 0.020);
  BOOST_TEST(code_drift_limit(DriftCode::asce7, "III", "", 1).drift_ratio == 0.015);
  BOOST_TEST(code_drift_limit(DriftCode::asce7, "IV", "", 1).drift_ratio == 0.010);
  // Eurocode 8 4.4.3.2: d_r nu <= 0.005 h, 0.0075 h, 0.010 h
  const auto tolerance = boost::test_tools::tolerance(1e-15);
  BOOST_TEST(code_drift_limit(DriftCode::eurocode8, "", "brittle", 0.5).drift_ratio == 0.010, tolerance);
  BOOST_TEST(code_drift_limit(DriftCode::eurocode8, "", "ductile", 0.5).drift_ratio == 0.015, tolerance);
  BOOST_TEST(code_drift_limit(DriftCode::eurocode8, "", "none", 0.4).drift_ratio == 0.025, tolerance);
  BOOST_TEST(code_drift_limit(DriftCode::eurocode8, "", "brittle", 1).drift_ratio == 0.005, tolerance);
}

BOOST_AUTO_TEST_CASE(user_limits_from_a_file)
{
  const DriftLimitParameters none = read_limits("");
  BOOST_TEST(none.limits().empty());
  const DriftLimitParameters p =
    read_limits("set Limits = 0.5 %, 1%, 0.02\nset Code = asce-7\nset Risk category = III\n");
  BOOST_TEST(p.limits().size() == 4u);
  const auto tolerance = boost::test_tools::tolerance(1e-15);
  BOOST_TEST(p.limits()[0].drift_ratio == 0.005, tolerance);
  BOOST_TEST(p.limits()[1].drift_ratio == 0.01, tolerance);
  BOOST_TEST(p.limits()[2].drift_ratio == 0.02, tolerance);
  BOOST_TEST(p.limits()[3].drift_ratio == 0.015);
  BOOST_TEST(p.limits()[0].name == "limit 0.5 %");
  for (const std::string bad : {"set Limits = 1 %%\n", "set Limits = 0.5 %, , 1 %\n",
                                "set Limits = 2\n", "set Limits = -1 %\n", "set Limits = one\n"})
    {
      try
        {
          read_limits(bad);
          BOOST_ERROR("accepted: " << bad);
        }
      catch (const InputError &e)
        {
          BOOST_TEST(e.line() == 2, bad << ": " << e.what());
          BOOST_TEST(e.parameter() == "Drift limits/Limits");
        }
    }
}

BOOST_AUTO_TEST_CASE(pass_and_fail_per_limit)
{
  const std::vector<DriftLimit> limits{{"a", 0.005}, {"b", 0.01}, {"c", 0.02}};
  const std::vector<DriftCheck> checks = check_drift_limits(limits, {0.004, 0.012, 0.01});
  BOOST_TEST(checks.size() == 3u);
  BOOST_TEST(!checks[0].passes);
  BOOST_TEST(checks[0].storeys_exceeding == std::vector<unsigned int>({2, 3}),
             boost::test_tools::per_element());
  BOOST_TEST(!checks[1].passes); // 0.01 at storey 3 is on the limit: passes there
  BOOST_TEST(checks[1].storeys_exceeding == std::vector<unsigned int>({2}),
             boost::test_tools::per_element());
  BOOST_TEST(checks[2].passes);
  for (const DriftCheck &c : checks)
    {
      BOOST_TEST(c.peak_drift_ratio == 0.012);
      BOOST_TEST(c.storey_of_peak == 2u);
    }
}

BOOST_AUTO_TEST_CASE(code_choice_names)
{
  for (const std::string &name : drift_code_names().names())
    BOOST_TEST(drift_code_names().name(drift_code_names().value(name)) == name);
  std::ostringstream out;
  print_parameters(out);
  std::string help; // PRM output wraps comments: join the lines
  for (const char c : out.str())
    if (c != '\n' && c != '#')
      help += c;
  help.erase(std::unique(help.begin(), help.end(),
                         [](char a, char b) { return a == ' ' && b == ' '; }),
             help.end());
  BOOST_TEST(help.find("Allowed: none, asce-7, eurocode-8.") != std::string::npos);
}
