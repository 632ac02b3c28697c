// The reliability engine (distributions, Nataf, limit-state expressions,
// FORM, SORM, Monte Carlo, importance sampling, system bounds) against
// independent references written here: closed forms, quadrature of the
// exact integral, a second method, and a published example (CalRel manual
// example 2). Tolerances and their reasons are stated with each check and in
// doc/verification.md.
#include <poundfe/excitation/stochastic.h>
#include <poundfe/reliability/distribution.h>
#include <poundfe/reliability/form.h>
#include <poundfe/reliability/limit_state.h>
#include <poundfe/reliability/nataf.h>
#include <poundfe/reliability/sampling.h>
#include <poundfe/reliability/sorm.h>
#include <poundfe/reliability/subset.h>
#include <poundfe/reliability/system_bounds.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include <cmath>

#include "test_utilities.h"

using namespace poundfe;
// MPI (for subset_simulation) is initialised by test_reliability.cc's fixture.

namespace
{
  using boost::math::quadrature::gauss_kronrod;

  /// int f over the support of d by adaptive Gauss-Kronrod on the
  /// quantile range [F^{-1}(1e-13), F^{-1}(1 - 1e-13)].
  template <typename F>
  double
  integral_over(const Distribution &d, F f)
  {
    return gauss_kronrod<double, 31>::integrate([&](double x) { return f(x) * d.pdf(x); },
                                                 d.quantile(1e-13), d.quantile(1 - 1e-13), 20,
                                                 1e-13);
  }

  ReliabilityProblem
  problem_of(std::vector<Distribution> d, std::vector<LimitStateFunction> g,
             const DenseMatrix &R = {}, SystemType s = SystemType::series)
  {
    return {NatafTransformation(std::move(d), R), std::move(g), s};
  }

  Distribution
  normal(double m, double s)
  {
    return Distribution::from_moments(DistributionType::normal, m, s);
  }
} // namespace

