// Moreau–Jean's scheme with rigid contact (integration/moreau_jean.h)
// against closed forms: a ball bouncing on a floor with restitution e (impact
// times and apex heights on the geometric series, the accumulation point and
// rest, the energy lost at impacts); two free masses colliding (Newton's
// law, momentum to round-off); and a shear pair whose Hertz-damp penalty
// contact (Newmark) approaches the rigid result as the stiffness grows; a
// harmonically forced oscillator against a rigid stop on its periodic
// impacting orbit (Shaw & Holmes 1983); Newton's cradle (three masses, one
// simultaneous impact by the LCP rule); two free slabs colliding obliquely
// in plan, off their centres (rigid-body impact along the normal, momenta).
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

namespace
{
  /// One mass on a spring, m x'' + k x = F cos(omega t), against a rigid
  /// stop at its rest position, x <= 0 (the gap g = -x).
  struct StopOscillator
  {
    double m = 1, omega0 = 2 * M_PI, r = 1.5, force = 10, e = 0.5;
    double omega() const { return r * omega0; }
    /// The static-response amplitude of the forcing, X = F / (k (1 - r^2)).
    double amplitude() const { return force / (m * omega0 * omega0 * (1 - r * r)); }
  };
} // namespace

BOOST_AUTO_TEST_CASE(forced_oscillator_against_a_stop_settles_on_the_shaw_holmes_orbit)
{
  if (!lcp_solver_available())
    return;
  // The 1:1 orbit (one impact per forcing period T = 2 pi / omega; Shaw &
  // Holmes, J. Sound Vib. 90 (1983) 129, §3). Between impacts
  //   x = y + X cos(omega t),  y'' + omega0^2 y = 0.
  // With the impact at phase phi = omega tau, x(tau) = 0, x'(tau-) = V > 0,
  // x'(tau+) = -e V, write Y = y(tau) = -X cos phi, P = X omega sin phi and
  // c, s = cos, sin(omega0 T). Periodicity over one flight of length T
  // (omega T = 2 pi, so the forcing term repeats):
  //   Y c + (P - e V) s / omega0 = Y,   -omega0 Y s + (P - e V) c = V + P.
  // The first gives Y = (P - e V) cot(beta) / omega0 with beta = omega0 T / 2
  // = pi / r (s / (1 - c) = cot beta); put in the second (s^2 / (1 - c) =
  // 1 + c) it leaves -2 P = (1 - e) V. Hence
  //   X omega sin phi = -(1 - e) V / 2,   X omega0 cos phi = (1 + e) V cot(beta) / 2,
  // and sin^2 + cos^2 = 1 gives the impact velocity
  //   V = 2 |X| omega0 / sqrt((1 - e)^2 / r^2 + (1 + e)^2 cot^2(pi / r)).
  // For r = 1.5, e = 0.5, F / m = 10 m/s^2, omega0 = 2 pi: V = 2.74417 m/s at
  // phi / 2 pi = 0.0584; an event-driven exact integration from x = -0.01
  // reaches it to 1e-6 within 20 periods.
  const StopOscillator o;
  const double         h = 1e-4, omega = o.omega(), X = o.amplitude(), T = 2 * M_PI / omega;
  const double         cot = 1 / std::tan(M_PI / o.r);
  const double V = 2 * std::abs(X) * o.omega0 /
                   std::sqrt(std::pow((1 - o.e) / o.r, 2) + std::pow((1 + o.e) * cot, 2));
  const double phi = std::atan2(-(1 - o.e) * V / (2 * X * omega),
                                (1 + o.e) * V * cot / (2 * X * o.omega0));
  LinearSystem system = free_masses({o.m});
  system.stiffness.insert(0, 0) = o.m * o.omega0 * o.omega0;
  UnilateralContact stop;
  stop.equations    = {0};
  stop.coefficients = {1}; // closure d = x: g = -x
  stop.restitution  = o.e;
  MoreauJeanParameters parameters;
  parameters.time_step = h;
  MoreauJeanIntegrator integrator(system, parameters, {stop});
  const LoadFunction   forcing = [&](double t, Vector &p) {
    p = Vector::Constant(1, o.force * std::cos(omega * t));
  };
  integrator.initialize(Vector::Constant(1, o.force), Vector::Constant(1, -0.01), Vector::Zero(1));
  while (integrator.time() < 30 * T)
    integrator.advance(forcing);
  std::vector<ContactImpulse> last;
  for (const ContactImpulse &i : first_impulses(integrator.impulses(), h))
    if (i.time > 25 * T)
      last.push_back(i);
  BOOST_REQUIRE_EQUAL(last.size(), 5u); // one impact per period
  const double phase = (phi < 0 ? phi + 2 * M_PI : phi) / omega;
  for (const ContactImpulse &i : last)
    {
      const double period = std::floor(i.time / T), t_closed = period * T + phase;
      BOOST_TEST_MESSAGE("impact at " << i.time << " s (" << t_closed << "), V "
                                      << -i.velocity_before << " m/s (" << V << ")");
      // the impulse step ends within a step after the crossing; the
      // velocity entering it is V less up to a step's acceleration
      // (|x''| <= F/m at x = 0: 1e-3 m/s)
      BOOST_TEST(i.time - t_closed >= -1e-9);
      BOOST_TEST(i.time - t_closed <= 2 * h);
      BOOST_TEST(std::abs(-i.velocity_before - V) <= 2 * o.force / o.m * h);
      BOOST_TEST(std::abs(i.velocity_after + o.e * i.velocity_before) <= 1e-9 * V);
    }
  BOOST_TEST(integrator.max_energy_error() < 1e-9);
}

