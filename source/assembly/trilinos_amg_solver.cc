// "trilinos-cg-ml": AztecOO's CG through deal.II's TrilinosWrappers::SolverCG
// preconditioned by ML's smoothed-aggregation algebraic multigrid
// (TrilinosWrappers::PreconditionAMG; Vanek, Mandel and Brezina 1996,
// Computing 56:179-196; Gee et al., ML 5.0 Smoothed Aggregation User's
// Guide, Sandia SAND2006-2649) with Chebyshev smoothing, on one Epetra
// matrix. CG as in Saad 2003, Alg. 9.1; the stopping test is on the
// unpreconditioned residual (AztecOO AZ_noscaled), x_0 = 0.
// The Epetra matrix gets the pattern once (analyze); factorize() overwrites
// its values row by row in place. ML's hierarchy (aggregates, smoothed
// prolongators, coarse operators, smoothers) is kept from the values of its
// build until the policy of IterativeLinearSolver asks for a rebuild; the
// finest level's residual always uses the current matrix.
// Near-null space: the constant vector (ML's default for a scalar problem):
// the equations carry no component labels at this layer.
#include <poundfe/assembly/iterative_solver.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/base/config.h>

#ifdef DEAL_II_WITH_TRILINOS
#  include <deal.II/lac/solver_control.h>
#  include <deal.II/lac/trilinos_precondition.h>
#  include <deal.II/lac/trilinos_solver.h>
#  include <deal.II/lac/trilinos_sparse_matrix.h>
#  include <deal.II/lac/trilinos_vector.h>

#  include "csr_copy.h"
#  include "dealii_matrix.h"

namespace poundfe
{
  namespace
  {
    class TrilinosMlSolver : public IterativeLinearSolver
    {
    public:
      explicit TrilinosMlSolver(const IterativeSolverSetup &setup)
        : IterativeLinearSolver(setup)
      {}

      void
      analyze(const SparseMatrix &matrix) override
      {
        pattern_changed();
        dealii::SparsityPattern pattern;
        copy_pattern(matrix, pattern);
        trilinos_matrix.reinit(pattern);
        csr.build(matrix, 0, matrix.rows());
        const dealii::IndexSet all = dealii::complete_index_set(matrix.rows());
        rhs.reinit(all, MPI_COMM_SELF);
        solution.reinit(all, MPI_COMM_SELF);
      }

      std::string
      name() const override
      {
        return "trilinos-cg-ml";
      }

    protected:
      void
      copy_values(const SparseMatrix &matrix) override
      {
        AssertDimension(matrix.nonZeros(), csr.n_nonzeros);
        csr.gather(matrix);
        for (Index row = 0; row + 1 < csr.row_start.size(); ++row)
          trilinos_matrix.set(row, csr.row_start[row + 1] - csr.row_start[row],
                              csr.columns.data() + csr.row_start[row],
                              csr.values.data() + csr.row_start[row], false);
        trilinos_matrix.compress(dealii::VectorOperation::insert);
      }

      void
      build_preconditioner() override
      {
        dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.aggregation_threshold = setup.parameters.aggregation_threshold;
        data.smoother_sweeps       = setup.parameters.smoother_sweeps;
        data.smoother_type         = "Chebyshev";
        data.coarse_type           = "Amesos-KLU";
        amg.initialize(trilinos_matrix, data);
      }

      CgResult
      conjugate_gradients(const Vector &b, Vector &x, const double tolerance) override
      {
        copy_to(b, rhs);
        solution = 0;
        dealii::SolverControl control(setup.parameters.max_iterations, tolerance, false, false);
        dealii::TrilinosWrappers::SolverCG cg(control);
        CgResult result;
        try
          {
            cg.solve(trilinos_matrix, solution, rhs, amg);
            result.converged = true;
          }
        catch (const dealii::SolverControl::NoConvergence &)
          {
            result.converged = false;
          }
        result.iterations    = control.last_step();
        result.residual_norm = control.last_value();
        copy_from(solution, x, b.size());
        return result;
      }

    private:
      using Index = dealii::types::global_dof_index;

      CsrCopy<Index>                              csr;
      dealii::TrilinosWrappers::SparseMatrix      trilinos_matrix;
      dealii::TrilinosWrappers::PreconditionAMG   amg;
      dealii::TrilinosWrappers::MPI::Vector       rhs, solution;
    };
  } // namespace

  std::unique_ptr<LinearSolver>
  create_trilinos_ml_solver(const IterativeSolverSetup &setup)
  {
    return std::make_unique<TrilinosMlSolver>(setup);
  }
} // namespace poundfe

#else

namespace poundfe
{
  std::unique_ptr<LinearSolver>
  create_trilinos_ml_solver(const IterativeSolverSetup &)
  {
    throw InputError("", 0, "Time integration/Linear solver",
                     linear_solver_unavailable("trilinos-cg-ml"));
  }
} // namespace poundfe

#endif