// Each marginal: mean and variance by quadrature of its pdf (a second
// route to the moments formulas), F(F^{-1}(p)) = p, the pdf as the derivative
// of the CDF, and u -> x -> u. Tolerances: quadrature converges to ~1e-12;
// the central difference of F with h = 1e-5 sd has error ~1e-9 relative.
BOOST_AUTO_TEST_CASE(distributions_moments_and_transforms)
{
  using T = DistributionType;
  const std::vector<Distribution> cases = {
    Distribution::from_moments(T::normal, 3, 0.7),
    Distribution::from_moments(T::lognormal, 2, 0.9),
    Distribution::from_moments(T::uniform, -1, 2),
    Distribution::from_native(T::truncated_normal, {1, 2, -0.5, 4}),
    Distribution::from_moments(T::gumbel, 1000, 200),
    Distribution::from_moments(T::weibull, 40, 5),
    Distribution::from_moments(T::weibull, 1, 0.8)};
  for (const Distribution &d : cases)
    {
      BOOST_TEST_CONTEXT(distribution_name(d.type()))
      {
        const double mean = integral_over(d, [](double x) { return x; });
        const double var  = integral_over(d, [&](double x) { return (x - mean) * (x - mean); });
        BOOST_TEST(d.mean() == mean, boost::test_tools::tolerance(1e-9));
        BOOST_TEST(d.standard_deviation() == std::sqrt(var), boost::test_tools::tolerance(1e-8));
        // absolute 1e-16 as well: a truncated normal's F is a difference
        // of two normal CDFs, exact to ~1e-17 absolute only
        for (const double p : {1e-10, 0.01, 0.3, 0.5, 0.9, 1 - 1e-9})
          BOOST_TEST(std::abs(d.cdf(d.quantile(p)) - p) <= 1e-9 * p + 1e-16);
        // bounded supports: a point 1e-14 below the bound carries only
        // eps |x| of it, so their round trip stops at |u| = 5
        const bool bounded =
          d.type() == DistributionType::uniform || d.type() == DistributionType::truncated_normal;
        for (const double u : {-6.0, -1.0, 0.0, 0.5, 3.0, 7.5})
          {
            if (bounded && std::abs(u) > 5)
              continue;
            const double x = d.from_standard_normal(u);
            BOOST_TEST(d.to_standard_normal(x) == u, boost::test_tools::tolerance(1e-8));
            const double h = 1e-5 * d.standard_deviation();
            if (d.pdf(x) > 1e-6 / d.standard_deviation() && d.pdf(x - h) > 0 && d.pdf(x + h) > 0)
              BOOST_TEST((d.cdf(x + h) - d.cdf(x - h)) / (2 * h) == d.pdf(x),
                         boost::test_tools::tolerance(1e-6));
          }
      }
    }
  // moment inputs come back: mean 40, sd 5 of the Weibull (shape solved)
  BOOST_TEST(cases[5].mean() == 40, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(cases[5].standard_deviation() == 5, boost::test_tools::tolerance(1e-10));
}

BOOST_AUTO_TEST_CASE(distributions_refuse_impossible_parameters)
{
  using T = DistributionType;
  BOOST_CHECK_THROW(Distribution::from_moments(T::normal, 1, -1), std::invalid_argument);
  BOOST_CHECK_THROW(Distribution::from_moments(T::lognormal, 0, 1), std::invalid_argument);
  BOOST_CHECK_THROW(Distribution::from_moments(T::weibull, -2, 1), std::invalid_argument);
  BOOST_CHECK_THROW(Distribution::from_native(T::uniform, {2, 1}), std::invalid_argument);
  BOOST_CHECK_THROW(Distribution::from_native(T::truncated_normal, {0, 1, 3, 2}),
                    std::invalid_argument);
  BOOST_CHECK_THROW(distribution_type("beta"), std::invalid_argument);
}

// Nataf. Normal pairs: R0 = R and the map is linear, so x = m + s L u has the
// covariance of R exactly. Quadrature path against exact relations:
// normal-uniform rho = rho0 sqrt(3/pi); uniform-uniform
// rho = (6/pi) asin(rho0/2) (both from the bivariate normal's orthant
// integrals; Liu & Der Kiureghian 1986 Table 2). Tolerance 1e-6: 64-point
// Gauss-Hermite on a function with a kink-free quantile.
BOOST_AUTO_TEST_CASE(nataf_equivalent_correlation)
{
  using T = DistributionType;
  const Distribution n = normal(0, 1), u = Distribution::from_moments(T::uniform, 0, 1);
  for (const double rho : {-0.6, 0.3, 0.9})
    {
      BOOST_TEST(equivalent_normal_correlation(n, n, rho) == rho);
      BOOST_TEST(equivalent_normal_correlation(n, u, rho) == rho * std::sqrt(M_PI / 3),
                 boost::test_tools::tolerance(1e-6));
      BOOST_TEST(equivalent_normal_correlation(u, u, rho) == 2 * std::sin(M_PI * rho / 6),
                 boost::test_tools::tolerance(1e-6));
    }
  // normal-uniform cannot reach rho = 0.99 (the largest is sqrt(3/pi) = 0.977)
  BOOST_CHECK_THROW(equivalent_normal_correlation(n, u, 0.99), std::invalid_argument);

  // correlated normals: to_physical is x = m + s L u exactly
  const DenseMatrix         R = {{1, 0.5, 0.2}, {0.5, 1, -0.3}, {0.2, -0.3, 1}};
  const NatafTransformation t({normal(1, 2), normal(-3, 0.5), normal(10, 4)}, R);
  const DenseMatrix         L = cholesky_factor(R);
  std::vector<double>       x, back;
  const std::vector<double> u0 = {0.3, -1.2, 2.0};
  t.to_physical(u0, x);
  const double m[] = {1, -3, 10}, s[] = {2, 0.5, 4};
  for (int i = 0; i < 3; ++i)
    {
      double z = 0;
      for (int k = 0; k <= i; ++k)
        z += L[i][k] * u0[k];
      BOOST_TEST(x[i] == m[i] + s[i] * z, boost::test_tools::tolerance(1e-14));
    }
  t.to_standard(x, back);
  for (int i = 0; i < 3; ++i)
    BOOST_TEST(back[i] == u0[i], boost::test_tools::tolerance(1e-12));

  // refused: not symmetric, not positive definite
  BOOST_CHECK_THROW(NatafTransformation({n, n}, {{1, 0.5}, {0.4, 1}}), std::invalid_argument);
  BOOST_CHECK_THROW(NatafTransformation({n, n, n}, {{1, 0.9, -0.9}, {0.9, 1, 0.9}, {-0.9, 0.9, 1}}),
                    std::invalid_argument);
}

// A Gumbel-Weibull pair with rho = 0.6 through Nataf: the sample correlation
// of 400,000 draws (a second method: no quadrature) within 4 standard errors
// (the sample correlation's sd is ~(1 - rho^2)/sqrt(N) = 0.0010).
BOOST_AUTO_TEST_CASE(nataf_sample_correlation)
{
  using T = DistributionType;
  const NatafTransformation t({Distribution::from_moments(T::gumbel, 10, 3),
                               Distribution::from_moments(T::weibull, 5, 2)},
                              {{1, 0.6}, {0.6, 1}});
  NormalStream              random(7, 0);
  const unsigned int        N = 400000;
  double                    sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  std::vector<double>       u(2), x;
  for (unsigned int i = 0; i < N; ++i)
    {
      u = {random.next(), random.next()};
      t.to_physical(u, x);
      sx += x[0], sy += x[1], sxx += x[0] * x[0], syy += x[1] * x[1], sxy += x[0] * x[1];
    }
  const double cov = sxy / N - sx * sy / N / N;
  const double rho = cov / std::sqrt((sxx / N - sx * sx / N / N) * (syy / N - sy * sy / N / N));
  BOOST_TEST(std::abs(rho - 0.6) < 4 * (1 - 0.36) / std::sqrt(double(N)));
}

// Expressions: values against the same formula in C++, and errors.
BOOST_AUTO_TEST_CASE(limit_state_expressions)
{
  const LimitStateExpression g("sigma_s - 6*sx*l/(w^2*h) - 6*sy*l/(w*h^2)", {"l", "w", "h"},
                               {{"sigma_s", 100.46154}, {"sx", 50}, {"sy", 100}});
  const double x[] = {957.64, 94.41, 199.87};
  BOOST_TEST(g(x) == 100.46154 - 6 * 50 * x[0] / (x[1] * x[1] * x[2]) -
                       6 * 100 * x[0] / (x[1] * x[2] * x[2]),
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(g.used_variables().size() == 3u);
  BOOST_CHECK_THROW(LimitStateExpression("a + * b", {"a", "b"}), std::invalid_argument);
  BOOST_CHECK_THROW(LimitStateExpression("a + c", {"a", "b"}), std::invalid_argument);
  BOOST_TEST(is_identifier("P_1"));
  BOOST_TEST(!is_identifier("1P"));
}

// Linear limit state in normals: g = a0 + sum a_i x_i. Exact: beta =
// mu_g/sigma_g, x*_i = mu_i - beta a_i s_i^2/sigma_g, d beta/d mu_i =
// a_i/sigma_g, d beta/d s_i = -beta a_i^2 s_i/sigma_g^2. FORM is exact here;
// tolerance 1e-7 (finite-difference gradient of a linear function is exact
// to round-off; the convergence test stops at 1e-6 relative in G).
BOOST_AUTO_TEST_CASE(form_linear_normal_exact)
{
  const std::vector<double> a = {1.5, -2, 0.5}, m = {10, 3, -4}, s = {1, 0.8, 2};
  const double              a0 = -1;
  const ReliabilityProblem  p =
    problem_of({normal(m[0], s[0]), normal(m[1], s[1]), normal(m[2], s[2])},
               {[&](const std::vector<double> &x) { return a0 + dot(a, x); }});
  const FormResult r = form(p, 0);
  double           mg = a0, vg = 0;
  for (int i = 0; i < 3; ++i)
    mg += a[i] * m[i], vg += a[i] * a[i] * s[i] * s[i];
  const double beta = mg / std::sqrt(vg);
  BOOST_TEST(r.converged);
  BOOST_TEST(r.beta == beta, boost::test_tools::tolerance(1e-7));
  BOOST_TEST(r.probability == standard_normal_cdf(-beta), boost::test_tools::tolerance(1e-6));
  BOOST_TEST(r.iterations <= 3u);
  for (int i = 0; i < 3; ++i)
    {
      BOOST_TEST(r.design_point_x[i] == m[i] - beta * a[i] * s[i] * s[i] / std::sqrt(vg),
                 boost::test_tools::tolerance(1e-7));
      BOOST_TEST(r.dbeta_dmean[i] == a[i] / std::sqrt(vg), boost::test_tools::tolerance(1e-6));
      BOOST_TEST(r.dbeta_dsd[i] == -beta * a[i] * a[i] * s[i] / vg,
                 boost::test_tools::tolerance(1e-6));
    }
}

// R - S with lognormals: the surface ln R = ln S is a plane in u, so FORM is
// exact: beta = ln(mR'/mS')/sqrt(zR^2 + zS^2), m' the medians. 1e-7 as above.
BOOST_AUTO_TEST_CASE(form_lognormal_resistance_load_exact)
{
  using T = DistributionType;
  const Distribution R = Distribution::from_moments(T::lognormal, 300, 45);
  const Distribution S = Distribution::from_moments(T::lognormal, 120, 36);
  const ReliabilityProblem p =
    problem_of({R, S}, {[](const std::vector<double> &x) { return x[0] - x[1]; }});
  const FormResult r = form(p, 0);
  const double     zR = R.parameters()[1], zS = S.parameters()[1];
  const double     beta =
    (R.parameters()[0] - S.parameters()[0]) / std::sqrt(zR * zR + zS * zS);
  BOOST_TEST(r.converged);
  BOOST_TEST(r.beta == beta, boost::test_tools::tolerance(1e-7));
  // and the sampling methods within 4 of their own standard errors
  SamplingSettings s;
  s.max_samples             = 2000000;
  const SamplingResult mc   = monte_carlo(p, s);
  const double         exact = standard_normal_cdf(-beta);
  BOOST_TEST(std::abs(mc.probability - exact) < 4 * mc.coefficient_of_variation * exact);
  s.max_samples            = 20000;
  const SamplingResult is  = importance_sampling(p, {r.design_point_u}, s);
  BOOST_TEST(std::abs(is.probability - exact) < 4 * is.coefficient_of_variation * exact);
  BOOST_TEST(is.coefficient_of_variation < 0.03); // the point of sampling around u*
}

// The paraboloid G = beta - u_n + (kappa/2) sum_{i<n} u_i^2 in standard
// normals: exact Pf = E[Phi(-beta - kappa/2 chi2_{n-1})], integrated here
// over the chi-square density. Breitung is asymptotically exact: its
// relative error must fall as beta grows (11 %, 6 %, 2.5 % measured at
// beta = 2, 4, 8; checked < 3 % at 8);
// the curvatures are kappa/(1) exactly (Hessian of a quadratic by central
// differences: exact to round-off/h^2 ~ 1e-9).
BOOST_AUTO_TEST_CASE(sorm_paraboloid_breitung_asymptotic)
{
  const unsigned int n = 4;
  const double       kappa = 0.2;
  double             previous_error = 1;
  for (const double beta : {2.0, 4.0, 8.0})
    {
      std::vector<Distribution> d(n, normal(0, 1));
      const ReliabilityProblem  p = problem_of(d, {[&](const std::vector<double> &u) {
                                                double s = 0;
                                                for (unsigned int i = 0; i + 1 < n; ++i)
                                                  s += u[i] * u[i];
                                                return beta - u[n - 1] + 0.5 * kappa * s;
                                              }});
      const FormResult r  = form(p, 0);
      const SormResult so = sorm(p, 0, r);
      const boost::math::chi_squared chi2(n - 1);
      const double exact = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
        [&](double s) { return standard_normal_cdf(-beta - 0.5 * kappa * s) * boost::math::pdf(chi2, s); },
        0.0, 200.0, 25, 1e-14);
      BOOST_TEST(r.beta == beta, boost::test_tools::tolerance(1e-7));
      for (const double k : so.curvatures)
        BOOST_TEST(k == kappa, boost::test_tools::tolerance(1e-5));
      const double error = std::abs(so.breitung / exact - 1);
      BOOST_TEST_MESSAGE("beta " << beta << ": exact " << exact << ", Breitung " << so.breitung
                                 << ", Tvedt " << so.tvedt << ", FORM " << r.probability);
      BOOST_TEST(error < previous_error);
      previous_error = error;
      // Tvedt's three terms are closer than Breitung's one
      BOOST_TEST(std::abs(so.tvedt / exact - 1) <= error);
    }
  BOOST_TEST(previous_error < 0.03);
}

// Series system of two linear limit states in normals: the exact
// P(G1 <= 0 or G2 <= 0) = P1 + P2 - Phi2(-b1, -b2; rho), with Phi2 computed
// here by a different formula (conditioning on U1: int_{-inf}^{a} phi(t)
// Phi((b - rho t)/sqrt(1 - rho^2)) dt). The engine's Phi2 (Genz's angle
// form) must agree to 1e-10, Ditlevsen's bounds must bracket the exact value,
// Monte Carlo and importance sampling within 4 standard errors. (1e-9: two
// adaptive quadratures, each to ~1e-10 relative.)
BOOST_AUTO_TEST_CASE(series_system_two_linear)
{
  const auto phi2 = [](double a, double b, double rho) {
    return gauss_kronrod<double, 61>::integrate(
      [&](double t) {
        return standard_normal_pdf(t) * standard_normal_cdf((b - rho * t) / std::sqrt(1 - rho * rho));
      },
      -40.0, a, 25, 1e-15);
  };
  for (const double rho : {-0.7, 0.2, 0.95})
    BOOST_TEST(bivariate_normal_cdf(-2.5, -1.8, rho) == phi2(-2.5, -1.8, rho),
               boost::test_tools::tolerance(1e-9));

  const ReliabilityProblem p = problem_of(
    {normal(0, 1), normal(0, 1)},
    {[](const std::vector<double> &u) { return 3.0 - (0.6 * u[0] + 0.8 * u[1]); },
     [](const std::vector<double> &u) { return 2.5 - (0.8 * u[0] - 0.6 * u[1]) / 1.0; }});
  const FormResult r1 = form(p, 0), r2 = form(p, 1);
  const double     rho = dot(r1.alpha, r2.alpha); // 0.6*0.8 - 0.8*0.6 = 0
  const double exact = standard_normal_cdf(-3.0) + standard_normal_cdf(-2.5) - phi2(-3.0, -2.5, rho);
  const SystemBounds b = system_bounds(SystemType::series, {r1.beta, r2.beta}, {r1.alpha, r2.alpha});
  BOOST_TEST(b.lower <= exact * (1 + 1e-9));
  BOOST_TEST(b.upper >= exact * (1 - 1e-9));
  SamplingSettings s;
  s.max_samples             = 1000000;
  const SamplingResult mc   = monte_carlo(p, s);
  BOOST_TEST(std::abs(mc.probability - exact) < 4 * mc.coefficient_of_variation * exact);
  s.max_samples           = 40000;
  const SamplingResult is = importance_sampling(p, {r1.design_point_u, r2.design_point_u}, s);
  BOOST_TEST(std::abs(is.probability - exact) < 4 * is.coefficient_of_variation * exact);

  // correlated components (rho = 0.8): the bounds bracket the exact value
  const ReliabilityProblem q = problem_of(
    {normal(0, 1), normal(0, 1)},
    {[](const std::vector<double> &u) { return 2.0 - u[0]; },
     [](const std::vector<double> &u) { return 2.2 - (0.8 * u[0] + 0.6 * u[1]); }});
  const FormResult q1 = form(q, 0), q2 = form(q, 1);
  const double exact_q = standard_normal_cdf(-2.0) + standard_normal_cdf(-2.2) - phi2(-2.0, -2.2, 0.8);
  const SystemBounds bq = system_bounds(SystemType::series, {q1.beta, q2.beta}, {q1.alpha, q2.alpha});
  BOOST_TEST(bq.lower <= exact_q * (1 + 1e-9));
  BOOST_TEST(bq.upper >= exact_q * (1 - 1e-9));
  // parallel system of the same two: exactly Phi2
  const SystemBounds pq = system_bounds(SystemType::parallel, {q1.beta, q2.beta}, {q1.alpha, q2.alpha});
  BOOST_TEST(pq.upper == phi2(-2.0, -2.2, 0.8), boost::test_tools::tolerance(1e-8));
}

// Published example: CalRel user manual (Liu, Lin & Der Kiureghian 1989,
// report UCB/SEMM-89/18), example 2, as reproduced in OpenSees's
// EXAMPLES/Reliability/CalRel_manual_2.tcl: X1 ~ LN(500, 100), X2 ~ LN(2000,
// 400), X3 ~ U(mean 5, sd 0.5), rho12 = 0.3, rho13 = rho23 = 0.2,
// g = 1 - X2/(1000 X3) - (X1/(200 X3))^2. Published FORM: beta = 1.772397,
// alpha = (0.7233, 0.2719, -0.6347), x* = (631.9, 2320, 4.526); SORM by
// curvature fitting: curvatures 0.3419 and -0.08982, Tvedt beta = 1.854139.
// Tolerances: beta to 5e-4 relative, alpha to 1e-3, x* to 1e-3 relative:
// CalRel stopped at e1 = e2 = 1e-3 and took R0 of the lognormal-uniform pairs
// from the empirical formulas of Liu & Der Kiureghian (1986), poundfe from the
// integral (measured: beta 1.772773, |d alpha| <= 4.5e-4); curvatures 2e-3
// relative (finite-difference Hessians on both sides), Tvedt beta to 1e-3.
BOOST_AUTO_TEST_CASE(calrel_manual_example_2)
{
  using T = DistributionType;
  const ReliabilityProblem p = problem_of(
    {Distribution::from_moments(T::lognormal, 500, 100),
     Distribution::from_moments(T::lognormal, 2000, 400),
     Distribution::from_moments(T::uniform, 5, 0.5)},
    {[](const std::vector<double> &x) {
      const double b = x[0] / (200 * x[2]);
      return 1 - x[1] / (1000 * x[2]) - b * b;
    }},
    {{1, 0.3, 0.2}, {0.3, 1, 0.2}, {0.2, 0.2, 1}});
  const FormResult r = form(p, 0);
  BOOST_TEST(r.converged);
  BOOST_TEST(r.beta == 1.772397, boost::test_tools::tolerance(5e-4));
  const double alpha[] = {0.7233, 0.2719, -0.6347}, x[] = {631.9, 2320, 4.526};
  for (int i = 0; i < 3; ++i)
    {
      BOOST_TEST(std::abs(r.alpha[i] - alpha[i]) < 1e-3);
      BOOST_TEST(r.design_point_x[i] == x[i], boost::test_tools::tolerance(1e-3));
    }
  const SormResult s = sorm(p, 0, r);
  BOOST_TEST(s.curvatures[0] == -0.08982, boost::test_tools::tolerance(2e-3));
  BOOST_TEST(s.curvatures[1] == 0.3419, boost::test_tools::tolerance(2e-3));
  BOOST_TEST(s.beta_tvedt == 1.854139, boost::test_tools::tolerance(1e-3));
  BOOST_TEST_MESSAGE("CalRel example 2: beta " << r.beta << " in " << r.iterations
                                               << " iterations, " << r.n_evaluations
                                               << " evaluations; Tvedt beta " << s.beta_tvedt
                                               << ", Breitung beta " << s.beta_breitung);
}

// One problem, five methods: the cantilever of the thesis (eq. 2.44) with the
// spreads of input/thesis-cantilever-reliability.prm (normal l, w, h with
// COV 0.10; end forces 10 kN and 15 kN). Reference: crude Monte Carlo with
// 4e6 samples. Importance sampling and Subset Simulation must agree with it
// within 4 combined standard errors (their own reported COVs); SORM (Tvedt)
// within 4 standard errors plus 3 % (an asymptotic formula); FORM within
// 25 % (it ignores the curvature the SORM result shows).
BOOST_AUTO_TEST_CASE(cantilever_methods_agree)
{
  const double sigma_s = 100.46154, fx = 1.0e4, fy = 1.5e4;
  const ReliabilityProblem p = problem_of(
    {normal(957.64, 95.764), normal(94.41, 9.441), normal(199.87, 19.987)},
    {[&](const std::vector<double> &x) {
      return sigma_s - 6 * fx * x[0] / (x[1] * x[1] * x[2]) - 6 * fy * x[0] / (x[1] * x[2] * x[2]);
    }});
  SamplingSettings s;
  s.max_samples             = 4000000;
  const SamplingResult mc   = monte_carlo(p, s);
  const double         ref  = mc.probability, ref_sd = mc.coefficient_of_variation * ref;
  const FormResult     f    = form(p, 0);
  const SormResult     so   = sorm(p, 0, f);
  s.max_samples             = 20000;
  const SamplingResult is   = importance_sampling(p, {f.design_point_u}, s);
  SubsetSettings       ss;
  ss.samples_per_level       = 2000;
  ss.conditional_probability = 0.1;
  const StandardSpaceLimitStates G(p);
  const SubsetResult sub = subset_simulation([&](const std::vector<double> &u) { return -G.system_value(u); },
                                             3, 0.0, ss, MPI_COMM_SELF);
  BOOST_TEST_MESSAGE("cantilever: MC " << ref << " (COV " << mc.coefficient_of_variation
                     << "), FORM " << f.probability << " (beta " << f.beta << ", "
                     << f.iterations << " iterations), SORM Breitung " << so.breitung
                     << " Tvedt " << so.tvedt << ", IS " << is.probability << " (COV "
                     << is.coefficient_of_variation << "), subset " << sub.probability
                     << " (COV " << sub.coefficient_of_variation << ", " << sub.model_runs << " runs)");
  const auto agree = [&](double p_method, double sd_method) {
    return std::abs(p_method - ref) < 4 * std::sqrt(ref_sd * ref_sd + sd_method * sd_method);
  };
  BOOST_TEST(f.converged);
  BOOST_TEST(agree(is.probability, is.coefficient_of_variation * is.probability));
  BOOST_TEST(agree(sub.probability, sub.coefficient_of_variation * sub.probability));
  BOOST_TEST(std::abs(so.tvedt - ref) < 4 * ref_sd + 0.03 * ref);
  BOOST_TEST(std::abs(f.probability - ref) < 0.25 * ref);
}

// Subset Simulation with the thesis's (p0, N) pairs (Table 2.5: 0.10/950,
// 0.15/925, 0.20/900, 0.35/825), whose p0 N or 1/p0 is not whole, on
// G = beta - sum(u_i)/sqrt(n), n = 10, beta = 3 (Pf = Phi(-3) = 1.35e-3,
// exact): the mean of 12 independent runs lies within 3 standard errors of
// Pf, the standard error taken from the runs' own scatter.
BOOST_AUTO_TEST_CASE(subset_any_conditional_probability)
{
  const unsigned int n = 10;
  const double       exact = standard_normal_cdf(-3.0);
  const std::pair<double, unsigned int> cases[] = {{0.10, 950}, {0.15, 925}, {0.20, 900}, {0.35, 825}};
  for (const auto &[p0, N] : cases)
    {
      double sum = 0, sum2 = 0;
      const unsigned int runs = 12;
      for (unsigned int r = 0; r < runs; ++r)
        {
          SubsetSettings s;
          s.samples_per_level       = N;
          s.conditional_probability = p0;
          s.seed                    = 100 + r;
          const SubsetResult result = subset_simulation(
            [&](const std::vector<double> &u) {
              double t = 0;
              for (const double x : u)
                t += x;
              return t / std::sqrt(double(n)) - 3.0;
            },
            n, 0.0, s, MPI_COMM_SELF);
          BOOST_TEST(result.reached_threshold);
          sum += result.probability, sum2 += result.probability * result.probability;
        }
      const double mean = sum / runs, sd = std::sqrt((sum2 - sum * sum / runs) / (runs - 1));
      BOOST_TEST_MESSAGE("subset p0 = " << p0 << ", N = " << N << ": mean Pf " << mean
                                        << " (exact " << exact << "), run COV " << sd / mean);
      BOOST_TEST(std::abs(mean - exact) < 3 * sd / std::sqrt(double(runs)));
    }
}
