// Newmark average acceleration against closed-form SDOF responses
// (Chopra, Dynamics of Structures, ch. 2-3) and against exact energy
// conservation in undamped free vibration.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/input/input_parameters.h>

#include <poundfe/base/exceptions.h>

#include <cmath>
#include <fstream>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  /// A one-storey shear building with mass-proportional damping, which for
  /// an SDOF is exactly c = 2 zeta omega m.
  Analysis
  sdof(const double m, const double k, const double zeta)
  {
    InputParameters p        = poundfe_test::shear_building_input(1, m, k, 0);
    p.model.buildings[0].damping_type = RayleighDamping::Kind::coefficients;
    p.model.buildings[0].rayleigh_a0  = 2 * zeta * std::sqrt(k / m);
    return prepare_analysis(p);
  }
} // namespace

BOOST_AUTO_TEST_CASE(harmonic_steady_state_amplitude)
{
  const double m = 1000, k = 5e6, zeta = 0.05, force = 1e4;
  const double omega = std::sqrt(k / m);
  const Analysis a   = sdof(m, k, zeta);
  for (const double r : {0.5, 1.0, 1.6})
    {
      const double big_omega = r * omega;
      const double dt        = 2 * M_PI / omega / 400;
      NewmarkIntegrator integrator(a.system, "eigen-ldlt", {dt, 0.5, 0.25, {}});
      Vector load = Vector::Zero(1);
      integrator.initialize(load);
      const unsigned int n = std::lround(8.0 / dt); // e^{-zeta omega 8} ~ 1e-12
      double             peak = 0;
      for (unsigned int i = 1; i <= n; ++i)
        {
          load[0] = force * std::sin(big_omega * i * dt);
          integrator.advance(load);
          if (i * dt > 6.0)
            peak = std::max(peak, std::abs(integrator.displacement()[0]));
        }
      const double exact =
        force / k / std::sqrt((1 - r * r) * (1 - r * r) + (2 * zeta * r) * (2 * zeta * r));
      // Period error (omega dt)^2/12 ~ 2e-5 and peak sampling ~1e-5.
      BOOST_TEST(peak == exact, boost::test_tools::tolerance(5e-4));
    }
}

BOOST_AUTO_TEST_CASE(free_vibration_decays_with_the_damping_ratio)
{
  const double m = 2000, k = 8e6, zeta = 0.03, u0 = 0.01;
  const double omega = std::sqrt(k / m), omega_d = omega * std::sqrt(1 - zeta * zeta);
  const Analysis a   = sdof(m, k, zeta);
  const double   dt  = 2 * M_PI / omega / 1000;
  NewmarkIntegrator integrator(a.system, "eigen-ldlt", {dt, 0.5, 0.25, {}});
  const Vector zero = Vector::Zero(1);
  integrator.initialize(zero, Vector::Constant(1, u0), zero);
  double worst = 0;
  std::vector<double> peaks;
  double previous = u0, before = u0;
  const unsigned int n = std::lround(10 * 2 * M_PI / omega_d / dt);
  for (unsigned int i = 1; i <= n; ++i)
    {
      integrator.advance(zero);
      const double t     = i * dt;
      const double u     = integrator.displacement()[0];
      const double exact = std::exp(-zeta * omega * t) *
                           (u0 * std::cos(omega_d * t) + zeta * omega * u0 / omega_d * std::sin(omega_d * t));
      worst = std::max(worst, std::abs(u - exact));
      if (previous > before && previous > u)
        peaks.push_back(previous);
      before   = previous;
      previous = u;
    }
  // phase error after 10 cycles ~ 10 * 2 pi (omega dt)^2 / 12 ~ 2e-4 rad
  BOOST_TEST(worst < 1e-3 * u0);
  BOOST_REQUIRE(peaks.size() >= 8u);
  const double cycles   = peaks.size() - 1;
  const double delta    = std::log(peaks.front() / peaks.back()) / cycles;
  const double measured = delta / std::sqrt(4 * M_PI * M_PI + delta * delta);
  BOOST_TEST(measured == zeta, boost::test_tools::tolerance(1e-3));
}

BOOST_AUTO_TEST_CASE(undamped_free_vibration_conserves_energy)
{
  // A frame with lumped mass (massless rotations) from the examples.
  InputParameters p = read_parameters("input/three-storey-frame.prm");
  p.model.buildings[0].damping_type = RayleighDamping::Kind::none;
  const Analysis a  = prepare_analysis(p);
  const unsigned int n = a.system.n_equations();
  Vector u0 = Vector::Zero(n);
  // start from a static deflection under lateral floor loads (smooth shape)
  {
    auto solver = create_eigen_ldlt_solver();
    solver->analyze_and_factorize(a.system.stiffness);
    solver->solve(a.system.mass * a.system.influence, u0);
  }
  NewmarkIntegrator integrator(a.system, "eigen-ldlt", {0.005, 0.5, 0.25, {}});
  const Vector      zero = Vector::Zero(n);
  integrator.initialize(zero, u0, zero);
  const double e0 = integrator.kinetic_energy() + integrator.strain_energy();
  double       drift = 0;
  for (unsigned int i = 0; i < 4000; ++i)
    {
      integrator.advance(zero);
      const double e = integrator.kinetic_energy() + integrator.strain_energy();
      drift          = std::max(drift, std::abs(e - e0) / e0);
    }
  BOOST_TEST_MESSAGE("max relative energy change " << drift);
  BOOST_TEST(drift < 1e-9); // exact in exact arithmetic; round-off only
}

