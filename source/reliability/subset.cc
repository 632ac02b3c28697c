#include <poundfe/reliability/subset.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/progress.h>
#include <poundfe/excitation/stochastic.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <numeric>
#include <sstream>

namespace poundfe
{
  namespace
  {

    /// Where the ranks other than 0 send their progress.
    std::ostream silent(nullptr);

    /// Stream of chain j at level l: independent of the level-0 stream (seed, i).
    std::uint64_t
    chain_seed(const std::uint64_t seed, const unsigned int level)
    {
      return seed ^ (0x9e3779b97f4a7c15ULL * (level + 1));
    }

    /// The samples of one level: responses of all (in global order), the
    /// vectors of this rank's samples.
    struct LevelSamples
    {
      std::vector<double>              response;       // global
      std::vector<unsigned int>        chain_length;   // per chain; level 0: all 1
      std::vector<unsigned int>        owned;          // global ids held here
      std::vector<std::vector<double>> xi;             // of `owned`
    };

    /// delta_i^2 of P(Y > b) from a level's chains (gamma = 0 when all chains
    /// have length 1, i.e. direct Monte Carlo).
    double
    level_variance(const LevelSamples &level, const double b, const double p)
    {
      const double n = level.response.size();
      if (p <= 0)
        return std::numeric_limits<double>::infinity();
      if (p >= 1)
        return 0;
      const unsigned int longest =
        *std::max_element(level.chain_length.begin(), level.chain_length.end());
      double gamma = 0;
      for (unsigned int lag = 1; lag < longest; ++lag)
        {
          double       sum = 0, pairs = 0;
          unsigned int start = 0;
          for (const unsigned int length : level.chain_length)
            {
              for (unsigned int k = 0; k + lag < length; ++k)
                sum += (level.response[start + k] > b) * (level.response[start + k + lag] > b);
              pairs += length > lag ? length - lag : 0;
              start += length;
            }
          const double rho = (sum / pairs - p * p) / (p * (1 - p));
          gamma += 2 * (pairs / n) * rho;
        }
      return (1 - p) / (n * p) * (1 + gamma);
    }

    /// N states in n_chains chains (seed j: chain j, the seeds largest
    /// response first): N / n_chains each, and N mod n_chains of them, drawn
    /// at random from `stream`, one longer. Not the first ones: those are the
    /// largest seeds, whose extra states would over-represent the upper tail
    /// (a bias of Pf that grows with the number of levels). The draw is a
    /// stream of its own, (stream, 2^64 - 1), which no chain uses (chain j
    /// draws from (stream, j)): the same on every rank and in a resumed run.
    std::vector<unsigned int>
    chain_lengths(const unsigned int N, const unsigned int n_chains, const std::uint64_t stream)
    {
      std::vector<unsigned int> length(n_chains, N / n_chains);
      const unsigned int        n_longer = N % n_chains;
      if (n_longer == 0)
        return length;
      NormalStream        random(stream, ~std::uint64_t(0));
      std::vector<double> key(n_chains);
      for (double &k : key)
        k = random.next();
      std::vector<unsigned int> order(n_chains);
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(),
                       [&](unsigned int a, unsigned int b) { return key[a] < key[b]; });
      for (unsigned int i = 0; i < n_longer; ++i)
        ++length[order[i]];
      return length;
    }

    /// Global ids in chain order, the owner of chain j is rank j mod P.
    std::vector<unsigned int>
    chain_starts(const std::vector<unsigned int> &lengths)
    {
      std::vector<unsigned int> start(lengths.size() + 1, 0);
      for (std::size_t j = 0; j < lengths.size(); ++j)
        start[j + 1] = start[j] + lengths[j];
      return start;
    }

    /// One Subset Simulation, phase by phase (deal.II step-26 style): the
    /// direct samples of level 0, then per level its threshold, the seeds
    /// moved to the ranks of their chains, and the chains.
    class SubsetRun
    {
    public:
      SubsetRun(const ResponseFunction &response, const unsigned int n_variables,
                const SubsetSettings &settings, const MPI_Comm comm, SubsetJournal *journal)
        : response(response)
        , n_variables(n_variables)
        , settings(settings)
        , comm(comm)
        , journal(journal)
        , rank(dealii::Utilities::MPI::this_mpi_process(comm))
        , n_ranks(dealii::Utilities::MPI::n_mpi_processes(comm))
        , N(settings.samples_per_level)
      {}

      SubsetResult run(double threshold);

    private:
      const ResponseFunction &response;
      const unsigned int      n_variables;
      const SubsetSettings   &settings;
      const MPI_Comm          comm;
      SubsetJournal *const    journal;
      const unsigned int      rank, n_ranks, N;
      SubsetResult            result;
      LevelSamples            level;      // the current level
      double                  acceptance = 0; // of the moves that produced it
      bool                    stopped    = false; // this rank saw SIGINT/SIGTERM

