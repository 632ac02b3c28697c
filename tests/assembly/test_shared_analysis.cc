// A symbolic analysis shared between solvers of one pattern
// (LinearSolver::reuse_analysis; UMFPACK): the solver that takes over
// another's analysis solves its own matrix (other values, same pattern) to
// round-off of Eigen's SparseLU solution of it (an independent
// factorisation; 1e-12 relative: both are backward stable on a
// well-conditioned matrix), also after the first solver is gone; a
// different pattern, or a backend that cannot share, is refused.
#include <poundfe/assembly/linear_solver.h>

#include <boost/test/unit_test.hpp>

#include <Eigen/SparseLU>

using namespace poundfe;

namespace
{
  /// A tridiagonal, diagonally dominant, nonsymmetric matrix scaled by s,
  /// with an extra coupling (0, n-1) when `wide`.
  SparseMatrix
  banded(const int n, const double s, const bool wide = false)
  {
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i)
      {
        t.emplace_back(i, i, s * (4.0 + 0.1 * i));
        if (i + 1 < n)
          {
            t.emplace_back(i, i + 1, -s);
            t.emplace_back(i + 1, i, -0.5 * s);
          }
      }
    if (wide)
      t.emplace_back(0, n - 1, 0.3);
    SparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    return A;
  }
} // namespace

BOOST_AUTO_TEST_CASE(umfpack_shares_its_analysis_within_a_pattern)
{
  const int    n = 40;
  const Vector b = Vector::LinSpaced(n, 1.0, 2.0);
  auto         first = create_linear_solver("umfpack");
  first->analyze_and_factorize(banded(n, 1.0));
  auto               second = create_linear_solver("umfpack");
  const SparseMatrix other  = banded(n, 3.5);
  BOOST_TEST(second->reuse_analysis(*first, other));
  first.reset(); // the analysis outlives the solver that made it
  second->factorize(other);
  Vector x;
  second->solve(b, x);
  Eigen::SparseLU<SparseMatrix> lu(other);
  const Vector reference = lu.solve(b);
  BOOST_TEST((x - reference).norm() <= 1e-12 * reference.norm());

  auto third = create_linear_solver("umfpack");
  BOOST_TEST(!third->reuse_analysis(*second, banded(n, 1.0, true))); // another pattern
  auto ldlt = create_linear_solver("eigen-ldlt");
  BOOST_TEST(!ldlt->reuse_analysis(*second, other)); // a backend that does not share
  BOOST_TEST(!third->analyze_or_reuse(nullptr, other));
}
