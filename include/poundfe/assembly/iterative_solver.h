// Preconditioned conjugate gradients for the effective matrix (Hestenes and
// Stiefel 1952; Saad, Iterative Methods for Sparse Linear Systems, 2nd ed.
// 2003, Alg. 9.1), preconditioned by algebraic multigrid: hypre BoomerAMG
// through PETSc (Henson and Yang 2002, Appl. Numer. Math. 41:155-177) or
// Trilinos ML smoothed aggregation (Gee et al., ML 5.0 User's Guide, 2006).
// K_eff = K + gamma/(beta dt) C + 1/(beta dt^2) M and every symmetric
// tangent added to it are symmetric positive definite, so CG applies.
//
// Each solve stops when ||b - A x|| <= eta ||b|| (x_0 = 0, unpreconditioned
// residual), eta = Linear tolerance factor x Newton residual tolerance: the
// linear error then adds at most eta ||R_i|| <= eta ||R_0|| to the next
// Newton residual, a fixed fraction of what the Newton test accepts
// (theory §3.5c). The preconditioner is built from the values of the
// first matrix and kept while the matrix changes (Preconditioner reuse):
// it is rebuilt only when a solve needs more than Preconditioner rebuild
// factor times the iterations of the first solve after the last build, or
// does not converge, and after a new pattern (analyze).
#ifndef poundfe_assembly_iterative_solver_h
#define poundfe_assembly_iterative_solver_h

#include <poundfe/assembly/linear_solver.h>

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  class InputFile;

  /// The `Time integration/Iterative solver` section (step-33 style: the
  /// part that owns the options declares them).
  struct IterativeSolverParameters
  {
    double       tolerance_factor   = 0.1;
    unsigned int max_iterations     = 1000;
    bool         reuse              = true;
    double       rebuild_factor     = 2.0;
    double       strong_threshold   = 0.5;  // hypre BoomerAMG, 3D-like elasticity
    double       aggregation_threshold = 1e-4; // ML
    unsigned int smoother_sweeps    = 2;    // ML Chebyshev degree

    /// Declare the section inside the current one (Time integration).
    void declare(dealii::ParameterHandler &prm);
    /// Throws InputError.
    void check(const InputFile &input) const;
  };

  /// What the iterative solvers of one integrator did.
  struct IterativeSolveCounts
  {
    unsigned long preconditioner_builds = 0;
    unsigned long rebuilds_slow = 0;   // rebuilt because a solve took too many iterations
    unsigned long rebuilds_failed = 0; // rebuilt because a solve did not converge
    unsigned long solves = 0;
    unsigned long iterations = 0;      // CG iterations over all solves
    unsigned int  max_iterations = 0;  // of one solve
  };

  /// How an iterative backend is set up: the options, the relative
  /// residual eta of each solve, where to count (may be null).
  struct IterativeSolverSetup
  {
    IterativeSolverParameters parameters;
    double                    relative_tolerance = 1e-13; // standalone use: near round-off
    std::string               tolerance_origin = "relative residual";
    IterativeSolveCounts     *counts = nullptr;
  };

  /// Whether `name` is one of the CG + AMG backends.
  bool linear_solver_is_iterative(const std::string &name);

  /// Empty when this build of deal.II/PETSc/Trilinos has the solver `name`,
  /// else why not (for the message naming Time integration/Linear solver).
  std::string linear_solver_unavailable(const std::string &name);

  std::unique_ptr<LinearSolver> create_petsc_boomeramg_solver(const IterativeSolverSetup &setup);
  std::unique_ptr<LinearSolver> create_trilinos_ml_solver(const IterativeSolverSetup &setup);

  /// The policy shared by the CG + AMG backends: factorize() copies the
  /// values in place and marks the preconditioner stale only when reuse is
  /// off; solve() runs CG, rebuilds and repeats on a slow or failed solve,
  /// and throws NumericalError when even a fresh preconditioner fails.
  class IterativeLinearSolver : public LinearSolver
  {
  public:
    explicit IterativeLinearSolver(const IterativeSolverSetup &setup);

    void factorize(const SparseMatrix &matrix) final;
    void solve(const Vector &b, Vector &x) final;

  protected:
    struct CgResult
    {
      bool         converged = false;
      unsigned int iterations = 0;
      double       residual_norm = 0;
    };

    /// Copy the values of `matrix` (the analysed pattern) into the backend.
    virtual void copy_values(const SparseMatrix &matrix) = 0;
    /// Build the preconditioner from the values now in the backend.
    virtual void build_preconditioner() = 0;
    /// CG from x = 0 to ||b - A x|| <= tolerance.
    virtual CgResult conjugate_gradients(const Vector &b, Vector &x, double tolerance) = 0;
    /// A new pattern: the next solve builds the preconditioner.
    void pattern_changed() { built = false; }

    const IterativeSolverSetup setup;

  private:
    void build();
    CgResult solve_once(const Vector &b, Vector &x, double tolerance);

    IterativeSolveCounts own_counts;
    IterativeSolveCounts &counts;
    bool         built = false;
    bool         values_since_build = false;
    unsigned int baseline_iterations = 0; // of the first solve after the last build
  };
} // namespace poundfe

#endif