      double evaluate(unsigned int l, unsigned int sample, const std::vector<double> &xi);
      std::unique_ptr<Progress> level_progress(unsigned int l, unsigned long total) const;
      void   sample_level_0();
      /// The level's exceedance of b (its probability and CoV) appended to the result.
      void   add_level(double b, double p);
      std::vector<std::vector<double>> move_seeds(const std::vector<unsigned int> &seeds) const;
      void   run_chains(unsigned int l, double b, const std::vector<unsigned int> &seeds);
      /// Every rank's responses of `next`; true when all ranks went on.
      bool   gather(LevelSamples &next);
    };

    double
    SubsetRun::evaluate(const unsigned int l, const unsigned int sample,
                        const std::vector<double> &xi)
    {
      double y = 0;
      if (journal && journal->find(l, sample, y))
        {
          ++result.resumed_runs;
          return y;
        }
      y = response(xi);
      ++result.model_runs;
      if (journal)
        journal->record(l, sample, y);
      return y;
    }

    std::unique_ptr<Progress>
    SubsetRun::level_progress(const unsigned int l, const unsigned long total) const
    {
      // On a terminal: rank 0's samples of each level (the others run as many).
      return std::make_unique<Progress>(rank == 0 ? std::cerr : silent,
                                        "level " + std::to_string(l) +
                                          (n_ranks > 1 ? " (rank 0): samples" : ": samples"),
                                        total);
    }

    void
    SubsetRun::sample_level_0()
    {
      // Direct Monte Carlo, sample i on rank i mod P.
      level.response.assign(N, 0.0);
      level.chain_length.assign(N, 1);
      const std::unique_ptr<Progress> progress = level_progress(0, (N + n_ranks - 1) / n_ranks);
      for (unsigned int i = rank; i < N; i += n_ranks)
        {
          if ((stopped = interruption_requested()))
            break;
          std::vector<double> xi(n_variables);
          standard_normals(settings.seed, i, xi);
          level.response[i] = evaluate(0, i, xi);
          level.owned.push_back(i);
          level.xi.push_back(std::move(xi));
          progress->update(level.owned.size());
        }
      progress->finish();
    }

    bool
    SubsetRun::gather(LevelSamples &next)
    {
      MPI_Allreduce(MPI_IN_PLACE, next.response.data(), N, MPI_DOUBLE, MPI_SUM, comm);
      // A rank that receives SIGINT or SIGTERM stops its samples; at the end
      // of the level, where all ranks meet anyway, they agree to drop it.
      result.interrupted = dealii::Utilities::MPI::logical_or(stopped, comm);
      return !result.interrupted;
    }

    void
    SubsetRun::add_level(const double b, const double p)
    {
      SubsetLevel info;
      info.acceptance_rate          = acceptance;
      info.threshold                = b;
      info.conditional_probability  = p;
      info.coefficient_of_variation = std::sqrt(level_variance(level, b, p));
      result.levels.push_back(info);
    }

    std::vector<std::vector<double>>
    SubsetRun::move_seeds(const std::vector<unsigned int> &seeds) const
    {
      // Every seed from the rank of its chain to the rank of its new chain
      // (all ranks in the same order).
      const std::vector<unsigned int> old_start = chain_starts(level.chain_length);
      std::vector<std::vector<double>> my_seeds;
      for (unsigned int j = 0; j < seeds.size(); ++j)
        {
          const unsigned int old_chain =
            std::upper_bound(old_start.begin(), old_start.end(), seeds[j]) - old_start.begin() - 1;
          const unsigned int from = old_chain % n_ranks, to = j % n_ranks;
          if (rank == from)
            {
              const auto at = std::lower_bound(level.owned.begin(), level.owned.end(), seeds[j]);
              Assert(at != level.owned.end() && *at == seeds[j], dealii::ExcInternalError());
              if (to == from)
                my_seeds.push_back(level.xi[at - level.owned.begin()]);
              else
                MPI_Send(level.xi[at - level.owned.begin()].data(), n_variables, MPI_DOUBLE, to, 3,
                         comm);
            }
          else if (rank == to)
            {
              my_seeds.emplace_back(n_variables);
              MPI_Recv(my_seeds.back().data(), n_variables, MPI_DOUBLE, from, 3, comm,
                       MPI_STATUS_IGNORE);
            }
        }
      return my_seeds;
    }

    /// The modified Metropolis candidate (reliability/subset.h): each
    /// component x of `state` moves to x + spread ξ (ξ standard normal) with the
    /// probability min(1, φ(x + spread ξ) / φ(x)), into `candidate`; returns
    /// whether any moved.
    bool
    propose_component_wise(const std::vector<double> &state, const double spread,
                           NormalStream &random, std::vector<double> &candidate)
    {
      bool moved = false;
      for (unsigned int c = 0; c < candidate.size(); ++c)
        {
          const double x     = state[c];
          const double xi    = x + spread * random.next();
          const double ratio = std::exp(0.5 * (x * x - xi * xi));
          const double u     = standard_normal_cdf(random.next());
          candidate[c]       = u < ratio ? xi : x;
          moved |= u < ratio;
        }
      return moved;
    }

