// Compliant foundations under 2D shear buildings (issue 26 item 1; doc/
// theory.md §1.16, doc/verification.md "Compliant foundations"):
//  - one storey on springs with a (nearly) massless foundation: the first
//    period is the closed form of three springs in series, T~/T = sqrt(1 +
//    k/K_x + k h²/K_θ) (Veletsos & Meek 1974; ASCE 7-16 eq. 19.2-2), and so
//    is the code's ratio the program prints;
//  - three storeys: the flexible-base frequencies against the sway-rocking
//    model's M and K written here in total coordinates (Wolf 1985, Dynamic
//    Soil-Structure Interaction, §2.1), solved by Eigen;
//  - a rigid block on a spring and dashpot: the sway's free vibration is
//    the damped oscillator's closed form (ω² = K_x/m, ζ = C_x/(2 sqrt(K_x m)));
//  - very stiff soil: the pounding pair reproduces its fixed-base run.
#include <poundfe/base/numbers.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/foundation_periods.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include <cmath>
#include <string>

#include "time_history_helpers.h"

using namespace poundfe;
using poundfe_test::input_of;

namespace
{
  /// Building 0 of p on typed-in springs and dashpots.
  void
  put_on_foundation(InputParameters &p, const unsigned int b, const double k_x,
                    const double k_theta, const double c_x, const double c_theta,
                    const double mass, const double inertia)
  {
    FoundationParameters &f = p.model.buildings[b].foundation;
    f.type                  = FoundationType::given;
    f.given.horizontal_stiffness = k_x;
    f.given.rocking_stiffness    = k_theta;
    f.given.horizontal_damping   = c_x;
    f.given.rocking_damping      = c_theta;
    f.impedance                  = f.given;
    f.mass                       = mass;
    f.rotary_inertia             = inertia;
  }
} // namespace

