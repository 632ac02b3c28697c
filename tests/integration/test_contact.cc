// Pounding through the whole program (model -> gap elements -> Newmark with
// event refinement -> impact log) against independent references: the
// elastic Hertz impact in closed form; the coefficient of restitution of
// calibrated laws measured from the run; momentum conservation and the
// stereo-mechanical velocities of two colliding masses; convergence of the
// event times as the step is halved.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/input/input_parameters.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <sstream>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  /// Single masses (one per building) on soft springs, with contact.
  InputParameters
  masses_input(const std::vector<double> &masses, const double support_stiffness,
               const std::string &law, const double stiffness, const double e)
  {
    InputParameters p = poundfe_test::shear_building_input(1, masses[0], support_stiffness, 0);
    p.model.buildings.resize(masses.size(), p.model.buildings[0]);
    for (unsigned int b = 0; b < masses.size(); ++b)
      {
        p.model.buildings[b].name         = "M" + std::to_string(b + 1);
        p.model.buildings[b].floor_masses = {masses[b]};
      }
    p.model.separations                 = {0.001};
    p.contact.law                 = law;
    p.contact.stiffness           = stiffness;
    p.contact.restitution         = e;
    p.contact.damping_from        = ContactDampingFrom::calibrated;
    return p;
  }

  struct Run
  {
    std::vector<Impact> impacts;
    Vector              velocity;
    double              energy_error = 0;
  };

  /// From u = 0 with velocities v0, no load, for `duration` s.
  Run
  run(const InputParameters &input, const Vector &v0, const double dt, const double duration,
      const unsigned int refinement = 4)
  {
    const Analysis    analysis = prepare_analysis(input);
    NonlinearElements elements = make_nonlinear_elements(analysis.model);
    NewmarkParameters parameters;
    parameters.time_step               = dt;
    parameters.newton.event_refinement = refinement;
    NewmarkIntegrator integrator(analysis.system, "eigen-ldlt", parameters, &elements);
    const Vector      zero = Vector::Zero(analysis.system.n_equations());
    integrator.initialize(zero, zero, v0);
    const unsigned int n = std::lround(duration / dt);
    for (unsigned int i = 0; i < n; ++i)
      integrator.advance(zero);
    return {integrator.impact_log().impacts(), integrator.velocity(),
            integrator.max_energy_error()};
  }
} // namespace

