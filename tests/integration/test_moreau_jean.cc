// Moreau–Jean's scheme with rigid contact (integration/moreau_jean.h)
// against closed forms: a ball bouncing on a floor with restitution e (impact
// times and apex heights on the geometric series, the accumulation point and
// rest, the energy lost at impacts); two free masses colliding (Newton's
// law, momentum to round-off); and a shear pair whose Hertz-damp penalty
// contact (Newmark) approaches the rigid result as the stiffness grows.
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/integration/moreau_jean.h>
#include <poundfe/integration/newmark.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  /// Free masses: M = diag(m), K = C = 0.
  LinearSystem
  free_masses(const std::vector<double> &m)
  {
    LinearSystem s;
    const int    n = m.size();
    s.mass.resize(n, n);
    s.stiffness.resize(n, n);
    for (int i = 0; i < n; ++i)
      s.mass.insert(i, i) = m[i];
    s.influence = Vector::Ones(n);
    return s;
  }

  /// The start of each bounce: the first impulse after a step without one
  /// (a contact held over consecutive steps is one bounce).
  std::vector<ContactImpulse>
  first_impulses(const std::vector<ContactImpulse> &impulses, const double h)
  {
    std::vector<ContactImpulse> firsts;
    double                      last = -1;
    for (const ContactImpulse &i : impulses)
      {
        if (firsts.empty() || i.time - last > 1.5 * h)
          firsts.push_back(i);
        last = i.time;
      }
    return firsts;
  }
} // namespace

BOOST_AUTO_TEST_CASE(bouncing_ball_follows_the_geometric_series_to_rest)
{
  if (!lcp_solver_available())
    return;
  // m x'' = -m g, x >= 0, Newton's law x'+ = -e x'-; from rest at x0:
  // t_1 = sqrt(2 x0 / g), v_1 = g t_1, impact k + 1 at t_k + 2 e^k v_1 / g,
  // apex e^(2k) x0 after impact k, accumulation t_inf = t_1 + 2 v_1 e / (g (1 - e)).
  const double m = 2, grav = 9.81, x0 = 1, e = 0.8, h = 1e-4;
  const LinearSystem system = free_masses({m});
  MoreauJeanParameters parameters;
  parameters.time_step = h;
  UnilateralContact floor;
  floor.label        = "floor";
  floor.equations    = {0};
  floor.coefficients = {-1}; // closure d = -x: g = x
  floor.restitution  = e;
  MoreauJeanIntegrator integrator(system, parameters, {floor});
  const LoadFunction   weight = [&](double, Vector &p) { p = Vector::Constant(1, -m * grav); };
  integrator.initialize(Vector::Constant(1, -m * grav), Vector::Constant(1, x0), Vector::Zero(1));
  const double t1 = std::sqrt(2 * x0 / grav), v1 = grav * t1;
  const double t_inf = t1 + 2 * v1 * e / (grav * (1 - e));
  std::vector<double> apexes{0};
  while (integrator.time() < t_inf + 0.5)
    {
      const bool was_rising = integrator.velocity()[0] > 0;
      integrator.advance(weight);
      if (was_rising && integrator.velocity()[0] <= 0)
        apexes.push_back(integrator.displacement()[0]);
    }
  const std::vector<ContactImpulse> bounces = first_impulses(integrator.impulses(), h);
  BOOST_TEST_MESSAGE(bounces.size() << " bounces, " << apexes.size() - 1 << " apexes; solver "
                                    << integrator.lcp_solver() << ", " << integrator.n_lcps()
                                    << " LCPs, largest error " << integrator.max_lcp_residual());
  BOOST_REQUIRE(bounces.size() > 10);
  double t_k = t1;
  for (unsigned int k = 0; k < 8; ++k)
    {
      const double apex = std::pow(e, 2 * (k + 1)) * x0;
      BOOST_TEST_MESSAGE("impact " << k + 1 << ": t " << bounces[k].time << " (" << t_k
                                   << "), apex " << apexes[k + 1] << " (" << apex << ")");
      // the scheme is first order at impacts: within two steps of the closed
      // form, and the apex within the height of a step's travel (v1 h)
      BOOST_TEST(std::abs(bounces[k].time - t_k) < 2 * h + 2 * k * h);
      BOOST_TEST(std::abs(apexes[k + 1] - apex) < 2 * v1 * h);
      // Newton's law in the one step of the impact
      BOOST_TEST(std::abs(bounces[k].velocity_after + e * bounces[k].velocity_before) <
                 1e-9 * v1 + grav * h);
      t_k += 2 * std::pow(e, k + 1) * v1 / grav;
    }
  // rest after the accumulation point: held on the floor by m g h a step
  BOOST_TEST(std::abs(integrator.velocity()[0]) < 1e-9);
  BOOST_TEST(std::abs(integrator.displacement()[0]) < 2 * v1 * h);
  BOOST_TEST(std::abs(integrator.impulses().back().impulse - m * grav * h) < 1e-9);
  BOOST_TEST(std::abs(bounces.back().time - t_inf) < 0.05 * (t_inf - t1));
  // the energy lost at impacts is the potential energy given up, and the
  // balance closes (theta = 1/2, a linear model)
  double lost = 0;
  for (const ContactImpulse &i : integrator.impulses())
    lost += i.energy_lost;
  BOOST_TEST_MESSAGE("energy lost at impacts " << lost << " J of " << m * grav * x0
                                                << "; balance error " << integrator.max_energy_error());
  const double given_up = m * grav * (x0 - integrator.displacement()[0]);
  BOOST_TEST(std::abs(lost - given_up) < 1e-9 * given_up);
  BOOST_TEST(integrator.max_energy_error() < 1e-9);
}

