// Banded LU with partial pivoting (LAPACK's dgbtrf/dgbtrs) after a
// Cuthill–McKee numbering of the effective matrix's graph (deal.II's
// SparsityTools::reorder_Cuthill_McKee; Cuthill & McKee 1969).
//   P A P^T = L U, A of lower and upper bandwidths kl, ku once renumbered;
//   the factorisation costs about n kl (kl + ku) multiply-adds and the
//   storage (2 kl + ku + 1) n numbers (LAPACK's band layout: the pivoting
//   fills kl more superdiagonals), a solve 2 n (2 kl + ku).
// For the mid-size nonsymmetric tangents of plane frame pairs (a few hundred
// equations, the floors' nodes side by side: kl = ku of a few dozen) this
// is several times cheaper than UMFPACK's general sparse factorisation and
// its iterative refinement, refactorised at every Newton iteration
// (doc/benchmarks.md, the fibre pair). The numbering and the map of each
// stored entry to its place in the band are made once per pattern
// (analyze); factorize and solve allocate nothing. Sources: E. Anderson et
// al. (1999), LAPACK Users' Guide, 3rd ed., SIAM, §2.4.2 and §5.3.3; E.
// Cuthill & J. McKee (1969), Proc. 24th ACM National Conference, 157-172.
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

extern "C"
{
  void dgbtrf_(const int *m, const int *n, const int *kl, const int *ku, double *ab,
               const int *ldab, int *ipiv, int *info);
  void dgbtrs_(const char *trans, const int *n, const int *kl, const int *ku, const int *nrhs,
               const double *ab, const int *ldab, const int *ipiv, double *b, const int *ldb,
               int *info, std::size_t trans_length);
}

namespace poundfe
{
  namespace
  {
    /// new_index[i]: the place of equation i in the Cuthill–McKee numbering
    /// of the symmetrised pattern of `matrix`.
    std::vector<int>
    cuthill_mckee_numbering(const SparseMatrix &matrix)
    {
      const unsigned int              n = matrix.rows();
      dealii::DynamicSparsityPattern pattern(n, n);
      for (unsigned int j = 0; j < n; ++j)
        {
          pattern.add(j, j);
          for (SparseMatrix::InnerIterator it(matrix, j); it; ++it)
            {
              pattern.add(it.row(), j);
              pattern.add(j, it.row());
            }
        }
      std::vector<dealii::types::global_dof_index> new_index(n);
      dealii::SparsityTools::reorder_Cuthill_McKee(pattern, new_index);
      return std::vector<int>(new_index.begin(), new_index.end());
    }

    /// The largest band storage band-lu takes (2 GiB): beyond it the band is
    /// the wrong format (umfpack stores only the fill), and LAPACK's 32-bit
    /// indices stay far from overflow below it.
    constexpr std::size_t max_band_bytes = std::size_t(1) << 31;

    class BandLuSolver : public LinearSolver
    {
    public:
      void
      analyze(const SparseMatrix &matrix) override
      {
        n     = matrix.rows();
        lower = upper = 0;
        leading       = 1;
        new_index.clear();
        place.clear();
        band.clear();
        if (n == 0)
          return;
        new_index = cuthill_mckee_numbering(matrix);
        for (int j = 0; j < n; ++j)
          for (SparseMatrix::InnerIterator it(matrix, j); it; ++it)
            {
              const int offset = new_index[it.row()] - new_index[j];
              lower            = std::max(lower, offset);
              upper            = std::max(upper, -offset);
            }
        // LAPACK's layout: A(i, j) at ab[(kl + ku + i - j) + j ldab], with
        // kl rows above for the fill of the row interchanges
        leading = 2 * lower + upper + 1;
        check_band_size();
        place.reserve(matrix.nonZeros());
        for (int j = 0; j < n; ++j)
          for (SparseMatrix::InnerIterator it(matrix, j); it; ++it)
            {
              const int row = new_index[it.row()], column = new_index[j];
              place.push_back(static_cast<std::size_t>(lower + upper + row - column) +
                              static_cast<std::size_t>(column) * leading);
            }
        band.assign(static_cast<std::size_t>(leading) * n, 0.0);
        pivots.assign(n, 0);
        buffer.resize(n);
      }
      void
      factorize(const SparseMatrix &matrix) override
      {
        Assert(static_cast<std::size_t>(matrix.nonZeros()) == place.size(),
               dealii::ExcMessage("factorize a matrix of the analysed pattern"));
        std::fill(band.begin(), band.end(), 0.0);
        if (n == 0)
          return;
        const double *values = matrix.valuePtr();
        bool          finite = true;
        for (std::size_t k = 0; k < place.size(); ++k)
          {
            band[place[k]] += values[k];
            finite = finite && std::isfinite(values[k]);
          }
        // dgbtrf reports only exact zero pivots: a NaN or inf entry, or a
        // factor that overflowed, is refused as UMFPACK refuses it
        if (!finite)
          throw_singular();
        int info = 0;
        dgbtrf_(&n, &n, &lower, &upper, band.data(), &leading, pivots.data(), &info);
        if (info > 0)
          throw_singular();
        AssertThrow(info == 0, dealii::ExcMessage("dgbtrf refused its arguments"));
        // U's diagonal: row kl + ku of the band
        for (int j = 0; j < n; ++j)
          if (!std::isfinite(band[lower + upper + static_cast<std::size_t>(j) * leading]))
            throw_singular();
      }
      void
      solve(const Vector &b, Vector &x) override
      {
        x.resize(n);
        if (n == 0)
          return;
        for (int i = 0; i < n; ++i)
          buffer[new_index[i]] = b[i];
        const int one = 1;
        int       info = 0;
        dgbtrs_("N", &n, &lower, &upper, &one, band.data(), &leading, pivots.data(),
                buffer.data(), &n, &info, 1);
        AssertThrow(info == 0, dealii::ExcMessage("dgbtrs refused its arguments"));
        for (int i = 0; i < n; ++i)
          x[i] = buffer[new_index[i]];
      }
      std::string
      name() const override
      {
        return "band-lu";
      }

    private:
      [[noreturn]] static void
      throw_singular()
      {
        throw NumericalError("band LU: the effective matrix is singular");
      }

      /// Refuses a band of more than max_band_bytes before it is allocated.
      void
      check_band_size() const
      {
        const double bytes = double(leading) * n * sizeof(double);
        if (bytes > double(max_band_bytes))
          throw NumericalError(
            "band-lu: the band of " + std::to_string(n) + " equations, bandwidths " +
            std::to_string(lower) + " and " + std::to_string(upper) + ", would take " +
            std::to_string(bytes / double(std::size_t(1) << 30)) +
            " GiB, more than its limit of 2 GiB; set Linear solver = umfpack");
      }

      int                      n = 0, lower = 0, upper = 0, leading = 1;
      std::vector<int>         new_index; // equation -> its place in the band
      std::vector<std::size_t> place;     // stored entry k -> its index in `band`
      std::vector<double>      band;      // the factors after factorize()
      std::vector<int>         pivots;
      Vector                   buffer;
    };
  } // namespace

  std::unique_ptr<LinearSolver>
  create_band_lu_solver()
  {
    return std::make_unique<BandLuSolver>();
  }
} // namespace poundfe
