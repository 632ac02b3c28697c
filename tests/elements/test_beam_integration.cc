// The beam integration rules: Gauss-Lobatto, Gauss-Legendre and HingeRadau
// against the exact integrals of monomials on [0, 1] and their known points.
#include <poundfe/base/exceptions.h>
#include <poundfe/elements/beam_integration.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;

namespace
{
  /// The largest relative error of the rule on xi^k, k = 0..degree.
  double
  monomial_error(const BeamIntegration &rule, const unsigned int degree)
  {
    double error = 0;
    for (unsigned int k = 0; k <= degree; ++k)
      {
        double sum = 0;
        for (unsigned int i = 0; i < rule.size(); ++i)
          sum += rule.weights[i] * std::pow(rule.points[i], k);
        error = std::max(error, std::abs(sum * (k + 1) - 1));
      }
    return error;
  }
} // namespace

BOOST_AUTO_TEST_CASE(gauss_rules_integrate_their_degrees)
{
  for (unsigned int n = 2; n <= 10; ++n)
    {
      const BeamIntegration lobatto = lobatto_integration(n);
      BOOST_TEST(lobatto.size() == n);
      BOOST_TEST(lobatto.points.front() == 0.0);
      BOOST_TEST(lobatto.points.back() == 1.0);
      BOOST_TEST(monomial_error(lobatto, 2 * n - 3) < 1e-14);
      if (n <= 4) // and not beyond
        BOOST_TEST(monomial_error(lobatto, 2 * n - 2) > 1e-5);
      for (unsigned int i = 1; i < n; ++i)
        BOOST_TEST(lobatto.points[i] > lobatto.points[i - 1]);
    }
  for (unsigned int n = 1; n <= 10; ++n)
    {
      const BeamIntegration legendre = legendre_integration(n);
      BOOST_TEST(monomial_error(legendre, 2 * n - 1) < 1e-14);
      if (n <= 4)
        BOOST_TEST(monomial_error(legendre, 2 * n) > 1e-5);
      for (unsigned int i = 1; i < n; ++i)
        BOOST_TEST(legendre.points[i] > legendre.points[i - 1]);
    }
  // known points: Lobatto 3 (0, 1/2, 1; 1/6, 2/3, 1/6), Legendre 2
  const BeamIntegration l3 = lobatto_integration(3);
  BOOST_TEST(l3.points[1] == 0.5, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(l3.weights[0] == 1.0 / 6, boost::test_tools::tolerance(1e-15));
  const BeamIntegration g2 = legendre_integration(2);
  BOOST_TEST(g2.points[0] == 0.5 - 0.5 / std::sqrt(3.0), boost::test_tools::tolerance(1e-15));
  BOOST_CHECK_THROW(lobatto_integration(1), InputError);
  BOOST_CHECK_THROW(lobatto_integration(11), InputError);
  BOOST_CHECK_THROW(legendre_integration(0), InputError);
}

BOOST_AUTO_TEST_CASE(hinge_radau_places_its_hinges_and_integrates_quadratics)
{
  const double          L = 4, lp_i = 0.3, lp_j = 0.2;
  const BeamIntegration rule = hinge_radau_integration(lp_i, lp_j, L);
  BOOST_TEST(rule.size() == 6u);
  BOOST_TEST(rule.points[0] == 0.0);
  BOOST_TEST(rule.weights[0] == lp_i / L, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(rule.points[1] == 8 * lp_i / (3 * L), boost::test_tools::tolerance(1e-15));
  BOOST_TEST(rule.weights[5] == lp_j / L, boost::test_tools::tolerance(1e-15));
  // exact to degree 2: an elastic force-based member is exact with it
  BOOST_TEST(monomial_error(rule, 2) < 1e-14);
  BOOST_CHECK_THROW(hinge_radau_integration(0, 0.1, L), InputError);
  BOOST_CHECK_THROW(hinge_radau_integration(0.6, 0.5, L), InputError);
}
