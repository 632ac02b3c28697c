// Solves (A + B D B^T) x = r with A factorised once and B = [b_1 ... b_m]
// fixed (each b_h has at most two nonzeros), D = diag(d_h) changing every
// call, by the Woodbury identity (Hager, SIAM Review 31 (1989) 221):
//   y = A^{-1} r,  (I + D_a G_aa) z = D_a B_a^T y,  x = y - W_a z,
// with W = A^{-1} B and G = B^T W computed once, and a = {h : d_h != 0}
// the active terms. The form with I + D G (rather than D^{-1} + G) stays
// valid when some d_h vanish or change sign. Per call: one solve with A and
// a dense LU of size |a|; nothing is allocated.
#ifndef poundfe_assembly_low_rank_update_h
#define poundfe_assembly_low_rank_update_h

#include <poundfe/assembly/linear_solver.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace poundfe
{
  /// A column b of B: rows < 0 are ignored.
  struct SparseColumn
  {
    std::array<int, 2>    rows{{-1, -1}};
    std::array<double, 2> values{{0.0, 0.0}};
  };

  class LowRankUpdateSolver
  {
  public:
    /// `factorised` must hold the factorisation of A for as long as this
    /// object is used.
    void initialize(LinearSolver &factorised, const std::vector<SparseColumn> &columns,
                    unsigned int n_rows);

    /// x = (A + B diag(d) B^T)^{-1} r. Throws NumericalError if the
    /// capacitance matrix is singular.
    void solve(const Vector &r, const std::vector<double> &d, Vector &x);

    unsigned int n_columns() const { return columns.size(); }
    /// Active terms in the last solve.
    unsigned int n_active() const { return active.size(); }

  private:
    LinearSolver             *base = nullptr;
    std::vector<SparseColumn> columns;
    Eigen::MatrixXd           W, G, S;
    Vector                    y, rhs_small;
    std::vector<unsigned int> active;
  };
} // namespace poundfe

#endif
