// Equations and sources: include/poundfe/reliability/nataf.h.
#include <poundfe/reliability/nataf.h>

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <string>

namespace poundfe
{
  namespace
  {
    /// Nodes and weights of Gauss-Hermite quadrature for the standard
    /// normal weight (E[f(Z)] ~ sum w_k f(z_k)), by Golub-Welsch: the nodes
    /// are the eigenvalues of the Jacobi matrix of the probabilists' Hermite
    /// polynomials (off-diagonal sqrt(k)), the weights the squared first
    /// components of its normalised eigenvectors.
    struct GaussHermite
    {
      std::vector<double> nodes, weights;
      explicit GaussHermite(const unsigned int n)
      {
        Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(n, n);
        for (unsigned int k = 1; k < n; ++k)
          jacobi(k, k - 1) = jacobi(k - 1, k) = std::sqrt(double(k));
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(jacobi);
        for (unsigned int k = 0; k < n; ++k)
          {
            nodes.push_back(eigen.eigenvalues()(k));
            weights.push_back(eigen.eigenvectors()(0, k) * eigen.eigenvectors()(0, k));
          }
      }
    };

    const GaussHermite &
    quadrature()
    {
      static const GaussHermite rule(64);
      return rule;
    }

    /// Mean and standard deviation of a marginal by the same quadrature
    /// (so that rho0 = 1 gives rho = 1 to round-off).
    struct QuadratureMoments
    {
      double mean = 0, sd = 0;
      explicit QuadratureMoments(const Distribution &d)
      {
        const GaussHermite &q = quadrature();
        double              second = 0;
        for (std::size_t k = 0; k < q.nodes.size(); ++k)
          mean += q.weights[k] * d.from_standard_normal(q.nodes[k]);
        for (std::size_t k = 0; k < q.nodes.size(); ++k)
          second += q.weights[k] * std::pow(d.from_standard_normal(q.nodes[k]) - mean, 2);
        sd = std::sqrt(second);
      }
    };

    /// rho of X_a, X_b when their normal images have correlation rho0:
    /// z_a = z_i, z_b = rho0 z_i + sqrt(1 - rho0^2) z_j over the 2-D rule.
    double
    correlation_of(const Distribution &a, const Distribution &b, const double rho0)
    {
      const GaussHermite     &q = quadrature();
      const QuadratureMoments ma(a), mb(b);
      const double            c   = std::sqrt(1 - rho0 * rho0);
      double                  sum = 0;
      for (std::size_t i = 0; i < q.nodes.size(); ++i)
        {
          double inner = 0;
          for (std::size_t j = 0; j < q.nodes.size(); ++j)
            inner += q.weights[j] * (b.from_standard_normal(rho0 * q.nodes[i] + c * q.nodes[j]) -
                                     mb.mean);
          sum += q.weights[i] * (a.from_standard_normal(q.nodes[i]) - ma.mean) * inner;
        }
      return sum / (ma.sd * mb.sd);
    }

    bool
    is(const Distribution &d, const DistributionType t)
    {
      return d.type() == t;
    }
  } // namespace

