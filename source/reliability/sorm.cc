// Equations and sources: include/poundfe/reliability/sorm.h.
#include <poundfe/excitation/stochastic.h>
#include <poundfe/reliability/distribution.h>
#include <poundfe/reliability/sorm.h>

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <limits>

namespace poundfe
{
  namespace
  {
    /// Orthogonal R whose last row is alpha: Gram-Schmidt on alpha then the
    /// unit vectors, dropping the one most parallel to alpha.
    Eigen::MatrixXd
    rotation(const std::vector<double> &alpha)
    {
      const Eigen::Index n = alpha.size();
      Eigen::VectorXd    a(n);
      for (Eigen::Index i = 0; i < n; ++i)
        a(i) = alpha[i];
      Eigen::Index largest;
      a.cwiseAbs().maxCoeff(&largest);
      std::vector<Eigen::VectorXd> rows{a.normalized()};
      for (Eigen::Index j = 0; j < n; ++j)
        {
          if (j == largest)
            continue;
          Eigen::VectorXd e = Eigen::VectorXd::Unit(n, j);
          for (const Eigen::VectorXd &r : rows)
            e -= e.dot(r) * r;
          rows.push_back(e.normalized());
        }
      Eigen::MatrixXd R(n, n);
      for (Eigen::Index i = 0; i + 1 < n; ++i)
        R.row(i) = rows[i + 1].transpose();
      R.row(n - 1) = rows[0].transpose();
      return R;
    }

    double
    beta_of(const double probability)
    {
      return probability > 0 && probability < 1 ? -standard_normal_quantile(probability) :
                                                   std::numeric_limits<double>::quiet_NaN();
    }
  } // namespace

  double
  breitung_probability(const double beta, const std::vector<double> &curvatures)
  {
    double factor = 1;
    for (const double kappa : curvatures)
      {
        if (!(1 + beta * kappa > 0))
          return std::numeric_limits<double>::quiet_NaN();
        factor /= std::sqrt(1 + beta * kappa);
      }
    return standard_normal_cdf(-beta) * factor;
  }

  double
  tvedt_probability(const double beta, const std::vector<double> &curvatures)
  {
    double               p1 = 1, p2 = 1;
    std::complex<double> p3 = 1;
    for (const double kappa : curvatures)
      {
        if (!(1 + beta * kappa > 0) || !(1 + (beta + 1) * kappa > 0))
          return std::numeric_limits<double>::quiet_NaN();
        p1 /= std::sqrt(1 + beta * kappa);
        p2 /= std::sqrt(1 + (beta + 1) * kappa);
        p3 /= std::sqrt(1.0 + std::complex<double>(beta, 1) * kappa);
      }
    const double psi = beta * standard_normal_cdf(-beta) - standard_normal_pdf(beta);
    return standard_normal_cdf(-beta) * p1 + psi * (p1 - p2) + (beta + 1) * psi * (p1 - p3.real());
  }

  SormResult
  sorm(const ReliabilityProblem &problem, const unsigned int k, const FormResult &form_result,
       const double h)
  {
    const StandardSpaceLimitStates G(problem);
    const std::vector<double>     &u = form_result.design_point_u;
    const Eigen::Index             n = u.size();
    SormResult                     result;
    Eigen::MatrixXd                H(n, n);
    std::vector<double>            v = u;
    const double                   g0 = G(k, u);
    // H_ii = (G(u + h e_i) - 2 G(u) + G(u - h e_i))/h^2; H_ij from the four
    // corners (u +- h e_i +- h e_j)/(4 h^2)
    const auto at = [&](const Eigen::Index i, const double si, const Eigen::Index j,
                        const double sj) {
      v[i] += si * h;
      v[j] += sj * h;
      const double value = G(k, v);
      v = u;
      return value;
    };
    for (Eigen::Index i = 0; i < n; ++i)
      {
        H(i, i) = (at(i, 1, i, 0) - 2 * g0 + at(i, -1, i, 0)) / (h * h);
        for (Eigen::Index j = 0; j < i; ++j)
          H(i, j) = H(j, i) =
            (at(i, 1, j, 1) - at(i, 1, j, -1) - at(i, -1, j, 1) + at(i, -1, j, -1)) / (4 * h * h);
      }
    if (n < 2) // one variable: a point, no curvature
      {
        result.breitung = result.tvedt = form_result.probability;
        result.beta_breitung = result.beta_tvedt = form_result.beta;
        result.n_evaluations = G.n_evaluations();
        return result;
      }
    const Eigen::MatrixXd R = rotation(form_result.alpha);
    const Eigen::MatrixXd A =
      (R * H * R.transpose()).topLeftCorner(n - 1, n - 1) / form_result.gradient_norm;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(A);
    for (Eigen::Index i = 0; i + 1 < n; ++i)
      result.curvatures.push_back(eigen.eigenvalues()(i));
    result.breitung      = breitung_probability(form_result.beta, result.curvatures);
    result.tvedt         = tvedt_probability(form_result.beta, result.curvatures);
    result.beta_breitung = beta_of(result.breitung);
    result.beta_tvedt    = beta_of(result.tvedt);
    result.n_evaluations = G.n_evaluations();
    return result;
  }
} // namespace poundfe
