// Second-order reliability method (SORM) from the principal curvatures of
// the limit-state surface at the FORM design point u*.
// Rotate the standard space so that its last axis is alpha: v = R u, R
// orthogonal with last row alpha (Gram-Schmidt). Near u*
//   G(u) ~ |grad G| (beta - v_n) + 1/2 (v - v*)^T R H R^T (v - v*),
// H the Hessian of G at u* (central finite differences in u), so the
// surface is v_n ~ beta + 1/2 v'^T A v', A = [R H R^T]_{n-1,n-1} / |grad G|,
// whose eigenvalues are the principal curvatures kappa_i (> 0: the failure
// domain curves away from the origin).
//   Breitung (1984):  Pf ~ Phi(-beta) prod_i (1 + beta kappa_i)^{-1/2}
//                     (asymptotically exact as beta -> infinity, kappa beta fixed);
//   Tvedt (1984), three terms, with psi = beta Phi(-beta) - phi(beta):
//     A1 = Phi(-beta) prod (1 + beta kappa_i)^{-1/2},
//     A2 = psi [prod (1 + beta kappa_i)^{-1/2} - prod (1 + (beta + 1) kappa_i)^{-1/2}],
//     A3 = (beta + 1) psi [prod (1 + beta kappa_i)^{-1/2}
//                          - Re prod (1 + (beta + i) kappa_i)^{-1/2}],
//     Pf ~ A1 + A2 + A3.
// Both need 1 + beta kappa_i > 0 (otherwise they are reported as NaN).
// Sources: K. Breitung, "Asymptotic approximations for multinormal
// integrals", J. Eng. Mech. 110(3) (1984) 357-366; L. Tvedt, "Two
// second-order approximations to the failure probability", Det Norske
// Veritas report RDIV/20-004-83 (1984), as given by Der Kiureghian (2005)
// eq. 14.43-14.44 and Melchers & Beck (2018) sec. 5.5.
#ifndef poundfe_reliability_sorm_h
#define poundfe_reliability_sorm_h

#include <poundfe/reliability/form.h>

#include <vector>

namespace poundfe
{
  struct SormResult
  {
    std::vector<double> curvatures; // kappa_i, ascending
    double              breitung = 0, tvedt = 0;
    /// beta of each: -Phi^{-1}(Pf).
    double              beta_breitung = 0, beta_tvedt = 0;
    unsigned long       n_evaluations = 0; // for the Hessian
  };

  /// SORM on limit state k at the converged FORM result `form_result`, the
  /// Hessian by central differences with step `hessian_step` (standard
  /// deviations).
  SormResult sorm(const ReliabilityProblem &problem, unsigned int k,
                  const FormResult &form_result, double hessian_step = 1e-3);

  /// The two formulas for given beta and curvatures.
  double breitung_probability(double beta, const std::vector<double> &curvatures);
  double tvedt_probability(double beta, const std::vector<double> &curvatures);
} // namespace poundfe

#endif
