// The solve of a small model's effective matrix three ways, for the choice of
// a fixed-size path (doc/benchmarks.md, "The step and its output"): Eigen's
// SimplicialLDLT as the eigen-ldlt solver uses it (permutation by index, L,
// D^-1, L^T; source/assembly/linear_solver.cc), Eigen's dense LDLT on storage
// of fixed maximum size 24 x 24 (no allocation) and L D L^T without pivoting
// in plain loops on a 24 x 24 array. The matrix: two shear buildings' K_eff
// (3 + 2 storeys, tridiagonal blocks) at 5 equations, and the same pattern
// at more. Each way prints the sum of the last unknown over the solves (they
// agree); the count to compare is callgrind's inclusive one of each
// *_solves function over 1 000 000 solves:
//
//   valgrind --tool=callgrind build/poundfe-bench-small-solve [equations]
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <vector>

using SparseMatrix = Eigen::SparseMatrix<double>;
using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 24, 24>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 24, 1>;

__attribute__((noinline)) double sparse_solves(const SparseMatrix &a, long n_solves)
{
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  ldlt.compute(a);
  const Eigen::Index n = a.rows();
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1, 2), x(n), buffer(n);
  const Eigen::VectorXd inverse_d = ldlt.vectorD().cwiseInverse();
  double sum = 0;
  for (long s = 0; s < n_solves; ++s)
    {
      b[0] += 1e-9;
      const auto &p = ldlt.permutationP().indices();
      if (p.size() > 0)
        for (Eigen::Index i = 0; i < n; ++i) buffer[p[i]] = b[i];
      else
        buffer = b;
      ldlt.matrixL().solveInPlace(buffer);
      buffer.array() *= inverse_d.array();
      ldlt.matrixU().solveInPlace(buffer);
      const auto &q = ldlt.permutationPinv().indices();
      if (q.size() > 0)
        for (Eigen::Index j = 0; j < n; ++j) x[q[j]] = buffer[j];
      else
        x = buffer;
      sum += x[n - 1];
    }
  return sum;
}

__attribute__((noinline)) double dense_solves(const SparseMatrix &a, long n_solves)
{
  const Small dense = Small(Eigen::MatrixXd(a));
  Eigen::LDLT<Small> ldlt(dense);
  const Eigen::Index n = a.rows();
  SmallVector b = SmallVector::LinSpaced(n, 1, 2), x(n);
  double sum = 0;
  for (long s = 0; s < n_solves; ++s)
    {
      b[0] += 1e-9;
      x = ldlt.solve(b);
      sum += x[n - 1];
    }
  return sum;
}

__attribute__((noinline)) double loop_solves(const SparseMatrix &a, long n_solves)
{
  // L D L^T without pivoting in plain loops on a 24 x 24 array
  const int n = a.rows();
  double l[24][24] = {}, d[24], b[24], x[24];
  const Eigen::MatrixXd dense(a);
  for (int j = 0; j < n; ++j)
    {
      double s = dense(j, j);
      for (int k = 0; k < j; ++k) s -= l[j][k] * l[j][k] * d[k];
      d[j] = s;
      for (int i = j + 1; i < n; ++i)
        {
          double t = dense(i, j);
          for (int k = 0; k < j; ++k) t -= l[i][k] * l[j][k] * d[k];
          l[i][j] = t / s;
        }
    }
  for (int i = 0; i < n; ++i) b[i] = 1 + i / double(n - 1);
  double sum = 0;
  for (long s = 0; s < n_solves; ++s)
    {
      b[0] += 1e-9;
      for (int i = 0; i < n; ++i) { double t = b[i]; for (int k = 0; k < i; ++k) t -= l[i][k] * x[k]; x[i] = t; }
      for (int i = 0; i < n; ++i) x[i] /= d[i];
      for (int i = n - 1; i >= 0; --i) { double t = x[i]; for (int k = i + 1; k < n; ++k) t -= l[k][i] * x[k]; x[i] = t; }
      sum += x[n - 1];
    }
  return sum;
}

int main(int argc, char **argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 5;
  SparseMatrix a(n, n);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i)
    {
      t.emplace_back(i, i, 4e9 + i);
      if (i + 1 < n && i != 2) { t.emplace_back(i, i + 1, -1e9); t.emplace_back(i + 1, i, -1e9); }
    }
  a.setFromTriplets(t.begin(), t.end());
  const long m = 1000000;
  std::printf("%d equations: %.17g %.17g %.17g\n", n, sparse_solves(a, m), dense_solves(a, m), loop_solves(a, m));
}
