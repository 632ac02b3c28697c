#include <poundfe/excitation/ground_motion.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace poundfe
{
  GroundMotion::GroundMotion(const double time_step, std::vector<double> acceleration,
                             std::string description, const bool held_samples)
    : dt(time_step)
    , values(std::move(acceleration))
    , text(std::move(description))
    , held(held_samples)
  {}

  double
  GroundMotion::value(const double t) const
  {
    if (values.empty() || t < 0)
      return 0;
    const double       s = t / dt;
    if (held)
      {
        // t = k dt in floating point may land just below k dt
        const std::size_t k = static_cast<std::size_t>(s + 1e-9);
        return k < values.size() ? values[k] : 0;
      }
    const std::size_t  i = static_cast<std::size_t>(s);
    if (i + 1 >= values.size())
      return (i + 1 == values.size() && s - i < 1e-9) ? values.back() : 0;
    const double f = s - i;
    return (1 - f) * values[i] + f * values[i + 1];
  }

  double
  GroundMotion::peak() const
  {
    double pga = 0;
    for (const double a : values)
      pga = std::max(pga, std::abs(a));
    return pga;
  }

  void
  GroundMotion::scale(const double factor)
  {
    for (double &a : values)
      a *= factor;
  }

  std::size_t
  GroundMotion::first_unusable_sample() const
  {
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i]) ||
          (values[i] != 0 && std::abs(values[i]) < std::numeric_limits<double>::min()))
        return i;
    return values.size();
  }
} // namespace poundfe
