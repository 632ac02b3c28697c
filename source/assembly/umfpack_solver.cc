#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/vector.h>

#include "dealii_matrix.h"

namespace poundfe
{
  namespace
  {
    // deal.II's UMFPACK wrapper redoes the symbolic analysis in every
    // factorize(); we only factorise once per run, so that is acceptable.
    class UmfpackSolver : public LinearSolver
    {
    public:
      void
      analyze(const SparseMatrix &matrix) override
      {
        copy_pattern(matrix, pattern);
        values.reinit(pattern);
        rhs.reinit(matrix.rows());
      }
      void
      factorize(const SparseMatrix &matrix) override
      {
        copy_values(matrix, values);
        try
          {
            umfpack.initialize(values);
          }
        catch (const dealii::ExceptionBase &)
          {
            throw NumericalError("UMFPACK: the effective matrix is singular");
          }
      }
      void
      solve(const Vector &b, Vector &x) override
      {
        std::copy(b.data(), b.data() + b.size(), rhs.begin());
        umfpack.solve(rhs);
        x.resize(b.size());
        std::copy(rhs.begin(), rhs.end(), x.data());
      }
      std::string
      name() const override
      {
        return "umfpack";
      }

    private:
      dealii::SparsityPattern      pattern;
      dealii::SparseMatrix<double> values;
      dealii::SparseDirectUMFPACK  umfpack;
      dealii::Vector<double>       rhs;
    };
  } // namespace

  std::unique_ptr<LinearSolver>
  create_umfpack_solver()
  {
    return std::make_unique<UmfpackSolver>();
  }
} // namespace poundfe
