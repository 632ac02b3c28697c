// Dynamic FORM: FORM (reliability/form.h, improved HL-RF) on a limit state
// over the responses of a time history, g(u) = g(responses(u), x(u)), with
// the gradient dG/du by finite differences of full time histories (n + 1
// per gradient forward, 2n central).
// The variables, in this order, are
//   - an optional random scale factor s on the loading's amplitude (its
//     distribution through Nataf, u_s = Phi^-1(F(s)));
//   - the first n_e standard normals of the random loading (white-noise
//     samples, spectral-representation phases Phi^-1(phi/2pi), ...), the
//     others held at those of one realization;
//   - the standard normals of the Random parameters (the runner maps them
//     to the parameters' values, dynamics/realization.h).
// Each evaluation of G is one time history; the design point u*, beta =
// alpha . u*, Pf = Phi(-beta) and alpha are FORM's. Optionally, at the
// converged u*: SORM (reliability/sorm.h: Breitung and Tvedt from the
// principal curvatures, the Hessian of G by central differences of time
// histories) and importance sampling around u* (reliability/sampling.h:
// samples u ~ N(u*, I), weight phi(u)/phi(u - u*)), so the FORM estimate is
// checked by a second-order one and by an unbiased one (Der Kiureghian 2000,
// sec. 6, on the curvature of the surfaces of nonlinear random vibration). For a response linear in
// Gaussian loading variables (a linear structure, a response at a fixed time)
// G is linear in u and FORM is exact.
// Sources: A. Der Kiureghian, "The geometry of random vibrations and
// solutions by FORM and SORM", Probabilistic Engineering Mechanics 15 (2000)
// 81-90; Der Kiureghian, ch. 14 of the Engineering Design Reliability
// Handbook (CRC 2005).
#ifndef poundfe_reliability_dynamic_form_h
#define poundfe_reliability_dynamic_form_h

#include <poundfe/reliability/distribution.h>
#include <poundfe/reliability/form.h>
#include <poundfe/reliability/sampling.h>
#include <poundfe/reliability/sorm.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace poundfe
{
  class RealizationRunner;
  class ResponseLimitStates;

  struct DynamicFormSettings
  {
    unsigned int              n_excitation = 0; // <= the runner's loading normals
    std::uint64_t             realization  = 0; // of the held loading normals
    std::vector<Distribution> scale;            // the scale factor's, or none
    FormSettings              form;
    bool                      sorm = false;            // then SORM at u*
    unsigned long             importance_samples = 0;  // then IS around u*, FORM's check
    std::uint64_t             importance_seed    = 1;
  };

  struct DynamicFormResult
  {
    FormResult               form;
    /// "scale" (with a scale factor), "xi1".."xi<n_e>", the parameters' names
    std::vector<std::string> variable_names;
    /// the design point's physical values: s, the loading normals, the
    /// parameters' values
    std::vector<double>      design_point;
    /// the runner's responses at the design point (one more time history)
    std::vector<double>      design_responses;
    double                   design_limit_state = 0; // g there (~0 when converged)
    unsigned long            n_time_histories = 0;  // all of them
    unsigned long            n_failed_runs    = 0;  // integrations that did not finish
    /// SORM at the design point (when asked and FORM converged) and its
    /// time histories
    std::optional<SormResult>     sorm;
    unsigned long                 n_sorm_time_histories = 0;
    /// importance sampling around the design point (when asked and FORM
    /// converged), and its warning when it and FORM disagree beyond its
    /// error ("" when they agree: form_disagreement)
    std::optional<SamplingResult> importance;
    std::string                   form_check;
  };

  /// FORM on the system value of `limit_states` over `runner`'s
  /// realizations. Returns converged = false when FORM does not converge
  /// (form.failure says why; no design point when the gradient is zero at
  /// the start). A limit state that is NaN (or, for FORM and SORM,
  /// infinite) on a time history is a NumericalError naming it.
  DynamicFormResult dynamic_form(RealizationRunner &runner, const ResponseLimitStates &limit_states,
                                 const DynamicFormSettings &settings);
} // namespace poundfe

#endif
