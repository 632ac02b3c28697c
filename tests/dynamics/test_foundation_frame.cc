// Compliant foundations under frames, 2D and 3D (issue 26; doc/theory.md
// §1.16 "Under frames", doc/verification.md "Compliant foundations under
// frames"):
//  - very stiff soil (springs 1e10 times the frame's storey stiffness)
//    reproduces the fixed-base frame with hinges to 1e-8 of every floor
//    DOF's peak, in 2D and in 3D;
//  - a rigid frame block (members 1e6 times stiffer than the soil) on the
//    foundation: its frequencies are the closed forms of a rigid block on
//    springs, the vertical ω² = K_z/(m_0 + m_1), the torsion (3D) ω² =
//    K_t/(J_0 + J_1), and in each vertical plane the sway-rocking pair
//    det(K - ω² M) = 0, M = [[m_0 + m_1, m_1 h], [m_1 h, I_0 + m_1 h² +
//    Σ m_j d_j²]] (the joints' masses m_j at distances d_j from the rocking
//    axis; Richart, Hall & Woods 1970, §7; Wolf 1985, §2.1); the
//    flexible-base period `modal` reports is the lowest of them;
//  - the energy balance closes to 1e-8 on Gazetas' soil with yielding hinges;
//  - two identical rigid blocks whose foundations rock on K_θ, sway held,
//    coupled through the soil by a rotational spring k_c (Links/Rocking
//    soil coupling): in phase they rock at ω² = K_θ/I, in anti-phase at
//    ω² = (K_θ + 2 k_c)/I, I = I_0 + m_1 h² (two coupled oscillators). The
//    run is compared with the average-acceleration scheme's exact discrete
//    solution θ_n = θ_0 cos(n Ω), tan(Ω/2) = ω Δt/2 (Newmark's method is
//    exact for the discrete recurrence: Hughes, The Finite Element Method,
//    2000, §9.3), so the tolerance is the stiff storeys' and sway's (1e-6).
#include <poundfe/base/numbers.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/foundation_periods.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "floor_histories.h"
#include "time_history_helpers.h"

using namespace poundfe;
using poundfe_test::input_of;

namespace
{
  std::string
  text_of(const double x)
  {
    return number_text(x);
  }

  /// A foundation subsection with typed-in springs (2D entries, and the 3D
  /// ones when `kt` > 0), dashpots c times the springs.
  std::string
  given_frame_foundation(const double kx, const double kz, const double kr, const double c,
                         const double m0, const double i0, const double kt = 0)
  {
    std::string s = " subsection Foundation\n  set Type = given\n  set Horizontal stiffness = " +
                    text_of(kx) + "\n  set Vertical stiffness = " + text_of(kz) +
                    "\n  set Rocking stiffness = " + text_of(kr) +
                    "\n  set Horizontal damping = " + text_of(c * kx) +
                    "\n  set Vertical damping = " + text_of(c * kz) +
                    "\n  set Rocking damping = " + text_of(c * kr) + "\n  set Mass = " +
                    text_of(m0) + "\n  set Rotary inertia = " + text_of(i0) + "\n";
    if (kt > 0)
      s += "  set Horizontal stiffness y = " + text_of(1.5 * kx) +
           "\n  set Rocking stiffness x = " + text_of(1.2 * kr) +
           "\n  set Torsional stiffness = " + text_of(kt) +
           "\n  set Rotary inertia x = " + text_of(1.1 * i0) +
           "\n  set Polar inertia = " + text_of(2 * i0) + "\n";
    return s + " end\n";
  }

  /// A mat on soil; `three_d`: with the inertias about x and the vertical
  /// (a planar model refuses these [3D] entries).
  std::string
  gazetas_mat(const bool three_d)
  {
    return " subsection Foundation\n  set Type = gazetas\n  set Shear-wave velocity = 150\n"
           "  set Soil density = 1900\n  set Poisson ratio = 0.3\n  set Length = 8\n"
           "  set Width = 8\n  set Embedment = 1\n  set Mass = 4e4\n  set Rotary inertia = "
           "2.4e5\n" +
           std::string(three_d ? "  set Rotary inertia x = 2.4e5\n  set Polar inertia = 4.3e5\n" :
                                 "") +
           " end\n";
  }