BOOST_AUTO_TEST_CASE(newtons_cradle_takes_the_lcp_rule_of_simultaneous_impact)
{
  if (!lcp_solver_available())
    return;
  // Three equal masses touching (gaps 0), the first arriving at v0. Both
  // contacts are in the step's index set, and Newton's law per contact,
  //   0 <= U_a+ + e U_a ⊥ P_a >= 0,  U_a = v2 - v1 = -v0,  U_b = v3 - v2 = 0,
  // with the Delassus operator W = [[2, -1], [-1, 2]] / m (positive
  // definite: one solution) gives both impulses positive:
  //   P_a = 2 (1 + e) m v0 / 3,  P_b = (1 + e) m v0 / 3,
  //   v+ = v0 ((1 - 2 e) / 3, (1 + e) / 3, (1 + e) / 3),
  // momentum kept and the energy lost (1 - e^2) m v0^2 / 3. At e = 1 the
  // energy is kept but the first mass rebounds at -v0 / 3 and the last two
  // leave together at 2 v0 / 3: not the cradle's (0, 0, v0), which takes
  // the impacts one after the other (Acary & Brogliato 2008, §4.3.2).
  const double       m = 2, v0 = 1.5, h = 1e-3;
  const LinearSystem system = free_masses({m, m, m});
  std::vector<UnilateralContact> contacts(2);
  for (unsigned int c = 0; c < 2; ++c)
    {
      contacts[c].equations    = {int(c), int(c + 1)};
      contacts[c].coefficients = {1, -1}; // closure u_c - u_c+1
    }
  for (const double e : {1.0, 0.9, 0.0})
    {
      for (UnilateralContact &c : contacts)
        c.restitution = e;
      MoreauJeanParameters parameters;
      parameters.time_step = h;
      MoreauJeanIntegrator integrator(system, parameters, contacts);
      const Vector         zero = Vector::Zero(3);
      integrator.initialize(zero, zero, Eigen::Vector3d(v0, 0, 0));
      for (unsigned int i = 0; i < 20; ++i)
        integrator.advance([](double, Vector &q) { q.setZero(3); });
      const Vector &w = integrator.velocity();
      const Eigen::Vector3d expected =
        v0 * Eigen::Vector3d(1 - 2 * e, 1 + e, 1 + e) / 3;
      std::vector<double> impulse(2, 0.0);
      double              lost = 0;
      for (const ContactImpulse &i : integrator.impulses())
        if (i.impulse > 1e-12 * m * v0)
          {
            BOOST_TEST(i.time <= h * (1 + 1e-12)); // all in the first step
            impulse[i.contact] += i.impulse;
            lost += i.energy_lost;
          }
      BOOST_TEST_MESSAGE("e = " << e << ": v+ " << w.transpose() << " (" << expected.transpose()
                                << "), impulses " << impulse[0] << ", " << impulse[1]);
      BOOST_TEST((w - expected).norm() < 1e-12 * v0);
      BOOST_TEST(std::abs(impulse[0] - 2 * (1 + e) * m * v0 / 3) < 1e-12 * m * v0);
      BOOST_TEST(std::abs(impulse[1] - (1 + e) * m * v0 / 3) < 1e-12 * m * v0);
      BOOST_TEST(std::abs(m * w.sum() - m * v0) < 1e-13 * m * v0);
      BOOST_TEST(std::abs(lost - (1 - e * e) * m * v0 * v0 / 3) < 1e-12 * m * v0 * v0);
      BOOST_TEST(integrator.max_energy_error() < 1e-9);
    }
}

