// Multiple-stripe and cloud analysis (assessment/msa.h):
//  - the binomial maximum-likelihood fit of stripes (Baker 2015, eq. 11):
//    on stripes whose counts are the expected ones of a lognormal fragility
//    (theta = 0.8, beta = 0.4, 10^6 runs a stripe, rounded) it recovers
//    theta and beta within 1e-3 (the rounding of the counts); on a small
//    set of stripes (Baker 2015's situation: 40 records a stripe) the fit
//    is the maximum of the likelihood written out here (eq. 11): no point
//    of a dense (theta, beta) grid around it is more likely (1e-9);
//  - the cloud: exact power-law data give the slope and constant to 1e-12
//    and no dispersion; residuals +/- e give the dispersion
//    sqrt(n e^2 / (n - 2)) (the closed form);
//  - the annual rate of exceedance on a power-law hazard lambda = k0 x^-k
//    against the closed form k0 theta^-k exp(k^2 beta^2 / 2) (Cornell et
//    al. 2002): 1e-4 relative (the curve's range holds all but ~1e-12 of
//    the integral; the trapezoid's error on 64 parts an interval is ~1e-6);
//  - a hazard curve's intensity at a return period reads back its rate.
#include <poundfe/assessment/msa.h>
#include <poundfe/base/standard_normal.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;

namespace
{
  /// Baker's (2015) eq. 11 written out: the binomial log-likelihood.
  double
  binomial_log_likelihood(const std::vector<StripeCount> &stripes, const double theta,
                          const double beta)
  {
    double sum = 0;
    for (const StripeCount &s : stripes)
      {
        const double p = standard_normal_cdf(std::log(s.intensity / theta) / beta);
        sum += s.exceeded * std::log(p) + (s.runs - s.exceeded) * std::log(1 - p);
      }
    return sum;
  }
} // namespace

BOOST_AUTO_TEST_CASE(binomial_fit_recovers_a_lognormal_fragility)
{
  std::vector<StripeCount> stripes;
  for (const double x : {0.2, 0.4, 0.6, 0.8, 1.0, 1.3, 1.7})
    {
      const unsigned int n = 1000000;
      const double       p = standard_normal_cdf(std::log(x / 0.8) / 0.4);
      stripes.push_back({x, n, static_cast<unsigned int>(std::round(n * p))});
    }
  const LognormalFragility fit = fit_stripe_fragility(stripes);
  BOOST_REQUIRE(fit.fitted);
  BOOST_TEST(fit.theta == 0.8, boost::test_tools::tolerance(1e-3));
  BOOST_TEST(fit.beta == 0.4, boost::test_tools::tolerance(1e-3));
}

BOOST_AUTO_TEST_CASE(binomial_fit_is_the_likelihood_maximum)
{
  // 40 records a stripe, counts of collapse growing with the intensity
  const std::vector<StripeCount> stripes{{0.2, 40, 0}, {0.4, 40, 2},  {0.6, 40, 7},
                                         {0.8, 40, 15}, {1.0, 40, 22}, {1.2, 40, 30},
                                         {1.5, 40, 36}};
  const LognormalFragility fit = fit_stripe_fragility(stripes);
  BOOST_REQUIRE(fit.fitted);
  const double best = binomial_log_likelihood(stripes, fit.theta, fit.beta);
  for (int i = -50; i <= 50; ++i)
    for (int j = -50; j <= 50; ++j)
      {
        const double theta = fit.theta * std::exp(0.004 * i), beta = fit.beta * std::exp(0.004 * j);
        BOOST_TEST(binomial_log_likelihood(stripes, theta, beta) <= best + 1e-9);
      }
}