  /// 2 s of Kanai-Tajimi motion in `components` horizontal components.
  std::string
  shaking(const unsigned int components)
  {
    return "subsection Ground motion\n set Type = kanai-tajimi\n set Components = " +
           std::to_string(components) +
           "\n subsection Stochastic\n  set Target PGA = 0.5\n  set Duration = 2\n"
           "  set Seed = 7\n  set Second seed = 8\n  set Method = spectral-representation\n"
           "  set Cutoff frequency = 50\n end\nend\n"
           "subsection Time integration\n set Time step = 0.005\nend\n";
  }

  /// A 2-storey, 2-bay 2D frame with Bouc-Wen hinges at the column bases
  /// and beam ends, on `foundation` (a subsection or empty).
  std::string
  frame_2d(const std::string &foundation)
  {
    return "subsection Model\n set Number of buildings = 1\nend\n"
           "subsection Building 1\n set Name = F\n set Type = frame\n"
           " set Number of storeys = 2\n set Number of bays = 2\n set Storey heights = 3.5, 3\n"
           " set Bay widths = 6, 4\n set Column E = 3e10\n set Column A = 0.16\n"
           " set Column I = 2.1e-3\n set Beam E = 3e10\n set Beam A = 0.15\n"
           " set Beam I = 3.1e-3\n set Floor masses = 3e4\n"
           " subsection Hinges\n  set Locations = column bases, beam ends\n"
           "  set Yield moment = 6e4\n end\n"
           " subsection Damping\n  set Type = coefficients\n  set a0 = 0.3\n  set a1 = 0.002\n"
           " end\n" + foundation + "end\n" + shaking(1);
  }

  /// A 2-storey 3D frame, 2 x 1 bays, with hinges at the column bases.
  std::string
  frame_3d(const std::string &foundation)
  {
    return "subsection Model\n set Dimension = 3\nend\n"
           "subsection Building 1\n set Name = F\n set Type = frame\n"
           " set Number of storeys = 2\n set Storey heights = 3.5, 3\n"
           " set Number of bays = 2\n set Bay widths = 5\n set Number of bays y = 1\n"
           " set Bay widths y = 6\n set Floor masses = 6e4\n"
           " set Column E = 3e10\n set Column G = 1.25e10\n set Column A = 0.16\n"
           " set Column I = 2.1e-3\n set Column Iz = 2.1e-3\n set Column J = 3.6e-3\n"
           " set Beam E = 3e10\n set Beam G = 1.25e10\n set Beam A = 0.15\n"
           " set Beam I = 3.1e-3\n set Beam Iz = 1.1e-3\n set Beam J = 2.6e-3\n"
           " subsection Plan\n  set Mass eccentricity = 0.5, 0.3\n end\n"
           " subsection Hinges\n  set Locations = column bases\n  set Yield moment = 1e5\n"
           " end\n subsection Damping\n  set Type = coefficients\n  set a0 = 0.3\n"
           "  set a1 = 0.002\n end\n" + foundation + "end\n" + shaking(2);
  }

  /// The largest difference of two runs' floor DOFs, relative to each
  /// DOF's peak in the first.
  double
  largest_relative_difference(const std::string &fixed_text, const std::string &stiff_text,
                              const unsigned int added_equations)
  {
    const InputParameters fixed_p = input_of("frame_fixed", fixed_text);
    const InputParameters stiff_p = input_of("frame_stiff", stiff_text);
    const Analysis        fixed = prepare_analysis(fixed_p), stiff = prepare_analysis(stiff_p);
    BOOST_REQUIRE(stiff.model.foundations.size() == 1u);
    BOOST_TEST(stiff.model.n_equations() == fixed.model.n_equations() + added_equations);
    const auto a = poundfe_test::floor_histories(fixed, poundfe_test::recorded_run(fixed, fixed_p));
    const auto b = poundfe_test::floor_histories(stiff, poundfe_test::recorded_run(stiff, stiff_p));
    BOOST_REQUIRE(a.size() == b.size());
    double worst = 0;
    for (unsigned int j = 0; j < a.size(); ++j)
      {
        BOOST_REQUIRE(a[j].size() == b[j].size());
        for (unsigned int s = 0; s < a[j].size(); ++s)
          worst = std::max(worst, std::abs(a[j][s] - b[j][s]) / poundfe_test::peak(a[j]));
      }
    return worst;
  }