  double
  equivalent_normal_correlation(const Distribution &a, const Distribution &b, const double rho)
  {
    using T = DistributionType;
    if (rho == 0)
      return 0;
    if (is(a, T::normal) && is(b, T::normal))
      return rho;
    const auto cov = [](const Distribution &d) { return d.standard_deviation() / d.mean(); };
    double rho0 = 2; // "no closed form"
    if (is(a, T::normal) && is(b, T::lognormal))
      rho0 = rho * cov(b) / b.parameters()[1];
    else if (is(a, T::lognormal) && is(b, T::normal))
      rho0 = rho * cov(a) / a.parameters()[1];
    else if (is(a, T::lognormal) && is(b, T::lognormal))
      rho0 = std::log1p(rho * cov(a) * cov(b)) / (a.parameters()[1] * b.parameters()[1]);
    if (rho0 != 2)
      {
        if (!(std::abs(rho0) < 1))
          throw std::invalid_argument("no joint normal image reaches the correlation " +
                                      std::to_string(rho) + " of these marginals");
        return rho0;
      }
    const auto rho_of = [&](const double r) { return correlation_of(a, b, r); };
    double     lo = -0.9999, hi = 0.9999;
    if (!(rho > rho_of(lo) && rho < rho_of(hi)))
      throw std::invalid_argument("no joint normal image reaches the correlation " +
                                  std::to_string(rho) + " of a " + distribution_name(a.type()) +
                                  " and a " + distribution_name(b.type()) + " variable");
    for (int i = 0; i < 60 && hi - lo > 1e-13; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (rho_of(mid) < rho ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }

  DenseMatrix
  cholesky_factor(const DenseMatrix &matrix)
  {
    const std::size_t n = matrix.size();
    DenseMatrix       L(n, std::vector<double>(n, 0.0));
    for (std::size_t j = 0; j < n; ++j)
      {
        double d = matrix[j][j];
        for (std::size_t k = 0; k < j; ++k)
          d -= L[j][k] * L[j][k];
        if (!(d > 1e-12 * std::abs(matrix[j][j])))
          throw std::invalid_argument("the correlation matrix is not positive definite");
        L[j][j] = std::sqrt(d);
        for (std::size_t i = j + 1; i < n; ++i)
          {
            double s = matrix[i][j];
            for (std::size_t k = 0; k < j; ++k)
              s -= L[i][k] * L[j][k];
            L[i][j] = s / L[j][j];
          }
      }
    return L;
  }

  NatafTransformation::NatafTransformation(std::vector<Distribution> marginals_in,
                                           const DenseMatrix        &correlation)
    : marginals(std::move(marginals_in))
    , correlation_given(correlation)
  {
    const std::size_t n = marginals.size();
    correlation0.assign(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i)
      correlation0[i][i] = 1;
    if (correlation.empty())
      return;
    if (correlation.size() != n)
      throw std::invalid_argument("the correlation matrix has " +
                                  std::to_string(correlation.size()) + " rows for " +
                                  std::to_string(n) + " random variables");
    bool independent = true;
    for (std::size_t i = 0; i < n; ++i)
      {
        if (correlation[i].size() != n)
          throw std::invalid_argument("row " + std::to_string(i + 1) +
                                      " of the correlation matrix has " +
                                      std::to_string(correlation[i].size()) + " entries, not " +
                                      std::to_string(n));
        if (std::abs(correlation[i][i] - 1) > 1e-12)
          throw std::invalid_argument("the correlation matrix's diagonal must be 1 (row " +
                                      std::to_string(i + 1) + ")");
        for (std::size_t j = 0; j < i; ++j)
          {
            const double r = correlation[i][j];
            if (std::abs(r - correlation[j][i]) > 1e-12)
              throw std::invalid_argument("the correlation matrix is not symmetric (rows " +
                                          std::to_string(j + 1) + " and " +
                                          std::to_string(i + 1) + ")");
            if (!(std::abs(r) < 1))
              throw std::invalid_argument("a correlation must lie in (-1, 1) (row " +
                                          std::to_string(i + 1) + ")");
            independent &= r == 0;
          }
      }
    cholesky_factor(correlation); // R itself must be positive definite
    if (independent)
      return;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < i; ++j)
        correlation0[i][j] = correlation0[j][i] =
          equivalent_normal_correlation(marginals[i], marginals[j], correlation[i][j]);
    try
      {
        cholesky = cholesky_factor(correlation0);
      }
    catch (const std::invalid_argument &)
      {
        throw std::invalid_argument("the equivalent normal correlation matrix R0 of the Nataf "
                                    "transformation is not positive definite");
      }
  }

  void
  NatafTransformation::to_physical(const std::vector<double> &u, std::vector<double> &x) const
  {
    const std::size_t n = marginals.size();
    x.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      {
        double z = u[i];
        if (!cholesky.empty())
          {
            z = 0;
            for (std::size_t k = 0; k <= i; ++k)
              z += cholesky[i][k] * u[k];
          }
        x[i] = marginals[i].from_standard_normal(z);
      }
  }

  void
  NatafTransformation::to_standard(const std::vector<double> &x, std::vector<double> &u) const
  {
    const std::size_t n = marginals.size();
    u.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      {
        const double z = marginals[i].to_standard_normal(x[i]);
        if (cholesky.empty())
          u[i] = z;
        else
          {
            // forward substitution L0 u = z
            double s = z;
            for (std::size_t k = 0; k < i; ++k)
              s -= cholesky[i][k] * u[k];
            u[i] = s / cholesky[i][i];
          }
      }
  }
} // namespace poundfe