BOOST_AUTO_TEST_CASE(step_ground_acceleration_gives_the_closed_form)
{
  // Undamped SDOF, a_g = A from t = 0: u(t) = -(A/omega^2)(1 - cos omega t).
  const double m = 1000, k = 4e6, A = 2.0;
  const double omega = std::sqrt(k / m);
  const Analysis a   = sdof(m, k, 0);
  const double   dt  = 2 * M_PI / omega / 500;
  const Excitation excitation(a.system, GroundMotion(dt, std::vector<double>(5001, A), "step"),
                              {});
  NewmarkIntegrator integrator(a.system, "eigen-ldlt", {dt, 0.5, 0.25, {}});
  Vector            load(1);
  excitation.load(0, load);
  integrator.initialize(load);
  BOOST_TEST(integrator.acceleration()[0] == -A, boost::test_tools::tolerance(1e-14));
  double worst = 0;
  for (unsigned int i = 1; i <= 5000; ++i)
    {
      excitation.load(i * dt, load);
      integrator.advance(load);
      const double exact = -(A / (omega * omega)) * (1 - std::cos(omega * i * dt));
      worst = std::max(worst, std::abs(integrator.displacement()[0] - exact));
    }
  // 10 cycles, phase error ~ 10 * 2 pi (2 pi / 500)^2 / 12 ~ 8e-4 rad
  BOOST_TEST(worst < 2e-3 * A / (omega * omega));
}

BOOST_AUTO_TEST_CASE(nodal_forces_from_the_input_reach_their_equation)
{
  InputParameters p  = poundfe_test::shear_building_input(3, 1000, 5e6, 0);
  p.nodal_forces.harmonic  = {"1 2 0 ux 800 30 0.5"};
  const std::string table = "/tmp/poundfe-test-force.csv";
  std::ofstream(table) << "time,force\n0 0\n0.5 1000\n1.5 -1000\n";
  p.nodal_forces.tabulated = {"1 3 0 ux " + table};
  const Analysis   a = prepare_analysis(p);
  const Excitation excitation(a.system, GroundMotion(), make_nodal_forces(p.nodal_forces, p.ground_motion, p.time_integration.newmark.time_step, p, a.model));
  Vector           load(3);
  excitation.load(0.75, load);
  BOOST_TEST(load[0] == 0.0);
  BOOST_TEST(load[1] == 800 * std::sin(30 * 0.75 + 0.5), boost::test_tools::tolerance(1e-14));
  BOOST_TEST(load[2] == 500.0, boost::test_tools::tolerance(1e-14)); // linear between rows
  excitation.load(2.0, load);
  BOOST_TEST(load[2] == 0.0); // zero after the table
  p.nodal_forces.harmonic = {"1 4 0 ux 800 30"};
  BOOST_CHECK_THROW(make_nodal_forces(p.nodal_forces, p.ground_motion, p.time_integration.newmark.time_step, p, a.model), InputError);
}

BOOST_AUTO_TEST_CASE(a_restart_steps_as_a_fresh_start)
{
  // K u is formed once per displacement and shared by the strain energy and
  // the next step's start residual: a restart, which replaces u, must step
  // and give energies to the bit as an integrator started at the new state.
  const Analysis a = sdof(1500, 6e6, 0.04);
  const double   dt = 1e-3;
  const Vector   load = Vector::Constant(1, 2e3), u1 = Vector::Constant(1, 0.004),
               v1 = Vector::Constant(1, -0.03);
  NewmarkIntegrator restarted(a.system, "eigen-ldlt", {dt, 0.5, 0.25, {}});
  restarted.initialize(load, Vector::Constant(1, -0.002), Vector::Zero(1));
  for (unsigned int i = 0; i < 3; ++i)
    restarted.advance(load);
  restarted.restart(load, u1, v1);
  NewmarkIntegrator fresh(a.system, "eigen-ldlt", {dt, 0.5, 0.25, {}});
  fresh.initialize(load, u1, v1);
  BOOST_TEST(restarted.strain_energy() == 0.5 * 6e6 * 0.004 * 0.004,
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(restarted.strain_energy() == fresh.strain_energy());
  for (unsigned int i = 0; i < 5; ++i)
    {
      restarted.advance(load);
      fresh.advance(load);
      BOOST_TEST(restarted.displacement()[0] == fresh.displacement()[0]);
      BOOST_TEST(restarted.strain_energy() == fresh.strain_energy());
    }
}
