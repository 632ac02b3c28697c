// The plan contact element (elements/plan_contact_element.h): its tangent
// against central differences of its force, an eccentric collision of two
// free rigid slabs that conserves linear and angular momentum, and the work
// of an undamped law against its stored energy (doc/verification.md,
// "Contact work of an undamped law").
#include <poundfe/elements/plan_contact_element.h>

#include <boost/test/unit_test.hpp>

using namespace poundfe;

namespace
{
  /// Floor 1 (centre (0, 0), 10 x 8) and floor 2 (centre (10.2, 3), 10 x 8):
  /// floor 1's east edge faces floor 2's west edge 0.2 m away; they overlap
  /// along y on [-1, 4] only, so the hit is eccentric for both.
  PlanContactGeometry
  offset_slabs(const unsigned int end)
  {
    PlanContactGeometry g;
    g.edges   = {{{{{5, -4}, {5, 4}}}, {{{5.2, 7}, {5.2, -1}}}}};
    g.centres = {{{0, 0}, {10.2, 3}}};
    g.end     = end;
    return g;
  }

  std::unique_ptr<ContactLaw>
  kelvin_voigt()
  {
    ContactLawParameters p;
    p.law            = "kelvin-voigt";
    p.stiffness      = 1e8;
    p.damping        = 0.1;
    p.effective_mass = 5e4;
    return make_contact_law(p);
  }

  PlanContactElement
  element(const unsigned int end, std::unique_ptr<ContactLaw> law = kelvin_voigt())
  {
    return PlanContactElement(0, "test", {0, 1, 2, 3, 4, 5}, offset_slabs(end), std::move(law));
  }

  /// The linear law, undamped: elastic, F = k δ.
  std::unique_ptr<ContactLaw>
  undamped_linear()
  {
    ContactLawParameters p;
    p.law            = "linear";
    p.stiffness      = 1e8;
    p.effective_mass = 5e4;
    return make_contact_law(p);
  }

