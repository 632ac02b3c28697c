// Compliant foundations under 3D (torsionally coupled) shear buildings
// (issue 26; doc/theory.md §1.16 "In 3D", doc/verification.md "Compliant
// foundations in 3D"):
//  - very stiff soil reproduces the fixed-base 3D run (two components,
//    eccentric mass) to 1e-8 of every floor DOF's peak;
//  - a rigid block (storeys 1e6 times stiffer than the soil): its five
//    frequencies are the closed forms of the rigid block on springs, torsion
//    ω² = K_t/(J_0 + J_1) and, in each vertical plane, the sway-rocking pair
//    det(K - ω² M) = 0 with M = [[m_0 + m_1, m_1 h], [m_1 h, I_0 + m_1 h²]]
//    (Richart, Hall & Woods 1970, Vibrations of Soils and Foundations, §7;
//    Wolf 1985 §2.1);
//  - the energy balance closes to 1e-8 on Gazetas' soil with dashpots;
//  - the same building and ground motion turned by 90° in plan give the
//    turned response (u_x, u_y, θ_z) -> (-u_y, u_x, θ_z).
#include <poundfe/base/numbers.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/foundation_periods.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include <cmath>
#include <string>

#include "floor_histories.h"
#include "time_history_helpers.h"

using namespace poundfe;
using poundfe_test::input_of;

namespace
{
  /// One 2-storey 3D shear building, 12 x 8 m, mass centre off the plan
  /// centre, turned by `rotation` degrees, with `foundation` (a subsection
  /// or empty), shaken by `components` Kanai-Tajimi samples at `incidence`.
  std::string
  building_on(const std::string &foundation, const double rotation = 0,
              const unsigned int components = 2, const double incidence = 0,
              const std::string &eccentricity = "1.0, 0.5",
              const std::string &stiffnesses = "4e7, 3e7", const double duration = 2)
  {
    return "subsection Model\n set Dimension = 3\nend\n"
           "subsection Building 1\n set Name = S\n set Type = shear\n"
           " set Number of storeys = 2\n set Storey heights = 3.5, 3.0\n"
           " set Floor masses = 5e4\n set Storey stiffnesses = " + stiffnesses + "\n"
           " subsection Plan\n  set Plan dimensions = 12, 8\n  set Rotation = " +
           std::to_string(rotation) + "\n  set Mass eccentricity = " + eccentricity +
           "\n end\n subsection Damping\n  set Type = coefficients\n  set a0 = 0.3\n"
           "  set a1 = 0.002\n end\n" + foundation + "end\n"
           "subsection Ground motion\n set Type = kanai-tajimi\n set Components = " +
           std::to_string(components) + "\n set Incidence angle = " + std::to_string(incidence) +
           "\n subsection Stochastic\n  set Target PGA = 0.4\n  set Duration = " +
           std::to_string(duration) + "\n  set Seed = 5\n  set Second seed = 6\n"
           "  set Method = spectral-representation\n  set Cutoff frequency = 50\n end\nend\n"
           "subsection Time integration\n set Time step = 0.01\nend\n";
  }

  std::string
  given_foundation(const double kx, const double ky, const double krx, const double kry,
                   const double kt, const double c, const double m0, const double irx,
                   const double iry, const double j0)
  {
    const auto n = [](const double x) { return number_text(x); };
    return " subsection Foundation\n  set Type = given\n  set Horizontal stiffness = " + n(kx) +
           "\n  set Horizontal stiffness y = " + n(ky) + "\n  set Rocking stiffness x = " +
           n(krx) + "\n  set Rocking stiffness = " + n(kry) + "\n  set Torsional stiffness = " +
           n(kt) + "\n  set Horizontal damping = " + n(c * kx) +
           "\n  set Horizontal damping y = " + n(c * ky) + "\n  set Rocking damping x = " +
           n(c * krx) + "\n  set Rocking damping = " + n(c * kry) +
           "\n  set Torsional damping = " + n(c * kt) + "\n  set Mass = " + n(m0) +
           "\n  set Rotary inertia x = " + n(irx) + "\n  set Rotary inertia = " + n(iry) +
           "\n  set Polar inertia = " + n(j0) + "\n end\n";
  }

