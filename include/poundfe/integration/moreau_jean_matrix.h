// The iteration matrix of Moreau–Jean's Newton (integration/moreau_jean.h)
//   J = M + h θ C + (h θ)^2 K + Σ_e (h θ)^2 B_e D_e B_e^T
// and its factor, kept between factorisations, with the Delassus operator
// of the active contacts' rows R (H's, and T's with friction),
//   W = R J^-1 R^T,
// by one solve per row (Acary & Brogliato, Numerical Methods for Nonsmooth
// Dynamical Systems, 2008, §10.1.3: W only on the index set's contacts).
// J is dense (LU with partial pivoting) or sparse on the pattern of M, C, K
// and the elements' equations, factored by a LinearSolver
// (assembly/linear_solver.h), whose symbolic analysis is done once. Both take
// the same solves, so they agree to round-off. Left to choose, it is sparse
// (eigen-ldlt) when a solve with the sparse factor is estimated cheaper than
// one with the dense LU, the solves being most of a step's work on J:
//   dense: 2.6 n^2,   sparse: 12.9 nnz(L)   instructions (+ 100 n either way)
// (nnz(L) the entries below the diagonal of the LDL^T factor of J's pattern
// under Eigen's AMD ordering, from one factorisation of J's constant part;
// the constants measured with callgrind, doc/benchmarks.md).
#ifndef poundfe_integration_moreau_jean_matrix_h
#define poundfe_integration_moreau_jean_matrix_h

#include <poundfe/assembly/linear_solver.h>
#include <poundfe/assembly/linear_system.h>

#include <Eigen/LU>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  using SparseRows = Eigen::SparseMatrix<double, Eigen::RowMajor>;

  /// How J is kept: dense, sparse, or whichever the cost model finds cheaper.
  enum class JacobianStorage
  {
    automatic,
    dense,
    sparse
  };

  class MoreauJeanMatrix
  {
  public:
    /// `base` the constant part M + h θ C + (h θ)^2 K; `element_equations`
    /// the equations (< 0: the ground) of every element whose tangent
    /// add() may bring; dense, or sparse factored by `linear_solver`
    /// (`automatic`: sparse by eigen-ldlt when cheaper, `dense_extra` empty).
    MoreauJeanMatrix(const SparseMatrix &base, const Eigen::MatrixXd &dense_extra,
                     const std::vector<const std::vector<int> *> &element_equations,
                     JacobianStorage storage, const std::string &linear_solver);
    /// Whether a solve with the sparse LDL^T factor of `pattern` (J's, with
    /// its constant part's values) is estimated cheaper than with its dense LU.
    static bool sparse_solve_is_cheaper(const SparseMatrix &pattern);
    ~MoreauJeanMatrix();

    /// J = the constant part, to which add() brings the elements' tangents.
    void start();
    /// J(equations, equations) += local (entries on the ground left out).
    void add(const std::vector<int> &equations, const Eigen::MatrixXd &local);
    /// Factor J; NumericalError when singular.
    void factorize();
    /// x = J^-1 b with the last factor.
    void solve(const Vector &b, Vector &x);
    /// W = R J^-1 R^T with the last factor.
    void delassus(const SparseRows &rows, Eigen::MatrixXd &W);
    bool is_dense() const { return dense; }
    /// Factorisations so far: a W built on one stays valid until the next.
    unsigned long n_factorizations() const { return factorizations; }

  private:
    /// The constant part's entries and every element's pairs (zeros).
    static SparseMatrix sparse_pattern(const SparseMatrix                          &base,
                                       const std::vector<const std::vector<int> *> &element_equations);

    bool                          dense = false;
    unsigned long                 factorizations = 0;
    Eigen::MatrixXd               dense_base, dense_matrix;
    Eigen::PartialPivLU<Eigen::MatrixXd> dense_factor;
    /// The sparse J on its full pattern, the constant part's values on it.
    SparseMatrix                  sparse_matrix;
    std::vector<double>           base_values;
    std::unique_ptr<LinearSolver> sparse_factor;
    Vector                        column, solution;
  };
} // namespace poundfe

#endif
