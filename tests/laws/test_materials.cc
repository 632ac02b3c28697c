// The fibre materials (Steel01, Steel02, Concrete01, Concrete02, ElasticPP,
// Hysteretic) and Mander's confinement against independent references:
// closed-form branches and turning points worked out by hand, central
// finite differences of the stress, exact revert against a copy that never
// tried, the mirror symmetry of symmetric laws, the registry's refusals,
// and Mander's ultimate strength surface against the paper's closed form.
#include <poundfe/base/exceptions.h>
#include <poundfe/laws/concrete02.h>
#include <poundfe/laws/elastic_pp.h>
#include <poundfe/laws/hysteretic.h>
#include <poundfe/laws/mander_confinement.h>
#include <poundfe/laws/opensees_dead_bands.h>
#include <poundfe/laws/steel01.h>
#include <poundfe/laws/steel02.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

using namespace poundfe;

namespace
{
  // Reinforcing steel: fy = 400 MPa, E0 = 200 GPa, b = 0.01 (eps_y = 0.002).
  Steel01Parameters
  rebar01(const double a1 = 0)
  {
    return {400e6, 200e9, 0.01, a1, 1, a1, 1}; // isotropic hardening alike both ways
  }

  Steel02Parameters
  rebar02()
  {
    Steel02Parameters p;
    p.fy = 400e6;
    p.E0 = 200e9;
    p.b  = 0.01;
    return p;
  }

  // Concrete: fpc = -30 MPa at -0.002 (Ec0 = 30 GPa), -6 MPa at -0.006.
  Concrete01Parameters
  concrete_c30()
  {
    return {-30e6, -0.002, -6e6, -0.006};
  }

  Concrete02Parameters
  concrete_c30_tension()
  {
    Concrete02Parameters p;
    p.compression = concrete_c30();
    p.lambda      = 0.1;
    p.ft          = 3e6;
    p.Ets         = 3e9;
    return p;
  }

  HystereticParameters
  trilinear(const double pinch = 1, const double damage1 = 0, const double beta = 0)
  {
    HystereticParameters p;
    p.positive = {100, 0.01, 150, 0.05, 120, 0.1};
    p.negative = {-80, -0.01, -120, -0.04, -60, -0.1};
    p.pinchX = p.pinchY = pinch;
    p.damage1           = damage1;
    p.damage2           = damage1;
    p.beta              = beta;
    return p;
  }

  /// Set and commit each strain in turn; the stress of the last.
  double
  material_walk(UniaxialLaw &law, const std::vector<double> &strains)
  {
    for (const double e : strains)
      {
        BOOST_REQUIRE(law.set_trial(e, 0));
        law.commit();
      }
    return law.force();
  }

  /// Stress of a trial from the committed state (then reverted).
  double
  material_try(UniaxialLaw &law, const double strain)
  {
    BOOST_REQUIRE(law.set_trial(strain, 0));
    const double f = law.force();
    law.revert();
    return f;
  }

  /// Along a random committed strain walk in [low, high], the tangent of
  /// trials from each committed state against central differences of the
  /// stress with step h, where the two one-sided differences agree (a kink
  /// of a piecewise law within h is skipped). Returns the fraction checked.
  double
  material_tangent_check(UniaxialLaw &law, const double low, const double high,
                         const double modulus, const unsigned int seed)
  {
    std::mt19937                           random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    const double                           h = 1e-8 * (high - low);
    unsigned int                           checked = 0, tried = 0;
    double                                 e       = 0;
    for (unsigned int step = 0; step < 300; ++step)
      {
        for (unsigned int k = 0; k < 4; ++k)
          {
            const double x = low + (high - low) * unit(random);
            if (std::abs(x - e) < 10 * h)
              continue;
            ++tried;
            const double f0 = material_try(law, x), fp = material_try(law, x + h),
                         fm = material_try(law, x - h);
            if (std::abs((fp - f0) - (f0 - fm)) / h > 1e-4 * modulus)
              continue; // a kink within h
            BOOST_REQUIRE(law.set_trial(x, 0));
            const double tangent = law.tangent();
            law.revert();
            // round-off of the stresses over h: 1e-16 |sigma| / h, far below
            // 1e-6 E; truncation h^2 sigma''' / 6 likewise (see verification.md)
            BOOST_TEST(std::abs(tangent - (fp - fm) / (2 * h)) <= 1e-6 * modulus,
                       "strain " << x << " after " << e << ": tangent " << tangent
                                 << ", central difference " << (fp - fm) / (2 * h));
            ++checked;
          }
        // walk on: a few small steps, then a jump, within the range
        e = std::clamp(e + (high - low) * (unit(random) - 0.5) * (step % 7 == 0 ? 0.6 : 0.05),
                       low, high);
        BOOST_REQUIRE(law.set_trial(e, 0));
        law.commit();
      }
    return double(checked) / tried;
  }

  /// After committed states and rejected trials, revert() and a trial give
  /// bit for bit the stress and tangent of a copy that never tried.
  template <class Material>
  void
  material_revert_check(Material law, const std::vector<double> &committed,
                        const std::vector<double> &rejected, const double next)
  {
    material_walk(law, committed);
    Material     fresh    = law;
    const double stress_c = law.force(), tangent_c = law.tangent();
    for (const double e : rejected)
      BOOST_REQUIRE(law.set_trial(e, 0));
    law.revert();
    BOOST_TEST(law.force() == stress_c);
    BOOST_TEST(law.tangent() == tangent_c);
    BOOST_REQUIRE(law.set_trial(next, 0));
    BOOST_REQUIRE(fresh.set_trial(next, 0));
    BOOST_TEST(law.force() == fresh.force());
    BOOST_TEST(law.tangent() == fresh.tangent());
    law.commit();
    fresh.commit();
    for (const double e : rejected)
      {
        BOOST_REQUIRE(law.set_trial(e, 0));
        BOOST_REQUIRE(fresh.set_trial(e, 0));
        BOOST_TEST(law.force() == fresh.force());
        BOOST_TEST(law.tangent() == fresh.tangent());
      }
  }

