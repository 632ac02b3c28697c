// "petsc-cg-boomeramg": PETSc's CG (KSPCG; Balay et al., PETSc Users
// Manual, KSP) preconditioned by hypre's BoomerAMG (PCHYPRE; Henson and Yang
// 2002, Appl. Numer. Math. 41:155-177; hypre Reference Manual,
// HYPRE_BoomerAMGSetStrongThreshold) on a sequential AIJ matrix.
//   x_{k+1} = x_k + alpha_k p_k, r_{k+1} = r_k - alpha_k A p_k,
//   z = P r (one BoomerAMG V-cycle), p_{k+1} = z_{k+1} + beta_k p_k
// (Saad 2003, Alg. 9.1). The pattern is copied once (analyze); factorize()
// writes the new values into the AIJ value array in place
// (MatSeqAIJGetArray), and KSPSetReusePreconditioner keeps BoomerAMG's
// hierarchy, built from earlier values, until the policy of
// IterativeLinearSolver asks for a rebuild. The stopping test is on the
// unpreconditioned residual (KSP_NORM_UNPRECONDITIONED), x_0 = 0.
#include <poundfe/assembly/iterative_solver.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/base/config.h>
#include <deal.II/base/exceptions.h>

#ifdef DEAL_II_PETSC_WITH_HYPRE
#  include <petscksp.h>

#  include <Eigen/Core>

#  include <stdexcept>
#  include <string>

#  include "csr_copy.h"

namespace poundfe
{
  namespace
  {
    void
    check(const PetscErrorCode code, const char *call)
    {
      if (code != 0)
        throw std::runtime_error(std::string("PETSc: ") + call + " failed (error " +
                                 std::to_string(code) + ")");
    }

    class PetscBoomerAmgSolver : public IterativeLinearSolver
    {
    public:
      explicit PetscBoomerAmgSolver(const IterativeSolverSetup &setup)
        : IterativeLinearSolver(setup)
      {}
      ~PetscBoomerAmgSolver() override { destroy(); }

      void
      analyze(const SparseMatrix &matrix) override
      {
        destroy();
        pattern_changed();
        const PetscInt n = matrix.rows();
        csr.build(matrix, 0, n);
        check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, n, n, csr.row_start.data(),
                                        csr.columns.data(), csr.values.data(), &petsc_matrix),
              "MatCreateSeqAIJWithArrays");
        check(MatCreateVecs(petsc_matrix, &solution, &rhs), "MatCreateVecs");
        create_krylov_solver();
      }

      std::string
      name() const override
      {
        return "petsc-cg-boomeramg";
      }

    protected:
      /// The AIJ matrix holds csr.values (MatCreateSeqAIJWithArrays): the
      /// new values are gathered into that array between MatSeqAIJGetArray
      /// and MatSeqAIJRestoreArray, which tells PETSc (and PCSetUp) that
      /// they changed.
      void
      copy_values(const SparseMatrix &matrix) override
      {
        Assert(matrix.nonZeros() == csr.n_nonzeros, dealii::ExcMessage("analyze() first"));
        PetscScalar *values = nullptr;
        check(MatSeqAIJGetArray(petsc_matrix, &values), "MatSeqAIJGetArray");
        Assert(values == csr.values.data(), dealii::ExcInternalError());
        csr.gather(matrix);
        check(MatSeqAIJRestoreArray(petsc_matrix, &values), "MatSeqAIJRestoreArray");
      }

      void
      build_preconditioner() override
      {
        // PCSetUp rebuilds only when the matrix state changed since the
        // last build (PetscObjectStateIncrease in copy_values)
        check(PCSetReusePreconditioner(preconditioner, PETSC_FALSE), "PCSetReusePreconditioner");
        check(PCSetUp(preconditioner), "PCSetUp");
        check(PCSetReusePreconditioner(preconditioner, PETSC_TRUE), "PCSetReusePreconditioner");
      }

