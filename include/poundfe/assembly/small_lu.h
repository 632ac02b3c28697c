// LU with partial pivoting of a small dense system in fixed storage, with
// the arithmetic of Eigen 3.4's PartialPivLU on a dynamic matrix of at most
// 8 equations (its unblocked factorisation below 16 equations, its
// triangular solves within one panel of 8 unknowns), so that both give the
// same bits without Eigen's allocations and blocking bookkeeping:
//   for k = 0 .. n-1: p = the first i >= k of the largest |a_ik|; rows k and
//     p swapped; where a_pk != 0, l_ik = a_ik / a_kk (i > k); then
//     a_ij -= l_ik a_kj (i, j > k);
//   solve: b permuted as the rows were; L y = b forward with L's unit
//   diagonal, U x = y backward, each unknown divided by u_kk and
//   eliminated from the others only when it is not exactly 0 (Eigen's
//   triangular_solve_vector).
// Source: Eigen 3.4, LU/PartialPivLU.h (partial_lu_impl::unblocked_lu,
// _solve_impl), Core/products/TriangularSolverVector.h.
#ifndef poundfe_assembly_small_lu_h
#define poundfe_assembly_small_lu_h

#include <array>
#include <cmath>
#include <utility>

namespace poundfe
{
  class SmallLU
  {
  public:
    /// The largest system: Eigen's triangular solves work in panels of 8
    /// unknowns, and beyond one panel sum in another order.
    static constexpr unsigned int max_size = 8;

    /// Factorises the n x n matrix whose entry (i, j) is a(i, j), n <=
    /// max_size. Returns false when a pivot is exactly 0 (singular), as
    /// Eigen's factors would have a zero on U's diagonal.
    template <typename Matrix>
    bool
    factorize(const Matrix &a, const unsigned int n)
    {
      size = n;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          lu[i][j] = a(i, j);
      for (unsigned int k = 0; k < n; ++k)
        {
          unsigned int p       = k;
          double       biggest = std::abs(lu[k][k]);
          for (unsigned int i = k + 1; i < n; ++i)
            if (std::abs(lu[i][k]) > biggest)
              {
                biggest = std::abs(lu[i][k]);
                p       = i;
              }
          transpositions[k] = p;
          if (biggest != 0) // a zero pivot: no division, the update goes on
            {
              if (p != k)
                std::swap(lu[k], lu[p]);
              for (unsigned int i = k + 1; i < n; ++i)
                lu[i][k] /= lu[k][k];
            }
          for (unsigned int i = k + 1; i < n; ++i)
            for (unsigned int j = k + 1; j < n; ++j)
              lu[i][j] -= lu[i][k] * lu[k][j];
        }
      for (unsigned int k = 0; k < n; ++k)
        if (lu[k][k] == 0)
          return false;
      return true;
    }

    /// x = A^-1 b with the last factorisation (x and b of its size; x may
    /// be b).
    template <typename Vector>
    void
    solve(const Vector &b, Vector &x) const
    {
      std::array<double, max_size> y;
      for (unsigned int i = 0; i < size; ++i)
        y[i] = b[i];
      for (unsigned int k = 0; k < size; ++k)
        std::swap(y[k], y[transpositions[k]]);
      for (unsigned int i = 0; i < size; ++i) // L y = P b
        if (y[i] != 0)
          for (unsigned int j = i + 1; j < size; ++j)
            y[j] -= y[i] * lu[j][i];
      for (unsigned int i = size; i-- > 0;) // U x = y
        if (y[i] != 0)
          {
            y[i] /= lu[i][i];
            for (unsigned int j = 0; j < i; ++j)
              y[j] -= y[i] * lu[j][i];
          }
      for (unsigned int i = 0; i < size; ++i)
        x[i] = y[i];
    }

  private:
    unsigned int                                           size = 0;
    std::array<std::array<double, max_size>, max_size>     lu{};
    std::array<unsigned int, max_size>                     transpositions{};
  };
} // namespace poundfe

#endif