BOOST_AUTO_TEST_CASE(one_storey_sway_rocking_period_is_three_springs_in_series)
{
  const double m = 1000, k = 5e6, h = 3, k_x = 2e7, k_theta = 3e8;
  InputParameters p = poundfe_test::shear_building_input(1, m, k, 0);
  // a foundation 1e6 times lighter than the floor: the closed form is for a
  // massless one, and the mass changes the period by ~1e-6 relative
  put_on_foundation(p, 0, k_x, k_theta, 0, 0, 1e-3 * m / 1e3, 1e-3 * m * h * h / 1e3);
  const Analysis analysis = prepare_analysis(p);
  const std::vector<FoundationPeriods> periods = foundation_periods(analysis.model);
  BOOST_REQUIRE(periods.size() == 1u);
  const double exact = std::sqrt(1 + k / k_x + k * h * h / k_theta);
  BOOST_TEST(periods[0].fixed_base_period == 2 * M_PI * std::sqrt(m / k),
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(periods[0].ratio() == exact, boost::test_tools::tolerance(1e-5));
  BOOST_TEST(periods[0].code_ratio == exact, boost::test_tools::tolerance(1e-5));
  BOOST_TEST(periods[0].effective_height == h, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(three_storey_sway_rocking_frequencies_match_the_model_written_here)
{
  const unsigned int n = 3;
  const double m = 1000, k = 5e6, h = 3, k_x = 4e7, k_theta = 6e8, m0 = 1500, i0 = 800;
  InputParameters p = poundfe_test::shear_building_input(n, m, k, 0);
  put_on_foundation(p, 0, k_x, k_theta, 0, 0, m0, i0);
  p.output.n_modes        = n + 2;
  const Analysis analysis = prepare_analysis(p);
  // q = (u_0, θ, u_1, ..., u_n), u_i total (relative to the ground);
  // storey i deforms by u_i - u_{i-1} - h θ: its spring is k a aᵀ.
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + 2, n + 2), M = K;
  K(0, 0) = k_x;
  K(1, 1) = k_theta;
  M(0, 0) = m0;
  M(1, 1) = i0;
  for (unsigned int i = 1; i <= n; ++i)
    {
      Eigen::VectorXd a = Eigen::VectorXd::Zero(n + 2);
      a[i == 1 ? 0 : i] = -1;
      a[i + 1]          = 1;
      a[1]              = -h;
      K += k * a * a.transpose();
      M(i + 1, i + 1) = m;
    }
  const Eigen::VectorXd lambda = poundfe_test::generalized_eigenvalues(K, M);
  BOOST_REQUIRE(analysis.modes.n_modes() == n + 2);
  for (unsigned int i = 0; i < n + 2; ++i)
    BOOST_TEST(analysis.modes.omega[i] == std::sqrt(lambda[i]),
               boost::test_tools::tolerance(1e-10));
}

BOOST_AUTO_TEST_CASE(rigid_block_on_spring_and_dashpot_is_the_damped_oscillator)
{
  // A 1000 kg floor on a storey 1e6 times stiffer than the soil (a rigid
  // block with the 500 kg foundation), rocking held by a spring 1e9 times
  // stiffer: the sway is one oscillator of mass 1500 kg.
  const double m1 = 1000, m0 = 500, mass = m1 + m0, k_x = 4e6, zeta = 0.05, u0 = 0.01;
  const double omega = std::sqrt(k_x / mass), c_x = 2 * zeta * std::sqrt(k_x * mass);
  const double period = 2 * M_PI / omega, dt = period / 400, end = 5 * period;
  const std::string foundation =
    "  subsection Foundation\n    set Type = given\n    set Horizontal stiffness = " +
    number_text(k_x) + "\n    set Rocking stiffness = 1e17\n    set Horizontal damping = " +
    number_text(c_x) + "\n    set Mass = " + number_text(m0) +
    "\n    set Rotary inertia = 100\n  end\n";
  const InputParameters p = input_of(
    "rigid_block",
    "subsection Model\n  set Number of buildings = 1\nend\n"
    "subsection Building 1\n  set Name = S\n  set Type = shear\n  set Number of storeys = 1\n"
    "  set Storey heights = 3\n  set Floor masses = " + number_text(m1) +
      "\n  set Storey stiffnesses = 4e12\n"
      "  subsection Damping\n    set Type = none\n  end\n" + foundation + "end\n"
      "subsection Ground motion\n  set Type = none\nend\n"
      "subsection Initial conditions\n  set Equation displacements = 0 = 0.01; 2 = 0.01\nend\n"
      "subsection Time integration\n  set Time step = " + number_text(dt) +
      "\n  set End time = " + number_text(end) + "\nend\n");
  const Analysis analysis = prepare_analysis(p);
  const int      sway = analysis.model.equation(Model::dof(analysis.model.foundations[0].node,
                                                              Component::ux));
  BOOST_REQUIRE(sway == 0);
  const poundfe_test::StepRecorder run = poundfe_test::recorded_run(analysis, p);
  const double wd = omega * std::sqrt(1 - zeta * zeta);
  // Newmark's average acceleration lags the phase by ω t (ω dt)²/12 (Chopra
  // §5.5): at most u0 ω t (ω dt)²/12 = 1.6e-6 m here; twice that bounds it.
  const double bound = 2 * u0 * omega * end * std::pow(omega * dt, 2) / 12;
  double       worst = 0;
  for (unsigned int s = 0; s < run.t.size(); ++s)
    {
      const double t     = run.t[s];
      const double exact = u0 * std::exp(-zeta * omega * t) *
                           (std::cos(wd * t) + zeta * omega / wd * std::sin(wd * t));
      worst = std::max(worst, std::abs(run.u[s][0] - exact));
    }
  BOOST_TEST_MESSAGE("rigid block: largest error " << worst << " m, bound " << bound << " m");
  BOOST_TEST(worst <= bound);
  // the dashpot took what the block lost: the balance closes
  BOOST_TEST(run.energy.foundation > 0.9 * 0.5 * k_x * u0 * u0);
  BOOST_TEST(run.max_energy_error <= 1e-8); // the Newton tolerance (1e-8) bounds it
}
