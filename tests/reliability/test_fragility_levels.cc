// A lognormal fragility rests on two or more distinct PGA levels (issue 28
// class 2): at one level the likelihood fixes only Phi(ln(a/theta)/beta)
// there, a ridge of (theta, beta) pairs, and the optimiser would stop
// anywhere on it: refused ("not fitted", with the reason), also when the one
// level is listed twice. Two levels: the maximum-likelihood curve passes
// through both empirical fractions (two equations, two unknowns, solved
// here); tolerance 1e-6, Nelder-Mead stops at a simplex of 1e-10 in
// (ln theta, ln beta) and the likelihood is flat to second order there.
#include <poundfe/reliability/statistics.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;

BOOST_AUTO_TEST_CASE(one_pga_level_is_not_fitted)
{
  for (const auto &levels : {std::vector<double>{0.2}, std::vector<double>{0.2, 0.2}})
    {
      const std::vector<unsigned long> failures(levels.size(), 3), trials(levels.size(), 10);
      const LognormalFragility         curve = fit_lognormal_fragility(levels, failures, trials);
      BOOST_TEST(!curve.fitted);
      BOOST_TEST(curve.note == "one PGA level: theta and beta need two or more distinct levels");
    }
  // two levels: fitted, and through the two empirical fractions exactly
  // (two equations, two unknowns: Phi^-1(0.3) and Phi^-1(0.8) at ln 0.2, ln 0.4)
  const LognormalFragility two = fit_lognormal_fragility({0.2, 0.4}, {3, 8}, {10, 10});
  BOOST_TEST(two.fitted);
  const double z1 = -0.5244005127080407, z2 = 0.8416212335729143; // Phi^-1(0.3), Phi^-1(0.8)
  const double beta = std::log(2.0) / (z2 - z1), theta = 0.2 * std::exp(-z1 * beta);
  BOOST_TEST(two.beta == beta, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(two.theta == theta, boost::test_tools::tolerance(1e-6));
}
