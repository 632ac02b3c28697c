// The banded LU solver ("band-lu": LAPACK's dgbtrf/dgbtrs after a
// Cuthill-McKee numbering) against Eigen's SparseLU, an independent sparse
// LU, on nonsymmetric matrices whose equations are numbered far from a band
// (a path graph shuffled, a coupling between its two ends) and one with a
// zero diagonal entry, which only a row interchange gets past. Tolerance
// 1e-12 of the solution's norm: both factorisations are backward stable and
// the matrices well conditioned (condition numbers below 1e2), so they agree
// to a few hundred round-offs. A refactorisation with other values of the
// same pattern solves that matrix; a singular one is a NumericalError, and
// so is one with a NaN or inf entry or whose factor overflows (LAPACK
// reports only exact zero pivots), as UMFPACK refuses them. A 0 x 0 matrix
// gives the empty solution; a band beyond band-lu's 2 GiB limit (an arrow
// matrix of 20 000 equations: bandwidths about n, 9.6 GB of band) is
// refused before it is allocated, in the words the caller gave for asking
// for UMFPACK instead. The numbering is deal.II's Cuthill-McKee
// numbering, checked against deal.II itself.
#include <poundfe/assembly/band_lu_solver.h>
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <boost/test/unit_test.hpp>

#include <Eigen/SparseLU>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>

using namespace poundfe;

namespace
{
  /// A chain i - (i+1) of n equations, nonsymmetric and scaled by s, its
  /// equations renumbered by a fixed shuffle, with a coupling of the chain's
  /// two ends; `zero_pivot`: the first equation's diagonal is 0.
  SparseMatrix
  shuffled_chain(const int n, const double s, const bool zero_pivot = false)
  {
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(5));
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i)
      {
        t.emplace_back(order[i], order[i], zero_pivot && i == 0 ? 0.0 : s * (4.0 + 0.1 * i));
        if (i + 1 < n)
          {
            t.emplace_back(order[i], order[i + 1], -s);
            t.emplace_back(order[i + 1], order[i], -0.5 * s);
          }
      }
    t.emplace_back(order[0], order[n - 1], 0.3 * s);
    SparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    return A;
  }

  Vector
  reference_solution(const SparseMatrix &A, const Vector &b)
  {
    Eigen::SparseLU<SparseMatrix> lu(A);
    return lu.solve(b);
  }
} // namespace

BOOST_AUTO_TEST_CASE(band_lu_solves_as_a_sparse_lu)
{
  const int    n      = 60;
  const Vector b      = Vector::LinSpaced(n, 1.0, 2.0);
  auto         solver = create_linear_solver("band-lu");
  BOOST_TEST(solver->name() == "band-lu");
  for (const bool zero_pivot : {false, true})
    {
      const SparseMatrix A = shuffled_chain(n, 1.0, zero_pivot);
      solver->analyze_and_factorize(A);
      Vector x;
      solver->solve(b, x);
      const Vector reference = reference_solution(A, b);
      BOOST_TEST((x - reference).norm() <= 1e-12 * reference.norm());
      BOOST_TEST((A * x - b).norm() <= 1e-12 * b.norm());
    }
  // refactorised with other values of the analysed pattern
  const SparseMatrix other = shuffled_chain(n, 3.5, true);
  solver->factorize(other);
  Vector x;
  solver->solve(b, x);
  const Vector reference = reference_solution(other, b);
  BOOST_TEST((x - reference).norm() <= 1e-12 * reference.norm());
}

BOOST_AUTO_TEST_CASE(band_lu_refuses_a_singular_matrix)
{
  SparseMatrix A = shuffled_chain(20, 1.0);
  auto         solver = create_linear_solver("band-lu");
  solver->analyze(A);
  A *= 0.0; // the pattern kept, every value zero
  BOOST_CHECK_THROW(solver->factorize(A), NumericalError);
}

BOOST_AUTO_TEST_CASE(band_lu_refuses_a_non_finite_matrix)
{
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()})
    {
      SparseMatrix A      = shuffled_chain(20, 1.0);
      auto         solver = create_linear_solver("band-lu");
      solver->analyze_and_factorize(A);
      A.coeffRef(7, 7) = bad;
      BOOST_CHECK_THROW(solver->factorize(A), NumericalError);
    }
  // finite entries, a factor that overflows: with the row interchange
  // (|1| = |-1|, the first row kept) U(1,1) = 1e308 + 1e308 = inf
  SparseMatrix A(2, 2);
  A.insert(0, 0) = 1.0;
  A.insert(0, 1) = 1e308;
  A.insert(1, 0) = -1.0;
  A.insert(1, 1) = 1e308;
  A.makeCompressed();
  auto solver = create_linear_solver("band-lu");
  solver->analyze(A);
  BOOST_CHECK_THROW(solver->factorize(A), NumericalError);
}