    void
    SubsetRun::run_chains(const unsigned int l, const double b,
                          const std::vector<unsigned int> &seeds)
    {
      LevelSamples       next;
      const unsigned int n_chains = seeds.size();
      next.chain_length = chain_lengths(N, n_chains, chain_seed(settings.seed, l));
      const std::vector<unsigned int> start = chain_starts(next.chain_length);
      next.response.assign(N, 0.0);
      std::vector<std::vector<double>> my_seeds = move_seeds(seeds);
      level.xi.clear();

      unsigned long accepted = 0, proposed = 0, my_states = 0;
      for (unsigned int j = rank; j < n_chains; j += n_ranks)
        my_states += next.chain_length[j];
      const std::unique_ptr<Progress> progress = level_progress(l, my_states);
      std::vector<double> candidate(n_variables);
      for (unsigned int j = rank, mine = 0; j < n_chains && !stopped; j += n_ranks, ++mine)
        {
          std::vector<double> state = std::move(my_seeds[mine]);
          // modified Metropolis from the seed, with the stream of (seed, level, chain)
          NormalStream random(chain_seed(settings.seed, l), j);
          double       y = level.response[seeds[j]];
          for (unsigned int k = 0; k < next.chain_length[j]; ++k)
            {
              if (k > 0)
                {
                  if ((stopped = interruption_requested()))
                    break;
                  ++proposed;
                  if (propose_component_wise(state, settings.proposal_spread, random, candidate))
                    {
                      const double y_candidate = evaluate(l, start[j] + k, candidate);
                      if (y_candidate > b)
                        {
                          state.swap(candidate);
                          y = y_candidate;
                          ++accepted;
                        }
                    }
                }
              next.response[start[j] + k] = y;
              next.owned.push_back(start[j] + k);
              next.xi.push_back(state);
              progress->update(next.owned.size());
            }
        }
      progress->finish();
      if (!gather(next))
        return;
      accepted   = dealii::Utilities::MPI::sum(accepted, comm);
      proposed   = dealii::Utilities::MPI::sum(proposed, comm);
      acceptance = proposed > 0 ? static_cast<double>(accepted) / proposed : 0;
      level      = std::move(next);
    }

    SubsetResult
    SubsetRun::run(const double threshold)
    {
      const unsigned int n_seeds = std::lround(settings.conditional_probability * N);
      sample_level_0();
      gather(level); // interrupted at level 0: no level, P = 1
      for (unsigned int l = 0; !result.interrupted; ++l)
        {
          // order: largest response first, ties by id (the same on every rank)
          std::vector<unsigned int> order(N);
          std::iota(order.begin(), order.end(), 0);
          std::stable_sort(order.begin(), order.end(), [&](unsigned int a, unsigned int b) {
            return level.response[a] > level.response[b];
          });
          const double b =
            0.5 * (level.response[order[n_seeds - 1]] + level.response[order[n_seeds]]);
          if (b >= threshold || l + 1 == settings.max_levels)
            {
              const double n_fail = std::count_if(level.response.begin(), level.response.end(),
                                                  [&](double y) { return y > threshold; });
              add_level(threshold, n_fail / N);
              result.reached_threshold = b >= threshold;
              break;
            }
          // Seeds: the samples strictly above b (fewer than p0 N on ties).
          std::vector<unsigned int> seeds;
          for (const unsigned int id : order)
            if (level.response[id] > b)
              seeds.push_back(id);
          if (seeds.empty())
            throw NumericalError("subset simulation: level " + std::to_string(l) +
                                 ": the response does not vary above its quantile " +
                                 std::to_string(b) + "; cannot form the next level");
          add_level(b, static_cast<double>(seeds.size()) / N);
          run_chains(l + 1, b, seeds);
        }
      // The levels' CoVs combined: uncorrelated (a lower bound) and fully
      // correlated (Au & Beck 2001's upper bound).
      double variance = 0, sum = 0;
      result.probability = 1;
      for (const SubsetLevel &L : result.levels)
        {
          result.probability *= L.conditional_probability;
          variance += L.coefficient_of_variation * L.coefficient_of_variation;
          sum += L.coefficient_of_variation;
        }
      result.coefficient_of_variation             = std::sqrt(variance);
      result.coefficient_of_variation_upper_bound = sum;
      return result;
    }
  } // namespace

  SubsetResult
  subset_simulation(const ResponseFunction &response, const unsigned int n_variables,
                    const double threshold, const SubsetSettings &settings, const MPI_Comm comm,
                    SubsetJournal *const journal)
  {
    SubsetResult result = SubsetRun(response, n_variables, settings, comm, journal).run(threshold);
    result.model_runs   = dealii::Utilities::MPI::sum(result.model_runs, comm);
    result.resumed_runs = dealii::Utilities::MPI::sum(result.resumed_runs, comm);
    return result;
  }

} // namespace poundfe
