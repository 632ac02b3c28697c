// The rows [first_row, end_row) of an Eigen column-major matrix in CSR form
// (what PETSc AIJ and Epetra take), with the position of each entry in the
// Eigen values, so that new values of the same pattern are copied in place
// (private to the solver backends).
#ifndef poundfe_source_assembly_csr_copy_h
#define poundfe_source_assembly_csr_copy_h

#include <poundfe/assembly/linear_system.h>

#include <vector>

namespace poundfe
{
  template <typename Index>
  struct CsrCopy
  {
    std::vector<Index>  row_start, columns;
    std::vector<long>   source; // position in the Eigen values of each entry
    std::vector<double> values;
    long                n_nonzeros = 0; // of the whole Eigen matrix

    void
    build(const SparseMatrix &matrix, const Index first_row, const Index end_row)
    {
      const Index n_local = end_row - first_row;
      row_start.assign(n_local + 1, 0);
      for (int column = 0; column < matrix.outerSize(); ++column)
        for (SparseMatrix::InnerIterator it(matrix, column); it; ++it)
          if (it.row() >= first_row && it.row() < end_row)
            ++row_start[it.row() - first_row + 1];
      for (Index i = 0; i < n_local; ++i)
        row_start[i + 1] += row_start[i];
      columns.resize(row_start[n_local]);
      source.resize(row_start[n_local]);
      values.resize(row_start[n_local]);
      std::vector<Index> next(row_start.begin(), row_start.end() - 1);
      // columns in increasing order: each row's entries come out sorted
      for (int column = 0; column < matrix.outerSize(); ++column)
        for (SparseMatrix::InnerIterator it(matrix, column); it; ++it)
          if (it.row() >= first_row && it.row() < end_row)
            {
              const Index k = next[it.row() - first_row]++;
              columns[k]    = column;
              source[k]     = &it.value() - matrix.valuePtr();
            }
      n_nonzeros = matrix.nonZeros();
      gather(matrix);
    }

    /// values <- the entries of `matrix` (the pattern of build()).
    void
    gather(const SparseMatrix &matrix)
    {
      const double *all = matrix.valuePtr();
      for (std::size_t k = 0; k < source.size(); ++k)
        values[k] = all[source[k]];
    }
  };
} // namespace poundfe

#endif
