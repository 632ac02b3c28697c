// Modes of torsionally coupled shear buildings read from a parameter file
// (Model/Dimension = 3): a one-storey system with an eccentric mass against
// Chopra's closed form, the effective modal masses in x, y and about z, and
// the bad input a 3D building refuses.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/model/model_builder.h>

#include "../test_utilities.h"

#include <boost/test/unit_test.hpp>

#include <numeric>

using namespace poundfe;

namespace
{
  /// One storey: a 10 x 6 m slab of 8e4 kg, four frames on its edges (k_x
  /// per x frame, k_y per y frame), the mass centre e east of the centre.
  std::string
  one_storey(const double e, const std::string &planes = "0 -3 0 2e7; 0 3 0 2e7; -5 0 90 "
                                                         "3e7; 5 0 90 3e7")
  {
    return "subsection Model\n set Dimension = 3\nend\n"
           "subsection Building 1\n set Type = shear\n set Number of storeys = 1\n"
           " set Floor masses = 8e4\n subsection Plan\n  set Plan dimensions = 10, 6\n"
           "  set Mass eccentricity = " + std::to_string(e) + ", 0\n"
           "  set Resisting planes = " + planes + "\n end\n"
           " subsection Damping\n  set Type = none\n end\nend\n"
           "subsection Ground motion\n set Type = none\nend\n"
           "subsection Output\n set Number of modes = 3\nend\n";
  }

  Analysis
  analysis_of(const std::string &name, const std::string &text)
  {
    return prepare_analysis(read_parameters(poundfe_test::temporary_file(name, text)));
  }
} // namespace

BOOST_AUTO_TEST_SUITE(plan_modes)

BOOST_AUTO_TEST_CASE(one_storey_matches_chopra)
{
  // Chopra (2012) ch. 9: about the mass centre C, e east of the stiffness
  // centre R (the plan centre): K_y = 6e7, K_θ(C) = K_θR + e^2 K_y with
  // K_θR = 2 (2e7 3^2 + 3e7 5^2), I = m (10^2 + 6^2) / 12; u_x uncouples.
  const double e = 1.2, m = 8e4, I = m * (100 + 36) / 12.0;
  const double ky = 6e7, kx = 4e7, k_theta = 2 * (2e7 * 9 + 3e7 * 25) + e * e * ky;
  const double wy2 = ky / m, wt2 = k_theta / I, r2 = I / m;
  const double mean = 0.5 * (wy2 + wt2);
  const double root = std::sqrt(0.25 * (wy2 - wt2) * (wy2 - wt2) + wy2 * wy2 * e * e / r2);
  std::vector<double> expected{std::sqrt(mean - root), std::sqrt(kx / m), std::sqrt(mean + root)};
  std::sort(expected.begin(), expected.end());
  const Analysis a = analysis_of("one_storey_3d.prm", one_storey(e));
  BOOST_REQUIRE_EQUAL(a.modes.n_modes(), 3u);
  // tolerance: the dense symmetric eigensolver is accurate to round-off
  for (unsigned int i = 0; i < 3; ++i)
    BOOST_TEST(a.modes.omega[i] == expected[i], boost::test_tools::tolerance(1e-10));
}

BOOST_AUTO_TEST_CASE(effective_masses_sum_to_one)
{
  // all three modes of one floor: the ratios in x, y and about z each add
  // up to 1 (completeness of the mass-normalised modes); with e along x the
  // x mode carries all of x and none of y or z
  const Analysis a = analysis_of("one_storey_3d_mass.prm", one_storey(1.2));
  const Modes   &m = a.modes;
  BOOST_REQUIRE_EQUAL(m.participating_mass_ratio_y.size(), 3u);
  const auto sum = [](const std::vector<double> &v) {
    return std::accumulate(v.begin(), v.end(), 0.0);
  };
  BOOST_TEST(sum(m.participating_mass_ratio) == 1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(sum(m.participating_mass_ratio_y) == 1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(sum(m.participating_mass_ratio_rz) == 1.0, boost::test_tools::tolerance(1e-12));
  for (unsigned int i = 0; i < 3; ++i)
    if (m.participating_mass_ratio[i] > 0.5)
      BOOST_TEST(m.participating_mass_ratio_y[i] + m.participating_mass_ratio_rz[i] < 1e-20);
}

BOOST_AUTO_TEST_CASE(bad_plans_are_refused)
{
  // all planes along x: no stiffness across them
  const std::string parallel = poundfe_test::input_error_of(
    [] { analysis_of("parallel_3d.prm", one_storey(0, "0 -3 0 2e7; 0 3 0 2e7")); });
  BOOST_TEST(parallel.find("Building 1/Plan/Resisting planes") != std::string::npos);
  BOOST_TEST(parallel.find("parallel") != std::string::npos);
  // two crossing planes through one point: no torsional stiffness
  const std::string pinned = poundfe_test::input_error_of(
    [] { analysis_of("pinned_3d.prm", one_storey(0, "0 0 0 2e7; 0 0 90 2e7")); });
  BOOST_TEST(pinned.find("torsional stiffness") != std::string::npos);
  BOOST_TEST(pinned.find("Building 1/Plan/Resisting planes") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
