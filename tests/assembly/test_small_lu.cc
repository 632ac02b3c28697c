// SmallLU (assembly/small_lu.h) against Eigen 3.4's PartialPivLU on the same
// dynamic matrices: the same bits of every solution, and the same verdict
// on singularity (a zero on U's diagonal), for 1 to 8 equations. Tolerance:
// none, the bits must be identical (`poundfe opensees` solves its small
// systems with SmallLU where it solved them with PartialPivLU, and its
// recorders' files must not change). The matrices: random entries of mixed
// signs and magnitudes; entries drawn from {-2, -1, 0, 1, 2}, where pivots
// tie in magnitude and whole columns vanish (zero pivots, singular
// matrices); right-hand sides with exact zeros (which the triangular solves
// skip) and negative zeros. The test fails on a pivot rule that takes the
// last of equal pivots, on a solve that divides a zero unknown (-0 for a
// negative u_kk), or on a reciprocal multiplied in place of the division.
#include <poundfe/assembly/small_lu.h>

#include <boost/test/unit_test.hpp>

#include <Eigen/LU>

#include <cstring>
#include <random>

using namespace poundfe;

namespace
{
  bool
  same_bits(const double a, const double b)
  {
    return std::memcmp(&a, &b, sizeof a) == 0;
  }

  /// A random n x n matrix: continuous entries, or small integers (ties,
  /// zeros, singular matrices).
  Eigen::MatrixXd
  random_matrix(std::mt19937 &random, const int n, const bool integers)
  {
    std::uniform_real_distribution<double> value(-1, 1), exponent(-3, 3);
    std::uniform_int_distribution<int>     small(-2, 2);
    Eigen::MatrixXd                        a(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        a(i, j) = integers ? small(random) : value(random) * std::pow(10.0, exponent(random));
    return a;
  }

  Eigen::VectorXd
  random_rhs(std::mt19937 &random, const int n)
  {
    std::uniform_int_distribution<int>     kind(0, 4);
    std::uniform_real_distribution<double> value(-1, 1);
    Eigen::VectorXd                        b(n);
    for (int i = 0; i < n; ++i)
      {
        const int k = kind(random);
        b[i]        = k == 0 ? 0.0 : k == 1 ? -0.0 : value(random);
      }
    return b;
  }
} // namespace

BOOST_AUTO_TEST_CASE(small_lu_gives_eigen_partial_piv_lu_bits)
{
  std::mt19937 random(20261207);
  unsigned int n_solutions = 0, n_singular = 0;
  for (int trial = 0; trial < 40000; ++trial)
    {
      const int             n = 1 + trial % SmallLU::max_size;
      const Eigen::MatrixXd a = random_matrix(random, n, trial % 3 == 0);
      Eigen::PartialPivLU<Eigen::MatrixXd> eigen(a);
      const bool eigen_singular = (eigen.matrixLU().diagonal().array() == 0).any();
      SmallLU    small;
      BOOST_REQUIRE_EQUAL(!small.factorize(a, n), eigen_singular);
      if (eigen_singular)
        {
          ++n_singular;
          continue;
        }
      for (int r = 0; r < 3; ++r)
        {
          const Eigen::VectorXd b = random_rhs(random, n);
          const Eigen::VectorXd x = eigen.solve(b);
          Eigen::VectorXd       y(n);
          small.solve(b, y);
          for (int i = 0; i < n; ++i)
            BOOST_REQUIRE_MESSAGE(same_bits(x[i], y[i]), "n " << n << " trial " << trial
                                                              << " x[" << i << "] " << x[i]
                                                              << " vs " << y[i]);
          ++n_solutions;
        }
    }
  BOOST_TEST_MESSAGE("SmallLU: " << n_solutions << " solutions, " << n_singular
                                  << " singular matrices, the same as PartialPivLU's");
  // both kinds of matrices were met
  BOOST_TEST(n_singular > 100u);
  BOOST_TEST(n_solutions > 90000u);
}
