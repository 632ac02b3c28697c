// Sampling estimates of the failure probability of a reliability problem
// (one limit state or the series/parallel system of all of them).
//   Crude Monte Carlo: u_i ~ N(0, I), Pf^ = n_f/N, COV = sqrt((1 - Pf)/(N Pf)).
//   Importance sampling around design points u*_1..u*_m (one per limit
//   state; m = 1 for one limit state): the sampling density is the equal
//   mixture h(u) = (1/m) sum_k phi_n(u - u*_k), sample i drawn from
//   component i mod m (deterministic equal allocation: the balance-heuristic
//   estimator stays unbiased, Veach & Guibas 1995, Owen & Zhou 2000), with
//   weight w = phi_n(u)/h(u) = 1 / [(1/m) sum_k exp(u . u*_k - |u*_k|^2/2)];
//   Pf^ = (1/N) sum I_i w_i, COV = s(I w)/(sqrt(N) Pf^).
// Sources: Melchers & Beck (2018) ch. 3 (Monte Carlo, importance sampling
// around the design point, sec. 3.4); Ditlevsen & Madsen (1996) ch. 9;
// R. Melchers, "Importance sampling in structural systems", Structural
// Safety 6 (1989) 3-10; A. Owen, Y. Zhou, "Safe and effective importance
// sampling", JASA 95 (2000) 135-143.
#ifndef poundfe_reliability_sampling_h
#define poundfe_reliability_sampling_h

#include <poundfe/reliability/reliability_problem.h>

#include <cstdint>
#include <string>
#include <vector>

namespace poundfe
{
  struct SamplingSettings
  {
    unsigned long max_samples = 100000;
    /// Stop once the estimator's COV is at or below this (checked every
    /// 1000 samples, once a failure was seen); 0: run all samples.
    double        target_cov = 0;
    std::uint64_t seed       = 1;
  };

  struct SamplingResult
  {
    double        probability = 0;
    double        coefficient_of_variation = 0; // infinity when no failure was seen
    unsigned long n_samples = 0, n_failures = 0;
    unsigned long n_evaluations = 0; // of the g_k
    bool          interrupted = false; // SIGINT/SIGTERM: the samples so far
  };

  /// Crude Monte Carlo of the system (all limit states of `problem`).
  SamplingResult monte_carlo(const ReliabilityProblem &problem, const SamplingSettings &settings);

  /// Importance sampling of the system around `design_points` (u-space).
  SamplingResult importance_sampling(const ReliabilityProblem              &problem,
                                     const std::vector<std::vector<double>> &design_points,
                                     const SamplingSettings                 &settings);

  /// The check of a FORM estimate by importance sampling `is` around its
  /// design point (unbiased whatever the shape of the limit state): a
  /// warning when FORM's `form_probability` and is.probability differ by
  /// more than three standard errors of the sampling (CoV Pf_IS), or when
  /// the sampling found no failure around the design point; "" when they
  /// agree.
  std::string form_disagreement(double form_probability, const SamplingResult &is);
} // namespace poundfe

#endif
