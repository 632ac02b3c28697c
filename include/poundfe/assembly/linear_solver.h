// Direct solvers for the effective matrix, selected by name. The matrix is
// factorised once and the factorisation reused for every solve; the sparsity
// pattern is analysed in `analyze`, so a later refactorisation of a matrix
// with the same pattern (the nonlinear case) skips that work.
// Each backend lives in its own file so its heavy headers stay there.
#ifndef poundfe_assembly_linear_solver_h
#define poundfe_assembly_linear_solver_h

#include <poundfe/assembly/linear_system.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class LinearSolver
  {
  public:
    virtual ~LinearSolver() = default;
    /// Symbolic analysis of the pattern (once per pattern).
    virtual void analyze(const SparseMatrix &matrix) = 0;
    /// Numeric factorisation; throws NumericalError if singular.
    virtual void factorize(const SparseMatrix &matrix) = 0;
    /// x = A^{-1} b with the last factorisation.
    virtual void solve(const Vector &b, Vector &x) = 0;
    virtual std::string name() const = 0;

    void
    analyze_and_factorize(const SparseMatrix &matrix)
    {
      analyze(matrix);
      factorize(matrix);
    }
  };

  /// "eigen-ldlt", "umfpack", "petsc" or "trilinos".
  std::unique_ptr<LinearSolver> create_linear_solver(const std::string &name);

  /// Names accepted by create_linear_solver.
  std::vector<std::string> linear_solver_names();

  /// Whether the solver needs MPI, PETSc and Trilinos initialised first
  /// (dealii::Utilities::MPI::MPI_InitFinalize): "petsc" and "trilinos".
  bool linear_solver_needs_mpi(const std::string &name);

  std::unique_ptr<LinearSolver> create_eigen_ldlt_solver();
  std::unique_ptr<LinearSolver> create_umfpack_solver();
  std::unique_ptr<LinearSolver> create_petsc_solver();
  std::unique_ptr<LinearSolver> create_trilinos_solver();
} // namespace poundfe

#endif
