// First-order reliability method (FORM): the design point u* is the point
// of the limit-state surface G(u) = 0 nearest the origin of the standard
// normal space,
//   u* = argmin |u|  subject to G(u) = 0,   beta = alpha . u*,   Pf ~ Phi(-beta),
//   alpha = -grad G(u*)/|grad G(u*)|  (the importance vector; alpha_i^2 the
//   share of variable i in the variance of the linearised G).
// Search: improved HL-RF (Zhang & Der Kiureghian 1995). From u_k the HL-RF
// step is d_k = [(grad G . u_k - G)/|grad G|^2] grad G - u_k; the step size
// lambda = b^j (b = 1/2, j = 0, 1, ...) is the first that decreases the merit
// function m(u) = |u|^2/2 + c |G(u)| by the Armijo rule
//   m(u_k + lambda d_k) <= m(u_k) + a lambda grad m(u_k) . d_k,   a = 1/2,
// with c = (2 |u_k| + 10)/|grad G(u_k)| > |u_k|/|grad G(u_k)|, which makes d_k
// a descent direction of m. Converged when |G(u)|/|G(u_0)| <= e1 and
// |u - (alpha . u) alpha| <= e2.
// Gradients by finite differences in u (central by default).
// Sensitivity of beta to a distribution parameter theta (mean or standard
// deviation of a marginal), at the design point x* held fixed
// (Hohenbichler & Rackwitz 1986; Der Kiureghian 2005, eq. 14.35):
//   d beta/d theta = alpha . d u(x*; theta)/d theta,
// the derivative of the transformation taken by central differences (R0
// recomputed), so it costs no limit-state evaluation.
// Sources: Y. Zhang, A. Der Kiureghian, "Two improved algorithms for
// reliability analysis", Reliability and Optimization of Structural Systems
// (1995) 297-304; A. Der Kiureghian, ch. 14 of the Engineering Design
// Reliability Handbook (CRC 2005); M. Hohenbichler, R. Rackwitz,
// "Sensitivity and importance measures in structural reliability", Civil
// Engineering Systems 3 (1986) 203-209; Melchers & Beck (2018) ch. 4.
#ifndef poundfe_reliability_form_h
#define poundfe_reliability_form_h

#include <poundfe/reliability/reliability_problem.h>

#include <string>
#include <vector>

namespace poundfe
{
  struct FormSettings
  {
    unsigned int max_iterations     = 100;
    double       tolerance_g        = 1e-6; // e1, relative to |G(u_0)|
    double       tolerance_u        = 1e-6; // e2, in standard deviations
    double       gradient_step      = 1e-4; // in standard deviations
    bool         central_difference = true;
  };

  struct FormResult
  {
    bool                converged = false;
    double              beta      = 0;
    double              probability = 0; // Phi(-beta)
    std::vector<double> design_point_u, design_point_x;
    std::vector<double> alpha; // importance vector
    /// |grad G(u*)| (SORM scales the Hessian by it).
    double              gradient_norm = 0;
    unsigned int        iterations    = 0; // HL-RF steps
    unsigned int        n_gradients   = 0;
    unsigned long       n_evaluations = 0; // of g, line search and gradients included
    /// d beta/d mean_i and d beta/d sd_i (for a truncated normal: its
    /// parent's mu and sigma).
    std::vector<double> dbeta_dmean, dbeta_dsd;
    /// Why FORM stopped without converging ("" when it converged): the
    /// iterations ran out, the gradient vanished, a value was not finite.
    std::string         failure;
    /// The gradient was zero at u = 0: FORM had no direction at all (no
    /// beta, no Pf can be reported).
    bool                zero_gradient_at_start = false;
  };

  /// FORM on limit state k of `problem` from u = 0. Returns converged = false
  /// (with the last iterate) when the iterations run out or the gradient
  /// vanishes; the caller decides whether that is an error.
  FormResult form(const ReliabilityProblem &problem, unsigned int k,
                  const FormSettings &settings = {});

  /// The sensitivities of beta at the design point of `result` (fills
  /// dbeta_dmean, dbeta_dsd).
  void beta_sensitivities(const NatafTransformation &transformation, FormResult &result);
} // namespace poundfe

#endif
