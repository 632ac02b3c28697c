// The hazard x fragility integral (hazard/site_hazard.h annual_failure_rate)
// and the gap of the pounding hazard (hazard/pounding_hazard.h) for ANY
// lognormal dispersion (issue 28 class 2), against closed forms written here:
//   - power law lambda(a) = k0 a^-k with the lower limit a_min = theta
//     e^(beta z0):  lambda_F = Phi(z0) lambda(a_min)
//                              + k0 theta^-k e^(k^2 beta^2 / 2) Phi(-z0 - k beta)
//     (Cornell, Jalayer, Hamburger & Foutch 2002 without the limit; the limit
//     by completing the square), beta from 1e-12 to 10, k from 0.5 to 3, z0
//     from "no limit" (12 standard deviations below the integrand's peak) to
//     45 (beyond the fragility), the reference in long double;
//   - a hazard curve with a kink (two power laws joined at a_b), the sum of
//     two such truncated Gaussians: the kink is where adaptive quadrature
//     has to work;
//   - beta = 0 (the step lambda(max(a_min, theta))) and its limit;
//   - the gap for a probability in T years of a demand without scatter
//     (beta_D = 0 and the 4e-15 of one realization per level, issue 28's
//     case), against the closed-form inverse g = c (k0 / lambda*)^(b/k).
#include <poundfe/hazard/pounding_hazard.h>
#include <poundfe/hazard/site_hazard.h>
#include <poundfe/base/exceptions.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;

namespace
{
  long double
  normal_cdf(const long double z)
  {
    return 0.5L * std::erfc(-z / std::sqrt(2.0L));
  }

  /// C int_{z1}^{z2} e^(-k beta z) phi(z) dz = C e^(k^2 beta^2/2) (Phi(z2 + k beta) - Phi(z1 + k beta)),
  /// written with the upper tails (accurate far out).
  long double
  gaussian_piece(const long double c, const long double k, const long double beta,
                 const long double z1, const long double z2)
  {
    const long double s = k * beta;
    return c * std::exp(s * s / 2) * (normal_cdf(-z1 - s) - normal_cdf(-z2 - s));
  }
} // namespace

BOOST_AUTO_TEST_CASE(power_law_with_a_lower_limit_for_any_beta)
{
  // Tolerance 1e-12 relative: the quadrature's own error is ~1e-15; the rest
  // is the rounding of exponents up to k beta (k beta + 12) ~ 640 in
  // lambda(theta e^(beta z)) and e^(k^2 beta^2 / 2) (~640 eps).
  const double k0      = 3e-4;
  double       largest = 0;
  unsigned int n_cases = 0;
  for (const double beta : {1e-12, 1e-9, 1e-6, 1e-3, 0.01, 0.1, 0.3, 1.0, 2.0, 5.0, 10.0})
    for (const double k : {0.5, 1.0, 2.0, 3.0})
      {
        // lambda itself overflows a double 12 standard deviations below the
        // integrand's peak beyond this (k = 3, beta = 10: e^1260)
        if (k * beta * (k * beta + 12) > 700)
          continue;
        // theta = 1 for the narrow curves: ln a_min is then exact to round-off
        const double theta = beta < 1e-3 ? 1.0 : 0.37;
        for (const double z0 : {-k * beta - 12, -3.0, -1.0, 0.0, 0.5, 3.0, 10.0, 45.0})
          {
            const double      a_min = theta * std::exp(beta * z0);
            const long double z     = (std::log(static_cast<long double>(a_min)) -
                                   std::log(static_cast<long double>(theta))) / beta;
            const long double c     = k0 * std::pow(static_cast<long double>(theta), -k);
            const long double exact =
              normal_cdf(z) * k0 * std::pow(static_cast<long double>(a_min), -k) +
              gaussian_piece(c, k, beta, z, INFINITY);
            const double numerical = annual_failure_rate(
              [&](const double a) { return k0 * std::pow(a, -k); }, a_min, {theta, beta});
            // beyond the curve with lambda(a_min) below the smallest double: both 0
            const double reference = double(exact);
            const double error = reference == 0 ? numerical : std::abs(numerical / reference - 1);
            largest            = std::max(largest, error);
            ++n_cases;
            BOOST_TEST(error <= 1e-12, "beta " << beta << ", k " << k << ", z0 " << z0 << ": "
                                               << numerical << " against " << double(exact));
          }
      }
  BOOST_TEST_MESSAGE(n_cases << " cases, largest relative difference " << largest);
}

