// Runs that start from the `Initial conditions` section (issue 25 item 1):
// free vibration of an SDOF and of a linear shear building against the
// closed-form damped solution (Chopra, Dynamics of Structures, 4th ed.,
// eq. 2.2.4 and §12.5, modal superposition with eigenvectors computed here),
// the energy balance of a pounding pair started out of rest, and a gap
// already closed at t = 0 (the consistent acceleration and the initial
// energy include the contact spring).
#include <poundfe/base/numbers.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/initial_conditions.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include <cmath>
#include <string>
#include <vector>

#include "time_history_helpers.h"

using namespace poundfe;
using poundfe_test::input_of;
using Recorder = poundfe_test::StepRecorder;

namespace
{
  /// A shear building S of n equal storeys (m, k), ground motion none,
  /// with the given Damping and Initial conditions lines and extra text.
  std::string
  shear_prm(const unsigned int n, const double m, const double k, const std::string &damping,
            const std::string &initial, const double dt, const double end,
            const std::string &extra = "")
  {
    return "subsection Model\n  set Number of buildings = 1\nend\n"
           "subsection Building 1\n  set Name = S\n  set Type = shear\n"
           "  set Number of storeys = " + std::to_string(n) + "\n  set Storey heights = 3\n"
           "  set Floor masses = " + number_text(m) + "\n  set Storey stiffnesses = " +
           number_text(k) + "\n  subsection Damping\n" + damping + "\n  end\nend\n"
           "subsection Ground motion\n  set Type = none\nend\n"
           "subsection Initial conditions\n" + initial + "\nend\n"
           "subsection Time integration\n  set Time step = " + number_text(dt) +
           "\n  set End time = " + number_text(end) + "\nend\n" + extra;
  }




  /// Damped free vibration of one mode from (q0, q0'):
  /// q = e^{-z w t} (q0 cos wd t + (q0' + z w q0)/wd sin wd t) and q'.
  std::array<double, 2>
  free_vibration(const double omega, const double zeta, const double q0, const double dq0,
                 const double t)
  {
    const double wd = omega * std::sqrt(1 - zeta * zeta), s = zeta * omega;
    const double B  = (dq0 + s * q0) / wd, e = std::exp(-s * t);
    const double q  = e * (q0 * std::cos(wd * t) + B * std::sin(wd * t));
    const double dq = e * (-wd * q0 * std::sin(wd * t) + wd * B * std::cos(wd * t)) - s * q;
    return {{q, dq}};
  }

  /// Newmark's average acceleration lengthens the period by (w dt)^2/12
  /// (Chopra §5.5): after t the phase lags by w t (w dt)^2/12, so a mode of
  /// amplitude A is off by at most A w t (w dt)^2 / 12 (velocity: w times
  /// that). Twice the bound, for the O((w dt)^2 zeta) amplitude error.
  double
  phase_bound(const double amplitude, const double omega, const double t, const double dt)
  {
    return 2 * amplitude * omega * t * std::pow(omega * dt, 2) / 12;
  }
} // namespace

BOOST_AUTO_TEST_CASE(sdof_free_vibration_from_u0_and_v0_is_the_closed_form)
{
  const double m = 2000, k = 8e6, zeta = 0.04, u0 = 0.01, v0 = -0.3;
  const double omega = std::sqrt(k / m), dt = 2 * M_PI / omega / 200, end = 10 * 2 * M_PI / omega;
  const InputParameters p =
    input_of("ic_sdof", shear_prm(1, m, k,
                                  "    set Type = coefficients\n    set a0 = " +
                                    number_text(2 * zeta * omega),
                                  "  set State = " + number_text(u0) + ", " + number_text(v0),
                                  dt, end));
  const Analysis analysis = prepare_analysis(p);
  const Recorder r        = poundfe_test::recorded_run(analysis, p);
  BOOST_TEST(r.u.front()[0] == u0);
  BOOST_TEST(r.v.front()[0] == v0);
  // a0 = -(c v0 + k u0)/m
  BOOST_TEST(r.a.front()[0] == -(2 * zeta * omega * m * v0 + k * u0) / m,
             boost::test_tools::tolerance(1e-13));
  const double amplitude = std::hypot(u0, (v0 + zeta * omega * u0) / omega);
  double       worst_u = 0, worst_v = 0;
  for (std::size_t i = 0; i < r.t.size(); ++i)
    {
      const auto exact = free_vibration(omega, zeta, u0, v0, r.t[i]);
      worst_u          = std::max(worst_u, std::abs(r.u[i][0] - exact[0]));
      worst_v          = std::max(worst_v, std::abs(r.v[i][0] - exact[1]));
    }
  const double bound = phase_bound(amplitude, omega, end, dt);
  BOOST_TEST_MESSAGE("SDOF: max |u - exact| = " << worst_u << " m, |v - exact| = " << worst_v
                                                << " m/s, bound " << bound << " m");
  BOOST_TEST(worst_u < bound);
  BOOST_TEST(worst_v < omega * bound);
  BOOST_TEST(worst_u > 1e-3 * bound); // the bound is not loose by orders of magnitude
}

