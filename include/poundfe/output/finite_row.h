// The check of a table's row before it is written (output/finite_output.h:
// no NaN or inf leaves poundfe): shared by the table writers, and by the
// queued writer, which checks on the stepping thread so that a run stops at
// the step whose row is not finite whether it writes inline or not.
#ifndef poundfe_output_finite_row_h
#define poundfe_output_finite_row_h

#include <string>
#include <vector>

namespace poundfe
{
  /// Throws NumericalError naming the first column of (first, values) that
  /// is not finite (`columns`[c], or "column c+1" past the header) and `file`.
  void check_row_finite(double first, const std::vector<double> &values,
                        const std::vector<std::string> &columns, const std::string &file);
} // namespace poundfe

#endif
