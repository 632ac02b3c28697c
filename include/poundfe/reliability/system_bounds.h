// First-order system reliability from the FORM results of the components.
// Component i: P_i = Phi(-beta_i); pair (i, j): P_ij = Phi2(-beta_i, -beta_j;
// rho_ij), rho_ij = alpha_i . alpha_j (the linearised safety margins'
// correlation).
//   Series system, Ditlevsen's bimodal bounds (components in decreasing P_i):
//     lower = P_1 + sum_{i>=2} max(0, P_i - sum_{j<i} P_ij),
//     upper = sum_i P_i - sum_{i>=2} max_{j<i} P_ij.
//   Parallel system: two components, P = P_12 (first-order exact); more
//   components: the second-order upper bound min_{i<j} P_ij, lower bound 0.
//   Phi2(a, b; rho) = Phi(a) Phi(b) + (1/2pi) int_0^{asin rho}
//                      exp(-(a^2 + b^2 - 2 a b sin t)/(2 cos^2 t)) dt
//   (Sheppard's formula in the angle form used by Genz 2004), integrated by
//   adaptive Gauss-Kronrod (15 points).
// Sources: O. Ditlevsen, "Narrow reliability bounds for structural
// systems", J. Struct. Mech. 7(4) (1979) 453-472; Melchers & Beck (2018)
// sec. 6.4; A. Genz, "Numerical computation of rectangular bivariate and
// trivariate normal and t probabilities", Statistics and Computing 14 (2004)
// 251-260.
#ifndef poundfe_reliability_system_bounds_h
#define poundfe_reliability_system_bounds_h

#include <poundfe/reliability/reliability_problem.h>

#include <vector>

namespace poundfe
{
  struct SystemBounds
  {
    double lower = 0, upper = 0;
  };

  /// P(U1 <= a, U2 <= b) for standard normals with correlation rho.
  double bivariate_normal_cdf(double a, double b, double rho);

  /// The bounds of the system of components with reliability indices
  /// `betas` and importance vectors `alphas`.
  SystemBounds system_bounds(SystemType system, const std::vector<double> &betas,
                             const std::vector<std::vector<double>> &alphas);
} // namespace poundfe

#endif
