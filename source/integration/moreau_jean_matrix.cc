// Moreau–Jean's iteration matrix J, dense or sparse, its factor and the
// Delassus operator W = R J^-1 R^T of the active contacts' rows R by one
// solve per row (integration/moreau_jean_matrix.h; Acary & Brogliato 2008,
// §10.1.3).
#include <poundfe/integration/moreau_jean_matrix.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/SparseCholesky>

namespace poundfe
{
  namespace
  {
    /// Instructions of one solve with J's factor per entry of the dense J
    /// and per entry of the sparse L below its diagonal (callgrind on
    /// frames and shear pairs of 8 to 150 equations, doc/benchmarks.md; the
    /// ~100 per equation of either is the same and drops out).
    constexpr double dense_cost_per_entry  = 2.6;
    constexpr double sparse_cost_per_entry = 12.9;
  } // namespace

  bool
  MoreauJeanMatrix::sparse_solve_is_cheaper(const SparseMatrix &pattern)
  {
    // L's entries under Eigen's AMD ordering, from one factorisation of
    // the constant part (a regular J: M, and h θ C + (h θ)^2 K on the
    // massless rows)
    const Eigen::SimplicialLDLT<SparseMatrix> probe(pattern);
    if (probe.info() != Eigen::Success)
      return false; // not factored as LDL^T: the LU
    const double n              = pattern.rows();
    const double factor_entries = probe.matrixL().nestedExpression().nonZeros();
    return sparse_cost_per_entry * factor_entries < dense_cost_per_entry * n * n;
  }

  MoreauJeanMatrix::MoreauJeanMatrix(const SparseMatrix &base, const Eigen::MatrixXd &dense_extra,
                                     const std::vector<const std::vector<int> *> &element_equations,
                                     const JacobianStorage storage, const std::string &linear_solver)
  {
    const Eigen::Index n = base.rows();
    column.setZero(n);
    solution.setZero(n);
    sparse_matrix = sparse_pattern(base, element_equations);
    // whether sparse is allowed is the caller's (MoreauJeanIntegrator::make_jacobian)
    Assert(storage != JacobianStorage::automatic ||
             (dense_extra.size() == 0 && linear_solver == "eigen-ldlt"),
           dealii::ExcMessage("the cost model is of sparse J by eigen-ldlt"));
    dense = storage == JacobianStorage::dense ||
            (storage == JacobianStorage::automatic && !sparse_solve_is_cheaper(sparse_matrix));
    if (dense)
      {
        dense_base = Eigen::MatrixXd(base);
        if (dense_extra.size() > 0)
          dense_base += dense_extra;
        sparse_matrix.resize(0, 0);
        return;
      }
    Assert(dense_extra.size() == 0, dealii::ExcMessage("a dense term on a sparse J"));
    base_values.assign(sparse_matrix.valuePtr(),
                       sparse_matrix.valuePtr() + sparse_matrix.nonZeros());
    sparse_factor = create_linear_solver(linear_solver);
    sparse_factor->analyze(sparse_matrix);
  }

  SparseMatrix
  MoreauJeanMatrix::sparse_pattern(const SparseMatrix                          &base,
                                   const std::vector<const std::vector<int> *> &element_equations)
  {
    // the pattern: the constant part's entries and every element's pairs
    std::vector<Eigen::Triplet<double>> entries;
    for (Eigen::Index k = 0; k < base.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(base, k); it; ++it)
        entries.emplace_back(it.row(), it.col(), it.value());
    for (const std::vector<int> *equations : element_equations)
      for (const int i : *equations)
        for (const int j : *equations)
          if (i >= 0 && j >= 0)
            entries.emplace_back(i, j, 0.0);
    SparseMatrix pattern(base.rows(), base.cols());
    pattern.setFromTriplets(entries.begin(), entries.end());
    pattern.makeCompressed();
    return pattern;
  }

  MoreauJeanMatrix::~MoreauJeanMatrix() = default;

  void
  MoreauJeanMatrix::start()
  {
    if (dense)
      dense_matrix = dense_base;
    else
      std::copy(base_values.begin(), base_values.end(), sparse_matrix.valuePtr());
  }

  void
  MoreauJeanMatrix::add(const std::vector<int> &equations, const Eigen::MatrixXd &local)
  {
    for (unsigned int j = 0; j < equations.size(); ++j)
      for (unsigned int i = 0; i < equations.size(); ++i)
        if (equations[i] >= 0 && equations[j] >= 0)
          {
            if (dense)
              dense_matrix(equations[i], equations[j]) += local(i, j);
            else // on the pattern: no insertion
              sparse_matrix.coeffRef(equations[i], equations[j]) += local(i, j);
          }
  }

  void
  MoreauJeanMatrix::factorize()
  {
    if (dense)
      dense_factor.compute(dense_matrix);
    else
      sparse_factor->factorize(sparse_matrix);
    ++factorizations;
  }

  void
  MoreauJeanMatrix::solve(const Vector &b, Vector &x)
  {
    if (dense)
      x = dense_factor.solve(b);
    else
      sparse_factor->solve(b, x);
  }

  void
  MoreauJeanMatrix::delassus(const SparseRows &rows, Eigen::MatrixXd &W)
  {
    const Eigen::Index m = rows.rows();
    W.resize(m, m);
    for (Eigen::Index k = 0; k < m; ++k)
      {
        column.setZero();
        for (SparseRows::InnerIterator it(rows, k); it; ++it)
          column[it.col()] = it.value();
        solve(column, solution);
        W.col(k) = rows * solution;
      }
  }
} // namespace poundfe
