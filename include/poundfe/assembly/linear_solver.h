// Solvers for the effective matrix, selected by name. A direct solver
// factorises the matrix once and reuses the factorisation for every solve;
// the sparsity pattern is analysed in `analyze`, so a later refactorisation
// of a matrix with the same pattern (the nonlinear case) skips that work.
// The iterative ones (assembly/iterative_solver.h) take the same calls:
// factorize() copies the values, solve() runs preconditioned CG.
// Each backend lives in its own file so its heavy headers stay there.
#ifndef poundfe_assembly_linear_solver_h
#define poundfe_assembly_linear_solver_h

#include <poundfe/assembly/linear_system.h>

#include <array>
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
    /// Take over the symbolic analysis of `analysed` (a solver of the same
    /// backend that analysed a matrix of the pattern of `matrix`: the
    /// effective matrix of another step size, or the tangent on K_eff's
    /// pattern) instead of analyze(matrix). False when this backend cannot
    /// share one or the patterns differ: then analyze().
    virtual bool
    reuse_analysis(const LinearSolver & /*analysed*/, const SparseMatrix & /*matrix*/)
    {
      return false;
    }
    virtual std::string name() const = 0;
    /// The largest of `seconds` over the processes that share this solver:
    /// a collective call where the backend spreads one solve over the MPI
    /// ranks (petsc-mumps), so that the costs the `auto` nonlinear solver
    /// compares are one number on every rank. Clock times differ between
    /// ranks; ranks that chose differently whether to refactorise would wait
    /// for each other in different collective calls for ever. The local
    /// value for a backend on one process.
    virtual double
    agreed_seconds(const double seconds) const
    {
      return seconds;
    }

    void
    analyze_and_factorize(const SparseMatrix &matrix)
    {
      analyze(matrix);
      factorize(matrix);
    }

    /// analyze(matrix) unless `analysed` (may be null) has done it already
    /// on the same pattern; true when the analysis was reused.
    bool
    analyze_or_reuse(const LinearSolver *analysed, const SparseMatrix &matrix)
    {
      if (analysed && reuse_analysis(*analysed, matrix))
        return true;
      analyze(matrix);
      return false;
    }
  };

  struct IterativeSolverSetup; // assembly/iterative_solver.h

  /// "eigen-ldlt", "umfpack", "petsc", "trilinos", "petsc-mumps", or the
  /// iterative "petsc-cg-boomeramg" and "trilinos-cg-ml" (set up by `setup`;
  /// without it, to a relative residual near round-off).
  std::unique_ptr<LinearSolver> create_linear_solver(const std::string &name);
  std::unique_ptr<LinearSolver> create_linear_solver(const std::string &name,
                                                     const IterativeSolverSetup &setup);

  /// Names accepted by create_linear_solver.
  std::vector<std::string> linear_solver_names();

  /// Whether the solver needs MPI, PETSc and Trilinos initialised first
  /// (dealii::Utilities::MPI::MPI_InitFinalize): all but "eigen-ldlt" and
  /// "umfpack".
  bool linear_solver_needs_mpi(const std::string &name);

  /// Whether the solver spreads one factorisation over the ranks of
  /// MPI_COMM_WORLD ("petsc-mumps"): then every rank must run the same
  /// analysis in step, and only rank 0 writes.
  bool linear_solver_is_distributed(const std::string &name);

  /// What the distributed solver did in this process, over all its
  /// instances (one per time step size): counts, wall seconds on this rank,
  /// and MUMPS's memory and factor size (largest seen).
  struct DistributedSolverProfile
  {
    unsigned long analyses = 0, factorizations = 0, solves = 0;
    unsigned long symmetric_factorizations = 0; // L D L^T (MUMPS SYM = 2)
    double        analysis_time = 0, factorization_time = 0, solve_time = 0;
    double        factor_megabytes_per_rank = 0; // MUMPS INFOG(21)
    double        factor_megabytes_total    = 0; // MUMPS INFOG(22)
    double        factor_entries            = 0; // MUMPS INFOG(29)
  };
  const DistributedSolverProfile &distributed_solver_profile();

  /// `inner` on the rows and columns [first, last) of every matrix it is
  /// given (this rank's block of a model partitioned by building,
  /// assembly/partition.h); solve() reads b there and returns x zero
  /// elsewhere.
  std::unique_ptr<LinearSolver> restrict_to_block(std::unique_ptr<LinearSolver> inner,
                                                  std::array<unsigned int, 2>  range);

  std::unique_ptr<LinearSolver> create_eigen_ldlt_solver();
  std::unique_ptr<LinearSolver> create_umfpack_solver();
  std::unique_ptr<LinearSolver> create_petsc_solver();
  std::unique_ptr<LinearSolver> create_trilinos_solver();
  std::unique_ptr<LinearSolver> create_petsc_mumps_solver();
} // namespace poundfe

#endif
