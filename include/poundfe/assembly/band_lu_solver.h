// LAPACK's banded LU after a Cuthill–McKee numbering (band_lu_solver.cc),
// for `poundfe run` (Linear solver = band-lu) and the OpenSees interpreter's
// banded systems alike: deal.II-free, so that the interpreter's module
// links without deal.II.
#ifndef poundfe_assembly_band_lu_solver_h
#define poundfe_assembly_band_lu_solver_h

#include <poundfe/assembly/linear_solver.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  /// The band-lu solver. A band beyond its storage limit is a NumericalError
  /// ending in `remedy`: how the caller's input asks for UMFPACK instead
  /// ("set Linear solver = umfpack", "give system UmfPack").
  std::unique_ptr<LinearSolver> create_band_lu_solver(const std::string &remedy);

  /// new_index[i]: the place of equation i in the Cuthill–McKee numbering
  /// of the symmetrised pattern of `matrix` with its diagonal: the numbering
  /// deal.II's SparsityTools::reorder_Cuthill_McKee gives that pattern.
  std::vector<int> cuthill_mckee_numbering(const SparseMatrix &matrix);
} // namespace poundfe

#endif
