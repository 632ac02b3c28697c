// The `reliability` analysis of algebraic limit states (no time history):
// the problem of the Reliability section (reliability_analysis_parameters.h)
// solved by the chosen methods, FORM and SORM per limit state, the others on
// the series/parallel system of all of them (with one limit state, on it).
// Equations: form.h, sorm.h, sampling.h, system_bounds.h, subset.h.
#ifndef poundfe_reliability_reliability_analysis_h
#define poundfe_reliability_reliability_analysis_h

#include <poundfe/reliability/form.h>
#include <poundfe/reliability/reliability_analysis_parameters.h>
#include <poundfe/reliability/sampling.h>
#include <poundfe/reliability/sorm.h>
#include <poundfe/reliability/system_bounds.h>

#include <mpi.h>

#include <optional>
#include <string>
#include <vector>

namespace poundfe
{
  struct LimitStateReliability
  {
    std::string               name, expression;
    std::optional<FormResult> form;
    std::optional<SormResult> sorm;
    /// Importance sampling around FORM's design point on this limit state
    /// alone (Sampling/Importance samples): the check of FORM's Pf.
    std::optional<SamplingResult> form_check;
  };

  /// An estimate of the system's failure probability by one method.
  struct SystemEstimate
  {
    std::string   method;
    double        probability = 0;
    double        coefficient_of_variation = 0; // 0 for FORM/SORM (no sampling error)
    unsigned long n_evaluations = 0;            // of limit-state functions
    double        wall_time_s   = 0;
    /// Subset Simulation: the CoV with its levels fully correlated (Au &
    /// Beck 2001's upper bound; `coefficient_of_variation` takes them
    /// uncorrelated, a lower bound); the other methods: none (their CoV is one value).
    std::optional<double> coefficient_of_variation_upper_bound;
  };

  struct ReliabilityReport
  {
    std::vector<LimitStateReliability> limit_states;
    /// FORM bounds of the system (more than one limit state and FORM run).
    std::optional<SystemBounds>  bounds;
    std::vector<SystemEstimate>  estimates;
    /// Non-empty when a method failed, what went wrong ("; " between
    /// several): FORM did not converge on a limit state (SORM and
    /// importance sampling, which need its design point, did not run; Monte
    /// Carlo and subset did), Subset Simulation stopped short, or a limit
    /// state was NaN at a sample (NumericalError: the methods after it did
    /// not run). What ran is kept.
    std::string                  failure;
    /// FORM's Pf and its importance-sampling check disagree beyond the
    /// sampling error (form_disagreement), per limit state.
    std::vector<std::string>     warnings;
    bool                         interrupted = false;
  };

  /// Runs the methods of `parameters` in the order FORM, SORM, importance
  /// sampling, Monte Carlo, subset (the last over the ranks of `comm`; the
  /// others run on every rank alike).
  ReliabilityReport run_reliability_analysis(const ReliabilityAnalysisParameters &parameters,
                                             MPI_Comm                             comm);

} // namespace poundfe

#endif