  const std::string gazetas =
    " subsection Foundation\n  set Type = gazetas\n  set Shear-wave velocity = 150\n"
    "  set Soil density = 1900\n  set Poisson ratio = 0.3\n  set Length = 12\n"
    "  set Width = 8\n  set Embedment = 1\n  set Mass = 2e5\n  set Rotary inertia = 2.4e6\n"
    "  set Rotary inertia x = 1.1e6\n  set Polar inertia = 3.5e6\n end\n";

  /// The largest of |a - sign b| over a column's steps, relative to a's peak.
  double
  relative_difference(const std::vector<double> &a, const std::vector<double> &b,
                      const double sign = 1)
  {
    BOOST_REQUIRE(a.size() == b.size());
    double worst = 0;
    for (unsigned int s = 0; s < a.size(); ++s)
      worst = std::max(worst, std::abs(a[s] - sign * b[s]));
    return worst / poundfe_test::peak(a);
  }
} // namespace

BOOST_AUTO_TEST_SUITE(foundation_3d)

BOOST_AUTO_TEST_CASE(stiff_soil_reproduces_the_fixed_base)
{
  // springs 1e10 times the storeys' (k/K ~ 1e-10 per part), no dashpots
  const InputParameters fixed_p = input_of("fixed_3d", building_on(""));
  const InputParameters stiff_p =
    input_of("stiff_3d",
             building_on(given_foundation(4e17, 4e17, 1e19, 1e19, 1e19, 0, 1e5, 1e6, 1e6, 2e6)));
  const Analysis fixed = prepare_analysis(fixed_p), stiff = prepare_analysis(stiff_p);
  BOOST_REQUIRE(stiff.model.foundations.size() == 1u);
  BOOST_REQUIRE(stiff.model.n_equations() == fixed.model.n_equations() + 5);
  const auto a = poundfe_test::floor_histories(fixed, poundfe_test::recorded_run(fixed, fixed_p));
  const auto b = poundfe_test::floor_histories(stiff, poundfe_test::recorded_run(stiff, stiff_p));
  double worst = 0;
  for (unsigned int j = 0; j < a.size(); ++j)
    {
      worst = std::max(worst, relative_difference(a[j], b[j]));
      BOOST_TEST(poundfe_test::peak(b[j]) == poundfe_test::peak(a[j]),
                 boost::test_tools::tolerance(1e-8));
    }
  BOOST_TEST_MESSAGE("stiff soil: largest difference " << worst << " of the DOF's peak");
  BOOST_TEST(worst <= 1e-8);
}