  Vector6
  force(PlanContactElement &e, const Vector6 &u, const Vector6 &v)
  {
    BOOST_REQUIRE(e.set_trial(u, v));
    Vector6 f;
    e.force_correction(f);
    return f;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(plan_contact_element)

BOOST_AUTO_TEST_CASE(tangent_matches_central_differences)
{
  // closed by 10-30 mm at a turned state, approaching: force, stiffness and
  // damping all act. D(c) = df/du + c df/dv; h = 1e-8 m against forces of
  // 1e5..1e6 N: the central-difference error is ~1e-6 relative.
  for (const unsigned int end : {0u, 1u})
    {
      PlanContactElement e = element(end);
      const Vector6 u(0.22, 0.01, 0.002, 0.0, -0.02, -0.001);
      const Vector6 v(0.3, 0.05, 0.01, -0.2, 0.0, -0.02);
      const double  c = 4 / 0.01 / 1.0; // gamma / (beta dt) for dt = 0.01 s
      BOOST_REQUIRE(e.set_trial(u, v));
      BOOST_REQUIRE(e.is_active());
      Eigen::MatrixXd d(6, 6);
      e.tangent_change(c, d);
      Eigen::MatrixXd fd(6, 6);
      const double    h = 1e-8;
      for (unsigned int j = 0; j < 6; ++j)
        {
          Vector6 up = u, um = u, vp = v, vm = v;
          up[j] += h;
          um[j] -= h;
          vp[j] += h;
          vm[j] -= h;
          fd.col(j) = (force(e, up, v) - force(e, um, v)) / (2 * h) +
                      c * (force(e, u, vp) - force(e, u, vm)) / (2 * h);
        }
      BOOST_TEST((fd - d).norm() / d.norm() < 1e-6);
    }
}

BOOST_AUTO_TEST_CASE(eccentric_collision_conserves_momenta)
{
  // Two free slabs, floor 1 moving east and turning; symplectic Euler with
  // the contact force at the configuration of the kick: every kick changes
  // the linear momentum by F - F = 0 and the angular momentum about the
  // origin by (x_c - c1) x F + c1 x F - (x_c - c2) x F - c2 x F = 0, every
  // drift leaves m c x v unchanged; so both are conserved to round-off.
  const double m1 = 6e4, m2 = 4e4, i1 = m1 * (100 + 64) / 12.0, i2 = m2 * (100 + 64) / 12.0;
  const Vector6 mass(m1, m1, i1, m2, m2, i2);
  std::array<PlanContactElement, 2> ends{{element(0), element(1)}};
  Vector6 u = Vector6::Zero(), v(1.0, 0.1, 0.02, -0.2, 0.0, 0.0);
  auto    momenta = [&]() {
    const double c1x = u[0], c1y = u[1], c2x = 10.2 + u[3], c2y = 3 + u[4];
    return Eigen::Vector3d(m1 * v[0] + m2 * v[3], m1 * v[1] + m2 * v[4],
                           i1 * v[2] + i2 * v[5] + m1 * (c1x * v[1] - c1y * v[0]) +
                             m2 * (c2x * v[4] - c2y * v[3]));
  };
  const Eigen::Vector3d before = momenta();
  const double          dt     = 1e-4;
  bool                  hit    = false;
  double                twist  = 0;
  for (unsigned int step = 0; step < 8000; ++step)
    {
      Vector6 f = Vector6::Zero();
      for (PlanContactElement &e : ends)
        {
          BOOST_REQUIRE(e.set_trial(u, v));
          Vector6 fe;
          e.force_correction(fe);
          f += fe;
          hit = hit || e.is_active();
          e.commit();
        }
      v -= dt * f.cwiseQuotient(mass);
      u += dt * v;
      twist = std::max(twist, std::abs(v[5]));
    }
  const Eigen::Vector3d after = momenta();
  BOOST_TEST(hit);
  BOOST_TEST(v[0] < v[3]); // floor 1 bounced back relative to floor 2
  BOOST_TEST(twist > 1e-3); // the eccentric hit set floor 2 turning
  BOOST_TEST(std::abs(after[0] - before[0]) < 1e-12 * m1);
  BOOST_TEST(std::abs(after[1] - before[1]) < 1e-12 * m1);
  BOOST_TEST(std::abs(after[2] - before[2]) < 1e-10 * std::abs(before[2]) + 1e-9 * i1);
}

BOOST_AUTO_TEST_CASE(undamped_work_is_the_stored_energy_unless_a_step_spans_the_touch)
{
  // Floor 1 pressed east into floor 2 while both turn (the normal turns with
  // them), in 400 steps that stay in contact: the trapezoidal work
  // Σ (F_n + F_n+1)/2 (δ_n+1 - δ_n) of F = k δ is exact, so the work done
  // equals the stored energy k δ²/2 to round-off: nothing is dissipated.
  // A step from open (δ_0 < 0) to closed (δ_1 > 0) counts (F_1/2)(δ_1 - δ_0),
  // F_1 |δ_0| / 2 more than the spring stores: the kink of the law inside
  // the step, which is the whole residue of an undamped contact in a run
  // (the integrator's trapezoid, which the energy balance shares).
  PlanContactElement e = element(0, undamped_linear());
  const Vector6      v = Vector6::Zero();
  const auto at = [](const double s) { // closed by 1-11 mm, turning
    return Vector6(0.201 + 0.01 * s, 0.02 * s, 5e-4 * s, -0.001 * s, 0.0, -3e-4 * s);
  };
  BOOST_REQUIRE(e.set_trial(at(0), v));
  BOOST_REQUIRE(e.is_active());
  e.commit();
  const double stored_at_start = e.stored_energy();
  double       work            = stored_at_start;
  for (unsigned int n = 1; n <= 400; ++n)
    {
      BOOST_REQUIRE(e.set_trial(at(n / 400.0), v));
      work += e.work_increment();
      e.commit();
    }
  BOOST_TEST(e.is_active());
  BOOST_TEST(std::abs(work - e.stored_energy()) <= 1e-9 * e.stored_energy());

  PlanContactElement touch = element(0, undamped_linear());
  BOOST_REQUIRE(touch.set_trial(Vector6(0.199, 0, 0, 0, 0, 0), v)); // open by 1 mm
  touch.commit();
  const double delta_0 = touch.history_variable();
  BOOST_REQUIRE(touch.set_trial(Vector6(0.203, 0, 0, 0, 0, 0), v)); // closed by 3 mm
  BOOST_TEST(delta_0 == -1e-3, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(touch.work_increment() - touch.stored_energy() ==
               0.5 * touch.force() * -delta_0, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_SUITE_END()
