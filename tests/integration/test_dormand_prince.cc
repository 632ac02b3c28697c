// The Dormand-Prince 5(4) integrator (integration/dormand_prince.h) against
// closed forms: its order on a linear oscillator, its adaptive accuracy on a
// damped forced oscillator with its energy balance, and the located events
// (contact onset, largest penetration, release) of an oscillator against a
// linear elastic barrier.
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/integration/dormand_prince.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  /// One mass m on a spring k with a dashpot c (a one-storey shear building).
  InputParameters
  oscillator_input(const double m, const double k, const double c)
  {
    InputParameters p = poundfe_test::shear_building_input(1, m, k, 0);
    p.model.buildings[0].storey_damping = {c};
    return p;
  }

  /// The error of (u, v / omega) at T = 1 s of the undamped oscillator
  /// from (0, 1 m/s) in fixed steps of h.
  double
  fixed_step_error(const Analysis &analysis, const double h)
  {
    DormandPrinceParameters parameters;
    parameters.time_step  = 1.0;
    parameters.fixed_step = h;
    DormandPrinceIntegrator integrator(analysis.system, parameters);
    const Vector            zero = Vector::Zero(1);
    integrator.initialize(zero, zero, Vector::Constant(1, 1.0));
    integrator.advance([](double, Vector &p) { p.setZero(1); });
    const double omega = 2 * M_PI;
    return std::hypot(integrator.displacement()[0] - std::sin(omega) / omega,
                      (integrator.velocity()[0] - std::cos(omega)) / omega);
  }
} // namespace

BOOST_AUTO_TEST_CASE(dormand_prince_converges_at_order_five_on_a_linear_oscillator)
{
  // m = 1 kg, k = 4 pi^2 N/m: 1 Hz; from u = 0, v = 1 m/s, u(t) = sin(2 pi t) / (2 pi).
  const Analysis analysis = prepare_analysis(oscillator_input(1, 4 * M_PI * M_PI, 0));
  const double   e1 = fixed_step_error(analysis, 1. / 16), e2 = fixed_step_error(analysis, 1. / 32),
               e3 = fixed_step_error(analysis, 1. / 64);
  const double order_1 = std::log2(e1 / e2), order_2 = std::log2(e2 / e3);
  BOOST_TEST_MESSAGE("errors " << e1 << " " << e2 << " " << e3 << ", orders " << order_1 << " "
                               << order_2);
  // the global error of a fifth-order method: 2^5 per halving, to within
  // the higher-order terms at these steps
  BOOST_TEST(std::abs(order_1 - 5) < 0.3);
  BOOST_TEST(std::abs(order_2 - 5) < 0.3);
}

BOOST_AUTO_TEST_CASE(adaptive_dormand_prince_meets_a_damped_forced_oscillator_and_its_energy)
{
  // 2 u'' + 4.1 u' + 210.125 u = -2 sin(14 t) from rest (the spillway without
  // its abutment, thesis §3.3.2); the closed form is the steady state plus the
  // damped free vibration that starts it from rest.
  const double m = 2, c = 4.1, k = 210.125, F = -2, W = 14;
  const Analysis analysis = prepare_analysis(oscillator_input(m, k, c));
  DormandPrinceParameters parameters;
  parameters.time_step          = 0.01;
  parameters.relative_tolerance = 1e-10;
  parameters.absolute_tolerance = 1e-12;
  DormandPrinceIntegrator integrator(analysis.system, parameters);
  const LoadFunction load = [&](double t, Vector &p) { p = Vector::Constant(1, F * std::sin(W * t)); };
  const Vector zero = Vector::Zero(1);
  integrator.initialize(zero, zero, zero);
  const double omega = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m));
  const double omega_d = omega * std::sqrt(1 - zeta * zeta);
  const double D = std::pow(k - m * W * W, 2) + std::pow(c * W, 2);
  const double A = F * (k - m * W * W) / D, B = -F * c * W / D;
  const double C1 = -B, C2 = (zeta * omega * C1 - A * W) / omega_d;
  const auto exact = [&](const double t) {
    return A * std::sin(W * t) + B * std::cos(W * t) +
           std::exp(-zeta * omega * t) * (C1 * std::cos(omega_d * t) + C2 * std::sin(omega_d * t));
  };
  double worst = 0;
  for (unsigned int i = 0; i < 300; ++i)
    {
      integrator.advance(load);
      worst = std::max(worst, std::abs(integrator.displacement()[0] - exact(integrator.time())));
    }
  const EnergyBalance energy = integrator.energy();
  const double final_energy_error =
    std::abs(energy.supplied() - energy.stored_and_dissipated()) / energy.supplied();
  BOOST_TEST_MESSAGE("largest error " << worst << " m, energy error " << integrator.max_energy_error()
                                      << " (largest), " << final_energy_error << " (at the end), steps "
                                      << integrator.statistics().steps);
  // amplitude ~ 1.4e-2 m: the global error stays within a few hundred local
  // tolerances (rtol 1e-10 of it, atol 1e-12)
  BOOST_TEST(worst < 1e-9);
  // the work integrals are integrated with the state at fifth order (the
  // largest relative error, ~7e-7, is at the start, where the motion is at
  // the absolute tolerance's level)
  BOOST_TEST(final_energy_error < 1e-8);
  BOOST_TEST(integrator.energy().damping > 0);
}

