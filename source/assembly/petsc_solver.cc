#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/lac/petsc_precondition.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include "dealii_matrix.h"

#include <memory>

namespace poundfe
{
  namespace
  {
    /// PETSc's own sequential LU (PCLU) on a sequential AIJ matrix. An
    /// MPI matrix would switch PCLU to MUMPS, which is ~10x slower here.
    class PetscSolver : public LinearSolver
    {
    public:
      void
      analyze(const SparseMatrix &matrix) override
      {
        copy_pattern(matrix, pattern);
        petsc_matrix.reinit(pattern);
        rhs.reinit(MPI_COMM_SELF, matrix.rows(), matrix.rows());
        solution.reinit(MPI_COMM_SELF, matrix.rows(), matrix.rows());
      }
      void
      factorize(const SparseMatrix &matrix) override
      {
        petsc_matrix = 0;
        for (int column = 0; column < matrix.outerSize(); ++column)
          for (SparseMatrix::InnerIterator it(matrix, column); it; ++it)
            petsc_matrix.set(it.row(), it.col(), it.value());
        petsc_matrix.compress(dealii::VectorOperation::insert);
        try
          {
            lu = std::make_unique<dealii::PETScWrappers::PreconditionLU>(
              petsc_matrix, dealii::PETScWrappers::PreconditionLU::AdditionalData());
          }
        catch (const dealii::ExceptionBase &)
          {
            throw NumericalError("PETSc LU: the effective matrix is singular");
          }
      }
      void
      solve(const Vector &b, Vector &x) override
      {
        copy_to(b, rhs);
        rhs.compress(dealii::VectorOperation::insert);
        lu->vmult(solution, rhs);
        copy_from(solution, x, b.size());
      }
      std::string
      name() const override
      {
        return "petsc";
      }

    private:
      dealii::SparsityPattern                               pattern;
      dealii::PETScWrappers::SparseMatrix                   petsc_matrix;
      std::unique_ptr<dealii::PETScWrappers::PreconditionLU> lu;
      dealii::PETScWrappers::MPI::Vector                    rhs, solution;
    };
  } // namespace

  std::unique_ptr<LinearSolver>
  create_petsc_solver()
  {
    return std::make_unique<PetscSolver>();
  }
} // namespace poundfe