BOOST_AUTO_TEST_CASE(elastic_hertz_impact_on_a_wall_matches_the_closed_form)
{
  const double m = 1000, k = 1e9, v0 = 0.5;
  InputParameters p = masses_input({m}, 1e-3, "hertz", k, 1.0);
  p.contact.barriers = {"1 1 right 0.001"};
  const double delta_max = std::pow(5 * m * v0 * v0 / (4 * k), 0.4);
  const double f_max     = k * std::pow(delta_max, 1.5);
  const double t_c       = 2.9432 * delta_max / v0;
  const Run    r = run(p, Vector::Constant(1, v0), t_c / 400, 0.002 + 2 * t_c);
  BOOST_REQUIRE(r.impacts.size() == 1u);
  const Impact &i = r.impacts[0];
  BOOST_TEST_MESSAGE("delta_max " << i.max_penetration << " / " << delta_max << ", F_max "
                                  << i.peak_force << " / " << f_max << ", t_c "
                                  << i.end_time - i.start_time << " / " << t_c);
  // Newmark with 400 steps per contact: O((pi/400)^2) ~ 6e-5 relative
  BOOST_TEST(i.max_penetration == delta_max, boost::test_tools::tolerance(1e-3));
  BOOST_TEST(i.peak_force == f_max, boost::test_tools::tolerance(2e-3));
  BOOST_TEST(i.end_time - i.start_time == t_c, boost::test_tools::tolerance(2e-3));
  BOOST_TEST(i.start_time == 0.001 / v0, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(i.approach_velocity == v0, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(i.separation_velocity == v0, boost::test_tools::tolerance(1e-3));
  BOOST_TEST(r.energy_error < 1e-6);
}

BOOST_AUTO_TEST_CASE(calibrated_laws_give_the_target_restitution_in_a_run)
{
  const double m = 500, v0 = 0.8;
  for (const std::string law :
       {"kelvin-voigt", "modified-kelvin-voigt", "hertz-damp", "jankowski"})
    for (const double e : {0.3, 0.5, 0.7, 0.9})
      {
        const bool      linear = law.find("kelvin") != std::string::npos;
        const double    k      = linear ? 1e8 : 2.75e9;
        InputParameters p      = masses_input({m}, 1e-3, law, k, e);
        p.contact.barriers     = {"1 1 right 0.001"};
        const double t_c =
          linear ? M_PI * std::sqrt(m / k) :
                   2.9432 * std::pow(5 * m * v0 * v0 / (4 * k), 0.4) / v0;
        const Run r = run(p, Vector::Constant(1, v0), t_c / 500, 0.001 / v0 + 3 * t_c);
        BOOST_REQUIRE(r.impacts.size() == 1u);
        const double measured = r.impacts[0].separation_velocity / r.impacts[0].approach_velocity;
        BOOST_TEST_INFO(law << " e = " << e << ": measured " << measured);
        BOOST_TEST(measured == e, boost::test_tools::tolerance(0.01));
        BOOST_TEST(r.energy_error < 1e-6);
      }
}

BOOST_AUTO_TEST_CASE(two_masses_conserve_momentum_and_approach_stereomechanics)
{
  const double m1 = 1000, m2 = 3000, v1 = 1.0, v2 = -0.5, e = 0.6;
  const double v1_plus = v1 - (1 + e) * m2 * (v1 - v2) / (m1 + m2);
  const double v2_plus = v2 + (1 + e) * m1 * (v1 - v2) / (m1 + m2);
  double       previous = 1e300;
  for (const double k : {1e6, 1e7, 1e8})
    {
      // supports of 1e4 N/m act during the contact; their share shrinks as
      // the contact stiffens and shortens
      InputParameters p   = masses_input({m1, m2}, 1e4, "kelvin-voigt", k, e);
      const double    m_e = m1 * m2 / (m1 + m2);
      const double    t_c = M_PI * std::sqrt(m_e / k);
      Vector          v0(2);
      v0 << v1, v2;
      const Run r = run(p, v0, t_c / 400, 0.001 / (v1 - v2) + 1.5 * t_c);
      BOOST_REQUIRE(r.impacts.size() == 1u);
      const double error = std::max(std::abs(r.velocity[0] - v1_plus), std::abs(r.velocity[1] - v2_plus)) /
                           (v1 - v2);
      BOOST_TEST_MESSAGE("k = " << k << ": v1+ " << r.velocity[0] << " (" << v1_plus << "), v2+ "
                                << r.velocity[1] << " (" << v2_plus << "), error " << error);
      BOOST_TEST(error < previous);
      previous = error;
      // with the contact force internal, momentum changes only by the
      // support springs' impulse, which shrinks the same way
      BOOST_TEST(r.energy_error < 1e-6);
    }
  BOOST_TEST(previous < 0.01);

  // free masses (supports 1e-6 N/m): momentum is conserved to round-off
  InputParameters p = masses_input({m1, m2}, 1e-6, "hertz-damp", 1e9, e);
  Vector          v0(2);
  v0 << v1, v2;
  const Run r = run(p, v0, 1e-5, 0.02);
  BOOST_REQUIRE(r.impacts.size() == 1u);
  BOOST_TEST(m1 * r.velocity[0] + m2 * r.velocity[1] == m1 * v1 + m2 * v2,
             boost::test_tools::tolerance(1e-9));
  BOOST_TEST((r.velocity[1] - r.velocity[0]) / (v1 - v2) == e, boost::test_tools::tolerance(0.01));
}

BOOST_AUTO_TEST_CASE(event_times_converge_as_the_step_is_halved)
{
  // the spillway of the thesis: its first impact located with ever finer steps
  InputParameters input = read_parameters("input/spillway-abutment.prm");
  std::vector<double> starts, ends;
  for (const double dt : {8e-4, 4e-4, 2e-4, 1e-4})
    {
      input.time_integration.newmark.time_step = dt;
      const Analysis   analysis   = prepare_analysis(input);
      const Excitation excitation(analysis.system, GroundMotion(),
                                  make_nodal_forces(input.nodal_forces, input.ground_motion,
                                                    input.time_integration.newmark.time_step, input,
                                                    analysis.model));
      NonlinearElements elements = make_nonlinear_elements(analysis.model);
      NewmarkParameters parameters;
      parameters.time_step = dt;
      NewmarkIntegrator integrator(analysis.system, "eigen-ldlt", parameters, &elements);
      Vector            load(1);
      excitation.load(0, load);
      integrator.initialize(load);
      for (unsigned int i = 0; i < std::lround(0.5 / dt); ++i)
        integrator.advance([&](double t, Vector &p) { excitation.load(t, p); });
      BOOST_REQUIRE(!integrator.impact_log().impacts().empty());
      starts.push_back(integrator.impact_log().impacts()[0].start_time);
      ends.push_back(integrator.impact_log().impacts()[0].end_time);
      BOOST_TEST_MESSAGE("dt " << dt << ": first impact " << starts.back() << " to " << ends.back());
    }
  for (unsigned int i = 2; i < starts.size(); ++i)
    {
      // second order: each halving shrinks the change about fourfold
      BOOST_TEST(std::abs(starts[i] - starts[i - 1]) < 0.5 * std::abs(starts[i - 1] - starts[i - 2]));
      BOOST_TEST(std::abs(ends[i] - ends[i - 1]) < 0.5 * std::abs(ends[i - 1] - ends[i - 2]));
    }
  BOOST_TEST(std::abs(starts[3] - starts[2]) < 1e-5); // far below the step, 1e-4 s
}

BOOST_AUTO_TEST_CASE(a_step_ending_just_past_a_jankowski_touch_converges_without_a_cut)
{
  // A 500 kg mass at 0.5 m/s against a Jankowski wall (beta = 2.75e9 N/m^1.5,
  // e = 0.65) that it touches 2e-8 s before the end of step 20 of 1e-4 s:
  // that step ends 1e-8 m into the contact, where the damping c(delta) ~
  // delta^(1/4) is steepest (theory §3.7a): from u_n Newton cycles between
  // open and closed there and the step is cut (1 cut); Contact onset from
  // acceleration's predictor and onset correction take it without a cut.
  // The impact against the same run at 1e-5 s.
  const double    v0 = 0.5, dt = 1e-4, lead = 2e-8;
  InputParameters p  = masses_input({500}, 1e-3, "jankowski", 2.75e9, 0.65);
  std::ostringstream barrier;
  barrier.precision(17);
  barrier << "1 1 right " << v0 * (20 * dt - lead);
  p.contact.barriers = {barrier.str()};
  const Analysis analysis = prepare_analysis(p);
  std::vector<Impact> impacts;
  for (const bool onset : {false, true})
    for (const double h : {dt, dt / 10})
      {
        NonlinearElements elements = make_nonlinear_elements(analysis.model);
        NewmarkParameters parameters;
        parameters.time_step                              = h;
        parameters.newton.contact_onset_from_acceleration = onset;
        NewmarkIntegrator integrator(analysis.system, "eigen-ldlt", parameters, &elements);
        const Vector      zero = Vector::Zero(1);
        integrator.initialize(zero, zero, Vector::Constant(1, v0));
        for (unsigned int i = 0; i < std::lround(0.02 / h); ++i)
          integrator.advance(zero);
        const IterationStatistics &s = integrator.statistics();
        BOOST_TEST_MESSAGE("onset " << onset << ", h " << h << ": " << s.step_cuts << " cuts, "
                                    << s.max_iterations << " iterations, peak force "
                                    << integrator.impact_log().impacts().at(0).peak_force);
        if (onset && h == dt)
          BOOST_TEST(s.step_cuts == 0u);
        impacts.push_back(integrator.impact_log().impacts().at(0));
      }
  // 75 steps per impact at 1e-4 s: the sampled peak within 1 % of 1e-5 s's
  BOOST_TEST(impacts[2].peak_force == impacts[3].peak_force, boost::test_tools::tolerance(0.01));
}
