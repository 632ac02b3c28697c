// Two horizontal components of a stochastic ground motion (Penzien & Watabe
// 1975; doc/theory.md, "Two correlated horizontal components"): the sample
// covariance of (a_x, a_y) that a 3D model's excitation applies, over an
// ensemble of Kanai-Tajimi samples, against the closed form
//   C_a = R(alpha) sigma^2 [[1, rho gamma], [rho gamma, gamma^2]] R(alpha)^T.
// The excitation is read through its load on a two-equation system with
// M = I, r_x = (1, 0), r_y = (0, 1): p = -(a_x, a_y).
#include <poundfe/excitation/excitation.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/excitation/stochastic_load.h>
#include <poundfe/model/model.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

using namespace poundfe;

namespace
{
  struct PairStatistics
  {
    double variance_ratio = 0; // Var a_y / Var a_x
    double correlation    = 0; // of a_x and a_y
    double principal_angle = 0; // of the sample covariance, rad, in (-pi/2, pi/2]
  };

  /// The sample moments of (a_x, a_y) over realizations 0..n-1, pooled over
  /// instants 0.5 s apart (several correlation times of the filter).
  PairStatistics
  sample_pair(const double ratio, const double correlation, const double angle)
  {
    StochasticMotion motion;
    motion.method             = StochasticMethod::spectral_representation;
    motion.filter             = soil_preset(Soil::firm, false);
    motion.spectral_intensity = 0.01;
    motion.duration           = 20;
    motion.sample_interval    = 0.02;
    motion.cutoff_frequency   = 100;
    LinearSystem system;
    system.mass.resize(2, 2);
    system.mass.setIdentity();
    system.influence   = Eigen::Vector2d(1, 0);
    system.influence_y = Eigen::Vector2d(0, 1);
    double sxx = 0, syy = 0, sxy = 0;
    Vector load(2);
    for (unsigned int r = 0; r < 300; ++r)
      {
        motion.seed        = 11;
        motion.realization = r;
        GroundMotion first = generate_ground_motion(motion);
        motion.seed         = 12;
        GroundMotion second = generate_ground_motion(motion);
        correlate_second_component(first.samples(), second.samples_for_update(), ratio,
                                   correlation);
        Excitation excitation(system, std::move(first), {});
        excitation.set_horizontal_pair(system, std::move(second), angle);
        for (double t = 1; t < 19; t += 0.5)
          {
            excitation.load(t, load);
            sxx += load[0] * load[0];
            syy += load[1] * load[1];
            sxy += load[0] * load[1];
          }
      }
    return {syy / sxx, sxy / std::sqrt(sxx * syy), 0.5 * std::atan2(2 * sxy, sxx - syy)};
  }

  /// The closed form of the same three numbers.
  PairStatistics
  closed_form(const double ratio, const double correlation, const double angle)
  {
    const double c = std::cos(angle), s = std::sin(angle);
    const double g11 = 1, g12 = correlation * ratio, g22 = ratio * ratio;
    // C_a = R C_g R^T with R = [[c, -s], [s, c]]
    const double xx = c * c * g11 - 2 * c * s * g12 + s * s * g22;
    const double yy = s * s * g11 + 2 * c * s * g12 + c * c * g22;
    const double xy = c * s * (g11 - g22) + (c * c - s * s) * g12;
    return {yy / xx, xy / std::sqrt(xx * yy), 0.5 * std::atan2(2 * xy, xx - yy)};
  }
} // namespace

// Sampling error: about 10 800 pooled pairs, nearly independent (the firm
// soil's filter forgets in ~1/(zeta_g omega_g) = 0.11 s << 0.5 s); the
// standard error of a correlation coefficient is (1 - r^2)/sqrt(n) < 0.01
// and that of a variance ratio about 2/sqrt(n) ~ 0.02 relative: the
// tolerances are about four of them.
BOOST_AUTO_TEST_CASE(pair_covariance_matches_penzien_watabe)
{
  struct Case
  {
    double ratio, correlation, angle_degrees;
  };
  for (const Case &c : {Case{1, 0, 0}, Case{0.5, 0, 30}, Case{0.6, 0.4, 30}, Case{1, -0.7, 0},
                        Case{0.8, 0.9, -60}})
    {
      const double         angle    = c.angle_degrees * M_PI / 180;
      const PairStatistics sample   = sample_pair(c.ratio, c.correlation, angle);
      const PairStatistics expected = closed_form(c.ratio, c.correlation, angle);
      BOOST_TEST_MESSAGE("gamma " << c.ratio << " rho " << c.correlation << " alpha "
                                  << c.angle_degrees << ": variance ratio " << sample.variance_ratio
                                  << " (closed form " << expected.variance_ratio
                                  << "), correlation " << sample.correlation << " ("
                                  << expected.correlation << "), principal angle "
                                  << sample.principal_angle * 180 / M_PI << " deg ("
                                  << expected.principal_angle * 180 / M_PI << ")");
      BOOST_TEST(std::abs(sample.variance_ratio / expected.variance_ratio - 1) < 0.08);
      BOOST_TEST(std::abs(sample.correlation - expected.correlation) < 0.04);
      // the principal axes: where the rotated pair is uncorrelated (defined
      // only when the two principal variances differ)
      if (std::abs(c.ratio - 1) > 0.1 || c.correlation != 0)
        BOOST_TEST(std::abs(sample.principal_angle - expected.principal_angle) < 3 * M_PI / 180);
    }
}