BOOST_AUTO_TEST_CASE(two_free_masses_collide_by_newtons_law)
{
  if (!lcp_solver_available())
    return;
  const double m1 = 1, m2 = 3, v1 = 2, v2 = -1, e = 0.6, g0 = 0.1;
  const LinearSystem system = free_masses({m1, m2});
  UnilateralContact  contact;
  contact.equations    = {0, 1};
  contact.coefficients = {1, -1}; // closure u1 - u2
  contact.initial_gap  = g0;
  contact.restitution  = e;
  const double M = m1 + m2, p = m1 * v1 + m2 * v2, m_eff = m1 * m2 / M;
  const double w1 = (p + m2 * e * (v2 - v1)) / M, w2 = (p + m1 * e * (v1 - v2)) / M;
  for (const double theta : {0.5, 1.0})
    for (const LcpSolverKind solver : {LcpSolverKind::lemke, LcpSolverKind::nsgs})
      {
        MoreauJeanParameters parameters;
        parameters.time_step  = 1e-3;
        parameters.theta      = theta;
        parameters.lcp.solver = solver;
        MoreauJeanIntegrator integrator(system, parameters, {contact});
        const Vector         zero = Vector::Zero(2);
        integrator.initialize(zero, zero, Eigen::Vector2d(v1, v2));
        for (unsigned int i = 0; i < 100; ++i)
          integrator.advance([](double, Vector &q) { q.setZero(2); });
        const Vector &w = integrator.velocity();
        BOOST_TEST_MESSAGE("theta " << theta << ", " << integrator.lcp_solver() << ": " << w.transpose()
                                    << " (" << w1 << ", " << w2 << "), impulses "
                                    << integrator.impulses().size() << ", gap " << integrator.gaps()[0]);
        BOOST_REQUIRE_EQUAL(integrator.impulses().size(), 1u);
        const ContactImpulse &i = integrator.impulses()[0];
        // the step in which the gap closes: g0 / (v1 - v2) = 1/30 s
        BOOST_TEST(std::abs(i.time - g0 / (v1 - v2)) <= parameters.time_step);
        BOOST_TEST(std::abs(w[0] - w1) < 1e-12);
        BOOST_TEST(std::abs(w[1] - w2) < 1e-12);
        BOOST_TEST(std::abs(m1 * w[0] + m2 * w[1] - p) < 1e-13 * std::abs(m1 * v1));
        BOOST_TEST(std::abs(i.impulse - m_eff * (1 + e) * (v1 - v2)) < 1e-12);
        BOOST_TEST(std::abs(i.energy_lost - 0.5 * (1 - e * e) * m_eff * std::pow(v1 - v2, 2)) <
                   1e-12);
        BOOST_TEST(integrator.gaps()[0] >= -(v1 - v2) * parameters.time_step);
      }
}