// Baker's (2015) worked example of a multiple-stripe analysis, as his
// fragility-fitting script gives it (illustrate_msa_fits.m, "Created by Jack
// Baker 2/4/2013", in the copy of his example_msa_code kept in the
// repository vacalderon/NLTHA_ConditionDependentPBEE,
// DataPlotter/FragilityFunction/, commit dd46700): eight IM levels, 40
// ground motions each, the collapses counted at each. The script prints no
// fit and the paper's own numbers were not at hand; the reference is the
// maximum of eq. 11 found independently by a grid refined around its best
// point (pure Python, 40 refinements: theta = 1.076116, beta = 0.429237, ln L
// = -107.899826), which the Nelder-Mead fit must reach within 1e-4.
BOOST_AUTO_TEST_CASE(binomial_fit_of_bakers_worked_example)
{
  const std::vector<double>       im{0.2, 0.3, 0.4, 0.6, 0.7, 0.8, 0.9, 1.0};
  const std::vector<unsigned int> collapses{0, 0, 0, 4, 6, 13, 12, 16};
  std::vector<StripeCount>        stripes;
  for (std::size_t j = 0; j < im.size(); ++j)
    stripes.push_back({im[j], 40, collapses[j]});
  const LognormalFragility fit = fit_stripe_fragility(stripes);
  BOOST_REQUIRE(fit.fitted);
  BOOST_TEST(fit.theta == 1.076116, boost::test_tools::tolerance(1e-4));
  BOOST_TEST(fit.beta == 0.429237, boost::test_tools::tolerance(1e-4));
  BOOST_TEST(binomial_log_likelihood(stripes, fit.theta, fit.beta) == -107.899826,
             boost::test_tools::tolerance(1e-7));
}