BOOST_AUTO_TEST_CASE(two_free_slabs_collide_obliquely_in_plan)
{
  if (!lcp_solver_available())
    return;
  // Two free slabs in plan (Model/Dimension = 3), each (ux, uy, θz) about
  // its mass centre: floor 1 the square [-5, 5]², floor 2 the square
  // [5.1, 9.1] x [0, 4] (centre (7.1, 2)), 0.1 m apart along x. The corner
  // (5.1, 4) of floor 2 against floor 1's edge x = 5 (the overlap's end 0,
  // alone) is hit obliquely and off both centres. Rigid-body impact by
  // Newton's law along the normal n = (1, 0) through the corner, with lever
  // arms r_k = x_c - c_k at the impact (the floors only translate before it):
  //   1/m_eff = 1/m1 + 1/m2 + (r1 × n)²/I1 + (r2 × n)²/I2,
  //   P = -(1 + e) m_eff U,  U = n·(v2 + ω2 × r2 - v1 - ω1 × r1) < 0,
  //   v2 += P n/m2, ω2 += P (r2 × n)/I2, v1 -= P n/m1, ω1 -= P (r1 × n)/I1;
  // the tangential (y) velocities unchanged; linear momentum and angular
  // momentum about the origin kept to round-off (free bodies, one impulse
  // through one point), the energy lost (1 - e²) m_eff U²/2.
  const double m1 = 4e4, I1 = m1 * 200 / 12, m2 = 1e4, I2 = m2 * 32 / 12, e = 0.5;
  const Eigen::Vector3d    w1(2, 0.5, 0), w2(-1, -0.3, 0); // (vx, vy, ω) before
  PlanContactGeometry      geometry;
  geometry.edges   = {{{{Point2{5, -5}, Point2{5, 5}}}, {{Point2{5.1, 4}, Point2{5.1, 0}}}}};
  geometry.centres = {{Point2{0, 0}, Point2{7.1, 2}}};
  geometry.end     = 0;
  UnilateralContact contact;
  contact.equations   = {0, 1, 2, 3, 4, 5};
  contact.in_plan     = true;
  contact.plan        = geometry;
  contact.restitution = e;
  const LinearSystem system = free_masses({m1, m1, I1, m2, m2, I2});
  auto cross = [](const Eigen::Vector2d &a, const Eigen::Vector2d &b) {
    return a.x() * b.y() - a.y() * b.x();
  };
  for (const double theta : {0.5, 1.0})
    {
      MoreauJeanParameters parameters;
      parameters.time_step = 1e-3;
      parameters.theta     = theta;
      MoreauJeanIntegrator integrator(system, parameters, {contact});
      Vector               v0(6);
      v0 << w1, w2;
      integrator.initialize(Vector::Zero(6), Vector::Zero(6), v0);
      for (unsigned int i = 0; i < 60; ++i)
        integrator.advance([](double, Vector &q) { q.setZero(6); });
      BOOST_REQUIRE_EQUAL(integrator.impulses().size(), 1u);
      const ContactImpulse &impact = integrator.impulses()[0];
      // the closed form at the impact: the floors translated by v t0 before it
      const double          t0 = impact.time - parameters.time_step;
      const Eigen::Vector2d n(1, 0), c1 = w1.head<2>() * t0,
                            c2 = Eigen::Vector2d(7.1, 2) + w2.head<2>() * t0,
                            xc = Eigen::Vector2d(5.1, 4) + w2.head<2>() * t0;
      const Eigen::Vector2d r1 = xc - c1, r2 = xc - c2;
      const double          U  = n.dot(w2.head<2>() - w1.head<2>());
      const double m_eff = 1 / (1 / m1 + 1 / m2 + std::pow(cross(r1, n), 2) / I1 +
                                std::pow(cross(r2, n), 2) / I2);
      const double P = -(1 + e) * m_eff * U;
      Vector       expected(6);
      expected << w1.x() - P / m1, w1.y(), -P * cross(r1, n) / I1, w2.x() + P / m2, w2.y(),
        P * cross(r2, n) / I2;
      const Vector &v = integrator.velocity();
      BOOST_TEST_MESSAGE("theta " << theta << ": v+ " << v.transpose() << " (" << expected.transpose()
                                  << "), P " << impact.impulse << " (" << P << ")");
      BOOST_TEST(std::abs(impact.time - 0.1 / 3) <= parameters.time_step);
      BOOST_TEST(std::abs(impact.impulse - P) < 1e-12 * P);
      for (unsigned int i = 0; i < 6; ++i)
        BOOST_TEST(std::abs(v[i] - expected[i]) < 1e-12 * (std::abs(expected[i]) + 1));
      BOOST_TEST(v[1] == w1.y()); // tangential: untouched
      BOOST_TEST(v[4] == w2.y());
      const Eigen::Vector2d p0 = m1 * w1.head<2>() + m2 * w2.head<2>(),
                            p1 = m1 * v.segment<2>(0) + m2 * v.segment<2>(3);
      BOOST_TEST((p1 - p0).norm() < 1e-13 * p0.norm());
      // angular momentum about the origin, the centres where the impulse
      // acted (through one point: kept exactly; the θ-scheme's positions
      // after the step move by h (θ v+ + (1 - θ) v), not along v+)
      const double L0 = m1 * cross(c1, w1.head<2>()) + m2 * cross(c2, w2.head<2>());
      const double L1 = I1 * v[2] + m1 * cross(c1, v.segment<2>(0)) + I2 * v[5] +
                        m2 * cross(c2, v.segment<2>(3));
      BOOST_TEST(std::abs(L1 - L0) < 1e-12 * m2 * c2.norm() * w2.norm());
      BOOST_TEST(std::abs(impact.energy_lost - 0.5 * (1 - e * e) * m_eff * U * U) <
                 1e-12 * m_eff * U * U);
    }
}

