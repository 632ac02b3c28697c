// Separation of adjacent buildings (the `separation` command): the joint
// width that avoids pounding, from the buildings' responses WITHOUT contact.
//
//   At each common level y of two adjacent buildings (every floor level of
//   either up to the lower roof, above both bases), with u_1, u_2 the peak
//   displacements of the left and right building there:
//     ABS   = u_1 + u_2
//     SRSS  = sqrt(u_1^2 + u_2^2)
//     DDC   = sqrt(u_1^2 + u_2^2 - 2 rho u_1 u_2)        (Jeng et al. 1992; Penzien 1997)
//     rho   = 8 sqrt(z_1 z_2) (z_1 + r z_2) r^1.5 /
//             ((1 - r^2)^2 + 4 z_1 z_2 r (1 + r^2) + 4 (z_1^2 + z_2^2) r^2),  r = w_2 / w_1,
//             the CQC correlation of the two buildings' fundamental modes
//             (Der Kiureghian 1981) with their own w_i and damping ratios z_i
//     EC8   = f sqrt(d_s1^2 + d_s2^2), d_si = q_i u_i (EN 1998-1 §4.4.2.7(3), eq. 4.23),
//             f = 0.7 where both buildings have a floor at y (§4.4.2.7(4)), else 1
//     ASCE7 = sqrt(d_M1^2 + d_M2^2), d_Mi = C_di u_i / I_ei (ASCE/SEI 7-16 §12.12.3,
//             eqs. 12.12-1 and 12.12-2)
//   and the time-history minimum separation max_t (u_left(y, t) - u_right(y, t)),
//   the largest approach of the two (positive toward each other).
//   A building without a floor at y: its displacement there is interpolated
//   linearly in height between its floors below and above (its base: 0) at
//   every step; u_i is the peak of that history. Floor displacement: the
//   mean ux of the floor's joints (output/floor_response.h).
//   Response-spectrum route (Separation/Peak displacements): u_i by modal
//   combination of the Eurocode 8 spectrum, no time history
//   (separation/separation_spectrum.h).
//   With random loading: Monte Carlo without contact; u_i and the
//   time-history value are the means over the realizations (EN 1998-1
//   §4.3.3.4.3(3) takes the average of the response histories), and the
//   probability of pounding against the gap g is the exceedance curve
//   P(D > g) of D = max over the pair's common levels of the largest
//   approach, with a pointwise Wilson score band; the gap for a target
//   probability p is the type-7 (1 - p) quantile of D (statistics.h).
//   With a site hazard (Separation/Site hazard): the probability of
//   pounding over an exposure time and the gap for a target, from the
//   Monte Carlo at several PGA levels (hazard/pounding_hazard.h).
// Sources: Der Kiureghian, EESD 9 (1981) 419-435; Jeng, Kasai & Maison,
// Earthquake Spectra 8(2) (1992) 201-223; Penzien, EESD 26 (1997) 849-858;
// Lopez Garcia, Proc. 13th WCEE, Vancouver (2004) (DDC for yielding
// structures); EN 1998-1:2004 §4.4.2.7 and §4.3.3.4.3;
// ASCE/SEI 7-16; Wilson, JASA 22 (1927) 209-212.
#ifndef poundfe_separation_separation_h
#define poundfe_separation_separation_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/modal_parameters.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/hazard/pounding_hazard.h>
#include <poundfe/output/floor_response.h>
#include <poundfe/output/observer.h>
#include <poundfe/reliability/distribution.h>
#include <poundfe/reliability/montecarlo.h>
#include <poundfe/reliability/nataf.h>
#include <poundfe/reliability/statistics.h>
#include <poundfe/separation/separation_parameters.h>

#include <mpi.h>

#include <array>
#include <memory>
#include <functional>
#include <string>
#include <vector>

namespace poundfe
{
  /// Der Kiureghian's (1981) correlation of two modes (rad/s, damping ratios).
  double modal_correlation(double omega_1, double zeta_1, double omega_2, double zeta_2);

  /// The code factors of one building.
  struct BuildingCodeFactors
  {
    double deflection_amplification = 1; // ASCE 7 C_d
    double importance_factor        = 1; // ASCE 7 I_e
    double behaviour_factor         = 1; // EC8 q
  };

  /// Required separations at one level, m.
  struct SeparationRules
  {
    double abs = 0, srss = 0, ddc = 0, ec8 = 0, asce7 = 0;
  };

