// The points and weights of a member's integration rules (Gauss-Lobatto,
// Gauss-Legendre, HingeRadau); the formulas are in the header.
#include <poundfe/base/exceptions.h>
#include <poundfe/elements/beam_integration.h>

#include <cmath>
#include <string>
#include <utility>

namespace poundfe
{
  namespace
  {
    /// P_n(x) and P_n'(x) by the three-term recurrence (|x| < 1 for P').
    std::pair<double, double>
    legendre_polynomial(const unsigned int n, const double x)
    {
      double p0 = 1, p1 = x;
      if (n == 0)
        return {1, 0};
      for (unsigned int k = 2; k <= n; ++k)
        {
          const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
          p0              = p1;
          p1              = p2;
        }
      return {p1, n * (x * p1 - p0) / (x * x - 1)};
    }

    /// A root of f near x0 by Newton's iteration with derivative df.
    template <typename Function>
    double
    newton_root(const Function &f_and_df, double x)
    {
      for (unsigned int k = 0; k < 100; ++k)
        {
          const auto [f, df] = f_and_df(x);
          const double dx    = f / df;
          x -= dx;
          if (std::abs(dx) < 1e-16)
            break;
        }
      return x;
    }

    void
    refuse_points(const unsigned int n, const char *rule, const unsigned int low)
    {
      if (n < low || n > max_integration_points)
        throw InputError("", 0, "Integration points",
                         std::string(rule) + " takes " + std::to_string(low) + " to " +
                           std::to_string(max_integration_points) + " points, not " +
                           std::to_string(n));
    }

    /// x on [-1, 1] to xi on [0, 1]; the weights halve.
    void
    add_point(BeamIntegration &rule, const double x, const double w)
    {
      rule.points.push_back(0.5 * (x + 1));
      rule.weights.push_back(0.5 * w);
    }
  } // namespace

  BeamIntegration
  legendre_integration(const unsigned int n)
  {
    refuse_points(n, "Gauss-Legendre", 1);
    BeamIntegration rule;
    for (unsigned int i = 0; i < n; ++i)
      {
        // Chebyshev-like first guess of the i-th root, ascending
        const double x0 = -std::cos(M_PI * (i + 0.75) / (n + 0.5));
        const double x  = newton_root([n](double y) { return legendre_polynomial(n, y); }, x0);
        const double dp = legendre_polynomial(n, x).second;
        add_point(rule, x, 2 / ((1 - x * x) * dp * dp));
      }
    return rule;
  }

  BeamIntegration
  lobatto_integration(const unsigned int n)
  {
    refuse_points(n, "Gauss-Lobatto", 2);
    BeamIntegration rule;
    const double    end_weight = 2.0 / (n * (n - 1));
    add_point(rule, -1, end_weight);
    // interior points: roots of P'_{n-1}; (1 - x^2) P'' = 2x P' - m(m+1) P
    const unsigned int m = n - 1;
    for (unsigned int i = 1; i + 1 < n; ++i)
      {
        const double x0 = -std::cos(M_PI * i / m);
        const double x  = newton_root(
          [m](double y) {
            const auto [p, dp] = legendre_polynomial(m, y);
            return std::make_pair(dp, (2 * y * dp - m * (m + 1.0) * p) / (1 - y * y));
          },
          x0);
        const double p = legendre_polynomial(m, x).first;
        add_point(rule, x, end_weight / (p * p));
      }
    add_point(rule, 1, end_weight);
    return rule;
  }

  BeamIntegration
  hinge_radau_integration(const double lp_i, const double lp_j, const double length)
  {
    if (!(lp_i > 0 && lp_j > 0 && 4 * (lp_i + lp_j) < length))
      throw InputError("", 0, "Hinge length",
                       "HingeRadau needs hinge lengths lpI, lpJ > 0 with 4 (lpI + lpJ) below "
                       "the member's length " + std::to_string(length) + " (lpI " +
                       std::to_string(lp_i) + ", lpJ " + std::to_string(lp_j) + ")");
    const double a = lp_i / length, b = lp_j / length;
    const double alpha = 0.5 - 2 * (a + b), beta = 0.5 + 2 * (a - b);
    const double r     = 1 / std::sqrt(3.0);
    return {{0, 8 * a / 3, beta - alpha * r, beta + alpha * r, 1 - 8 * b / 3, 1},
            {a, 3 * a, alpha, alpha, 3 * b, b}};
  }
} // namespace poundfe