BOOST_AUTO_TEST_CASE(a_slab_sliding_along_an_edge_decelerates_by_coulombs_law)
{
  if (!lcp_solver_available())
    return;
  // A block (the square [5, 9] x [0, 4], no rotation) pressed by a constant
  // force F against the fixed edge x = 5 of a slab, sliding along it at v0:
  // Coulomb's friction decelerates it at mu F / m until it sticks at
  // t_s = m v0 / (mu F), then it rests:
  //   v_y(t) = max(v0 - mu F t / m, 0),  v_x = 0,
  // which Moreau-Jean gives to round-off for a constant force (the normal
  // impulse F h each step, the tangential -mu F h while it slides), with
  // each of Siconos's fc2d solvers.
  const double m = 2e3, F = 5e3, v0 = 0.3, mu = 0.4, h = 1e-3;
  PlanContactGeometry geometry;
  geometry.edges   = {{{{Point2{5, -50}, Point2{5, 50}}}, {{Point2{5, 4}, Point2{5, 0}}}}};
  geometry.centres = {{Point2{0, 0}, Point2{7, 2}}};
  UnilateralContact contact;
  contact.equations = {-1, -1, -1, 0, 1, -1}; // the slab fixed, the block's (ux, uy)
  contact.in_plan   = true;
  contact.plan      = geometry;
  contact.friction  = mu;
  const LinearSystem   system = free_masses({m, m});
  const LoadFunction   press  = [&](double, Vector &p) { p = Eigen::Vector2d(-F, 0); };
  for (const FrictionSolverKind solver :
       {FrictionSolverKind::nsgs, FrictionSolverKind::lemke, FrictionSolverKind::enumeration})
    {
      MoreauJeanParameters parameters;
      parameters.time_step       = h;
      parameters.friction.solver = solver;
      MoreauJeanIntegrator integrator(system, parameters, {contact});
      integrator.initialize(Eigen::Vector2d(-F, 0), Vector::Zero(2), Eigen::Vector2d(0, v0));
      const double t_stop = m * v0 / (mu * F);
      double       worst = 0, normal = 0;
      while (integrator.time() < 1.5 * t_stop)
        {
          integrator.advance(press);
          const double expected = std::max(v0 - mu * F * integrator.time() / m, 0.0);
          worst  = std::max(worst, std::abs(integrator.velocity()[1] - expected));
          normal = std::max(normal, std::abs(integrator.velocity()[0]));
        }
      BOOST_TEST_MESSAGE(integrator.friction_solver() << ": largest velocity difference " << worst
                                                      << " m/s, normal velocity " << normal
                                                      << " m/s, stuck at " << integrator.velocity()[1]);
      BOOST_TEST(worst < 1e-10 * v0);
      // NSGS's iterate may leave the resting contact open by round-off; the
      // index set by prediction (g + h U <= 0, no tolerance) then skips it
      // for one step, a free step under the force (F h / m) and a plastic
      // impact after it: the held contact is exact with the pivoting solvers
      if (solver == FrictionSolverKind::nsgs)
        continue;
      BOOST_TEST(normal < 1e-10 * v0);
      BOOST_TEST(std::abs(integrator.velocity()[1]) < 1e-10 * v0);
      const ContactImpulse &first = integrator.impulses().front();
      BOOST_TEST(std::abs(first.impulse - F * h) < 1e-10 * F * h);
      BOOST_TEST(std::abs(first.tangential_impulse + mu * F * h) < 1e-10 * F * h);
      // the work of friction over the slide: the kinetic energy m v0^2 / 2
      double lost = 0;
      for (const ContactImpulse &i : integrator.impulses())
        lost += i.energy_lost;
      BOOST_TEST(std::abs(lost - 0.5 * m * v0 * v0) < 1e-9 * m * v0 * v0);
    }
}

