// Copy an Eigen sparse matrix into deal.II's SparsityPattern/SparseMatrix
// (private to the solver backends that need deal.II matrices).
#ifndef poundfe_source_assembly_dealii_matrix_h
#define poundfe_source_assembly_dealii_matrix_h

#include <poundfe/assembly/linear_system.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

namespace poundfe
{
  inline void
  copy_pattern(const SparseMatrix &matrix, dealii::SparsityPattern &pattern)
  {
    dealii::DynamicSparsityPattern dsp(matrix.rows(), matrix.cols());
    for (int column = 0; column < matrix.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(matrix, column); it; ++it)
        dsp.add(it.row(), it.col());
    pattern.copy_from(dsp);
  }

  inline void
  copy_values(const SparseMatrix &matrix, dealii::SparseMatrix<double> &target)
  {
    target = 0;
    for (int column = 0; column < matrix.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(matrix, column); it; ++it)
        target.set(it.row(), it.col(), it.value());
  }
} // namespace poundfe

#endif