  /// The sway-rocking pair of one vertical plane: the roots of
  /// (M11 M22 - M12²) λ² - (K11 M22 + K22 M11) λ + K11 K22 = 0.
  std::array<double, 2>
  sway_rocking_pair(const double k, const double k_theta, const double m11, const double m12,
                    const double m22)
  {
    const double p = m11 * m22 - m12 * m12, q = k * m22 + k_theta * m11, r = k * k_theta;
    const double root = std::sqrt(q * q - 4 * p * r);
    return {{std::sqrt((q - root) / (2 * p)), std::sqrt((q + root) / (2 * p))}};
  }

  void
  check_frequencies(const Analysis &a, std::vector<double> expected)
  {
    std::sort(expected.begin(), expected.end());
    BOOST_REQUIRE(a.modes.n_modes() == expected.size());
    // the members' flexibility shifts ω by ~ K/k_member = 1e-6 relative
    double worst = 0;
    for (unsigned int i = 0; i < expected.size(); ++i)
      {
        BOOST_TEST(a.modes.omega[i] == expected[i], boost::test_tools::tolerance(1e-5));
        worst = std::max(worst, std::abs(a.modes.omega[i] / expected[i] - 1));
      }
    BOOST_TEST_MESSAGE("rigid frame block: largest relative frequency error " << worst);
    // `modal`'s flexible-base period is the lowest mode's
    const std::vector<FoundationPeriods> periods = foundation_periods(a.model);
    BOOST_REQUIRE(periods.size() == 1u);
    BOOST_TEST(periods[0].flexible_base_period == 2 * M_PI / expected[0],
               boost::test_tools::tolerance(1e-5));
    BOOST_TEST(periods[0].ratio() > 1);
  }
} // namespace

BOOST_AUTO_TEST_SUITE(foundation_frame)

BOOST_AUTO_TEST_CASE(stiff_soil_reproduces_the_fixed_base_2d_frame)
{
  // the storeys' lateral stiffness is ~ 1e8 N/m; springs 1e10 times that
  const double worst = largest_relative_difference(
    frame_2d(""), frame_2d(given_frame_foundation(1e18, 1e20, 1e20, 0, 1e4, 1e5)), 3);
  BOOST_TEST_MESSAGE("2D frame on stiff soil: largest difference " << worst
                                                                   << " of the DOF's peak");
  BOOST_TEST(worst <= 1e-8);
}

BOOST_AUTO_TEST_CASE(stiff_soil_reproduces_the_fixed_base_3d_frame)
{
  const double worst = largest_relative_difference(
    frame_3d(""), frame_3d(given_frame_foundation(1e18, 1e20, 1e20, 0, 1e4, 1e5, 1e20)), 6);
  BOOST_TEST_MESSAGE("3D frame on stiff soil: largest difference " << worst
                                                                   << " of the DOF's peak");
  BOOST_TEST(worst <= 1e-8);
}