  /// The rules at a level where the buildings' peak displacements are u_1
  /// and u_2 (>= 0), their fundamental modes correlate by rho.
  SeparationRules separation_rules(double u_1, double u_2, double rho,
                                   const BuildingCodeFactors &left,
                                   const BuildingCodeFactors &right, bool floors_coincide,
                                   double coinciding_levels_factor);

  /// A building's displacement at a level: (1 - weight) x_below + weight
  /// x_above, x the FloorResponse floor displacements (index -1: the base, 0).
  struct LevelInterpolation
  {
    int    below  = -1;
    int    above  = -1;
    double weight = 0;
  };

  /// The value at `where` of per-floor values x (FloorResponse order).
  double value_at(const std::vector<double> &floor_values, const LevelInterpolation &where);

  struct CommonLevel
  {
    double                            level           = 0; // m
    bool                              floors_coincide = false;
    std::array<LevelInterpolation, 2> sides; // left, right building
  };

  /// Two buildings side by side (right = left + 1) and their common levels.
  struct AdjacentPair
  {
    unsigned int             left = 0, right = 1;
    double                   existing_gap = 0; // clear distance in the model, m
    std::vector<CommonLevel> levels;
    std::string              name; // "A3-B2"
  };

  /// Every pair of neighbours of `model` with its common levels.
  std::vector<AdjacentPair> adjacent_pairs(const Model &model);

  /// The fundamental (first) mode of a building and its damping ratio
  /// phi^T C phi / (2 omega) (phi mass-normalised, C the assembled damping).
  struct FundamentalMode
  {
    double omega = 0, damping_ratio = 0;
  };
  /// Uses the modes prepare_analysis computed, else computes the first by
  /// `eigensolver` (Modal analysis/Eigensolver).
  FundamentalMode fundamental_mode(const Analysis &analysis, unsigned int building,
                                   Eigensolver eigensolver = Eigensolver::automatic);

  /// Watches the pairs in a time history: at every step and sub-step the
  /// displacements of both buildings at each common level, their peaks
  /// |u| and the largest approach u_left - u_right.
  class SeparationObserver : public StepObserver
  {
  public:
    struct LevelResponse
    {
      double peak_left = 0, peak_right = 0; // max |u|
      double max_approach = 0;              // max (u_left - u_right)
      double approach     = 0;              // at the last observed step
    };

    SeparationObserver(const Model &model, const std::vector<AdjacentPair> &pairs);

    /// Forgets an earlier run, then observes the initial state.
    void initialize(const ResponseView &state) override;
    void observe_step(const ResponseView &state) override;
    void observe_substep(const ResponseView &state) override { observe_step(state); }

    /// Per pair, per common level.
    const std::vector<std::vector<LevelResponse>> &responses() const { return levels; }

  private:
    const std::vector<AdjacentPair>        &pairs;
    FloorResponse                           floors;
    std::vector<std::vector<LevelResponse>> levels;
  };

  /// A point of the exceedance curve P(D > gap) with its band.
  struct ExceedancePoint
  {
    double        gap = 0;
    unsigned long n_exceeding = 0;
    double        probability = 0, lower = 0, upper = 1;
  };

  /// The empirical P(D > g) of `sample` at each of `gaps`, with the Wilson
  /// band at `confidence`.
  std::vector<ExceedancePoint> exceedance_curve(const std::vector<double> &sample,
                                                const std::vector<double> &gaps,
                                                double                     confidence);

  /// The gaps of an exceedance curve: the input's Gap values, or Number of
  /// gap values evenly from 0 to 1.2 `largest` (1 m when largest <= 0).
  std::vector<double> gap_grid(const SeparationParameters &p, double largest);

  /// The values of one common level: peaks, time-history value, rules.
  struct LevelResult
  {
    double          u_left = 0, u_right = 0, time_history = 0;
    SeparationRules rules;
  };

  /// A pair's fundamental modes, their correlation and its levels.
  struct PairResult
  {
    FundamentalMode          left_mode, right_mode;
    double                   rho = 0;
    std::vector<LevelResult> levels;
    /// Monte Carlo: per completed realization, the largest approach over
    /// the pair's levels.
    std::vector<double> largest_approach;
    /// Monte Carlo with a random separation of the pair (RandomSeparations):
    /// per completed realization, its sampled separation (else empty).
    std::vector<double> random_separation;
  };

