// Monte Carlo over the random loading, split over MPI ranks, and the
// fragility analysis built on it.
//   Realization r is the sample of (seed, r) on every number of ranks, and
//   the statistics are taken over the rows sorted by r: one rank and many
//   give the same numbers. Each finished realization is appended to
//   realizations.csv by rank 0 (workers send their rows to it), so a killed
//   run started again with the same command runs only the missing ones.
//   SIGINT or SIGTERM stops a run after the realizations under way; it then
//   writes its results over the rows it has with status "interrupted" and
//   exits with 128 + the signal.
#ifndef poundfe_reliability_montecarlo_h
#define poundfe_reliability_montecarlo_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/realization.h>

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace poundfe
{
  class Progress;

  struct MonteCarloTable
  {
    std::vector<std::string>         columns;      // response names
    std::vector<std::uint64_t>       realizations; // ascending
    std::vector<bool>                completed;
    std::vector<std::vector<double>> responses;
    unsigned long                    n_run_now = 0; // realizations run by this call
    double                           wall_time = 0; // s
    /// Stopped by SIGINT or SIGTERM (on every rank): realizations are missing,
    /// and a later call with the same file runs them.
    bool interrupted = false;

    /// Values of column c over the completed realizations.
    std::vector<double> completed_values(unsigned int c) const;
  };

  /// What each realization of a run computes: a row of values named `names`
  /// (realizations.csv's columns after 'realization,seed,completed') from
  /// the noise of (seed, realization); `run` returns false when the
  /// integration failed.
  struct RealizationJob
  {
    std::vector<std::string>                                       names;
    std::uint64_t                                                  seed = 1;
    std::function<bool(std::uint64_t realization, std::vector<double> &row)> run;
  };

  /// Runs the realizations 0..n-1 of `job` that `file` does not hold yet over
  /// the ranks of `comm` (each must call it), appending each to `file` as it
  /// finishes; on SIGINT or SIGTERM (interruption.h) it stops after the
  /// realizations under way. Returns the table of the realizations of 0..n-1
  /// done on rank 0 and an empty one elsewhere. Rank 0 reports to `progress`
  /// (as progress_offset + realizations done) or, when that does not show,
  /// prints a line every tenth.
  MonteCarloTable run_realizations(const RealizationJob &job, unsigned long n,
                                   const std::string &file, MPI_Comm comm,
                                   const std::string &label = "", Progress *progress = nullptr,
                                   unsigned long progress_offset = 0);

  /// run_realizations of the runner's peak responses (amplitudes times
  /// amplitude_factor).
  MonteCarloTable run_monte_carlo(RealizationRunner &runner, unsigned long n,
                                  double amplitude_factor, const std::string &file,
                                  MPI_Comm comm, const std::string &label = "",
                                  Progress *progress = nullptr, unsigned long progress_offset = 0);

  /// The `montecarlo` command, on every rank of `comm`.
  int montecarlo_command(const Analysis &analysis, const std::string &output_directory,
                         MPI_Comm comm);
  /// The `fragility` command, on every rank of `comm`.
  int fragility_command(const Analysis &analysis, const std::string &output_directory,
                        MPI_Comm comm);
} // namespace poundfe

#endif