BOOST_AUTO_TEST_CASE(rigid_2d_frame_block_has_the_closed_form_frequencies)
{
  // one storey h = 3 m, one bay b = 6 m, 1e5 kg at the floor (half at each
  // joint, on ux and uy), massless members 1e6 times stiffer than the soil
  const double m1 = 1e5, h = 3, b = 6, kx = 2e8, kz = 3e8, kr = 4e9, m0 = 5e4, i0 = 2e5;
  const std::string text =
    "subsection Model\n set Number of buildings = 1\nend\n"
    "subsection Building 1\n set Name = R\n set Type = frame\n set Number of storeys = 1\n"
    " set Number of bays = 1\n set Storey heights = 3\n set Bay widths = 6\n"
    " set Column E = 3e18\n set Column A = 0.16\n set Column I = 2e-3\n"
    " set Beam E = 3e18\n set Beam A = 0.15\n set Beam I = 3e-3\n set Floor masses = 1e5\n"
    " subsection Damping\n  set Type = none\n end\n" +
    given_frame_foundation(kx, kz, kr, 0, m0, i0) +
    "end\nsubsection Ground motion\n set Type = none\nend\n"
    "subsection Output\n set Number of modes = 3\nend\n";
  const Analysis a = prepare_analysis(input_of("rigid_frame_2d", text));
  const auto pair = sway_rocking_pair(kx, kr, m0 + m1, m1 * h, i0 + m1 * h * h + m1 * b * b / 4);
  check_frequencies(a, {pair[0], pair[1], std::sqrt(kz / (m0 + m1))});
}

BOOST_AUTO_TEST_CASE(rigid_3d_frame_block_has_the_closed_form_frequencies)
{
  // one storey h = 3 m, one bay 6 m along x and 4 m along y, the floor's
  // 1e5 kg on the diaphragm (ux, uy) and a quarter on each joint's uz
  const double m1 = 1e5, h = 3, ax = 6, ay = 4, kx = 2e8, kz = 3e8, kr = 4e9, kt = 6e9;
  const double m0 = 5e4, i0 = 2e5;
  const std::string text =
    "subsection Model\n set Dimension = 3\nend\n"
    "subsection Building 1\n set Name = R\n set Type = frame\n set Number of storeys = 1\n"
    " set Storey heights = 3\n set Number of bays = 1\n set Bay widths = 6\n"
    " set Number of bays y = 1\n set Bay widths y = 4\n set Floor masses = 1e5\n"
    " set Column E = 3e18\n set Column G = 1.2e18\n set Column A = 0.16\n"
    " set Column I = 2e-3\n set Column Iz = 2e-3\n set Column J = 3e-3\n"
    " set Beam E = 3e18\n set Beam G = 1.2e18\n set Beam A = 0.15\n set Beam I = 3e-3\n"
    " set Beam Iz = 1e-3\n set Beam J = 2e-3\n"
    " subsection Damping\n  set Type = none\n end\n" +
    given_frame_foundation(kx, kz, kr, 0, m0, i0, kt) +
    "end\nsubsection Ground motion\n set Type = none\nend\n"
    "subsection Output\n set Number of modes = 6\nend\n";
  const Analysis a = prepare_analysis(input_of("rigid_frame_3d", text));
  // the floor's polar moment is an input (the plan's), read from the model
  double j1 = 0;
  for (const NodalMass &m : a.model.masses)
    j1 += m.polar_moment;
  BOOST_REQUIRE(j1 > 0);
  // about y (plane x-z): Rocking stiffness, Rotary inertia; about x: the y ones
  const auto in_xz = sway_rocking_pair(kx, kr, m0 + m1, m1 * h, i0 + m1 * h * h + m1 * ax * ax / 4);
  const auto in_yz =
    sway_rocking_pair(1.5 * kx, 1.2 * kr, m0 + m1, m1 * h, 1.1 * i0 + m1 * h * h + m1 * ay * ay / 4);
  check_frequencies(a, {in_xz[0], in_xz[1], in_yz[0], in_yz[1], std::sqrt(kz / (m0 + m1)),
                        std::sqrt(kt / (2 * i0 + j1))});
}

BOOST_AUTO_TEST_CASE(energy_balance_closes_on_gazetas_soil_with_hinges)
{
  for (const bool three_d : {false, true})
    {
      const InputParameters p =
        input_of(three_d ? "gazetas_frame_3d" : "gazetas_frame_2d",
                 three_d ? frame_3d(gazetas_mat(true)) : frame_2d(gazetas_mat(false)));
      const Analysis                   a   = prepare_analysis(p);
      const poundfe_test::StepRecorder run = poundfe_test::recorded_run(a, p);
      BOOST_TEST_MESSAGE((three_d ? "3D" : "2D")
                         << " frame on soil: balance error " << run.max_energy_error
                         << ", foundation " << run.energy.foundation << " J, hinges "
                         << run.energy.hysteretic << " J");
      BOOST_TEST(run.energy.foundation > 0);
      BOOST_TEST(run.energy.hysteretic > 0); // the hinges yield
      BOOST_TEST(run.max_energy_error <= 1e-8);
    }
}

