#include <poundfe/base/exceptions.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/finite_row.h>

#include <cmath>

namespace poundfe
{
  void
  throw_not_finite(const double value, const std::string &quantity, const std::string &file)
  {
    const std::string what = std::isnan(value) ? "NaN (not a number)" : value > 0 ? "+inf" : "-inf";
    throw NumericalError("the result '" + quantity + "'" + (file.empty() ? "" : " of " + file) +
                         " is " + what +
                         ": a quantity overflowed or an input is out of any physical range "
                         "(look for an absurd value); nothing infinite is written");
  }

  void
  check_row_finite(const double first, const std::vector<double> &values,
                   const std::vector<std::string> &columns, const std::string &file)
  {
    bool finite = std::isfinite(first); // one test per number, no branch
    for (const double v : values)
      finite &= std::isfinite(v);
    if (finite)
      return;
    const auto name = [&](const std::size_t c) {
      return c < columns.size() ? columns[c] : "column " + std::to_string(c + 1);
    };
    if (!std::isfinite(first))
      throw_not_finite(first, name(0), file);
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i]))
        throw_not_finite(values[i], name(i + 1), file);
  }
} // namespace poundfe
