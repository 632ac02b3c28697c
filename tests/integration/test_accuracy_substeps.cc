// Sub-steps for accuracy (integration/accuracy_substeps.h, theory §3.7b):
//  - the Gershgorin bound of omega_max of a 2-storey shear building (k, m):
//    rows (2k, -k) and (-k, k) give sqrt(3k/m); the exact highest frequency,
//    from the closed-form eigenvalues (3 +- sqrt(5))/2 k/m, lies below it
//    and within 10 % of it;
//  - a massless equation (a rotation) does not enter the bound;
//  - the level: the smallest c with (dt / 2^c) omega <= 2 pi / N, checked
//    against the inequality itself on both sides, and 0 when N = 0.
#include <poundfe/integration/accuracy_substeps.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

using namespace poundfe;

namespace
{
  SparseMatrix
  dense_to_sparse_for_accuracy(const std::vector<std::vector<double>> &rows)
  {
    const int    n = rows.size();
    SparseMatrix matrix(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (rows[i][j] != 0)
          matrix.insert(i, j) = rows[i][j];
    matrix.makeCompressed();
    return matrix;
  }
} // namespace

BOOST_AUTO_TEST_CASE(gershgorin_bound_of_a_two_storey_shear_building)
{
  const double k = 4e6, m = 1000;
  const SparseMatrix stiffness = dense_to_sparse_for_accuracy({{2 * k, -k}, {-k, k}});
  const SparseMatrix mass      = dense_to_sparse_for_accuracy({{m, 0}, {0, m}});
  const double bound = highest_frequency_bound(stiffness, mass);
  BOOST_TEST(bound == std::sqrt(3 * k / m), boost::test_tools::tolerance(1e-14));
  const double exact = std::sqrt((3 + std::sqrt(5.0)) / 2 * k / m);
  BOOST_TEST(exact <= bound);
  BOOST_TEST(bound <= 1.1 * exact);
}

BOOST_AUTO_TEST_CASE(massless_equations_do_not_enter_the_bound)
{
  // a third, massless equation with a huge stiffness
  const SparseMatrix stiffness =
    dense_to_sparse_for_accuracy({{2e6, -1e6, 0}, {-1e6, 1e6, 0}, {0, 0, 1e12}});
  const SparseMatrix mass = dense_to_sparse_for_accuracy({{1e3, 0, 0}, {0, 1e3, 0}, {0, 0, 0}});
  BOOST_TEST(highest_frequency_bound(stiffness, mass) == std::sqrt(3e3),
             boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(level_is_the_smallest_that_meets_the_steps_per_period)
{
  const double omega = 109.5445, dt = 1e-2;
  for (const unsigned int n : {10u, 50u, 200u})
    {
      const unsigned int c = accuracy_level(dt, omega, n, 20);
      BOOST_TEST(dt / std::ldexp(1.0, c) * omega <= 2 * M_PI / n);
      if (c > 0)
        BOOST_TEST(dt / std::ldexp(1.0, c - 1) * omega > 2 * M_PI / n);
    }
  BOOST_TEST(accuracy_level(dt, omega, 50, 20) == 4u); // h = 6.25e-4 <= 1.147e-3 < 1.25e-3
  BOOST_TEST(accuracy_level(dt, omega, 0, 20) == 0u);
  BOOST_TEST(accuracy_level(dt, omega, 100000, 3) == 3u); // capped
}