BOOST_AUTO_TEST_CASE(hazard_curve_with_a_kink)
{
  // lambda = k0 a^-k1 below a_b, k0 a_b^(k2 - k1) a^-k2 above (continuous):
  // two truncated Gaussians. Tolerance 1e-11: the kink is found by bisection
  // (Gauss-Kronrod's error estimate) rather than placed on a panel's end.
  const double k0 = 1e-4, k1 = 1.5, k2 = 3.5, a_b = 0.2;
  const auto   hazard = [&](const double a) {
    return a < a_b ? k0 * std::pow(a, -k1) : k0 * std::pow(a_b, k2 - k1) * std::pow(a, -k2);
  };
  for (const double beta : {1e-12, 1e-4, 0.05, 0.4, 1.5})
    for (const double theta : {0.1, 0.2, 0.35})
      {
        const double      a_min = 0.01;
        const long double z_min = (std::log(0.01L) - std::log((long double)theta)) / beta;
        const long double z_b   = (std::log((long double)a_b) - std::log((long double)theta)) / beta;
        const long double exact =
          normal_cdf(z_min) * hazard(a_min) +
          gaussian_piece(k0 * std::pow((long double)theta, -k1), k1, beta, z_min, z_b) +
          gaussian_piece(k0 * std::pow((long double)a_b, k2 - k1) * std::pow((long double)theta, -k2),
                         k2, beta, z_b, INFINITY);
        const double numerical = annual_failure_rate(hazard, a_min, {theta, beta});
        BOOST_TEST(numerical == double(exact), boost::test_tools::tolerance(1e-11));
      }
}

BOOST_AUTO_TEST_CASE(step_fragility_and_its_limit)
{
  const auto hazard = [](const double a) { return 2e-4 * std::pow(a, -2.2); };
  // beta = 0: every event above theta (or above a_min if theta is below it)
  BOOST_TEST(annual_failure_rate(hazard, 0.01, {0.3, 0}) == hazard(0.3));
  BOOST_TEST(annual_failure_rate(hazard, 0.5, {0.3, 0}) == hazard(0.5));
  // the limit: k^2 beta^2 / 2 = 1.2e-24, below round-off
  BOOST_TEST(annual_failure_rate(hazard, 0.01, {0.3, 1e-12}) == hazard(0.3),
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(annual_failure_rate(hazard, 0.5, {0.3, 1e-12}) == hazard(0.5),
             boost::test_tools::tolerance(1e-14));
  // a hazard that underflows to 0 across the whole curve: 0, found at once
  const auto none_above_1g = [](const double a) { return a < 1 ? 1e-3 : 0.0; };
  BOOST_TEST(annual_failure_rate(none_above_1g, 0.01, {100, 0.01}) == 0);
  // one that overflows within the curve's spread: refused, not inf
  const auto steep = [](const double a) { return std::pow(a, -3.0); };
  BOOST_CHECK_THROW(annual_failure_rate(steep, 1e-200, {1, 10}), NumericalError);
}

BOOST_AUTO_TEST_CASE(gap_of_a_demand_without_scatter)
{
  // D = c a^b exactly: lambda(g) = lambda_h(max(a_min, (g/c)^(1/b))), so the
  // gap for lambda* = -ln(1 - p)/T is c (k0 / lambda*)^(b/k). Before issue
  // 28, beta_D = 4e-15 (one realization per level) gave a gap ten times too
  // small: Simpson's steps, capped in number, were far wider than beta.
  // Tolerance 1e-10: toms748 stops at 2^-39 relative in ln g (~1e-11 in g).
  const double    k0 = 2e-4, k = 2.5, years = 50, p = 0.1;
  const PgaHazard hazard = power_law_hazard(k0, k, 1e-3);
  const double    target = -std::log1p(-p) / years;
  for (const double dispersion : {0.0, 4e-15, 1e-9})
    {
      const PowerLawDemand demand{0.021, 1.0, dispersion, 36};
      const double         exact = 0.021 * std::pow(k0 / target, 1.0 / k);
      BOOST_TEST(gap_for_probability_in_years(hazard, demand, years, p) == exact,
                 boost::test_tools::tolerance(1e-10));
      BOOST_TEST(probability_in_years(annual_pounding_rate(hazard, demand, exact), years) == p,
                 boost::test_tools::tolerance(1e-12));
    }
}
