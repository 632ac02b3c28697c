// Krylov–Newton, BFGS and the line search (integration/newton_acceleration.h)
// on small problems with independent references:
//  - a linear system K u = b with H_0 = diag(K)^{-1}: Krylov–Newton with a
//    subspace as large as the system is a Krylov method, so it ends at the
//    direct solution (Eigen's LLT, computed here) to round-off in at most
//    n + 1 iterations (Carlson & Miller 1998, §3); BFGS reaches it too;
//  - the BFGS secant condition H_1 y_0 = s_0 (Matthies & Strang 1979, eq. 9),
//    exact up to round-off;
//  - a cubic system R(u) = b - K u - c u^3 (componentwise): Krylov–Newton
//    and BFGS on a frozen tangent converge to the root found by full Newton
//    written in this test, in fewer iterations than modified Newton;
//  - the secant line search finds the root of a linear G(s) in one step
//    (exact: the secant of a line is the line).
#include <poundfe/integration/newton_acceleration.h>

#include <boost/test/unit_test.hpp>

#include <Eigen/Dense>

#include <cmath>

using namespace poundfe;

namespace
{
  /// An SPD matrix with strong off-diagonal coupling (a chain of springs).
  Eigen::MatrixXd
  chain_matrix(const int n)
  {
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
      {
        K(i, i) = 2.0 + 0.5 * i;
        if (i + 1 < n)
          K(i, i + 1) = K(i + 1, i) = -0.9 - 0.05 * i;
      }
    return K;
  }

  /// Iterations of u += correction(R(u)) until ||R|| <= 1e-12 ||R(0)||;
  /// `correction` sees the residual and records the step it returns.
  template <typename Residual, typename Correction>
  unsigned int
  iterate(const Residual &residual, const Correction &correction, Vector &u, unsigned int max)
  {
    u.setZero();
    Vector       r  = residual(u);
    const double r0 = r.norm();
    for (unsigned int it = 1; it <= max; ++it)
      {
        u += correction(r);
        r = residual(u);
        if (r.norm() <= 1e-12 * r0)
          return it;
      }
    return max + 1;
  }
  /// The correction of `update` (KrylovAcceleration or BfgsUpdate), which
  /// records the step it returns.
  template <typename Update>
  auto
  accelerated(Update &update, const InverseOperator &h0)
  {
    return [&update, &h0](const Vector &r) {
      Vector d;
      update.direction(r, h0, d);
      update.record_step(d);
      return d;
    };
  }

  /// The modified-Newton correction H_0 R.
  auto
  frozen(const InverseOperator &h0)
  {
    return [&h0](const Vector &r) {
      Vector d;
      h0(r, d);
      return d;
    };
  }
} // namespace

BOOST_AUTO_TEST_CASE(krylov_newton_solves_a_linear_system_in_n_plus_one_iterations)
{
  const int             n = 8;
  const Eigen::MatrixXd K = chain_matrix(n);
  const Vector          b = Vector::LinSpaced(n, 1.0, -0.5);
  const Vector          exact = K.llt().solve(b);
  const Vector          diagonal = K.diagonal();
  const InverseOperator h0 = [&](const Vector &x, Vector &y) { y = x.cwiseQuotient(diagonal); };
  const auto            residual = [&](const Vector &u) -> Vector { return b - K * u; };

  KrylovAcceleration krylov(n);
  Vector             u(n);
  const unsigned int k_iterations = iterate(residual, accelerated(krylov, h0), u, 50);
  BOOST_TEST(k_iterations <= static_cast<unsigned int>(n + 1));
  BOOST_TEST((u - exact).norm() <= 1e-10 * exact.norm());

  const unsigned int modified = iterate(residual, frozen(h0), u, 10000);
  BOOST_TEST_MESSAGE("linear system of " << n << ": Krylov–Newton " << k_iterations
                                         << " iterations, modified Newton " << modified);
  BOOST_TEST(modified > 3 * k_iterations);

  BfgsUpdate   bfgs(n);
  const unsigned int b_iterations = iterate(residual, accelerated(bfgs, h0), u, 200);
  BOOST_TEST_MESSAGE("BFGS " << b_iterations << " iterations");
  BOOST_TEST(b_iterations < modified);
  BOOST_TEST((u - exact).norm() <= 1e-10 * exact.norm());
}