BOOST_AUTO_TEST_CASE(binomial_fit_without_exceedance_is_no_fit)
{
  BOOST_TEST(!fit_stripe_fragility({{0.5, 10, 0}, {1.0, 10, 0}}).fitted);
  BOOST_TEST(!fit_stripe_fragility({{0.5, 10, 10}, {1.0, 10, 10}}).fitted);
  // separated stripes (none partly exceeded): a fit, with the warning that beta is unbounded
  const LognormalFragility separated = fit_stripe_fragility({{0.5, 10, 0}, {1.0, 10, 10}});
  BOOST_TEST(separated.note.find("no stripe is partly exceeded") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(cloud_fit_of_a_power_law)
{
  std::vector<double> x, d, noisy;
  for (int i = 1; i <= 8; ++i)
    {
      x.push_back(0.1 * i * i);
      d.push_back(0.02 * x.back()); // a linear model: D proportional to IM
      noisy.push_back(0.03 * std::pow(x.back(), 1.2) * std::exp(i % 2 ? 0.3 : -0.3));
    }
  const CloudFit exact = fit_cloud(x, d);
  BOOST_REQUIRE(exact.fitted);
  BOOST_TEST(exact.b == 1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(exact.a == 0.02, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(exact.dispersion < 1e-12);
  const CloudFit fit = fit_cloud(x, noisy);
  // the residuals +/-0.3 alternate: least squares leaves them only if they
  // are orthogonal to ln x; check the dispersion against the residuals' own
  double squares = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    squares += std::pow(std::log(noisy[i]) - std::log(fit.a) - fit.b * std::log(x[i]), 2);
  BOOST_TEST(fit.dispersion == std::sqrt(squares / (x.size() - 2)),
             boost::test_tools::tolerance(1e-12));
  // its fragility of a threshold: P(D > d | x) at x = theta is one half
  const LognormalFragility f = fit.fragility(0.05);
  BOOST_TEST(fit.a * std::pow(f.theta, fit.b) == 0.05, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(f.beta == fit.dispersion / fit.b, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(hazard_integration_against_the_closed_form)
{
  const double k0 = 1e-4, k = 2.5;
  HazardCurve  curve;
  for (int i = 0; i <= 50; ++i)
    {
      const double x = 1e-3 * std::pow(1e5, i / 50.0); // 0.001 to 100
      curve.intensity.push_back(x);
      curve.rate.push_back(k0 * std::pow(x, -k));
    }
  for (const auto &[theta, beta] : {std::pair{0.6, 0.5}, std::pair{0.3, 0.3}, std::pair{1.5, 0.6}})
    {
      LognormalFragility fragility;
      fragility.theta = theta, fragility.beta = beta, fragility.fitted = true;
      const double exact = k0 * std::pow(theta, -k) * std::exp(k * k * beta * beta / 2);
      BOOST_TEST(exceedance_rate(curve, fragility) == exact, boost::test_tools::tolerance(1e-4));
    }
  // the intensity of a return period: its rate is 1 / T
  const double x = curve.intensity_of_return_period(475);
  BOOST_TEST(curve.rate_at(x) == 1 / 475.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::isnan(curve.intensity_of_return_period(1e30)));
}

BOOST_AUTO_TEST_CASE(limit_states_count_collapse_and_thresholds)
{
  IdaPoint point;
  point.demands = {0.005, 0.0, 2.0};
  const LimitState drift{"d", 0, 0.004}, impacts{"i", 2, 0}, none{"n", 1, 0};
  BOOST_TEST(drift.exceeded(point));
  BOOST_TEST(impacts.exceeded(point));
  BOOST_TEST(!none.exceeded(point));
  point.collapsed = true;
  BOOST_TEST(none.exceeded(point));
}

// Nested limit states (msa.h, NestedRate): "force > 2e4" is exceeded only by
// runs that also impact (3 stripes of 10 runs; 1, 5, 9 impacts and 1, 2, 5
// of them above the force). Fitted one by one, the nested state gets the
// wider curve (beta ~1.04 against ~0.54) and, on a power-law hazard, the
// higher annual rate; the nesting is found from the runs, the inversion is
// reported once, and the nested state's rate is bounded by the other's.
BOOST_AUTO_TEST_CASE(nested_limit_states_keep_their_rates_in_order)
{
  const std::vector<double>       x{0.2, 0.4, 0.8};
  const std::vector<unsigned int> impacts{1, 5, 9}, forces{1, 2, 5};
  std::vector<IdaPoint>           points;
  for (std::size_t j = 0; j < x.size(); ++j)
    for (unsigned int i = 0; i < 10; ++i)
      {
        IdaPoint p;
        p.intensity = x[j];
        p.demands   = {i < impacts[j] ? 1.0 : 0.0, i < forces[j] ? 3e4 : (i < impacts[j] ? 1e4 : 0.0)};
        points.push_back(p);
      }
  const std::vector<LimitState> states{{"collapse", -1, 0}, {"impact", 0, 0}, {"force", 1, 2e4}};
  std::vector<const IdaPoint *> pointers;
  for (const IdaPoint &p : points)
    pointers.push_back(&p);
  const auto within = nested_limit_states(states, pointers);
  BOOST_TEST(within[0].empty()); // nothing collapsed: nothing to order
  BOOST_TEST(within[1].empty());
  BOOST_TEST(within[2] == std::vector<unsigned int>{1}, boost::test_tools::per_element());

  HazardCurve curve;
  for (double a = 0.01; a < 50; a *= 1.2)
    curve.intensity.push_back(a), curve.rate.push_back(1e-4 * std::pow(a, -3));
  std::vector<double> rates{std::nan("")};
  for (const auto *counts : {&impacts, &forces})
    {
      std::vector<StripeCount> stripes;
      for (std::size_t j = 0; j < x.size(); ++j)
        stripes.push_back({x[j], 10, (*counts)[j]});
      rates.push_back(exceedance_rate(curve, fit_stripe_fragility(stripes)));
    }
  BOOST_REQUIRE(rates[2] > rates[1]); // fitted one by one, the rates invert
  const NestedRate nested = order_nested_rates(states, within, rates);
  BOOST_TEST(nested.warnings.size() == 1u);
  BOOST_TEST(nested.warnings[0].find("'force' is nested in 'impact'") != std::string::npos);
  BOOST_TEST(nested.bound[1] == rates[1]);
  BOOST_TEST(nested.bound[2] == rates[1]);
  // in order already: no warning, the rates are their own bounds
  const NestedRate ordered = order_nested_rates(states, within, {std::nan(""), 2.0, 1.0});
  BOOST_TEST(ordered.warnings.empty());
  BOOST_TEST(ordered.bound[2] == 1.0);
}
