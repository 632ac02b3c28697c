// Subset Simulation (Au & Beck 2001, Probabilistic Engineering Mechanics
// 16(4)) of P(Y(xi) > b) with xi independent standard normals.
//   Level 0: N direct samples. Level i: the threshold b_i is the (1 - p0)
//   quantile of Y; the n_s = round(p0 N) samples above it seed Markov chains
//   of N/n_s states each (the seed is the first state; when N/n_s is not
//   whole, N mod n_s chains drawn at random have one state more: Papaioannou
//   et al. 2015, Probabilistic Engineering Mechanics 41, sec. 3; giving them
//   to the largest seeds instead over-represents the upper tail at every
//   level and biases Pf upwards), grown by the modified
//   Metropolis algorithm: component-wise Gaussian proposal xi_k + s N(0,1),
//   accepted with min(1, phi(candidate) / phi(xi_k)); the candidate vector is
//   then kept only if Y > b_i, otherwise the chain repeats its state.
//   Pf = p0^(m-1) P(Y > b | level m-1).
//   CoV: delta_i^2 = (1 - P_i)/(N P_i) (1 + gamma_i), gamma_i from the
//   correlation of the indicators along the chains (Au & Beck 2001, eq. 27-29).
//   The levels' estimates are correlated (each level's chains start from the
//   previous level's samples), so the CoV of Pf lies between two bounds:
//   sqrt(sum delta_i^2) (levels uncorrelated: a lower bound) and
//   sum delta_i (levels fully correlated: Au & Beck 2001's upper bound).
// Parallel: chain j runs on rank j mod P from a random stream of (seed,
// level, j), and the longer chains are drawn from a stream of (seed, level)
// on every rank alike, so the estimate does not depend on the number of ranks.
// Resumable: with a journal (reliability/subset_journal.h) every response
// is recorded, and one an earlier run recorded is taken, not recomputed.
#ifndef poundfe_reliability_subset_h
#define poundfe_reliability_subset_h

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace poundfe
{
  struct SubsetSettings
  {
    unsigned int  samples_per_level       = 1000;
    double        conditional_probability = 0.1;
    unsigned int  max_levels              = 10;
    double        proposal_spread         = 1.0;
    std::uint64_t seed                    = 1;
  };

  struct SubsetLevel
  {
    double threshold              = 0; // b_i (the final level: the target)
    double conditional_probability = 0; // P_i
    double acceptance_rate        = 0; // of the chain moves that produced it (0 at level 0)
    double coefficient_of_variation = 0; // delta_i
  };

  struct SubsetResult
  {
    double                   probability = 0;
    /// sqrt(sum delta_i^2): the CoV if the levels were uncorrelated, a lower
    /// bound (the levels are positively correlated).
    double                   coefficient_of_variation = 0;
    /// sum delta_i: the CoV if the levels were fully correlated (Au & Beck
    /// 2001: delta^2 <= sum_ij delta_i delta_j), an upper bound.
    double                   coefficient_of_variation_upper_bound = 0;
    std::vector<SubsetLevel> levels;
    unsigned long            model_runs = 0;  // run by this call
    unsigned long            resumed_runs = 0; // taken from the journal of an earlier run
    bool                     reached_threshold = false; // false: stopped at max_levels
    /// Stopped by SIGINT or SIGTERM: `levels` are the thresholds reached
    /// (none when level 0 was cut), `probability` is P(Y > levels.back().threshold).
    bool interrupted = false;
  };

  /// Y(xi) of one sample; called on the rank that owns the chain.
  using ResponseFunction = std::function<double(const std::vector<double> &)>;

  /// The responses of earlier runs, by (level, sample: its place in the
  /// level, chain by chain), and where each new one is recorded.
  class SubsetJournal
  {
  public:
    virtual ~SubsetJournal() = default;
    /// Whether an earlier run computed this sample's response (then in `response`).
    virtual bool find(unsigned int level, unsigned int sample, double &response) const = 0;
    virtual void record(unsigned int level, unsigned int sample, double response) = 0;
  };

  /// Runs over the ranks of `comm` (each rank must call it); the result is
  /// the same on every rank. Stops at the next sample on SIGINT or SIGTERM
  /// (interruption.h) and drops the level under way.
  SubsetResult subset_simulation(const ResponseFunction &response, unsigned int n_variables,
                                 double threshold, const SubsetSettings &settings, MPI_Comm comm,
                                 SubsetJournal *journal = nullptr);
} // namespace poundfe

#endif