BOOST_AUTO_TEST_CASE(an_oblique_impact_in_plan_sticks_or_slips_by_coulombs_law)
{
  if (!lcp_solver_available())
    return;
  // The two free slabs of two_free_slabs_collide_obliquely_in_plan, with
  // friction at the corner. With the rigid bodies' Delassus operator at the
  // contact, in the normal n = (1, 0) and the tangent t = J n = (0, 1),
  //   W_nn = 1/m1 + 1/m2 + (r1 × n)²/I1 + (r2 × n)²/I2,
  //   W_nt = (r1 × n)(r1 × t)/I1 + (r2 × n)(r2 × t)/I2,
  //   W_tt = 1/m1 + 1/m2 + (r1 × t)²/I1 + (r2 × t)²/I2,
  // and the relative velocities U = (U_n, U_t) before, Newton's law U_n+ =
  // -e U_n and Coulomb's: stick, U_t+ = 0, with P = W^-1 (U+ - U) if
  // |P_t| <= mu P_n; else slip, P_t = -mu s P_n and P_n = -(1 + e) U_n /
  // (W_nn - mu s W_nt), s the sliding direction after the impact, that of
  // U_t+ = U_t + W_tn P_n + W_tt P_t (here the impulse turns it: s = +1
  // where U_t < 0).
  const double m1 = 4e4, I1 = m1 * 200 / 12, m2 = 1e4, I2 = m2 * 32 / 12, e = 0.5;
  PlanContactGeometry geometry;
  geometry.edges   = {{{{Point2{5, -5}, Point2{5, 5}}}, {{Point2{5.1, 4}, Point2{5.1, 0}}}}};
  geometry.centres = {{Point2{0, 0}, Point2{7.1, 2}}};
  auto cross = [](const Eigen::Vector2d &a, const Eigen::Vector2d &b) {
    return a.x() * b.y() - a.y() * b.x();
  };
  const LinearSystem system = free_masses({m1, m1, I1, m2, m2, I2});
  // (mu, tangential velocity of floor 2): a slip and a stick
  for (const auto &[mu, vy2] : {std::pair{0.1, -0.8}, std::pair{2.0, -0.05}})
    {
      const Eigen::Vector3d w1(2, 0.1, 0), w2(-1, vy2, 0);
      UnilateralContact     contact;
      contact.equations   = {0, 1, 2, 3, 4, 5};
      contact.in_plan     = true;
      contact.plan        = geometry;
      contact.restitution = e;
      contact.friction    = mu;
      MoreauJeanParameters parameters;
      parameters.time_step = 1e-3;
      MoreauJeanIntegrator integrator(system, parameters, {contact});
      Vector               v0(6);
      v0 << w1, w2;
      integrator.initialize(Vector::Zero(6), Vector::Zero(6), v0);
      for (unsigned int i = 0; i < 40; ++i)
        integrator.advance([](double, Vector &q) { q.setZero(6); });
      BOOST_REQUIRE_EQUAL(integrator.impulses().size(), 1u);
      const ContactImpulse &impact = integrator.impulses()[0];
      const double          t0     = impact.time - parameters.time_step;
      const Eigen::Vector2d n(1, 0), t(0, 1), c1 = w1.head<2>() * t0,
                            c2 = Eigen::Vector2d(7.1, 2) + w2.head<2>() * t0,
                            xc = Eigen::Vector2d(5.1, 4) + w2.head<2>() * t0;
      const Eigen::Vector2d r1 = xc - c1, r2 = xc - c2;
      Eigen::Matrix2d       W;
      W(0, 0) = 1 / m1 + 1 / m2 + std::pow(cross(r1, n), 2) / I1 + std::pow(cross(r2, n), 2) / I2;
      W(0, 1) = W(1, 0) = cross(r1, n) * cross(r1, t) / I1 + cross(r2, n) * cross(r2, t) / I2;
      W(1, 1) = 1 / m1 + 1 / m2 + std::pow(cross(r1, t), 2) / I1 + std::pow(cross(r2, t), 2) / I2;
      const Eigen::Vector2d U(n.dot(w2.head<2>() - w1.head<2>()), t.dot(w2.head<2>() - w1.head<2>()));
      Eigen::Vector2d P = W.inverse() * (Eigen::Vector2d(-e * U[0], 0) - U);
      const bool      stick = std::abs(P[1]) <= mu * P[0];
      if (!stick) // the slip whose direction is that of U_t+ (the impulse may turn it)
        {
          unsigned int consistent = 0;
          for (const double s : {1.0, -1.0})
            {
              const double Pn = -(1 + e) * U[0] / (W(0, 0) - mu * s * W(0, 1));
              const double Ut = U[1] + W(1, 0) * Pn - W(1, 1) * mu * s * Pn;
              if (Pn > 0 && s * Ut > 0)
                P = Eigen::Vector2d(Pn, -mu * s * Pn), ++consistent;
            }
          BOOST_TEST(consistent == 1u);
        }
      BOOST_TEST_MESSAGE((stick ? "stick" : "slip") << ": P " << impact.impulse << ", "
                                                    << impact.tangential_impulse << " (" << P.transpose() << ")");
      BOOST_TEST(stick == (mu > 1)); // the cases are what they say
      BOOST_TEST(std::abs(impact.impulse - P[0]) < 1e-9 * P[0]);
      BOOST_TEST(std::abs(impact.tangential_impulse - P[1]) < 1e-9 * P[0]);
      BOOST_TEST(std::abs(impact.tangential_impulse) <= mu * impact.impulse * (1 + 1e-12));
      const Vector         &v  = integrator.velocity();
      const Eigen::Vector2d p0 = m1 * w1.head<2>() + m2 * w2.head<2>(),
                            p1 = m1 * v.segment<2>(0) + m2 * v.segment<2>(3);
      BOOST_TEST((p1 - p0).norm() < 1e-12 * p0.norm());
      const double L0 = m1 * cross(c1, w1.head<2>()) + m2 * cross(c2, w2.head<2>());
      const double L1 = I1 * v[2] + m1 * cross(c1, v.segment<2>(0)) + I2 * v[5] +
                        m2 * cross(c2, v.segment<2>(3));
      BOOST_TEST(std::abs(L1 - L0) < 1e-11 * m2 * c2.norm() * w2.norm());
    }
}

