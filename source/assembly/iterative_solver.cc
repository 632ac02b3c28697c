// The options and the preconditioner-reuse policy of the CG + AMG backends
// (assembly/iterative_solver.h): CG (Saad 2003, Alg. 9.1) to
// ||b - A x|| <= eta ||b||, eta = Linear tolerance factor x Newton residual
// tolerance; the preconditioner P ~ A_0^-1 of an earlier matrix A_0 kept
// while it still makes CG converge in at most Preconditioner rebuild factor
// times the iterations it took right after its build (a spectrally close
// A_0: Saad 2003 §10.1 on preconditioners of nearby matrices).
#include <poundfe/assembly/iterative_solver.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_file.h>
#include <poundfe/base/numbers.h>

#include <deal.II/base/config.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>

namespace poundfe
{
  void
  IterativeSolverParameters::declare(dealii::ParameterHandler &prm)
  {
    namespace Patterns = dealii::Patterns;
    prm.enter_subsection("Iterative solver");
    prm.add_parameter("Linear tolerance factor", tolerance_factor,
                      "petsc-cg-boomeramg, trilinos-cg-ml: each CG solve stops when its "
                      "residual ||b - A x|| is below this times the Newton residual "
                      "tolerance times ||b|| (x starts at 0), so the linear error adds at "
                      "most this fraction of what the Newton test accepts (theory §3.5c). "
                      "Unit: dimensionless.",
                      Patterns::Double(1e-6, 1));
    prm.add_parameter("Linear maximum iterations", max_iterations,
                      "CG iterations of one solve; a solve that does not converge in them "
                      "is repeated once with a rebuilt preconditioner, then the Newton "
                      "iteration fails (the step is cut; exit 2 when cuts run out). "
                      "Unit: count.",
                      Patterns::Integer(1, 100000));
    prm.add_parameter("Preconditioner reuse", reuse,
                      "Keep the algebraic multigrid preconditioner built from an earlier "
                      "matrix while the effective matrix or tangent changes (false: rebuild "
                      "it after every new matrix). Unit: -.");
    prm.add_parameter("Preconditioner rebuild factor", rebuild_factor,
                      "With Preconditioner reuse: rebuild it when a solve needs more than "
                      "this times the CG iterations of the first solve after the last "
                      "build (counted as at least 5). Unit: dimensionless.",
                      Patterns::Double(1, 1000));
    prm.add_parameter("AMG strong threshold", strong_threshold,
                      "petsc-cg-boomeramg: hypre BoomerAMG's strength threshold (0.25 for "
                      "2D Laplace-like, 0.5 or more for 3D or elasticity; hypre manual). "
                      "Unit: dimensionless.",
                      Patterns::Double(0, 0.99));
    prm.add_parameter("ML aggregation threshold", aggregation_threshold,
                      "trilinos-cg-ml: ML's aggregation drop tolerance (ML 5.0 User's "
                      "Guide, 'aggregation: threshold'). Unit: dimensionless.",
                      Patterns::Double(0, 1));
    prm.add_parameter("ML smoother sweeps", smoother_sweeps,
                      "trilinos-cg-ml: degree of the Chebyshev smoother on each level. "
                      "Unit: count.",
                      Patterns::Integer(1, 10));
    prm.leave_subsection();
  }

  void
  IterativeSolverParameters::check(const InputFile & /*input*/) const
  {
    // every range is in the declared patterns
  }

  bool
  linear_solver_is_iterative(const std::string &name)
  {
    return name == "petsc-cg-boomeramg" || name == "trilinos-cg-ml";
  }

  std::string
  linear_solver_unavailable(const std::string &name)
  {
    if (name == "petsc" || name == "petsc-mumps" || name == "petsc-cg-boomeramg")
      {
#ifndef DEAL_II_WITH_PETSC
        return "this deal.II is built without PETSc";
#endif
      }
    if (name == "petsc-cg-boomeramg")
      {
#ifndef DEAL_II_PETSC_WITH_HYPRE
        return "this PETSc is built without hypre (BoomerAMG)";
#endif
      }
    if (name == "petsc-mumps")
      {
#ifndef DEAL_II_PETSC_WITH_MUMPS
        return "this PETSc is built without MUMPS";
#endif
      }
    if (name == "trilinos" || name == "trilinos-cg-ml")
      {
#ifndef DEAL_II_WITH_TRILINOS
        return "this deal.II is built without Trilinos";
#endif
      }
    return "";
  }

  IterativeLinearSolver::IterativeLinearSolver(const IterativeSolverSetup &setup)
    : setup(setup)
    , counts(setup.counts ? *setup.counts : own_counts)
  {}

  void
  IterativeLinearSolver::factorize(const SparseMatrix &matrix)
  {
    copy_values(matrix);
    values_since_build = true;
    if (!setup.parameters.reuse)
      built = false;
  }

  void
  IterativeLinearSolver::build()
  {
    build_preconditioner();
    built              = true;
    values_since_build = false;
    ++counts.preconditioner_builds;
  }

  IterativeLinearSolver::CgResult
  IterativeLinearSolver::solve_once(const Vector &b, Vector &x, const double tolerance)
  {
    const CgResult result = conjugate_gradients(b, x, tolerance);
    ++counts.solves;
    counts.iterations += result.iterations;
    counts.max_iterations = std::max(counts.max_iterations, result.iterations);
    return result;
  }

  void
  IterativeLinearSolver::solve(const Vector &b, Vector &x)
  {
    const double b_norm = b.norm();
    if (b_norm == 0)
      {
        x.setZero(b.size());
        return;
      }
    const double tolerance = setup.relative_tolerance * b_norm;
    bool         fresh     = !built;
    if (fresh)
      build();
    CgResult result = solve_once(b, x, tolerance);
    const bool slow =
      result.iterations > setup.parameters.rebuild_factor * std::max(baseline_iterations, 5u);
    if (!fresh && values_since_build && (!result.converged || slow))
      {
        ++(result.converged ? counts.rebuilds_slow : counts.rebuilds_failed);
        build();
        fresh  = true;
        result = solve_once(b, x, tolerance);
      }
    if (fresh)
      baseline_iterations = result.iterations;
    if (!result.converged)
      throw NumericalError(
        name() + " did not converge in " + std::to_string(result.iterations) +
        " iterations with a preconditioner built from this matrix: residual " + number_text(result.residual_norm) +
        " = " + number_text(result.residual_norm / b_norm) + " of ||b||, above " +
        setup.tolerance_origin + " " + number_text(setup.relative_tolerance) +
        " (Time integration/Iterative solver/Linear maximum iterations = " +
        std::to_string(setup.parameters.max_iterations) + ")");
  }
} // namespace poundfe
