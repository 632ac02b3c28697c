// Solves (A + B D B^T) x = r with A factorised once and B = [b_1 ... b_m]
// fixed (sparse columns), D = diag(D_1, ..., D_p) block diagonal (each D_e
// dense r_e x r_e, any sign or symmetry, over r_e consecutive columns of B)
// changing every call, by the Woodbury identity (Hager, SIAM Review 31
// (1989) 221):
//   y = A^{-1} r,  (I + D_a G_aa) z = D_a B_a^T y,  x = y - W_a z,
// with W = A^{-1} B and G = B^T W computed once, and a the columns of the
// active blocks (those with any nonzero entry). The form with I + D G
// (rather than D^{-1} + G) stays valid when some D_e are singular, vanish
// or change sign. Per call: one solve with A and a dense LU of size
// sum_a r_e, the LU kept while the active blocks of D stay the same to the
// bit; nothing is allocated.
// With many elements, W (n x m, dense) would not fit: then at most
// `max_columns` columns of W (and their entries of G) are kept, each
// computed the first time its block is active (one solve with A), and a
// column whose block is inactive makes room for a new one. A call whose
// active columns exceed max_columns returns false: the caller solves with
// the assembled tangent instead (Newmark's `hybrid` tangent update).
#ifndef poundfe_assembly_low_rank_update_h
#define poundfe_assembly_low_rank_update_h

#include <poundfe/assembly/linear_solver.h>

#include <Eigen/Core>

#include <vector>

namespace poundfe
{
  /// A column b of B: entries with rows < 0 are ignored.
  struct SparseColumn
  {
    std::vector<int>    rows;
    std::vector<double> values;
  };

  class LowRankUpdateSolver
  {
  public:
    /// `factorised` must hold the factorisation of A for as long as this
    /// object is used. `block_sizes` (r_e, summing to the number of
    /// columns) groups consecutive columns into the blocks of D; empty:
    /// every block has one column (D diagonal).
    /// `max_columns` (0: all) bounds the columns of W kept; all are
    /// computed here when it covers them, else each when first needed.
    void initialize(LinearSolver &factorised, const std::vector<SparseColumn> &columns,
                    unsigned int n_rows, const std::vector<unsigned int> &block_sizes = {},
                    unsigned int max_columns = 0);

    /// x = (A + B D B^T)^{-1} r; `d` holds the blocks D_e one after
    /// another, each column-major. Returns false (x untouched) when the
    /// active columns exceed max_columns. Throws NumericalError if the
    /// capacitance matrix is singular.
    bool solve(const Vector &r, const std::vector<double> &d, Vector &x);

    unsigned int n_columns() const { return column_block.size(); }
    /// Columns of the active blocks in the last solve.
    unsigned int n_active() const { return active.size(); }
    /// Columns of W computed so far (each one solve with A).
    unsigned long n_columns_computed() const { return columns_computed; }

  private:
    /// b^T v of column c.
    double column_dot(unsigned int c, const Eigen::Ref<const Vector> &v) const;
    /// A slot of W for each active column, computing the missing ones.
    /// False if they do not fit.
    bool   fill_slots();
    /// Column c of W into `slot`, with its entries of G against the
    /// columns in the other slots.
    void   compute_column(unsigned int c, unsigned int slot);
    /// Whether S's factorisation is that of the active blocks of `d` (the
    /// same active columns, slots and entries: modal damping's constant D,
    /// a linear law's tangent at every iteration); else notes them, and the
    /// caller sets `factored` once it has factorised S for them.
    bool   reuses_capacitance(const std::vector<double> &d);
    /// rhs_small = D_a B_a^T y of the k active columns (bty holds B_a^T y)
    /// and, unless `reuse`, S = I + D_a G_aa.
    void   form_capacitance(unsigned int k, const std::vector<double> &d, bool reuse);
    /// Gaussian elimination with partial pivoting of the leading k x k
    /// block of S: the multipliers below its diagonal, the pivot rows in
    /// `pivot`.
    void   factor_capacitance(unsigned int k);
    /// The elimination's steps applied to rhs_small, in the order the
    /// elimination made them, and the back substitution: rhs_small becomes z.
    void   substitute_capacitance(unsigned int k);

    LinearSolver *base = nullptr;
    // B in compressed columns: column c's entries are [column_start[c], column_start[c + 1]).
    std::vector<unsigned int> column_start;
    std::vector<int>          entry_row;
    std::vector<double>       entry_value;
    // Block e has columns [block_start[e], block_start[e + 1]) and its D_e
    // at d[d_offset[e]]; column c is in block column_block[c].
    std::vector<unsigned int> block_start, d_offset, column_block;
    // W and G by slot: slot_of[c] (-1: not kept), column_in[s] (-1: free)
    Eigen::MatrixXd           W, G, S;
    Vector                    y, bty, rhs_small, column_buffer, w_buffer;
    std::vector<unsigned int> active;
    std::vector<int>          slot_of, column_in;
    std::vector<char>         is_active;
    unsigned long             columns_computed = 0;
    // S's factorisation: its pivot rows, and what it was formed from
    std::vector<unsigned int> pivot, factored_active;
    std::vector<double>       factored_d;
    unsigned long             factored_columns = 0;
    bool                      factored         = false;
  };
} // namespace poundfe

#endif
