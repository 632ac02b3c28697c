// The Nataf transformation (Liu & Der Kiureghian 1986): random variables
// X_i with marginals F_i and correlation matrix R are mapped to independent
// standard normals u by
//   z_i = Phi^{-1}(F_i(x_i)),   z = L0 u,   L0 L0^T = R0,
// where z is taken jointly normal with the "equivalent" correlation R0 whose
// entries rho0_ij reproduce the given rho_ij:
//   rho_ij = E[(X_i - m_i)(X_j - m_j)] / (s_i s_j)
//          = int int (x_i(z_i) - m_i)/s_i (x_j(z_j) - m_j)/s_j phi2(z_i, z_j; rho0_ij) dz_i dz_j.
// The integral is evaluated by Gauss-Hermite quadrature (64 x 64 points,
// z_j = rho0 z_i + sqrt(1 - rho0^2) w) and solved for rho0 by bisection on
// (-1, 1) (rho is increasing in rho0: Liu & Der Kiureghian 1986, sec. 3).
// Where an exact relation exists it is used instead: normal-normal
// rho0 = rho; normal-lognormal rho0 = rho d_j/zeta_j; lognormal-lognormal
// rho0 = ln(1 + rho d_i d_j)/(zeta_i zeta_j) (d: COV; Liu & Der Kiureghian
// 1986, Table 2 and eqs. 17-19). The empirical formulas of that paper are not
// used: the quadrature covers every pair of marginals with one code.
// Sources: P.-L. Liu, A. Der Kiureghian, "Multivariate distribution models
// with prescribed marginals and covariances", Probabilistic Engineering
// Mechanics 1(2) (1986) 105-112; Melchers & Beck (2018) sec. 4.4;
// Ditlevsen & Madsen (1996) sec. 7.3.
#ifndef poundfe_reliability_nataf_h
#define poundfe_reliability_nataf_h

#include <poundfe/reliability/distribution.h>

#include <vector>

namespace poundfe
{
  /// A symmetric matrix stored row by row (n x n).
  using DenseMatrix = std::vector<std::vector<double>>;

  class NatafTransformation
  {
  public:
    /// `correlation`: empty (independent) or n x n, symmetric, unit
    /// diagonal, positive definite. Throws std::invalid_argument saying what
    /// is wrong (not symmetric, an entry outside [-1, 1], not positive
    /// definite, a correlation the marginals cannot reach, R0 not positive
    /// definite).
    NatafTransformation(std::vector<Distribution> marginals, const DenseMatrix &correlation = {});

    unsigned int n_variables() const { return marginals.size(); }
    const std::vector<Distribution> &distributions() const { return marginals; }
    /// R as given (empty: independent).
    const DenseMatrix &correlation() const { return correlation_given; }
    /// R0 (identity when the variables are independent).
    const DenseMatrix &equivalent_correlation() const { return correlation0; }

    /// x = T(u) (u: independent standard normals).
    void to_physical(const std::vector<double> &u, std::vector<double> &x) const;
    /// u = T^{-1}(x).
    void to_standard(const std::vector<double> &x, std::vector<double> &u) const;

  private:
    std::vector<Distribution> marginals;
    DenseMatrix               correlation_given;
    DenseMatrix               correlation0;
    /// Lower Cholesky factor of R0 (empty: independent).
    DenseMatrix cholesky;
  };

  /// rho0 of the pair (a, b) with correlation rho (see the file's head).
  /// Throws std::invalid_argument when no rho0 in (-1, 1) gives rho.
  double equivalent_normal_correlation(const Distribution &a, const Distribution &b, double rho);

  /// Lower Cholesky factor of a symmetric matrix; throws std::invalid_argument
  /// when it is not positive definite.
  DenseMatrix cholesky_factor(const DenseMatrix &matrix);
} // namespace poundfe

#endif
