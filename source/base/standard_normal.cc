#include <poundfe/base/standard_normal.h>

#include <cmath>

namespace poundfe
{
  double
  standard_normal_pdf(const double z)
  {
    return std::exp(-0.5 * z * z) / std::sqrt(2 * M_PI);
  }

  double
  standard_normal_cdf(const double z)
  {
    // erfc keeps the lower tail's relative accuracy where 1 + erf(x) would
    // cancel (Phi(-8) = 6.2e-16)
    return 0.5 * std::erfc(-z / std::sqrt(2.0));
  }
} // namespace poundfe