namespace
{
  /// The default example's frames (hinges, massless rotations, two gaps)
  /// under a harmonic ground acceleration for 3 s, stepped with J kept as
  /// `storage` asks: the end state, every impulse, the largest |u|.
  struct FramesRun
  {
    Vector                      u, v;
    std::vector<ContactImpulse> impulses;
    double                      peak = 0;
  };

  FramesRun
  default_example_run(const Analysis &analysis, const JacobianStorage storage)
  {
    NonlinearElements              elements = make_nonlinear_elements(analysis.model);
    std::vector<UnilateralContact> contacts;
    BOOST_REQUIRE(unilateral_contacts(analysis.model, elements, 0.65, contacts).empty());
    MoreauJeanParameters parameters;
    parameters.time_step = 2e-3;
    MoreauJeanIntegrator stepper(analysis.system, parameters, contacts, &elements, storage);
    // the default example (60 equations) left to choose is sparse: its L
    // has 265 entries, 12.9 x 265 instructions a solve against 2.6 x 60^2
    BOOST_TEST(stepper.dense_jacobian() == (storage == JacobianStorage::dense));
    const Vector zero = Vector::Zero(analysis.system.n_equations());
    const Vector inertia = analysis.system.mass * analysis.system.influence;
    stepper.initialize(zero, zero, zero);
    FramesRun run;
    while (stepper.time() < 3 - 1e-9)
      {
        // 0.5 g at 1.5 Hz: the frames pound and their hinges yield
        stepper.advance([&](const double t, Vector &p) {
          p = -0.5 * 9.81 * std::sin(2 * M_PI * 1.5 * t) * inertia;
        });
        run.peak = std::max(run.peak, stepper.displacement().cwiseAbs().maxCoeff());
      }
    run.u        = stepper.displacement();
    run.v        = stepper.velocity();
    run.impulses = stepper.impulses();
    return run;
  }
} // namespace