BOOST_AUTO_TEST_CASE(rigid_block_has_the_closed_form_frequencies)
{
  // one floor of 1e5 kg (J_1 = m (12² + 8²)/12) at h = 3 m over the
  // foundation's centre, its storey 1e6 times stiffer than the soil
  const double m1 = 1e5, j1 = m1 * (144 + 64) / 12, h = 3;
  const double kx = 2e8, ky = 3e8, krx = 4e9, kry = 5e9, kt = 6e9;
  const double m0 = 5e4, irx = 2e5, iry = 3e5, j0 = 4e5;
  const std::string text =
    "subsection Model\n set Dimension = 3\nend\n"
    "subsection Building 1\n set Name = B\n set Type = shear\n set Number of storeys = 1\n"
    " set Storey heights = 3\n set Floor masses = 1e5\n set Storey stiffnesses = 1e15\n"
    " subsection Plan\n  set Plan dimensions = 12, 8\n end\n"
    " subsection Damping\n  set Type = none\n end\n" +
    given_foundation(kx, ky, krx, kry, kt, 0, m0, irx, iry, j0) +
    "end\nsubsection Ground motion\n set Type = none\nend\n"
    "subsection Output\n set Number of modes = 5\nend\n";
  const Analysis a = prepare_analysis(input_of("rigid_block_3d", text));
  // the sway-rocking pair of one vertical plane: the roots of
  // (M11 M22 - M12²) λ² - (K11 M22 + K22 M11) λ + K11 K22 = 0
  const auto pair = [&](const double k, const double k_theta, const double i0) {
    const double m11 = m0 + m1, m12 = m1 * h, m22 = i0 + m1 * h * h;
    const double p = m11 * m22 - m12 * m12, q = k * m22 + k_theta * m11, r = k * k_theta;
    const double root = std::sqrt(q * q - 4 * p * r);
    return std::array<double, 2>{{std::sqrt((q - root) / (2 * p)),
                                  std::sqrt((q + root) / (2 * p))}};
  };
  const auto in_xz = pair(kx, kry, iry), in_yz = pair(ky, krx, irx);
  std::vector<double> expected{in_xz[0], in_xz[1], in_yz[0], in_yz[1], std::sqrt(kt / (j0 + j1))};
  std::sort(expected.begin(), expected.end());
  BOOST_REQUIRE(a.modes.n_modes() == 5u);
  // the storeys' flexibility shifts ω by ~ K/k_storey = 1e-6 relative
  double worst = 0;
  for (unsigned int i = 0; i < 5; ++i)
    {
      BOOST_TEST(a.modes.omega[i] == expected[i], boost::test_tools::tolerance(1e-5));
      worst = std::max(worst, std::abs(a.modes.omega[i] / expected[i] - 1));
    }
  BOOST_TEST_MESSAGE("rigid block: largest relative frequency error " << worst);
  // the flexible-base periods in 3D: the first mode is the x-z pair's
  const std::vector<FoundationPeriods> periods = foundation_periods(a.model);
  BOOST_REQUIRE(periods.size() == 1u);
  BOOST_TEST(periods[0].flexible_base_period == 2 * M_PI / expected[0],
             boost::test_tools::tolerance(1e-5));
  BOOST_TEST(periods[0].ratio() > 1);
}

BOOST_AUTO_TEST_CASE(energy_balance_closes_on_gazetas_soil)
{
  const InputParameters p = input_of("gazetas_3d", building_on(gazetas));
  const Analysis        a = prepare_analysis(p);
  const poundfe_test::StepRecorder run = poundfe_test::recorded_run(a, p);
  BOOST_TEST_MESSAGE("3D on soil: balance error " << run.max_energy_error << ", foundation "
                                                  << run.energy.foundation << " J");
  BOOST_TEST(run.energy.foundation > 0);
  BOOST_TEST(run.max_energy_error <= 1e-8);
}

BOOST_AUTO_TEST_CASE(turning_by_90_degrees_turns_the_response)
{
  // one component along x on the building as given; along y (incidence
  // 90°) on the building turned by 90°: (u_x, u_y, θ_z) -> (-u_y, u_x, θ_z)
  const InputParameters p0 = input_of("turn_0", building_on(gazetas, 0, 1, 0));
  const InputParameters p1 = input_of("turn_90", building_on(gazetas, 90, 1, 90));
  const Analysis        a0 = prepare_analysis(p0), a1 = prepare_analysis(p1);
  const auto h0 = poundfe_test::floor_histories(a0, poundfe_test::recorded_run(a0, p0));
  const auto h1 = poundfe_test::floor_histories(a1, poundfe_test::recorded_run(a1, p1));
  double worst = 0;
  for (unsigned int f = 0; f < h0.size() / 3; ++f)
    {
      worst = std::max(worst, relative_difference(h0[3 * f], h1[3 * f + 1]));      // u_x -> u_y
      worst = std::max(worst, relative_difference(h0[3 * f + 1], h1[3 * f], -1)); // u_y -> -u_x
      worst = std::max(worst, relative_difference(h0[3 * f + 2], h1[3 * f + 2]));
    }
  BOOST_TEST_MESSAGE("turned by 90 degrees: largest difference " << worst << " of the peak");
  // cos 90° is 6e-17, not 0, and the two solves round differently
  BOOST_TEST(worst <= 1e-8);
}

BOOST_AUTO_TEST_SUITE_END()