BOOST_AUTO_TEST_CASE(bfgs_update_meets_the_secant_condition)
{
  const int             n = 5;
  const Eigen::MatrixXd K = chain_matrix(n);
  const Vector          diagonal = K.diagonal();
  const InverseOperator h0 = [&](const Vector &x, Vector &y) { y = x.cwiseQuotient(diagonal); };
  // R(u) = b - K u: a step s from u = 0 gives y = R_0 - R_1 = K s.
  const Vector b = Vector::LinSpaced(n, 2.0, 1.0);
  const Vector s = Vector::LinSpaced(n, 0.3, -0.1);
  const Vector y = K * s;
  // H_1 y = s, with H_1 applied by the two-loop recursion to R_1 and to
  // R_1 - y (H_1 is linear): H_1 y = H_1 R_1 - H_1 (R_1 - y). The second
  // call follows no recorded step, so it adds no pair.
  const Vector r1 = b - y, other = r1 - y;
  Vector       ignored, h_r1, h_other;
  BfgsUpdate   bfgs(3);
  bfgs.direction(b, h0, ignored);
  bfgs.record_step(s);
  bfgs.direction(r1, h0, h_r1);
  bfgs.direction(other, h0, h_other);
  BOOST_TEST(bfgs.n_pairs() == 1u);
  BOOST_TEST((h_r1 - h_other - s).norm() <= 1e-14 * s.norm() * 10);
}

BOOST_AUTO_TEST_CASE(accelerated_corrections_find_the_newton_root_of_a_cubic_system)
{
  const int             n = 10;
  const Eigen::MatrixXd K = chain_matrix(n);
  const Vector          b = Vector::LinSpaced(n, 0.9, -0.6);
  const double          c = 1.0;
  const auto residual = [&](const Vector &u) -> Vector { return b - K * u - c * u.array().cube().matrix(); };
  // full Newton, the reference: K_t = K + 3 c diag(u^2)
  Vector root = Vector::Zero(n);
  for (int it = 0; it < 50; ++it)
    {
      Eigen::MatrixXd tangent = K;
      tangent.diagonal() += 3 * c * root.array().square().matrix();
      root += tangent.lu().solve(residual(root));
    }
  BOOST_TEST(residual(root).norm() <= 1e-13 * b.norm());
  // the frozen tangent: at u = 0, H_0 = K^{-1}
  const Eigen::LLT<Eigen::MatrixXd> llt(K);
  const InverseOperator h0 = [&](const Vector &x, Vector &y) { y = llt.solve(x); };

  Vector             u(n);
  const unsigned int modified = iterate(residual, frozen(h0), u, 10000);
  KrylovAcceleration krylov(5);
  const unsigned int krylov_iterations = iterate(residual, accelerated(krylov, h0), u, 200);
  BOOST_TEST((u - root).norm() <= 1e-10 * root.norm());
  BfgsUpdate         bfgs(5);
  const unsigned int bfgs_iterations = iterate(residual, accelerated(bfgs, h0), u, 200);
  BOOST_TEST((u - root).norm() <= 1e-10 * root.norm());
  BOOST_TEST_MESSAGE("cubic system: modified Newton " << modified << ", Krylov–Newton "
                                                      << krylov_iterations << ", BFGS "
                                                      << bfgs_iterations << " iterations");
  BOOST_TEST(krylov_iterations < modified);
  BOOST_TEST(bfgs_iterations < modified);
}

BOOST_AUTO_TEST_CASE(secant_line_search_finds_the_root_of_a_linear_work)
{
  // G(s) = G0 (1 - s / 0.4): the secant through s = 0 and s = 1 hits 0.4.
  const double         g0 = 2.0;
  const auto           g  = [&](const double s) { return g0 * (1 - s / 0.4); };
  LineSearchParameters parameters;
  BOOST_TEST(line_search(g0, g(1.0), g, parameters) == 0.4, boost::test_tools::tolerance(1e-15));
  // a full step that is good enough is kept
  BOOST_TEST(line_search(g0, 0.5 * g0, g, parameters) == 1.0);
  // a nonlinear G: the result meets |G(s)| <= eta |G(0)|
  const auto   curved = [](const double s) { return 1.0 - 3 * s + s * s * s; };
  const double s      = line_search(curved(0), curved(1), curved, parameters);
  BOOST_TEST(std::abs(curved(s)) <= parameters.tolerance * std::abs(curved(0)));
}