BOOST_AUTO_TEST_CASE(sparse_and_dense_iteration_matrices_agree_on_frames)
{
  if (!lcp_solver_available())
    return;
  const Analysis  analysis = prepare_analysis(read_parameters("input/two-buildings.prm"));
  const FramesRun dense    = default_example_run(analysis, JacobianStorage::dense);
  const FramesRun sparse   = default_example_run(analysis, JacobianStorage::automatic);
  BOOST_TEST_MESSAGE(dense.impulses.size() << " impulses; peak |u| " << dense.peak << " m");
  BOOST_REQUIRE(dense.impulses.size() > 10);
  BOOST_REQUIRE_EQUAL(dense.impulses.size(), sparse.impulses.size());
  double impulse_scale = 0, impulse_difference = 0;
  for (unsigned int k = 0; k < dense.impulses.size(); ++k)
    {
      BOOST_TEST(dense.impulses[k].contact == sparse.impulses[k].contact);
      BOOST_TEST(dense.impulses[k].time == sparse.impulses[k].time);
      impulse_scale = std::max(impulse_scale, dense.impulses[k].impulse);
      impulse_difference = std::max(impulse_difference, std::abs(dense.impulses[k].impulse -
                                                                 sparse.impulses[k].impulse));
    }
  const double u_difference = (dense.u - sparse.u).cwiseAbs().maxCoeff() / dense.peak;
  const double v_difference =
    (dense.v - sparse.v).cwiseAbs().maxCoeff() / dense.v.cwiseAbs().maxCoeff();
  BOOST_TEST_MESSAGE("dense against sparse: u " << u_difference << ", v " << v_difference
                                                << ", impulses " << impulse_difference / impulse_scale);
  // the two solve the same equations with different factors of J: round-off
  // (1e-16 times J's condition) carried through Newton's tolerance 1e-10 on v
  BOOST_TEST(u_difference < 1e-9);
  BOOST_TEST(v_difference < 1e-9);
  BOOST_TEST(impulse_difference < 1e-9 * impulse_scale);
}

BOOST_AUTO_TEST_CASE(sparse_iteration_matrix_where_its_solves_are_cheaper)
{
  // the cost model's choice on two patterns whose factor is known in closed
  // form: a tridiagonal J of n equations factors without fill (n - 1 entries
  // in L: 12.9 (n - 1) < 2.6 n^2 from n = 4), a full one fills all of L
  // (n (n - 1) / 2 entries: 6.45 n^2 > 2.6 n^2 at every n)
  const auto tridiagonal = [](const int n) {
    SparseMatrix J(n, n);
    for (int i = 0; i < n; ++i)
      {
        J.insert(i, i) = 4;
        if (i > 0)
          J.insert(i, i - 1) = J.insert(i - 1, i) = -1;
      }
    return J;
  };
  BOOST_TEST(!MoreauJeanMatrix::sparse_solve_is_cheaper(tridiagonal(3)));
  BOOST_TEST(MoreauJeanMatrix::sparse_solve_is_cheaper(tridiagonal(4)));
  BOOST_TEST(MoreauJeanMatrix::sparse_solve_is_cheaper(tridiagonal(200)));
  const Eigen::MatrixXd full =
    Eigen::MatrixXd::Constant(30, 30, 1.0) + 30 * Eigen::MatrixXd::Identity(30, 30);
  BOOST_TEST(!MoreauJeanMatrix::sparse_solve_is_cheaper(full.sparseView()));
}
