#include <poundfe/reliability/reliability_problem.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  double
  dot(const std::vector<double> &a, const std::vector<double> &b)
  {
    double s = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      s += a[i] * b[i];
    return s;
  }

  double
  norm(const std::vector<double> &a)
  {
    return std::sqrt(dot(a, a));
  }

  double
  StandardSpaceLimitStates::operator()(const unsigned int k, const std::vector<double> &u) const
  {
    problem.transformation.to_physical(u, x);
    ++evaluations;
    return problem.limit_states[k](x);
  }

  double
  StandardSpaceLimitStates::system_value(const std::vector<double> &u) const
  {
    problem.transformation.to_physical(u, x);
    double value = problem.limit_states[0](x);
    for (std::size_t k = 1; k < problem.limit_states.size(); ++k)
      {
        const double g = problem.limit_states[k](x);
        value = problem.system == SystemType::series ? std::min(value, g) : std::max(value, g);
      }
    evaluations += problem.limit_states.size();
    return value;
  }

  void
  StandardSpaceLimitStates::gradient(const unsigned int k, const std::vector<double> &u,
                                     const double value, const double h, const bool central,
                                     std::vector<double> &gradient) const
  {
    std::vector<double> v = u;
    gradient.resize(u.size());
    for (std::size_t i = 0; i < u.size(); ++i)
      {
        v[i]              = u[i] + h;
        const double plus = (*this)(k, v);
        if (central)
          {
            v[i]        = u[i] - h;
            gradient[i] = (plus - (*this)(k, v)) / (2 * h);
          }
        else
          gradient[i] = (plus - value) / h;
        v[i] = u[i];
      }
  }
} // namespace poundfe
