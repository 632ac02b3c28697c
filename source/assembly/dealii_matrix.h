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

  /// Copy an Eigen vector into a wrapper vector with operator[] (PETSc,
  /// Trilinos), and back.
  template <typename TargetVector>
  void
  copy_to(const Vector &source, TargetVector &target)
  {
    for (unsigned int i = 0; i < source.size(); ++i)
      target[i] = source[i];
  }

  template <typename SourceVector>
  void
  copy_from(const SourceVector &source, Vector &target, const unsigned int n)
  {
    target.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      target[i] = source[i];
  }
} // namespace poundfe

#endif