BOOST_AUTO_TEST_CASE(dormand_prince_locates_the_contact_events_of_an_elastic_barrier)
{
  // m u'' + k_s u = 0 from (0, v0); a barrier at g with a linear spring k_c.
  // Onset t1 = asin(g omega / v0) / omega; in contact the mass oscillates at
  // Omega = sqrt((k_s + k_c) / m) about u_eq = k_c g / (k_s + k_c), from
  // x = g - u_eq = d with x' = v1 = v0 cos(omega t1): x = A cos(Omega tau - phi),
  // A = sqrt(d^2 + (v1 / Omega)^2), phi = atan2(v1 / Omega, d); the largest
  // penetration A - d at tau = phi / Omega, release at tau = 2 phi / Omega with
  // velocity -v1.
  const double m = 1, k_s = 100, k_c = 1e5, g = 0.01, v0 = 0.5;
  InputParameters p = oscillator_input(m, k_s, 0);
  p.contact.law            = "linear";
  p.contact.stiffness      = k_c;
  p.contact.damping_from   = ContactDampingFrom::given;
  p.contact.damping        = 0;
  p.contact.effective_mass = m;
  p.contact.barriers       = {"1 1 right " + std::to_string(g)};
  const Analysis    analysis = prepare_analysis(p);
  NonlinearElements elements = make_nonlinear_elements(analysis.model);
  BOOST_REQUIRE_EQUAL(elements.size(), 1u);
  DormandPrinceParameters parameters;
  parameters.time_step          = 0.01;
  parameters.relative_tolerance = 1e-10;
  parameters.absolute_tolerance = 1e-12;
  DormandPrinceIntegrator integrator(analysis.system, parameters, &elements);
  const Vector            zero = Vector::Zero(1);
  integrator.initialize(zero, zero, Vector::Constant(1, v0));
  for (unsigned int i = 0; i < 10; ++i)
    integrator.advance([](double, Vector &q) { q.setZero(1); });

  const double omega = std::sqrt(k_s / m), Omega = std::sqrt((k_s + k_c) / m);
  const double t1 = std::asin(g * omega / v0) / omega, v1 = v0 * std::cos(omega * t1);
  const double d = g * k_s / (k_s + k_c), A = std::hypot(d, v1 / Omega);
  const double phi = std::atan2(v1 / Omega, d);
  const std::vector<Impact> &impacts = integrator.impact_log().impacts();
  BOOST_REQUIRE_EQUAL(impacts.size(), 1u);
  const Impact &i = impacts[0];
  BOOST_TEST_MESSAGE("onset " << i.start_time - t1 << ", peak " << i.max_penetration_time - (t1 + phi / Omega)
                              << ", release " << i.end_time - (t1 + 2 * phi / Omega) << " s off; "
                              << integrator.n_events() << " events");
  // events located to 1e-12 s on a solution accurate to ~1e-10 relative
  BOOST_TEST(std::abs(i.start_time - t1) < 1e-9);
  BOOST_TEST(std::abs(i.max_penetration_time - (t1 + phi / Omega)) < 1e-9);
  BOOST_TEST(std::abs(i.end_time - (t1 + 2 * phi / Omega)) < 1e-9);
  BOOST_TEST(std::abs(i.max_penetration - (A - d)) < 1e-9 * g);
  BOOST_TEST(std::abs(i.approach_velocity - v1) < 1e-8);
  BOOST_TEST(std::abs(i.separation_velocity - v1) < 1e-8); // > 0: separating
  BOOST_TEST(integrator.max_energy_error() < 1e-8);
}