  /// Random separations of pairs in a Monte Carlo without contact: they do
  /// not change the free responses, so each realization samples its pair's
  /// separation s_r, from the normal that follows the runner's in the
  /// realization's stream (x = F^-1(Phi(u))), and pounds when its largest
  /// approach exceeds s_r: P(pounding) = #{a_r > s_r} / n. Correlated
  /// (Random parameters/Correlation), the separations are the last
  /// components of x = T(u) of `joint`, a Nataf transformation over the
  /// structure's variables then the separations, u the realization's
  /// normals after the loading's: the Cholesky factor of R0 is lower
  /// triangular, so its leading block is the structure's own and the
  /// structure's values are those the runner samples.
  struct RandomSeparations
  {
    std::vector<unsigned int> pairs; // index in the pairs of each variable
    std::vector<Distribution> distributions;
    std::shared_ptr<const NatafTransformation> joint; // null: independent
  };

  /// The rule values and their names, in the order of separation.csv.
  inline const std::array<const char *, 5> rule_names{{"ABS", "SRSS", "DDC", "EC8", "ASCE7"}};

  inline std::array<double, 5>
  rule_values(const SeparationRules &r)
  {
    return {{r.abs, r.srss, r.ddc, r.ec8, r.asce7}};
  }

  /// The results before any run: each building's fundamental mode, rho, the levels.
  std::vector<PairResult> pair_results_before_run(const Analysis                  &analysis,
                                                  const std::vector<AdjacentPair> &pairs,
                                                  Eigensolver                      eigensolver);

  /// One time history of the analysis' (deterministic) excitation without
  /// contact: the peaks and largest approach into each level of `results`.
  RunStatus run_without_contact(const Analysis &analysis, const TimeHistoryParameters &parameters,
                                const std::vector<AdjacentPair> &pairs,
                                std::vector<PairResult> &results);

  /// Monte Carlo of realizations 0..n-1 over the random loading on every rank
  /// of `comm` (run_realizations: directory/realizations.csv, resumed; an
  /// empty `directory`: none, results in memory): the
  /// means of the peaks and the largest approach of every realization into
  /// `results` (rank 0). `attach_parameters` makes model parameters random
  /// in the runner (reliability/random_parameters.h); `separations` samples
  /// pairs' separations. Returns the table (rank 0).
  MonteCarloTable run_realizations_without_contact(const Analysis                  &analysis,
                                                   const TimeHistoryParameters &parameters,
                                                   const std::vector<AdjacentPair> &pairs,
                                                   unsigned long n, const std::string &directory,
                                                   MPI_Comm comm, std::vector<PairResult> &results,
                                                   const std::function<void(RealizationRunner &)>
                                                     &attach_parameters = {},
                                                   const RandomSeparations &separations = {});

  /// P(pounding) of a pair with a random separation: #{a_r > s_r} / n over
  /// its completed realizations (largest approach a_r, sampled separation s_r).
  ProbabilityEstimate pounding_at_random_separation(const PairResult &result);

  /// The pounding hazard's realization (hazard/pounding_hazard.h): `runner`
  /// with `observer` watching `pairs`; the largest approach over each pair's
  /// levels. `runner` and `observer` must outlive the job.
  ApproachJob largest_approach_job(RealizationRunner &runner, SeparationObserver &observer,
                                   const std::vector<AdjacentPair> &pairs);

  /// Fill the rules of every level from its u_left, u_right.
  void apply_rules(const SeparationParameters &p, const AdjacentPair &pair, PairResult &result);

  /// The gaps of the exceedance curve: past the largest approach and the existing gaps.
  std::vector<double> gap_grid(const SeparationParameters &p, const std::vector<AdjacentPair> &pairs,
                               const std::vector<PairResult> &results);

  /// The gap whose P(D > g) is the target, interpolated (type-7 quantile).
  double gap_for_probability(std::vector<double> sample, double probability);

  /// The smallest gap at which the band's upper limit is at most the
  /// target: no more than k exceedances with wilson(k, n).upper <= p;
  /// NaN when even none is not enough (too few realizations).
  double gap_for_probability_upper(std::vector<double> sample, double probability,
                                   double confidence);

  /// The joint of a pair: each rule's and the time history's largest
  /// requirement over the levels.
  struct Joint
  {
    std::array<double, 5> required{};
    double                time_history = 0;
    /// The larger of the two code rules: EC8 (3) or ASCE 7 (4).
    unsigned int governing_code_rule() const { return required[3] >= required[4] ? 3 : 4; }
  };

  Joint joint_of(const PairResult &result);
} // namespace poundfe

#endif
