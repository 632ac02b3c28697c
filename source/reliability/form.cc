// Equations and sources: include/poundfe/reliability/form.h.
#include <poundfe/excitation/stochastic.h>
#include <poundfe/reliability/form.h>

#include <cmath>
#include <string>

namespace poundfe
{
  namespace
  {
    /// The improved HL-RF step from u (value G, gradient grad): the new u.
    std::vector<double>
    ihlrf_step(const StandardSpaceLimitStates &G, const unsigned int k,
               const std::vector<double> &u, const double value,
               const std::vector<double> &grad)
    {
      const double        n2 = dot(grad, grad), ng = std::sqrt(n2);
      const double        s  = (dot(grad, u) - value) / n2;
      std::vector<double> d(u.size());
      for (std::size_t i = 0; i < u.size(); ++i)
        d[i] = s * grad[i] - u[i];
      const double c      = (2 * norm(u) + 10) / ng;
      const auto   merit  = [&](const std::vector<double> &v, const double g) {
        return 0.5 * dot(v, v) + c * std::abs(g);
      };
      const double m0    = merit(u, value);
      const double slope = dot(u, d) + c * (value >= 0 ? 1 : -1) * dot(grad, d);
      std::vector<double> v(u.size());
      double              lambda = 1;
      for (unsigned int j = 0; j < 30; ++j, lambda *= 0.5)
        {
          for (std::size_t i = 0; i < u.size(); ++i)
            v[i] = u[i] + lambda * d[i];
          if (merit(v, G(k, v)) <= m0 + 0.5 * lambda * slope)
            break;
        }
      return v;
    }

    /// Marginal i with its mean (which = 0) or standard deviation (1)
    /// shifted by delta.
    Distribution
    shifted(const Distribution &d, const unsigned int which, const double delta)
    {
      if (d.type() == DistributionType::truncated_normal)
        {
          std::vector<double> p = d.parameters();
          p[which] += delta;
          return Distribution::from_native(d.type(), p);
        }
      return Distribution::from_moments(d.type(), d.mean() + (which == 0 ? delta : 0),
                                        d.standard_deviation() + (which == 1 ? delta : 0));
    }

    /// The spread of d that scales the finite-difference step.
    double
    spread(const Distribution &d)
    {
      return d.type() == DistributionType::truncated_normal ? d.parameters()[1] :
                                                              d.standard_deviation();
    }

    /// Why FORM has no direction to search at iteration `it`, where the
    /// limit state is `value` and its gradient's norm `ng`: either is not
    /// finite, or the gradient is zero; empty when it has one.
    std::string
    why_no_search_direction(const double value, const double ng, const unsigned int it)
    {
      if (!std::isfinite(value) || !std::isfinite(ng))
        return "the limit state or its gradient is not finite at iteration " + std::to_string(it) +
               " (an expression undefined or infinite near that point)";
      if (ng > 0)
        return {};
      return it == 0 ? "its gradient is zero at the start (u = 0, the variables' medians): "
                       "the limit state does not vary there, so FORM has no direction to "
                       "search (a limit state that does not depend on the variables FORM "
                       "varies, or is flat around the medians); FORM does not apply" :
                       "its gradient vanished at iteration " + std::to_string(it);
    }
  } // namespace

  FormResult
  form(const ReliabilityProblem &problem, const unsigned int k, const FormSettings &settings)
  {
    const StandardSpaceLimitStates G(problem);
    FormResult                     result;
    std::vector<double>            u(G.n_variables(), 0.0), grad, alpha(G.n_variables());
    double                         scale = 0;
    for (unsigned int it = 0;; ++it)
      {
        const double value = G(k, u);
        G.gradient(k, u, value, settings.gradient_step, settings.central_difference, grad);
        ++result.n_gradients;
        if (it == 0)
          scale = std::abs(value) > 0 ? std::abs(value) : 1;
        const double ng = norm(grad);
        if (const std::string why = why_no_search_direction(value, ng, it); !why.empty())
          {
            // say so rather than report u = 0 as a design point
            const bool finite             = std::isfinite(value) && std::isfinite(ng);
            result.zero_gradient_at_start = finite && it == 0;
            result.failure                = why;
            break;
          }
        for (std::size_t i = 0; i < u.size(); ++i)
          alpha[i] = -grad[i] / ng;
        const double        projection = dot(alpha, u);
        std::vector<double> off(u.size());
        for (std::size_t i = 0; i < u.size(); ++i)
          off[i] = u[i] - projection * alpha[i];
        result.design_point_u = u;
        result.alpha          = alpha;
        result.gradient_norm  = ng;
        result.beta           = projection;
        result.iterations     = it;
        if (std::abs(value) / scale <= settings.tolerance_g && norm(off) <= settings.tolerance_u)
          {
            result.converged = true;
            break;
          }
        if (it == settings.max_iterations)
          {
            result.failure = "it did not converge in " + std::to_string(it) + " iterations";
            break;
          }
        u = ihlrf_step(G, k, u, value, grad);
      }
    result.probability = standard_normal_cdf(-result.beta);
    if (!result.design_point_u.empty())
      problem.transformation.to_physical(result.design_point_u, result.design_point_x);
    result.n_evaluations = G.n_evaluations();
    if (result.converged)
      beta_sensitivities(problem.transformation, result);
    return result;
  }

  void
  beta_sensitivities(const NatafTransformation &transformation, FormResult &result)
  {
    const unsigned int n = transformation.n_variables();
    result.dbeta_dmean.assign(n, 0.0);
    result.dbeta_dsd.assign(n, 0.0);
    std::vector<double> up, down;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int which = 0; which < 2; ++which)
        {
          const Distribution &d     = transformation.distributions()[i];
          const double        delta = 1e-5 * spread(d);
          std::vector<Distribution> plus = transformation.distributions(), minus = plus;
          plus[i]  = shifted(d, which, delta);
          minus[i] = shifted(d, which, -delta);
          NatafTransformation(plus, transformation.correlation())
            .to_standard(result.design_point_x, up);
          NatafTransformation(minus, transformation.correlation())
            .to_standard(result.design_point_x, down);
          double derivative = 0;
          for (unsigned int j = 0; j < n; ++j)
            derivative += result.alpha[j] * (up[j] - down[j]) / (2 * delta);
          (which == 0 ? result.dbeta_dmean : result.dbeta_dsd)[i] = derivative;
        }
  }
} // namespace poundfe
