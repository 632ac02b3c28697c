// Banded LU with partial pivoting (LAPACK's dgbtrf/dgbtrs) after a
// Cuthill–McKee numbering of the effective matrix's graph (the numbering
// of deal.II's SparsityTools::reorder_Cuthill_McKee, without deal.II;
// Cuthill & McKee 1969).
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
#include <poundfe/assembly/band_lu_solver.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/lean_assert.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
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
    /// The symmetrised pattern of `matrix` with its diagonal: the sorted
    /// neighbours of each equation (itself among them), as deal.II's
    /// DynamicSparsityPattern holds it.
    std::vector<std::vector<int>>
    symmetric_neighbours(const SparseMatrix &matrix)
    {
      std::vector<std::vector<int>> neighbours(matrix.rows());
      for (int j = 0; j < matrix.outerSize(); ++j)
        {
          neighbours[j].push_back(j);
          for (SparseMatrix::InnerIterator it(matrix, j); it; ++it)
            {
              neighbours[it.row()].push_back(j);
              neighbours[j].push_back(it.row());
            }
        }
      for (std::vector<int> &row : neighbours)
        {
          std::sort(row.begin(), row.end());
          row.erase(std::unique(row.begin(), row.end()), row.end());
        }
      return neighbours;
    }

    /// deal.II's find_unnumbered_starting_index: the first unnumbered
    /// equation of fewest neighbours (itself counted), fewer than n; failing
    /// that the first unnumbered one; -1 when all are numbered.
    int
    unnumbered_start(const std::vector<std::vector<int>> &neighbours,
                     const std::vector<int>               &new_index)
    {
      const int n     = neighbours.size();
      int       start = -1;
      for (int i = 0, fewest = n; i < n; ++i)
        if (new_index[i] < 0 && static_cast<int>(neighbours[i].size()) < fewest)
          {
            fewest = neighbours[i].size();
            start  = i;
          }
      if (start < 0)
        start = std::find(new_index.begin(), new_index.end(), -1) - new_index.begin();
      return start < n ? start : -1;
    }
  } // namespace

  std::vector<int>
  cuthill_mckee_numbering(const SparseMatrix &matrix)
  {
    // the fronts of a breadth-first search from a start of fewest
    // neighbours; each front numbered by its members' numbers of
    // neighbours, ties by their index; a new start for each unconnected
    // part (deal.II's reorder_Cuthill_McKee without starting indices)
    const std::vector<std::vector<int>> neighbours = symmetric_neighbours(matrix);
    std::vector<int>                    new_index(neighbours.size(), -1);
    std::vector<int>                    front, next_front;
    std::vector<std::pair<std::size_t, int>> by_neighbours;
    int                                  next_number = 0;
    for (int start = unnumbered_start(neighbours, new_index); start >= 0;
         start     = unnumbered_start(neighbours, new_index))
      {
        new_index[start] = next_number++;
        front            = {start};
        while (!front.empty())
          {
            next_front.clear();
            for (const int i : front)
              for (const int j : neighbours[i])
                if (new_index[j] < 0)
                  {
                    new_index[j] = 0; // in the front: not collected twice
                    next_front.push_back(j);
                  }
            by_neighbours.clear();
            for (const int j : next_front)
              by_neighbours.emplace_back(neighbours[j].size(), j);
            std::sort(by_neighbours.begin(), by_neighbours.end());
            for (const auto &[count, j] : by_neighbours)
              new_index[j] = next_number++;
            front.swap(next_front);
          }
      }
    return new_index;
  }

  namespace
  {
    /// The largest band storage band-lu takes (2 GiB): beyond it the band is
    /// the wrong format (umfpack stores only the fill), and LAPACK's 32-bit
    /// indices stay far from overflow below it.
    constexpr std::size_t max_band_bytes = std::size_t(1) << 31;

    class BandLuSolver : public LinearSolver
    {
    public:
      explicit BandLuSolver(const std::string &remedy)
        : remedy(remedy)
      {}
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
        if (info != 0)
          throw std::logic_error("dgbtrf refused its arguments");
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
        if (info != 0)
          throw std::logic_error("dgbtrs refused its arguments");
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
            " GiB, more than its limit of 2 GiB; " + remedy);
      }

      std::string              remedy; // the caller's words for UMFPACK instead
      int                      n = 0, lower = 0, upper = 0, leading = 1;
      std::vector<int>         new_index; // equation -> its place in the band
      std::vector<std::size_t> place;     // stored entry k -> its index in `band`
      std::vector<double>      band;      // the factors after factorize()
      std::vector<int>         pivots;
      Vector                   buffer;
    };
  } // namespace

  std::unique_ptr<LinearSolver>
  create_band_lu_solver(const std::string &remedy)
  {
    return std::make_unique<BandLuSolver>(remedy);
  }
} // namespace poundfe
