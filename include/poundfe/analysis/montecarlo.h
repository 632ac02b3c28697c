// Monte Carlo over the random loading, split over MPI ranks, and the
// fragility analysis built on it.
//   Realization r is the sample of (seed, r) on every number of ranks, and
//   the statistics are taken over the rows sorted by r: one rank and many
//   give the same numbers. Each finished realization is appended to
//   realizations.csv by rank 0 (workers send their rows to it), so a killed
//   run started again with the same command runs only the missing ones.
#ifndef poundfe_analysis_montecarlo_h
#define poundfe_analysis_montecarlo_h

#include <poundfe/analysis/analysis.h>
#include <poundfe/analysis/realization.h>

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace poundfe
{
  struct MonteCarloTable
  {
    std::vector<std::string>         columns;      // response names
    std::vector<std::uint64_t>       realizations; // ascending
    std::vector<bool>                completed;
    std::vector<std::vector<double>> responses;
    unsigned long                    n_run_now = 0; // realizations run by this call
    double                           wall_time = 0; // s

    /// Values of column c over the completed realizations.
    std::vector<double> completed_values(unsigned int c) const;
  };

  /// Runs the realizations 0..n-1 that `file` does not hold yet over the
  /// ranks of `comm` (each must call it), appending each to `file` as it
  /// finishes. Returns the table of 0..n-1 on rank 0 and an empty one elsewhere.
  MonteCarloTable run_monte_carlo(RealizationRunner &runner, unsigned long n,
                                  double amplitude_factor, const std::string &file,
                                  MPI_Comm comm, const std::string &label = "");

  /// The `montecarlo` command, on every rank of `comm`.
  int montecarlo_command(const Analysis &analysis, const std::string &output_directory,
                         MPI_Comm comm);
  /// The `fragility` command, on every rank of `comm`.
  int fragility_command(const Analysis &analysis, const std::string &output_directory,
                        MPI_Comm comm);
} // namespace poundfe

#endif