namespace
{
  /// Two one-storey shear buildings 0.01 m apart, approaching each other.
  InputParameters
  shear_pair(const double contact_stiffness, const double e)
  {
    InputParameters p = poundfe_test::shear_building_input(1, 1e4, 4e6, 0);
    p.model.buildings.resize(2, p.model.buildings[0]);
    p.model.buildings[1].name               = "T";
    p.model.buildings[1].floor_masses       = {2e4};
    p.model.buildings[1].storey_stiffnesses = {1.5e7};
    p.model.separations                     = {0.01};
    p.contact.law                           = "hertz-damp";
    p.contact.stiffness                     = contact_stiffness;
    p.contact.restitution                   = e;
    p.contact.damping_from                  = ContactDampingFrom::calibrated;
    return p;
  }

  struct PairPeaks
  {
    double left = 0, right = 0; // the largest |u| of each floor
    double velocity = 0;        // the left floor's velocity at the end
  };

  /// Over the first impact (at ~0.02 s), to 0.12 s, before the floors
  /// meet again, from u = 0, v = v0.
  template <typename Stepper>
  PairPeaks
  pair_peaks(Stepper &stepper, const Vector &v0)
  {
    const Vector zero = Vector::Zero(2);
    stepper.initialize(zero, zero, v0);
    PairPeaks peaks;
    while (stepper.time() < 0.12 - 1e-9)
      {
        stepper.advance([](double, Vector &q) { q.setZero(2); });
        const Vector &u = stepper.displacement();
        peaks.left      = std::max(peaks.left, std::abs(u[0]));
        peaks.right     = std::max(peaks.right, std::abs(u[1]));
      }
    peaks.velocity = stepper.velocity()[0];
    return peaks;
  }
} // namespace

BOOST_AUTO_TEST_CASE(hertz_damp_pounding_approaches_rigid_contact_as_the_stiffness_grows)
{
  if (!lcp_solver_available())
    return;
  const double e = 0.65, h = 1e-5;
  const Vector v0 = Eigen::Vector2d(0.4, -0.2);
  // the rigid result
  const Analysis rigid_model = prepare_analysis(shear_pair(1e9, e));
  NonlinearElements rigid_elements = make_nonlinear_elements(rigid_model.model);
  std::vector<UnilateralContact> contacts;
  BOOST_REQUIRE(unilateral_contacts(rigid_model.model, rigid_elements, e, contacts).empty());
  BOOST_REQUIRE_EQUAL(contacts.size(), 1u);
  MoreauJeanParameters parameters;
  parameters.time_step = h;
  MoreauJeanIntegrator rigid(rigid_model.system, parameters, contacts, &rigid_elements);
  const PairPeaks      reference = pair_peaks(rigid, v0);
  BOOST_TEST_MESSAGE("nonsmooth: peaks " << reference.left << ", " << reference.right
                                         << " m, velocity " << reference.velocity << " m/s");
  BOOST_TEST_MESSAGE("Kn (N/m^1.5)   left peak error   right peak error   velocity error / approach");
  std::vector<double> errors;
  for (const double kn : {1e9, 1e10, 1e11, 1e12})
    {
      const Analysis    analysis = prepare_analysis(shear_pair(kn, e));
      NonlinearElements elements = make_nonlinear_elements(analysis.model);
      NewmarkParameters newmark;
      newmark.time_step = h;
      NewmarkIntegrator penalty(analysis.system, "eigen-ldlt", newmark, &elements);
      const PairPeaks   p = pair_peaks(penalty, v0);
      const double      left = std::abs(p.left / reference.left - 1),
                   right = std::abs(p.right / reference.right - 1),
                   // on the approach velocity: the floor is near its peak at the end
                   rebound = std::abs(p.velocity - reference.velocity) / (v0[0] - v0[1]);
      BOOST_TEST_MESSAGE(kn << "   " << left << "   " << right << "   " << rebound);
      errors.push_back(std::max({left, right, rebound}));
    }
  // a monotone approach (the impact lasts ~ Kn^-0.4: each decade shortens
  // it 2.5 times), to within 3 % at Kn = 1e12 (an impact of 2 ms)
  for (unsigned int i = 1; i < errors.size(); ++i)
    BOOST_TEST(errors[i] < errors[i - 1]);
  BOOST_TEST(errors.back() < 0.03);
}