  /// The InputError of make_material names `parameter`.
  void
  material_refused(const std::string &material, std::map<std::string, double> values,
                   const std::string &parameter)
  {
    try
      {
        make_material({material, std::move(values)});
        BOOST_ERROR(material << ": refusal of '" << parameter << "' expected");
      }
    catch (const InputError &error)
      {
        BOOST_TEST(error.parameter() == parameter, material << ": " << error.what());
      }
  }
} // namespace

BOOST_AUTO_TEST_CASE(steel01_branches_and_reversal)
{
  Steel01 steel(rebar01());
  // elastic slope, yield point, hardening slope
  BOOST_TEST(material_try(steel, 0.001) == 200e6, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(material_try(steel, 0.002) == 400e6, boost::test_tools::tolerance(1e-14));
  BOOST_REQUIRE(steel.set_trial(0.01, 0));
  BOOST_TEST(steel.force() == 400e6 + 2e9 * 0.008, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(steel.tangent() == 2e9, boost::test_tools::tolerance(1e-14));
  steel.commit();
  // unloading: elastic over the full range 2 fy (kinematic hardening) down
  // to the compression asymptote 2e9 eps - 396e6, met at eps = 0.006 where
  // sigma = -384 MPa
  BOOST_REQUIRE(steel.set_trial(0.0061, 0));
  BOOST_TEST(steel.force() == 416e6 - 200e9 * 0.0039, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(steel.tangent() == 200e9);
  BOOST_TEST(material_try(steel, 0.006) == -384e6, boost::test_tools::tolerance(1e-12));
  BOOST_REQUIRE(steel.set_trial(0.005, 0));
  BOOST_TEST(steel.force() == 2e9 * 0.005 - 396e6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(steel.tangent() == 2e9);
  // compression side symmetric from the virgin state
  Steel01 fresh(rebar01());
  BOOST_TEST(material_try(fresh, -0.01) == -416e6, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(steel01_isotropic_hardening_shifts_the_asymptote)
{
  // a1 = 0.5, a2 = 1: after loading to 0.01 the compression asymptote moves
  // out by s_n = 1 + 0.5 (0.01 / (2 x 0.002))^0.8 (from the step after the
  // reversal on, as OpenSees)
  Steel01      steel(rebar01(0.5));
  const double shift = 1 + 0.5 * std::pow(0.01 / 0.004, 0.8);
  material_walk(steel, {0.005, 0.01, 0.0099});
  BOOST_TEST(material_try(steel, -0.002) == 2e9 * -0.002 - 396e6 * shift,
             boost::test_tools::tolerance(1e-12));
  // without a1 the same path meets the unshifted asymptote
  Steel01 plain(rebar01());
  material_walk(plain, {0.005, 0.01, 0.0099});
  BOOST_TEST(material_try(plain, -0.002) == 2e9 * -0.002 - 396e6,
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(steel02_curve_asymptotes_and_reversal)
{
  Steel02 steel(rebar02());
  // first loading, R = R0 = 20: elastic at 0.2 eps_y, on the hardening
  // asymptote fy + b E0 (eps - eps_y) at 10 eps_y, and at eps_y the curve's
  // value fy (b + (1 - b) / 2^(1/20))
  BOOST_TEST(material_try(steel, 0.0004) == 80e6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(material_try(steel, 0.02) == 400e6 + 2e9 * 0.018, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(material_try(steel, 0.002) == 400e6 * (0.01 + 0.99 / std::pow(2.0, 0.05)),
             boost::test_tools::tolerance(1e-12));
  BOOST_REQUIRE(steel.set_trial(0.02, 0));
  BOOST_TEST(steel.tangent() == 2e9, boost::test_tools::tolerance(1e-9));
  steel.commit();
  // reversal at (0.02, sigma_r): the elastic line from it meets the
  // compression asymptote -fy + b E0 (eps + eps_y) at eps_0; the excursion
  // xi = |eps_pl - eps_0| / eps_y with eps_pl = -eps_y (the virgin minimum)
  // gives R; at eps_0 the curve is sigma_r + (b + (1 - b) / 2^(1/R)) (sigma_0 - sigma_r)
  const double sigma_r = steel.force();
  const double eps_0   = (-400e6 + 2e9 * 0.002 - sigma_r + 200e9 * 0.02) / (200e9 - 2e9);
  const double sigma_0 = -400e6 + 2e9 * (eps_0 + 0.002);
  const double xi      = std::abs(-0.002 - eps_0) / 0.002;
  const double R       = 20 * (1 - 0.925 * xi / (0.15 + xi));
  BOOST_REQUIRE(steel.set_trial(0.0199, 0));
  BOOST_TEST(steel.tangent() < 200e9);
  BOOST_TEST(steel.tangent() > 0.99 * 200e9); // elastic at the reversal
  BOOST_TEST(material_try(steel, eps_0) ==
               sigma_r + (0.01 + 0.99 / std::pow(2.0, 1 / R)) * (sigma_0 - sigma_r),
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(concrete01_envelope_values)
{
  Concrete01 c(concrete_c30());
  const std::vector<std::pair<double, double>> points{
    {-0.001, -22.5e6}, // parabola: fpc (2 eta - eta^2), eta = 0.5
    {-0.002, -30e6},   // peak
    {-0.004, -18e6},   // linear descent: -30 + (-6e9)(-0.002) MPa
    {-0.006, -6e6},    // crushing
    {-0.008, -6e6},    // residual
    {0.001, 0}};       // no tension
  // at a corner the branch beyond it holds, as OpenSees (the peak's
  // tangent is the descent's, the crushing point's is the residual's)
  const std::vector<double> tangents{15e9, -6e9, -6e9, 0, 0, 0};
  for (unsigned int i = 0; i < points.size(); ++i)
    {
      BOOST_REQUIRE(c.set_trial(points[i].first, 0));
      BOOST_TEST(c.force() == points[i].second, boost::test_tools::tolerance(1e-12));
      BOOST_TEST(std::abs(c.tangent() - tangents[i]) <= 1e-6 * 30e9);
      c.revert();
    }
  BOOST_TEST(c.initial_stiffness() == 30e9);
}

BOOST_AUTO_TEST_CASE(concrete01_unloading_from_the_peak_strain)
{
  // eps_min = -0.003 (sigma = -24 MPa, eta = 1.5): Karsan-Jirsa plastic
  // strain eps_p = epsc0 (0.145 eta^2 + 0.13 eta) = -0.0010425; the line to
  // it has slope 24e6 / 0.0019575 (< Ec0)
  Concrete01 c(concrete_c30());
  material_walk(c, {-0.001, -0.002, -0.003});
  const double slope = 24e6 / (0.003 - 0.0010425);
  BOOST_REQUIRE(c.set_trial(-0.002, 0));
  BOOST_TEST(c.force() == -24e6 + slope * 0.001, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(c.tangent() == slope, boost::test_tools::tolerance(1e-12));
  c.commit();
  BOOST_TEST(material_try(c, -0.0005) == 0); // past eps_p: open crack
  material_walk(c, {-0.0005, 0.001});
  // reloading: zero stress to eps_p, then the same line back to eps_min
  BOOST_TEST(material_try(c, -0.0010425 + 1e-6) == 0);
  BOOST_TEST(material_try(c, -0.0025) == -24e6 + slope * 0.0005,
             boost::test_tools::tolerance(1e-12));
  // past eps_min: the envelope again
  BOOST_TEST(material_try(c, -0.0035) == -21e6, boost::test_tools::tolerance(1e-12));

  // small eta: the line to eps_p would be steeper than Ec0, so the slope is Ec0
  Concrete01 early(concrete_c30());
  material_walk(early, {-0.0005});
  BOOST_REQUIRE(early.set_trial(-0.0004, 0));
  BOOST_TEST(early.tangent() == 30e9);
  BOOST_TEST(early.force() == -30e6 * (0.5 - 0.0625) + 30e9 * 1e-4,
             boost::test_tools::tolerance(1e-12));
  // beyond eta = 2 and beyond epscu (eta taken at epscu)
  for (const auto &[eps_min, sigma, eta] :
       {std::tuple{-0.005, -12e6, 2.5}, std::tuple{-0.008, -6e6, 3.0}})
    {
      Concrete01 far(concrete_c30());
      material_walk(far, {-0.002, eps_min});
      const double eps_p = -0.002 * (0.707 * (eta - 2) + 0.834);
      BOOST_REQUIRE(far.set_trial(eps_min + 1e-4, 0));
      BOOST_TEST(far.tangent() == sigma / (eps_min - eps_p), boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(concrete01_crushed_to_zero_strength)
{
  // fpcu = 0: beyond epscu the fibre carries nothing, its unloading line is
  // flat (slope 0 / (eps_min - eps_p)) and its stored energy 0, not 0/0
  Concrete01 c({-30e6, -0.002, 0, -0.006});
  material_walk(c, {-0.002, -0.004, -0.007});
  BOOST_TEST(c.force() == 0);
  BOOST_TEST(c.stored_energy() == 0);
  BOOST_TEST(material_try(c, -0.003) == 0);
  BOOST_TEST(material_try(c, -0.008) == 0);
  BOOST_REQUIRE(c.set_trial(-0.005, 0));
  BOOST_TEST(c.stored_energy() == 0);
}

BOOST_AUTO_TEST_CASE(concrete02_tension_softening_and_unloading)
{
  Concrete02 c(concrete_c30_tension());
  // tension: Ec0 eps to ft = 3 MPa at 1e-4, then 3e6 - 3e9 (eps - 1e-4) to
  // zero at 1.1e-3
  BOOST_TEST(material_try(c, 5e-5) == 1.5e6, boost::test_tools::tolerance(1e-12));
  BOOST_REQUIRE(c.set_trial(6e-4, 0));
  BOOST_TEST(c.force() == 1.5e6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(c.tangent() == -3e9);
  c.revert();
  BOOST_TEST(material_try(c, 2e-3) == 0);
  // compression as Concrete01
  BOOST_TEST(material_try(c, -0.004) == -18e6, boost::test_tools::tolerance(1e-12));

  // unloading from eps_min = -0.003 (sigma_m = -24 MPa): point R at
  // eps_R = (fpcu - lambda Ec0 epscu) / (Ec0 (1 - lambda)), the reloading
  // slope Er and zero-stress strain eps_t
  material_walk(c, {-0.001, -0.002, -0.003});
  const double eps_R = (-6e6 + 0.1 * 30e9 * 0.006) / (30e9 * 0.9);
  const double Er    = (-24e6 - 30e9 * eps_R) / (-0.003 - eps_R);
  const double eps_t = -0.003 + 24e6 / Er;
  BOOST_REQUIRE(c.set_trial(-0.0029, 0)); // elastic start of unloading
  BOOST_TEST(c.force() == -24e6 + 30e9 * 1e-4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(c.tangent() == 30e9);
  c.revert();
  BOOST_REQUIRE(c.set_trial(-0.0015, 0)); // bounded by the unloading curve
  BOOST_TEST(c.force() == 0.5 * Er * (-0.0015 - eps_t), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(c.tangent() == 0.5 * Er, boost::test_tools::tolerance(1e-12));
  c.revert();
  // across eps_t into tension: the tension envelope shifted by eps_t
  BOOST_TEST(material_try(c, eps_t + 5e-5) == 1.5e6, boost::test_tools::tolerance(1e-9));
  // after cracking to 6e-4 beyond eps_t, unloading follows the secant to
  // that point (1.5 MPa at 6e-4)
  material_walk(c, {eps_t + 6e-4});
  BOOST_TEST(material_try(c, eps_t + 3e-4) == 0.75e6, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(elastic_pp_yields_and_keeps_its_plastic_strain)
{
  ElasticPP m({200e9, 0.002, -0.001, 0});
  BOOST_TEST(material_try(m, 0.001) == 200e6, boost::test_tools::tolerance(1e-14));
  BOOST_REQUIRE(m.set_trial(0.003, 0));
  BOOST_TEST(m.force() == 400e6, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(m.tangent() == 0);
  m.commit();
  // plastic strain 0.001: unloading to 0.002 gives E (0.002 - 0.001)
  BOOST_TEST(material_try(m, 0.002) == 200e6, boost::test_tools::tolerance(1e-12));
  // compression yields at -E |epsyN| = -200 MPa
  BOOST_TEST(material_try(m, -0.0005) == -200e6, boost::test_tools::tolerance(1e-14));
  // the initial strain shifts the origin
  ElasticPP shifted({200e9, 0.002, 0, 0.0005});
  BOOST_TEST(material_try(shifted, 0.001) == 100e6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(material_try(shifted, -0.003) == -400e6, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(hysteretic_envelope_and_reloading)
{
  Hysteretic h(trilinear());
  // envelope points and the held residual
  BOOST_TEST(material_try(h, 0.005) == 50, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(material_try(h, 0.03) == 125, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(material_try(h, 0.08) == 132, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(material_try(h, 0.2) == 120, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(material_try(h, -0.02) == -80 - 40.0 / 0.03 * 0.01,
             boost::test_tools::tolerance(1e-12));
  // unloading from 0.03 at the largest positive slope 1e4
  material_walk(h, {0.03});
  BOOST_TEST(material_try(h, 0.02) == 25, boost::test_tools::tolerance(1e-12));
  // reloading towards (e1n, s1n) = (-0.01, -80) from the zero-stress strain
  // 0.03 - 125 / 1e4 = 0.0175 (no pinching)
  BOOST_TEST(material_try(h, 0.005) == -80 * 0.0125 / 0.0275, boost::test_tools::tolerance(1e-12));
  // at zero strain the negative envelope holds (the largest negative
  // excursion is still 0), as OpenSees
  BOOST_TEST(material_try(h, 0.0) == 0);

  // damage1 = 0.1: after -0.03 (mu - 1 = 2 on the negative side) the
  // positive target grows to 0.03 (1 + 0.2) = 0.036, s = 132.5; reloading
  // from the zero-stress strain -0.03 + 106.667 / 8000
  Hysteretic   damaged(trilinear(1, 0.1));
  const double sigma_n = -80 - 40.0 / 0.03 * 0.02;
  material_walk(damaged, {0.03, -0.03});
  BOOST_TEST(damaged.force() == sigma_n, boost::test_tools::tolerance(1e-12));
  const double zero = -0.03 - sigma_n / 8000;
  // damage2 also set: add its energy term by hand
  const double area = 0.5 * (0.01 * 100 + 0.04 * 250 + 0.05 * 270) +
                      0.5 * (0.01 * 80 + 0.03 * 200 + 0.06 * 180);
  const double energy_in = 0.5 * 125 * 0.03 + 0.5 * (125 + sigma_n) * -0.06;
  const double energy    = energy_in - 0.5 * sigma_n * sigma_n / 8000;
  const double target    = 0.03 * (1 + 0.1 * energy / area + 0.1 * 2);
  const double s_target  = 100 + 1250 * (target - 0.01);
  BOOST_TEST(material_try(damaged, 0.01) == s_target * (0.01 - zero) / (target - zero),
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(symmetric_materials_are_odd)
{
  // A symmetric law driven along -path gives -sigma: checks the negative
  // branches (Hysteretic's mirrored increments, Steel02's compression
  // reversal) against the positive ones.
  HystereticParameters hp = trilinear(0.5, 0.05, 0.3);
  hp.negative             = {-100, -0.01, -150, -0.05, -120, -0.1};
  Hysteretic a(hp), b(hp);
  Steel02    s(rebar02()), t(rebar02());
  Steel01    u(rebar01(0.3)), v(rebar01(0.3));
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> step(-0.02, 0.021);
  double                                 e = 0;
  for (unsigned int i = 0; i < 400; ++i)
    {
      e = std::clamp(e + step(random), -0.12, 0.12);
      for (auto [p, q, scale] : {std::tuple<UniaxialLaw *, UniaxialLaw *, double>{&a, &b, 1.0},
                                 {&s, &t, 0.2},
                                 {&u, &v, 0.2}})
        {
          BOOST_REQUIRE(p->set_trial(scale * e, 0));
          BOOST_REQUIRE(q->set_trial(-scale * e, 0));
          BOOST_TEST(p->force() == -q->force(), boost::test_tools::tolerance(1e-12));
          BOOST_TEST(p->tangent() == q->tangent(), boost::test_tools::tolerance(1e-12));
          p->commit();
          q->commit();
        }
    }
}

BOOST_AUTO_TEST_CASE(material_tangents_match_central_differences)
{
  // Random committed walks; h = 1e-8 of the strain range. The fraction of
  // trials checked (no kink within h) is reported and must be most of them.
  Steel01    s1(rebar01(0.2));
  Steel02    s2([] {
    Steel02Parameters p = rebar02();
    p.a1 = p.a3 = 0.1;
    return p;
  }());
  Concrete01 c1(concrete_c30());
  Concrete02 c2(concrete_c30_tension());
  ElasticPP  pp({200e9, 0.002, -0.001, 0.0002});
  Hysteretic hy(trilinear(0.6, 0.02, 0.4));
  const std::vector<std::tuple<const char *, UniaxialLaw *, double, double, double>> cases{
    {"Steel01", &s1, -0.02, 0.02, 200e9},        {"Steel02", &s2, -0.02, 0.02, 200e9},
    {"Concrete01", &c1, -0.008, 0.002, 30e9},    {"Concrete02", &c2, -0.008, 0.002, 30e9},
    {"ElasticPP", &pp, -0.005, 0.005, 200e9},    {"Hysteretic", &hy, -0.12, 0.12, 1e4}};
  unsigned int seed = 1;
  for (const auto &[name, law, low, high, modulus] : cases)
    {
      BOOST_TEST_CONTEXT(name)
      {
        const double fraction = material_tangent_check(*law, low, high, modulus, seed++);
        BOOST_TEST_MESSAGE(name << ": " << fraction << " of the trials away from a kink");
        BOOST_TEST(fraction > 0.8);
      }
    }
}

BOOST_AUTO_TEST_CASE(material_revert_restores_the_committed_state_exactly)
{
  const std::vector<double> steel{0.003, 0.01, 0.004, -0.006, -0.001};
  const std::vector<double> steel_trials{0.02, -0.03, 0.0011};
  material_revert_check(Steel01(rebar01(0.3)), steel, steel_trials, 0.002);
  material_revert_check(Steel02(rebar02()), steel, steel_trials, 0.002);
  material_revert_check(ElasticPP({200e9, 0.002, -0.001, 0}), steel, steel_trials, 0.002);
  const std::vector<double> concrete{-0.001, -0.003, -0.001, 0.0005, -0.002};
  const std::vector<double> concrete_trials{-0.007, 0.001, -0.0004};
  material_revert_check(Concrete01(concrete_c30()), concrete, concrete_trials, -0.0025);
  material_revert_check(Concrete02(concrete_c30_tension()), concrete, concrete_trials, -0.0025);
  material_revert_check(Hysteretic(trilinear(0.5, 0.05, 0.3)), {0.03, -0.02, 0.01, -0.05},
                        {0.09, -0.1, 0.0}, 0.02);
}

BOOST_AUTO_TEST_CASE(material_refuses_a_strain_that_is_not_finite)
{
  Steel02 steel(rebar02());
  material_walk(steel, {0.003});
  BOOST_TEST(!steel.set_trial(NAN, 0));
  BOOST_TEST(steel.failure().find("not all finite") != std::string::npos);
  steel.revert();
  BOOST_TEST(steel.force() == material_try(steel, 0.003));
  Concrete01 c(concrete_c30());
  BOOST_TEST(!c.set_trial(-INFINITY, 0));
}

BOOST_AUTO_TEST_CASE(registry_makes_every_material_by_name)
{
  const std::vector<std::string> names{"Steel01",    "Steel02",   "Concrete01",   "Concrete02",
                                       "ElasticPP",  "Hysteretic", "Elastic",     "ElasticPPGap",
                                       "ImpactMaterial", "Hertzdamp", "JankowskiImpact",
                                       "ViscoelasticGap", "Viscous", "BoucWen"};
  BOOST_TEST(material_names() == names, boost::test_tools::per_element());
  // defaults filled in: Steel02 by name behaves as Steel02 with OpenSees's
  // R0 = 20, cR1 = 0.925, cR2 = 0.15, a1 = a3 = 0, a2 = a4 = 1
  auto    by_name = make_material({"Steel02", {{"fy", 400e6}, {"E0", 200e9}, {"b", 0.01}}});
  Steel02 direct(rebar02());
  for (const double e : {0.001, 0.004, 0.02, 0.01, -0.01, 0.003})
    {
      BOOST_REQUIRE(by_name->set_trial(e, 0));
      BOOST_REQUIRE(direct.set_trial(e, 0));
      BOOST_TEST(by_name->force() == direct.force());
      by_name->commit();
      direct.commit();
    }
  auto hysteretic = make_material(
    {"Hysteretic", {{"s1p", 100}, {"e1p", 0.01}, {"s2p", 150}, {"e2p", 0.05}, {"s3p", 120},
                    {"e3p", 0.1}, {"s1n", -80}, {"e1n", -0.01}, {"s2n", -120}, {"e2n", -0.04},
                    {"s3n", -60}, {"e3n", -0.1}}});
  BOOST_TEST(hysteretic->initial_stiffness() == 1e4);
  // two points a side: the second becomes the third, the middle one halfway
  auto bilinear = make_material({"Hysteretic", {{"s1p", 100}, {"e1p", 0.01}, {"s2p", 120},
                                                {"e2p", 0.1}, {"s1n", -80}, {"e1n", -0.01},
                                                {"s2n", -60}, {"e2n", -0.1}}});
  Hysteretic three({{100, 0.01, 110, 0.055, 120, 0.1}, {-80, -0.01, -70, -0.055, -60, -0.1}});
  for (const double e : {0.03, 0.08, -0.05, 0.12, -0.11, 0.0})
    {
      BOOST_REQUIRE(bilinear->set_trial(e, 0));
      BOOST_REQUIRE(three.set_trial(e, 0));
      BOOST_TEST(bilinear->force() == three.force(), boost::test_tools::tolerance(1e-14));
      bilinear->commit();
      three.commit();
    }
  auto concrete = make_material(
    {"Concrete02",
     {{"fpc", -30e6}, {"epsc0", -0.002}, {"fpcu", -6e6}, {"epscu", -0.006}, {"ft", 3e6},
      {"Ets", 3e9}}});
  BOOST_TEST(material_try(*concrete, 6e-4) == 1.5e6, boost::test_tools::tolerance(1e-12));
  auto epp = make_material({"ElasticPP", {{"E", 200e9}, {"epsyP", 0.002}}});
  BOOST_TEST(material_try(*epp, -0.004) == -400e6, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(bad_parameters_are_refused_by_name)
{
  const std::map<std::string, double> steel{{"fy", 400e6}, {"E0", 200e9}, {"b", 0.01}};
  auto with = [](std::map<std::string, double> values, const std::string &key, const double v) {
    values[key] = v;
    return values;
  };
  for (const char *name : {"Steel01", "Steel02"})
    {
      material_refused(name, with(steel, "fy", -400e6), "fy");
      material_refused(name, with(steel, "E0", 0), "E0");
      material_refused(name, with(steel, "b", 1), "b");
      material_refused(name, with(steel, "b", -0.1), "b");
      material_refused(name, with(steel, "a2", 0), "a2");
      material_refused(name, with(steel, "fu", 500e6), "fu"); // not a parameter
      material_refused(name, {{"E0", 200e9}, {"b", 0.01}}, "fy"); // required
      material_refused(name, with(steel, "fy", NAN), "fy");
    }
  material_refused("Steel02", with(steel, "cR1", 1), "cR1");
  const std::map<std::string, double> concrete{
    {"fpc", -30e6}, {"epsc0", -0.002}, {"fpcu", -6e6}, {"epscu", -0.006}};
  const auto tension = with(with(concrete, "ft", 3e6), "Ets", 3e9);
  for (const auto &[name, values] :
       {std::pair{"Concrete01", concrete}, std::pair{"Concrete02", tension}})
    {
      material_refused(name, with(values, "fpcu", -40e6), "fpcu");  // |fpcu| > |fpc|
      material_refused(name, with(values, "epscu", -0.001), "epscu"); // |epscu| < |epsc0|
      material_refused(name, with(values, "epscu", -0.002), "epscu");
      material_refused(name, with(values, "fpc", 0), "fpc");
    }
  material_refused("Concrete02", with(tension, "lambda", 1), "lambda");
  material_refused("Concrete02", with(tension, "Ets", 0), "Ets");
  material_refused("Concrete02", with(tension, "ft", -1e6), "ft");
  material_refused("ElasticPP", {{"E", 200e9}, {"epsyP", -0.002}}, "epsyP");
  const std::map<std::string, double> hysteretic{
    {"s1p", 100}, {"e1p", 0.01}, {"s2p", 150}, {"e2p", 0.05}, {"s3p", 120}, {"e3p", 0.1},
    {"s1n", -80}, {"e1n", -0.01}, {"s2n", -120}, {"e2n", -0.04}, {"s3n", -60}, {"e3n", -0.1}};
  material_refused("Hysteretic", with(hysteretic, "e2p", 0.005), "e2p");
  material_refused("Hysteretic", with(hysteretic, "e3n", -0.03), "e3n");
  material_refused("Hysteretic", with(hysteretic, "pinchX", 1.5), "pinchX");
  material_refused("Hysteretic", with(hysteretic, "beta", -1), "beta");
  material_refused("Steel03", steel, "Material");
}

BOOST_AUTO_TEST_CASE(mander_surface_reproduces_the_closed_form)
{
  // Unconfined: the surface passes through uniaxial compression (the
  // meridians' six-digit constants: 4e-6).
  BOOST_TEST(mander_surface_ratio(0, 0) == 1.0, boost::test_tools::tolerance(1e-5));
  // Equal confinement lies on the compression meridian, where the paper's
  // eq. 29 is the surface's closed form: they agree to the constants'
  // rounding (measured 4e-5 at most).
  for (const double x : {0.02, 0.05, 0.1, 0.2, 0.3})
    BOOST_TEST(mander_surface_ratio(x, x) == mander_equal_confinement_ratio(x),
               boost::test_tools::tolerance(1e-4));
  // Unequal confinement lies between the equal cases of its two stresses,
  // and the order of the two does not matter.
  for (const auto &[a, b] : {std::pair{0.0, 0.1}, std::pair{0.05, 0.3}, std::pair{0.1, 0.2}})
    {
      const double k = mander_surface_ratio(a, b);
      BOOST_TEST(k > mander_equal_confinement_ratio(a));
      BOOST_TEST(k < mander_equal_confinement_ratio(b));
      BOOST_TEST(mander_surface_ratio(b, a) == k);
    }
}

BOOST_AUTO_TEST_CASE(mander_circular_column_by_hand)
{
  // Spiral 12 mm at 100 mm (clear 88 mm) on a 500 mm core, rho_cc = 0.02,
  // f'c0 = 30 MPa, fyh = 400 MPa, eps_su = 0.1, worked by hand:
  //   rho_s = 4 x 113.1e-6 / (0.5 x 0.1) = 0.009048
  //   ke    = (1 - 0.088 / 1.0) / 0.98 = 0.930612
  //   fl'   = ke rho_s fyh / 2 = 1.684036 MPa, fl'/f'c0 = 0.0561345
  //   K     = -1.254 + 2.254 sqrt(1 + 7.94 x 0.0561345) - 2 x 0.0561345 = 1.343887
  //   f'cc  = 40.3166 MPa, eps_cc = 0.002 (1 + 5 x 0.343887) = 0.00543887
  //   eps_cu = 0.004 + 1.4 x 0.009048 x 400e6 x 0.1 / 40.3166e6 = 0.0165677
  ManderCircularSection c;
  c.materials = {30e6, 0.002, 400e6, 0.1};
  c.ds        = 0.5;
  c.s         = 0.1;
  c.s_clear   = 0.088;
  c.Asp       = 113.1e-6;
  c.rho_cc    = 0.02;
  c.spiral    = true;
  const ManderConfinement m = mander_circular(c);
  BOOST_TEST(m.rho_s == 0.009048, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.ke == 0.930612, boost::test_tools::tolerance(1e-5));
  BOOST_TEST(m.fl_x == 1.684036e6, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(m.fcc == 40.3166e6, boost::test_tools::tolerance(1e-5));
  BOOST_TEST(m.eps_cc == 0.00543887, boost::test_tools::tolerance(1e-5));
  BOOST_TEST(m.eps_cu == 0.0165677, boost::test_tools::tolerance(1e-5));
  // circular hoops: the arching factor squared
  c.spiral = false;
  BOOST_TEST(mander_circular(c).ke == 0.912 * 0.912 / 0.98, boost::test_tools::tolerance(1e-12));

  // Concrete01 parameters: the peak of Mander's curve, and at eps_cu the
  // curve's stress; the curve peaks at (eps_cc, f'cc)
  const Concrete01Parameters q = mander_concrete01(m, 30e6);
  BOOST_TEST(q.fpc == -m.fcc);
  BOOST_TEST(q.epsc0 == -m.eps_cc);
  BOOST_TEST(q.epscu == -m.eps_cu);
  const double Ec = 5000e6 * std::sqrt(30.0);
  BOOST_TEST(mander_stress(m, Ec, m.eps_cc) == m.fcc, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(-q.fpcu == mander_stress(m, Ec, m.eps_cu), boost::test_tools::tolerance(1e-14));
  BOOST_TEST(-q.fpcu < m.fcc);
  Concrete01 core(q); // a valid Concrete01
  BOOST_TEST(material_try(core, -m.eps_cc) == -m.fcc, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(mander_rectangular_section_by_hand)
{
  // 400 x 600 mm core (bc = 0.4 along x, dc = 0.6 along y), hoops at 100 mm
  // (clear 90 mm), 4 legs of 10 mm along x and 3 along y, ten restrained
  // bars with clear spacings 4 x 0.12 and 6 x 0.17 m, rho_cc = 0.025:
  //   ke = (1 - (4 x 0.0144 + 6 x 0.0289) / (6 x 0.24)) (1 - 0.09/0.8) (1 - 0.09/1.2) / 0.975
  //   rho_x = 4 x 78.54e-6 / (0.1 x 0.6), rho_y = 3 x 78.54e-6 / (0.1 x 0.4)
  ManderRectangularSection r;
  r.materials = {35e6, 0.002, 420e6, 0.12};
  r.bc        = 0.4;
  r.dc        = 0.6;
  r.s         = 0.1;
  r.s_clear   = 0.09;
  r.Asx       = 4 * 78.54e-6;
  r.Asy       = 3 * 78.54e-6;
  r.rho_cc    = 0.025;
  r.w_clear   = {0.12, 0.12, 0.12, 0.12, 0.17, 0.17, 0.17, 0.17, 0.17, 0.17};
  const ManderConfinement m  = mander_rectangular(r);
  const double            ke = (1 - (4 * 0.0144 + 6 * 0.0289) / (6 * 0.24)) * (1 - 0.09 / 0.8) *
                    (1 - 0.09 / 1.2) / 0.975;
  const double rho_x = 4 * 78.54e-6 / 0.06, rho_y = 3 * 78.54e-6 / 0.04;
  BOOST_TEST(m.ke == ke, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.fl_x == ke * rho_x * 420e6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.fl_y == ke * rho_y * 420e6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.rho_s == rho_x + rho_y, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.fcc == 35e6 * mander_surface_ratio(m.fl_x / 35e6, m.fl_y / 35e6),
             boost::test_tools::tolerance(1e-12));
  // equal steel both ways (square core) gives the circular closed form
  r.bc = r.dc = 0.5;
  r.Asy       = r.Asx;
  const ManderConfinement sq = mander_rectangular(r);
  BOOST_TEST(sq.fl_x == sq.fl_y, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(sq.fcc / 35e6 == mander_equal_confinement_ratio(sq.fl_x / 35e6),
             boost::test_tools::tolerance(1e-4));
  // bad data named
  r.materials.fyh = -1;
  BOOST_CHECK_EXCEPTION(mander_rectangular(r), InputError,
                        [](const InputError &e) { return e.parameter() == "fyh"; });
}

BOOST_AUTO_TEST_CASE(hysteretic_pinching_and_unloading_stiffness)
{
  // pinchX = 0.5, pinchY = 0.3 after 0.03 -> -0.03 (no damage): reloading
  // from the zero-stress strain z = -0.03 + 106.667 / 8000 heads for the
  // pinching point, strain z + 0.5 (0.03 - 0.7 x 125 / 1e4 - z), stress
  // 0.3 x 125, then for (0.03, 125)
  HystereticParameters p = trilinear();
  p.pinchX               = 0.5;
  p.pinchY               = 0.3;
  Hysteretic   h(p);
  const double sigma_n = -80 - 40.0 / 0.03 * 0.02;
  material_walk(h, {0.03, -0.03});
  const double z       = -0.03 - sigma_n / 8000;
  const double pinched = z + 0.5 * (0.03 - 0.7 * 125 / 1e4 - z);
  BOOST_REQUIRE(h.set_trial(-0.005, 0));
  BOOST_TEST(h.force() == 37.5 * (-0.005 - z) / (pinched - z), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(h.tangent() == 37.5 / (pinched - z), boost::test_tools::tolerance(1e-12));
  h.revert();
  BOOST_REQUIRE(h.set_trial(0.02, 0));
  BOOST_TEST(h.force() == 37.5 + (0.02 - pinched) * 87.5 / (0.03 - pinched),
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(h.tangent() == 87.5 / (0.03 - pinched), boost::test_tools::tolerance(1e-12));
  h.revert();
  BOOST_TEST(material_try(h, z - 1e-4) == sigma_n + 8000 * (z - 1e-4 + 0.03),
             boost::test_tools::tolerance(1e-9)); // still unloading
  // beta = 0.5: unloading from 0.03 (mu = 3) at 1e4 / sqrt(3)
  Hysteretic soft(trilinear(1, 0, 0.5));
  material_walk(soft, {0.03});
  BOOST_REQUIRE(soft.set_trial(0.02, 0));
  BOOST_TEST(soft.force() == 125 - 1e4 / std::sqrt(3.0) * 0.01,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(soft.tangent() == 1e4 / std::sqrt(3.0), boost::test_tools::tolerance(1e-12));
  // with pinching as above, after -0.03 (mu = 3 both ways) both the
  // zero-stress strain and the pinching point use the degraded moduli
  p.beta = 0.5;
  Hysteretic degraded(p);
  material_walk(degraded, {0.03, -0.03});
  const double k       = std::sqrt(3.0);
  const double z_k     = -0.03 - sigma_n / (8000 / k);
  const double pinch_k = z_k + 0.5 * (0.03 - 0.7 * 125 / (1e4 / k) - z_k);
  BOOST_TEST(material_try(degraded, 0.0) == 37.5 * (0.0 - z_k) / (pinch_k - z_k),
             boost::test_tools::tolerance(1e-12));
}

// OpenSees's gap materials and Elastic (source/laws/gap_materials.cc), by
// hand from OpenSees 3.8's EPPGapMaterial, ImpactMaterial and
// ElasticMaterial sources.
namespace
{
  double
  gap_stress(UniaxialLaw &law, const double strain)
  {
    BOOST_REQUIRE(law.set_trial(strain, 0));
    return law.force();
  }
} // namespace

BOOST_AUTO_TEST_CASE(elastic_pp_gap_is_openSees_epp_gap)
{
  // compression gap: E 100, Fy -10, gap -0.1; elastic range [-0.2, -0.1]
  for (const bool damage : {false, true})
    {
      auto law = make_material(
        {"ElasticPPGap", {{"E", 100}, {"Fy", -10}, {"gap", -0.1}, {"damage", damage ? 1 : 0}}});
      BOOST_TEST(gap_stress(*law, -0.05) == 0);
      BOOST_TEST(gap_stress(*law, -0.15) == -5, boost::test_tools::tolerance(1e-12));
      BOOST_TEST(law->tangent() == 100);
      BOOST_TEST(gap_stress(*law, -0.3) == -10); // yielded: range [-0.3, -0.2]
      BOOST_TEST(law->tangent() == 0);
      law->commit();
      BOOST_TEST(gap_stress(*law, -0.15) == 0); // open: the gap grew
      law->commit(); // without damage the gap closes back to -0.15
      BOOST_TEST(gap_stress(*law, -0.2) == (damage ? 0.0 : -5.0),
                 boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(impact_material_is_openSees_impact_material)
{
  auto law = make_material({"ImpactMaterial", {{"K1", 100}, {"K2", 10}, {"Delta_y", -0.1},
                                               {"gap", -0.05}}});
  BOOST_TEST(gap_stress(*law, -0.02) == 0);
  // from the open committed state: sigma_c + K1 d eps = -10 lies past the
  // K2 line K1 Delta_y + K2 (eps - gap - Delta_y) = -9.5
  BOOST_TEST(gap_stress(*law, -0.1) == -9.5, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(law->tangent() == 10);
  law->commit();
  BOOST_TEST(gap_stress(*law, -0.08) == -7.5, boost::test_tools::tolerance(1e-12)); // unloading, K1
  BOOST_TEST(law->tangent() == 100);
  BOOST_TEST(gap_stress(*law, -0.1) == -9.5, boost::test_tools::tolerance(1e-12)); // no step: kept
  BOOST_TEST(gap_stress(*law, -0.04) == 0);
}

BOOST_AUTO_TEST_CASE(elastic_is_openSees_elastic_with_eta_and_eneg)
{
  auto law = make_material({"Elastic", {{"E", 5}, {"eta", 2}, {"Eneg", 1}}});
  BOOST_REQUIRE(law->set_trial(0.5, 3));
  BOOST_TEST(law->force() == 8.5);
  BOOST_TEST(law->tangent() == 5);
  BOOST_TEST(law->damping_tangent() == 2);
  BOOST_REQUIRE(law->set_trial(-0.5, 0));
  BOOST_TEST(law->force() == -0.5);
  auto symmetric = make_material({"Elastic", {{"E", 5}}});
  BOOST_REQUIRE(symmetric->set_trial(-0.5, 0));
  BOOST_TEST(symmetric->force() == -2.5);
}

BOOST_AUTO_TEST_CASE(opensees_dead_bands_only_when_asked)
{
  // the rules of OpenSees 3.8's setTrialStrain (Concrete01, Concrete02,
  // Steel02) for a strain change below DBL_EPSILON (Steel02: 10 DBL_EPSILON
  // from a virgin state), and poundfe's laws without the entry
  const auto banded = [](const std::string &name, std::map<std::string, double> values) {
    values[opensees_dead_band_entry] = 1;
    return make_material({name, std::move(values)});
  };
  const std::map<std::string, double> c01{
    {"fpc", -30e6}, {"epsc0", -0.002}, {"fpcu", -6e6}, {"epscu", -0.005}};
  // Concrete01 stretched by 1e-17 from the virgin state: its committed
  // tangent Ec0 = 2 fpc / epsc0 in the band, tension's 0 without it
  auto with = banded("Concrete01", c01), without = make_material({"Concrete01", c01});
  BOOST_REQUIRE(with->set_trial(1e-17, 0) && without->set_trial(1e-17, 0));
  BOOST_TEST(with->tangent() == 3e10);
  BOOST_TEST(without->tangent() == 0);
  // Concrete02: a trial in the band keeps the stress and tangent of the last
  // trial (here -0.001, not committed); after a revert, the committed ones
  std::map<std::string, double> c02 = c01;
  c02.insert({{"lambda", 0.1}, {"ft", 3e6}, {"Ets", 1.5e9}});
  auto concrete02 = banded("Concrete02", c02);
  BOOST_REQUIRE(concrete02->set_trial(-0.001, 0));
  const double stress = concrete02->force(), tangent = concrete02->tangent();
  BOOST_TEST(stress < 0);
  BOOST_REQUIRE(concrete02->set_trial(1e-17, 0));
  BOOST_TEST(concrete02->force() == stress);
  BOOST_TEST(concrete02->tangent() == tangent);
  concrete02->revert();
  BOOST_REQUIRE(concrete02->set_trial(1e-17, 0));
  BOOST_TEST(concrete02->force() == 0);
  // Steel02 given 1e-15 from the virgin state: virgin (stress 0, E0) in the
  // band, on its curve (E0 1e-15) without it
  const std::map<std::string, double> s02{{"fy", 450e6}, {"E0", 2e11}, {"b", 0.01}};
  auto steel = banded("Steel02", s02), plain_steel = make_material({"Steel02", s02});
  BOOST_REQUIRE(steel->set_trial(1e-15, 0) && plain_steel->set_trial(1e-15, 0));
  BOOST_TEST(steel->force() == 0);
  BOOST_TEST(steel->tangent() == 2e11);
  BOOST_TEST(plain_steel->force() == 2e11 * 1e-15, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(hysteretic_opensees_dead_band_only_when_asked)
{
  // OpenSees 3.8's HystereticMaterial::setTrialStrain: a change below
  // DBL_EPSILON from the committed strain keeps the committed history with
  // the last trial's stress and tangent; poundfe's law without the entry
  // takes it as a step
  Hysteretic banded(trilinear(), true), plain(trilinear());
  for (Hysteretic *h : {&banded, &plain})
    {
      BOOST_REQUIRE(h->set_trial(0.02, 0)); // on the hardening branch
      h->commit();
    }
  const double hardening = banded.tangent(), stress = banded.force();
  BOOST_REQUIRE(banded.set_trial(0.02 - 1e-17, 0) && plain.set_trial(0.02 - 1e-17, 0));
  BOOST_TEST(banded.tangent() == hardening);
  BOOST_TEST(banded.force() == stress);
  BOOST_TEST(plain.tangent() > 2 * hardening); // unloading
  // the last trial's stress and tangent, not the committed ones
  BOOST_REQUIRE(banded.set_trial(0.015, 0));
  const double unloaded = banded.force(), unloading = banded.tangent();
  BOOST_REQUIRE(banded.set_trial(0.02 - 1e-17, 0));
  BOOST_TEST(banded.force() == unloaded);
  BOOST_TEST(banded.tangent() == unloading);
  banded.revert();
  BOOST_REQUIRE(banded.set_trial(0.02 - 1e-17, 0));
  BOOST_TEST(banded.force() == stress);
  // but the tangent the reverted trial left: OpenSees's revertToLastCommit
  // keeps Ttangent (a step retried after a failure starts from it)
  BOOST_TEST(banded.tangent() == unloading);
  // a reset forgets it: the virgin modulus
  banded.reset();
  BOOST_REQUIRE(banded.set_trial(1e-17, 0));
  BOOST_TEST(banded.tangent() == banded.initial_stiffness());
  // from the virgin state: back at strain 0 after a trial at 0.001, the
  // stress of that trial stays (OpenSees's TloadIndicator is then 1)
  Hysteretic virgin(trilinear(), true);
  BOOST_REQUIRE(virgin.set_trial(0.001, 0));
  const double first = virgin.force();
  BOOST_REQUIRE(virgin.set_trial(0, 0));
  BOOST_TEST(virgin.force() == first);
  BOOST_TEST(first > 0);
}