BOOST_AUTO_TEST_CASE(shear_building_free_vibration_is_the_modal_superposition)
{
  const unsigned int n = 3;
  const double       m = 1000, k = 5e6, zeta = 0.05;
  const poundfe_test::ShearBuildingModes modes(n, m, k); // by Eigen, here
  const Eigen::VectorXd                 &omega = modes.omega;
  const Eigen::MatrixXd                 &phi   = modes.phi;
  // Rayleigh fitted at modes 1 and 2 (Chopra eq. 11.4.9); zeta_i of each mode
  const double a0 = 2 * zeta * omega[0] * omega[1] / (omega[0] + omega[1]);
  const double a1 = 2 * zeta / (omega[0] + omega[1]);
  const double dt = 2 * M_PI / omega[n - 1] / 200, end = 4 * 2 * M_PI / omega[0];
  const Vector u0 = (Vector(3) << 0.01, 0.02, 0.03).finished();
  const Vector v0 = Vector::Constant(3, 0.1);
  const InputParameters p = input_of(
    "ic_shear", shear_prm(n, m, k,
                          "    set Type = modes\n    set Damping ratio = " + number_text(zeta),
                          "  set Floor displacements = S: 0.01 0.02 0.03\n"
                          "  set Floor velocities = 1: all 0.1",
                          dt, end));
  const Analysis analysis = prepare_analysis(p);
  const Recorder r        = poundfe_test::recorded_run(analysis, p);
  BOOST_TEST((r.u.front() - u0).norm() == 0);
  BOOST_TEST((r.v.front() - v0).norm() == 0);
  double worst = 0, bound = 0;
  for (unsigned int j = 0; j < n; ++j)
    {
      const double q0 = phi.col(j).dot(m * u0), dq0 = phi.col(j).dot(m * v0);
      const double z  = a0 / (2 * omega[j]) + a1 * omega[j] / 2;
      bound += phase_bound(std::hypot(q0, (dq0 + z * omega[j] * q0) / omega[j]) *
                             phi.col(j).cwiseAbs().maxCoeff(),
                           omega[j], end, dt);
    }
  for (std::size_t i = 0; i < r.t.size(); ++i)
    {
      Vector exact = Vector::Zero(n);
      for (unsigned int j = 0; j < n; ++j)
        {
          const double z = a0 / (2 * omega[j]) + a1 * omega[j] / 2;
          exact += free_vibration(omega[j], z, phi.col(j).dot(m * u0), phi.col(j).dot(m * v0),
                                  r.t[i])[0] *
                   phi.col(j);
        }
      worst = std::max(worst, (r.u[i] - exact).cwiseAbs().maxCoeff());
    }
  BOOST_TEST_MESSAGE("shear building: max |u - exact| = " << worst << " m, bound " << bound);
  BOOST_TEST(worst < bound);
}

BOOST_AUTO_TEST_CASE(pounding_pair_started_out_of_rest_balances_its_energy)
{
  // Two shear buildings 1 cm apart; the taller one starts leaning 3 cm
  // toward the other and moving: it strikes at once and repeatedly.
  const std::string text =
    "subsection Model\n  set Number of buildings = 2\n  set Separations = 0.01\nend\n"
    "subsection Building 1\n  set Name = tall\n  set Type = shear\n  set Number of storeys = 3\n"
    "  set Storey heights = 3\n  set Floor masses = 1e5\n  set Storey stiffnesses = 1.2e8\n"
    "  set Storey yield drifts = 0.004\nend\n"
    "subsection Building 2\n  set Name = short\n  set Type = shear\n  set Number of storeys = 2\n"
    "  set Storey heights = 3\n  set Floor masses = 1.2e5\n  set Storey stiffnesses = 2.5e8\nend\n"
    "subsection Ground motion\n  set Type = none\nend\n"
    "subsection Contact\n  set Law = jankowski\n  set Stiffness = 2.75e9\n"
    "  set Coefficient of restitution = 0.65\nend\n"
    "subsection Initial conditions\n  set Floor displacements = tall: 0.01 0.02 0.03\n"
    "  set Floor velocities = tall: all 0.2; short: 0 -0.1\nend\n"
    "subsection Time integration\n  set Time step = 0.002\n  set End time = 3\nend\n";
  const InputParameters p        = input_of("ic_pair", text);
  const Analysis        analysis = prepare_analysis(p);
  const Recorder        r        = poundfe_test::recorded_run(analysis, p);
  BOOST_TEST_MESSAGE("pounding pair from initial conditions: max energy error "
                     << r.max_energy_error << ", initial " << r.energy.initial << " J, contact "
                     << r.energy.contact << " J, hysteretic " << r.energy.hysteretic << " J");
  BOOST_TEST(r.energy.initial > 0);
  BOOST_TEST(r.energy.contact > 0); // they did pound
  BOOST_TEST(r.max_energy_error <= 1e-8);
  const double imbalance = std::abs(r.energy.supplied() - r.energy.stored_and_dissipated());
  BOOST_TEST(imbalance <= 1e-8 * r.energy.initial);
}

