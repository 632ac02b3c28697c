#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include "dealii_matrix.h"

namespace poundfe
{
  namespace
  {
    /// Amesos KLU through deal.II's TrilinosWrappers::SolverDirect.
    class TrilinosSolver : public LinearSolver
    {
    public:
      TrilinosSolver()
        : control(1, 0)
        , direct(control, dealii::TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Klu"))
      {}
      void
      analyze(const SparseMatrix &matrix) override
      {
        copy_pattern(matrix, pattern);
        values.reinit(pattern);
        const dealii::IndexSet all = dealii::complete_index_set(matrix.rows());
        rhs.reinit(all, MPI_COMM_SELF);
        solution.reinit(all, MPI_COMM_SELF);
      }
      void
      factorize(const SparseMatrix &matrix) override
      {
        copy_values(matrix, values);
        trilinos_matrix.reinit(values);
        try
          {
            direct.initialize(trilinos_matrix);
          }
        catch (const dealii::ExceptionBase &)
          {
            throw NumericalError("Trilinos Amesos KLU: the effective matrix is singular");
          }
      }
      void
      solve(const Vector &b, Vector &x) override
      {
        copy_to(b, rhs);
        direct.solve(solution, rhs);
        copy_from(solution, x, b.size());
      }
      std::string
      name() const override
      {
        return "trilinos";
      }

    private:
      dealii::SparsityPattern                  pattern;
      dealii::SparseMatrix<double>             values;
      dealii::TrilinosWrappers::SparseMatrix   trilinos_matrix;
      dealii::SolverControl                    control;
      dealii::TrilinosWrappers::SolverDirect   direct;
      dealii::TrilinosWrappers::MPI::Vector    rhs, solution;
    };
  } // namespace

  std::unique_ptr<LinearSolver>
  create_trilinos_solver()
  {
    return std::make_unique<TrilinosSolver>();
  }
} // namespace poundfe
