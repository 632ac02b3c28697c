// Equations and sources: include/poundfe/reliability/system_bounds.h.
#include <poundfe/excitation/stochastic.h>
#include <poundfe/reliability/system_bounds.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace poundfe
{
  double
  bivariate_normal_cdf(const double a, const double b, const double rho)
  {
    const double independent = standard_normal_cdf(a) * standard_normal_cdf(b);
    if (rho == 0)
      return independent;
    const auto integrand = [&](const double t) {
      const double c = std::cos(t);
      if (c <= 0)
        return 0.0;
      return std::exp(-(a * a + b * b - 2 * a * b * std::sin(t)) / (2 * c * c));
    };
    const double integral = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
      integrand, 0.0, std::asin(std::max(-1.0, std::min(1.0, rho))), 15, 1e-14);
    return std::max(0.0, independent + integral / (2 * M_PI));
  }

  SystemBounds
  system_bounds(const SystemType system, const std::vector<double> &betas,
                const std::vector<std::vector<double>> &alphas)
  {
    const std::size_t   n = betas.size();
    std::vector<double> P(n);
    for (std::size_t i = 0; i < n; ++i)
      P[i] = standard_normal_cdf(-betas[i]);
    const auto joint = [&](const std::size_t i, const std::size_t j) {
      return bivariate_normal_cdf(-betas[i], -betas[j], dot(alphas[i], alphas[j]));
    };
    SystemBounds bounds;
    if (n == 1)
      return {P[0], P[0]};
    if (system == SystemType::parallel)
      {
        bounds.upper = 1;
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t j = 0; j < i; ++j)
            bounds.upper = std::min(bounds.upper, joint(i, j));
        bounds.lower = n == 2 ? bounds.upper : 0;
        return bounds;
      }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return P[a] > P[b]; });
    bounds.lower = bounds.upper = P[order[0]];
    for (std::size_t r = 1; r < n; ++r)
      {
        const std::size_t i   = order[r];
        double            sum = 0, largest = 0;
        for (std::size_t s = 0; s < r; ++s)
          {
            const double pij = joint(i, order[s]);
            sum += pij;
            largest = std::max(largest, pij);
          }
        bounds.lower += std::max(0.0, P[i] - sum);
        bounds.upper += P[i] - largest;
      }
    bounds.upper = std::min(bounds.upper, 1.0);
    return bounds;
  }
} // namespace poundfe