      CgResult
      conjugate_gradients(const Vector &b, Vector &x, const double tolerance) override
      {
        PetscScalar *values = nullptr;
        check(VecGetArray(rhs, &values), "VecGetArray");
        Eigen::Map<Vector>(values, b.size()) = b;
        check(VecRestoreArray(rhs, &values), "VecRestoreArray");
        check(KSPSetTolerances(ksp, 0.0, tolerance, PETSC_DEFAULT,
                               setup.parameters.max_iterations),
              "KSPSetTolerances");
        check(KSPSolve(ksp, rhs, solution), "KSPSolve");
        KSPConvergedReason reason;
        PetscInt           iterations = 0;
        PetscReal          norm       = 0;
        check(KSPGetConvergedReason(ksp, &reason), "KSPGetConvergedReason");
        check(KSPGetIterationNumber(ksp, &iterations), "KSPGetIterationNumber");
        check(KSPGetResidualNorm(ksp, &norm), "KSPGetResidualNorm");
        const PetscScalar *result = nullptr;
        check(VecGetArrayRead(solution, &result), "VecGetArrayRead");
        x = Eigen::Map<const Vector>(result, b.size());
        check(VecRestoreArrayRead(solution, &result), "VecRestoreArrayRead");
        return {reason > 0, static_cast<unsigned int>(iterations), norm};
      }

    private:
      /// CG on the unpreconditioned residual from x = 0; BoomerAMG with the
      /// strength threshold of the input, hypre's defaults otherwise. The
      /// options go through a prefix of this solver's own so that no other
      /// PETSc object sees them.
      void
      create_krylov_solver()
      {
        check(KSPCreate(PETSC_COMM_SELF, &ksp), "KSPCreate");
        check(KSPSetOperators(ksp, petsc_matrix, petsc_matrix), "KSPSetOperators");
        check(KSPSetType(ksp, KSPCG), "KSPSetType");
        check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
        check(KSPSetInitialGuessNonzero(ksp, PETSC_FALSE), "KSPSetInitialGuessNonzero");
        check(KSPSetOptionsPrefix(ksp, "poundfe_amg_"), "KSPSetOptionsPrefix");
        const std::string threshold = std::to_string(setup.parameters.strong_threshold);
        check(PetscOptionsSetValue(nullptr, "-poundfe_amg_pc_hypre_boomeramg_strong_threshold",
                                   threshold.c_str()),
              "PetscOptionsSetValue");
        check(KSPGetPC(ksp, &preconditioner), "KSPGetPC");
        check(PCSetType(preconditioner, PCHYPRE), "PCSetType");
        check(PCHYPRESetType(preconditioner, "boomeramg"), "PCHYPRESetType");
        check(PCSetFromOptions(preconditioner), "PCSetFromOptions");
        check(KSPSetReusePreconditioner(ksp, PETSC_TRUE), "KSPSetReusePreconditioner");
      }

      void
      destroy()
      {
        KSPDestroy(&ksp);
        preconditioner = nullptr;
        VecDestroy(&solution);
        VecDestroy(&rhs);
        MatDestroy(&petsc_matrix);
      }

      CsrCopy<PetscInt> csr; // the AIJ arrays, shared with petsc_matrix
      Mat               petsc_matrix = nullptr;
      Vec               rhs = nullptr, solution = nullptr;
      KSP               ksp = nullptr;
      PC                preconditioner = nullptr; // ksp's
    };
  } // namespace

  std::unique_ptr<LinearSolver>
  create_petsc_boomeramg_solver(const IterativeSolverSetup &setup)
  {
    return std::make_unique<PetscBoomerAmgSolver>(setup);
  }
} // namespace poundfe

#else

namespace poundfe
{
  std::unique_ptr<LinearSolver>
  create_petsc_boomeramg_solver(const IterativeSolverSetup &)
  {
    throw InputError("", 0, "Time integration/Linear solver",
                     linear_solver_unavailable("petsc-cg-boomeramg"));
  }
} // namespace poundfe

#endif