BOOST_AUTO_TEST_CASE(band_lu_solves_an_empty_matrix)
{
  SparseMatrix A(0, 0);
  A.makeCompressed();
  auto solver = create_linear_solver("band-lu");
  solver->analyze_and_factorize(A);
  Vector x = Vector::Ones(3);
  solver->solve(Vector(0), x);
  BOOST_TEST(x.size() == 0);
}

BOOST_AUTO_TEST_CASE(band_lu_refuses_a_band_beyond_its_limit)
{
  // an arrow: equation 0 coupled to every other; any numbering leaves a
  // bandwidth of about n / 2 on each side (Cuthill-McKee's about n)
  const int                           n = 20000;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i)
    {
      t.emplace_back(i, i, 4.0);
      if (i > 0)
        {
          t.emplace_back(0, i, 1.0);
          t.emplace_back(i, 0, -1.0);
        }
    }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  // the refusal ends with the caller's remedy: `poundfe run`'s entry, the
  // interpreter's command
  const auto refused_with = [&A](LinearSolver &solver, const std::string &remedy) {
    try
      {
        solver.analyze(A);
      }
    catch (const NumericalError &e)
      {
        const std::string message = e.what();
        return message.size() >= remedy.size() &&
               message.compare(message.size() - remedy.size(), remedy.size(), remedy) == 0;
      }
    return false;
  };
  BOOST_TEST(refused_with(*create_linear_solver("band-lu"), "set Linear solver = umfpack"));
  BOOST_TEST(refused_with(*create_band_lu_solver("give system UmfPack"), "give system UmfPack"));
}

namespace
{
  /// deal.II's Cuthill-McKee numbering of the symmetrised pattern of A with
  /// its diagonal: the reference the deal.II-free numbering must equal.
  std::vector<int>
  deal_ii_numbering(const SparseMatrix &A)
  {
    const unsigned int             n = A.rows();
    dealii::DynamicSparsityPattern pattern(n, n);
    for (unsigned int j = 0; j < n; ++j)
      {
        pattern.add(j, j);
        for (SparseMatrix::InnerIterator it(A, j); it; ++it)
          {
            pattern.add(it.row(), j);
            pattern.add(j, it.row());
          }
      }
    std::vector<dealii::types::global_dof_index> new_index(n);
    dealii::SparsityTools::reorder_Cuthill_McKee(pattern, new_index);
    return std::vector<int>(new_index.begin(), new_index.end());
  }

  /// n equations, each coupled to `per_row` others drawn at random (a
  /// nonsymmetric pattern), and `isolated` equations coupled to none: some
  /// draws leave the graph in several parts.
  SparseMatrix
  random_pattern(const int n, const int per_row, const int isolated, const unsigned int seed)
  {
    std::mt19937                        draw(seed);
    std::uniform_int_distribution<int>  column(0, n - 1);
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i)
      {
        t.emplace_back(i, i, 1.0);
        if (i >= n - isolated)
          continue;
        for (int k = 0; k < per_row; ++k)
          {
            const int j = column(draw);
            if (j < n - isolated)
              t.emplace_back(i, j, 1.0);
          }
      }
    SparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    return A;
  }
} // namespace

// The deal.II-free Cuthill-McKee numbering (band_lu_solver.cc) against
// deal.II's SparsityTools::reorder_Cuthill_McKee, exactly (tolerance 0: a
// numbering is integers): random patterns from 1 to 300 equations, sparse
// ones in many parts, with isolated equations, dense ones (every equation
// coupled to all: the starting rule's fallback), the shuffled chain.
BOOST_AUTO_TEST_CASE(cuthill_mckee_numbers_as_deal_ii)
{
  unsigned int seed = 1;
  for (const int n : {1, 2, 3, 7, 40, 300})
    for (const int per_row : {0, 1, 2, 5})
      for (const int isolated : {0, 1, 3})
        if (isolated < n)
          {
            const SparseMatrix A = random_pattern(n, per_row, isolated, seed++);
            BOOST_TEST(cuthill_mckee_numbering(A) == deal_ii_numbering(A),
                       "n " << n << ", per row " << per_row << ", isolated " << isolated);
          }
  for (const int n : {1, 2, 6})
    {
      const SparseMatrix full = Eigen::MatrixXd::Ones(n, n).sparseView();
      BOOST_TEST(cuthill_mckee_numbering(full) == deal_ii_numbering(full));
    }
  const SparseMatrix chain = shuffled_chain(60, 1.0);
  BOOST_TEST(cuthill_mckee_numbering(chain) == deal_ii_numbering(chain));
}