// The independent, equal pair (gamma = 1, rho = 0) is left bit for bit as
// generated, so every existing 3D input keeps its numbers.
BOOST_AUTO_TEST_CASE(independent_equal_pair_is_unchanged)
{
  const std::vector<double> first{1.0, -2.0, 3.5};
  std::vector<double>       second{0.25, 4.0, -1.0};
  const std::vector<double> kept = second;
  correlate_second_component(first, second, 1, 0);
  BOOST_TEST(second == kept, boost::test_tools::per_element());
  correlate_second_component(first, second, 0.5, 1); // fully correlated: gamma g_1
  for (unsigned int k = 0; k < 3; ++k)
    BOOST_TEST(second[k] == 0.5 * first[k]);
}

// The vertical component of a stochastic motion (Components = 3; theory
// §1.12, "The vertical component"): a_z = gamma_v z_3, z_3 an independent
// sample of the same process from (Vertical seed, realization). Over 300
// realizations drawn as Monte Carlo draws them (StochasticLoad), pooled
// every 0.5 s as above: Var a_z / Var a_x = gamma_v^2 and corr(a_x, a_z) =
// 0, with the same tolerances (about four standard errors); and realization
// 0 of StochasticLoad is the motion a run makes (make_excitation's path:
// make_ground_motion, add_vertical_component), to 1e-12.
BOOST_AUTO_TEST_CASE(vertical_component_has_the_vertical_ratio)
{
  GroundMotionParameters g;
  g.type               = GroundMotionType::kanai_tajimi;
  g.soil               = Soil::firm;
  g.method             = StochasticMethod::spectral_representation;
  g.cutoff_frequency   = 100;
  g.spectral_intensity = 0.01;
  g.duration           = 20;
  g.sample_interval    = 0.02;
  g.envelope           = EnvelopeKind::none;
  g.seed               = 11;
  g.n_components       = 3;
  g.vertical_ratio     = 0.6;
  LinearSystem system;
  system.mass.resize(2, 2);
  system.mass.setIdentity();
  system.influence   = Eigen::Vector2d(1, 0);
  system.influence_z = Eigen::Vector2d(0, 1);
  const InputFile input;
  const Model     model; // frames only: no shear building to refuse it
  Excitation      run(system, make_ground_motion(g, input, g.sample_interval), {});
  add_vertical_component(run, system, model, g, input, g.sample_interval);
  BOOST_REQUIRE(run.has_vertical());

  Excitation           drawn = run;
  const StochasticLoad load(g, g.sample_interval, drawn);
  std::vector<double>  xi;
  Vector               p(2), q(2);
  double               sxx = 0, szz = 0, sxz = 0, worst = 0;
  for (unsigned int r = 0; r < 300; ++r)
    {
      load.standard_normals(r, xi);
      load.apply(xi, drawn);
      for (double t = 1; t < 19; t += 0.5)
        {
          drawn.load(t, p);
          sxx += p[0] * p[0];
          szz += p[1] * p[1];
          sxz += p[0] * p[1];
          if (r == 0)
            {
              run.load(t, q);
              worst = std::max(worst, (p - q).cwiseAbs().maxCoeff() / q.cwiseAbs().maxCoeff());
            }
        }
    }
  const double ratio = szz / sxx, correlation = sxz / std::sqrt(sxx * szz);
  BOOST_TEST_MESSAGE("vertical component: variance ratio " << ratio << " (gamma_v^2 = 0.36), "
                                                          << "correlation " << correlation
                                                          << ", realization 0 against the run "
                                                          << worst);
  BOOST_TEST(std::abs(ratio / 0.36 - 1) < 0.08);
  BOOST_TEST(std::abs(correlation) < 0.04);
  BOOST_TEST(worst <= 1e-12);
}