BOOST_AUTO_TEST_CASE(rocking_soil_coupling_splits_in_phase_and_anti_phase_rocking)
{
  const double m1 = 1e5, h = 3, k_theta = 4e9, m0 = 5e4, i0 = 2e5, k_c = 1e9, theta0 = 1e-4;
  const double inertia = i0 + m1 * h * h;
  const double omega_in = std::sqrt(k_theta / inertia);
  const double omega_anti = std::sqrt((k_theta + 2 * k_c) / inertia);
  const double dt = 2 * M_PI / omega_anti / 200;
  const auto   building = [&](const int i) {
    return "subsection Building " + std::to_string(i) +
           "\n set Name = B" + std::to_string(i) + "\n set Type = shear\n"
           " set Number of storeys = 1\n set Storey heights = 3\n set Floor masses = 1e5\n"
           " set Storey stiffnesses = 1e16\n subsection Damping\n  set Type = none\n end\n"
           " subsection Foundation\n  set Type = given\n  set Horizontal stiffness = 1e17\n"
           "  set Rocking stiffness = 4e9\n  set Mass = 5e4\n  set Rotary inertia = 2e5\n"
           " end\nend\n";
  };
  // equations: (u_0, θ, u_1) of building 1, then of building 2
  const auto run = [&](const double sign, const double c) {
    const std::string t0 = text_of(theta0), u0 = text_of(h * theta0);
    const std::string t1 = text_of(sign * theta0), u1 = text_of(sign * h * theta0);
    const InputParameters p = input_of(
      "rocking_coupling",
      "subsection Model\n set Number of buildings = 2\n set Separations = 0.5\nend\n" +
        building(1) + building(2) + "subsection Links\n set Rocking soil coupling = B1 B2 " +
        text_of(k_c) + " " + text_of(c) + "\nend\n"
        "subsection Ground motion\n set Type = none\nend\n"
        "subsection Initial conditions\n set Equation displacements = 1 = " + t0 + "; 2 = " +
        u0 + "; 4 = " + t1 + "; 5 = " + u1 + "\nend\n"
        "subsection Time integration\n set Time step = " + text_of(dt) +
        "\n set End time = " + text_of(600 * dt) + "\nend\n");
    const Analysis a = prepare_analysis(p);
    BOOST_REQUIRE(a.model.equation(Model::dof(a.model.foundations[1].node, Component::rz)) == 4);
    BOOST_REQUIRE(a.model.building_links.size() == 1u);
    return poundfe_test::recorded_run(a, p);
  };
  for (const double sign : {1.0, -1.0})
    {
      const poundfe_test::StepRecorder r = run(sign, 0);
      const double omega = sign > 0 ? omega_in : omega_anti;
      const double big_omega = 2 * std::atan(omega * dt / 2);
      double       worst     = 0;
      for (unsigned int s = 0; s < r.t.size(); ++s)
        {
          const double n = std::round(r.t[s] / dt);
          worst = std::max({worst, std::abs(r.u[s][1] - theta0 * std::cos(n * big_omega)),
                            std::abs(r.u[s][4] - sign * theta0 * std::cos(n * big_omega))});
        }
      BOOST_TEST_MESSAGE((sign > 0 ? "in phase" : "anti-phase")
                         << ": largest error " << worst / theta0 << " of θ_0");
      BOOST_TEST(worst <= 1e-6 * theta0);
    }
  // with a dashpot the anti-phase rocking decays through it: the balance
  const poundfe_test::StepRecorder damped = run(-1, 0.05 * k_c / omega_anti);
  BOOST_TEST(damped.energy.links > 0);
  BOOST_TEST(damped.max_energy_error <= 1e-8);
}

BOOST_AUTO_TEST_SUITE_END()
