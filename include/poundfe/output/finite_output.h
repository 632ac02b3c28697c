// No NaN or inf leaves poundfe in a result with exit status 0.
// Every number of a results file goes out through one of four
// writers: CsvWriter and NpyWriter (the tables of the recorders, sweeps,
// spectra), append_number (the tables built as text) and JsonWriter
// (summary.json). Each checks its numbers here; a value that is not finite
// is a numerical failure (an overflow, or an absurd input that got past the
// checks): NumericalError naming the quantity and the file, which the
// command's guard reports with exit status 2 (commands/command_guard.h).
// JSON alone keeps one exception: NaN, which JsonWriter writes as null, is
// how a summary says "not defined here" (a ratio to a time history the
// response-spectrum route does not run, beta of a probability 0 or 1); an
// infinite value there is still refused.
#ifndef poundfe_output_finite_output_h
#define poundfe_output_finite_output_h

#include <cmath>
#include <limits>
#include <string>

namespace poundfe
{
  /// A quantity that is infinite by its definition, not by an overflow (the
  /// coefficient of variation of an estimate 0: sigma/0) is not defined:
  /// NaN, which a summary writes as null.
  inline double
  undefined_if_infinite(const double x)
  {
    return std::isinf(x) ? std::numeric_limits<double>::quiet_NaN() : x;
  }

  /// Throws NumericalError: "<quantity> in <file> is inf: it overflowed ...".
  [[noreturn]] void throw_not_finite(double value, const std::string &quantity,
                                     const std::string &file);
} // namespace poundfe

#endif
