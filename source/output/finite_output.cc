#include <poundfe/base/exceptions.h>
#include <poundfe/output/finite_output.h>

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
} // namespace poundfe