BOOST_AUTO_TEST_CASE(a_gap_closed_at_t0_pushes_back_at_once)
{
  // An SDOF (m, k) against a rigid barrier 5 mm to its right with a linear
  // contact spring k_c, starting 1 mm into it: a0 = -(k u0 + k_c (u0 - g))/m
  // and the initial energy is k u0^2/2 + k_c (u0 - g)^2/2.
  const double m = 2, k = 210.125, kc = 1e5, gap = 0.005, u0 = 0.006;
  const std::string contact = "subsection Contact\n  set Law = linear\n  set Stiffness = " +
                              number_text(kc) + "\n  set Barriers = 1 1 right " +
                              number_text(gap) + "\nend\n";
  const InputParameters p = input_of(
    "ic_gap", shear_prm(1, m, k, "    set Type = none",
                        "  set Equation displacements = 0 = " + number_text(u0), 1e-4, 0.05,
                        contact));
  const Analysis analysis = prepare_analysis(p);
  const Recorder r        = poundfe_test::recorded_run(analysis, p);
  const double   a0       = -(k * u0 + kc * (u0 - gap)) / m;
  BOOST_TEST(r.a.front()[0] == a0, boost::test_tools::tolerance(1e-12));
  const double e0 = 0.5 * k * u0 * u0 + 0.5 * kc * (u0 - gap) * (u0 - gap);
  BOOST_TEST(r.energy.initial == e0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(r.u[1][0] < u0); // pushed out of the barrier
  BOOST_TEST(r.max_energy_error <= 1e-8);
}

BOOST_AUTO_TEST_CASE(rest_is_the_default)
{
  InitialConditionParameters none;
  BOOST_TEST(none.at_rest());
  const InputParameters p = input_of(
    "ic_rest", shear_prm(2, 1000, 5e6, "    set Type = none", "", 0.01, 0.1));
  const Analysis     analysis = prepare_analysis(p);
  const InitialState s        = initial_state(p.initial_conditions, analysis.model, p);
  BOOST_TEST(s.displacement.norm() == 0);
  BOOST_TEST(s.velocity.norm() == 0);
  BOOST_TEST(s.displacement.size() == 2);
}

BOOST_AUTO_TEST_CASE(bad_initial_conditions_name_the_entry)
{
  const auto error_of = [](const std::string &initial) {
    return poundfe_test::input_error_of([&]() {
      const InputParameters p = input_of(
        "ic_bad", shear_prm(3, 1000, 5e6, "    set Type = none", initial, 0.01, 0.1));
      const Analysis analysis = prepare_analysis(p);
      initial_state(p.initial_conditions, analysis.model, p);
    });
  };
  BOOST_TEST(error_of("  set Equation velocities = 7 = 1").find("there is no equation 7") !=
             std::string::npos);
  BOOST_TEST(error_of("  set Floor displacements = S: 1 2").find("has 3 floors, 2 values") !=
             std::string::npos);
  BOOST_TEST(error_of("  set Floor displacements = S: all inf").find("not a finite number") !=
             std::string::npos);
  BOOST_TEST(error_of("  set Floor displacements = S 1 2 3").find("is not 'building:") !=
             std::string::npos);
  BOOST_TEST(error_of("  set Equation displacements = 1.5 = 2").find("index an integer") !=
             std::string::npos);
  BOOST_TEST(error_of("  set State = 1, 2, 3, 4, 5, 6\n  set Floor velocities = S: all 1")
               .find("leave the Floor and Equation entries empty") != std::string::npos);
  BOOST_TEST(error_of("  set State = 1, 2").find("needs 2 x 3 = 6 values") != std::string::npos);
}
