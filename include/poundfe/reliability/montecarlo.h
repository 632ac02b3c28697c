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

#include <poundfe/dynamics/realization.h>
#include <poundfe/reliability/reliability_parameters.h>
#include <poundfe/reliability/statistics.h>

#include <mpi.h>

#include <array>
#include <cstdint>
#include <functional>
#include <map>
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
    std::uint64_t                    seed      = 0; // the job's: realizations.csv's seed column
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
    /// Print a line every tenth of the realizations when the progress line
    /// does not show (a caller that runs many short tables says its own).
    bool report_lines = true;
  };

  /// A row of realizations.csv: 'realization,seed,completed', then the responses.
  struct RealizationRow
  {
    std::uint64_t       realization = 0;
    bool                completed   = false;
    std::vector<double> responses;
  };

  /// The line of `row` in realizations.csv (with its newline).
  std::string realization_line(const RealizationRow &row, std::uint64_t seed);

  /// Opens the realizations.csv `file` of the responses `names` and `seed`
  /// for appending (each rank of `comm` calls it; rank 0 reads and writes):
  /// a new file gets its header; an existing one, after its record is
  /// checked (output_directory.h: resume_file), gives its complete rows by
  /// realization (rank 0; empty elsewhere), and is rewritten without a
  /// damaged line (the partial last line of a killed run). InputError on
  /// every rank when the file or its record belongs to another run.
  std::map<std::uint64_t, RealizationRow>
  open_realization_table(const std::string &file, const std::vector<std::string> &names,
                         std::uint64_t seed, MPI_Comm comm);

  /// Runs the realizations 0..n-1 of `job` that `file` does not hold yet over
  /// the ranks of `comm` (each must call it), appending each to `file` as it
  /// finishes (an empty `file`: all of them, nothing written: results in
  /// memory); on SIGINT or SIGTERM (interruption.h) it stops after the
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

  /// The text of realizations.csv holding `table`'s realizations in their
  /// order (rank 0's table): what a run in memory gives for the journal a
  /// run into files appends to.
  std::string realizations_text(const MonteCarloTable &table);

  /// Pounding and drift-limit exceedances of a table's completed realizations.
  struct Exceedances
  {
    ProbabilityEstimate              pounding; // when the runner has gaps
    std::vector<ProbabilityEstimate> drift;    // one per limit
    /// Per damage state column of the runner (fibre members), the
    /// probability that the storey reaches each limit or a worse one, in
    /// the order of SectionLimit (yield, spalling, crushing, fracture).
    std::vector<std::array<ProbabilityEstimate, n_section_limits>> damage;
  };

  /// The realizations of `table` that pounded, those whose largest drift
  /// ratio exceeds each of `drift_limits`, and per storey those whose damage
  /// state reaches each limit.
  Exceedances count_exceedances(const MonteCarloTable &table, const RealizationRunner &runner,
                                const std::vector<double> &drift_limits);

  class JsonWriter;
  /// An estimate's "probability", "coefficient_of_variation" (null when
  /// infinite), "failures" and "realizations" in the object open.
  void write_probability(JsonWriter &json, const ProbabilityEstimate &p);
  /// summary.json's "storey_damage_states" of `e` (nothing without damage
  /// state columns): per storey column its name and, per damage state, the
  /// probability of reaching it (failures, realizations, CoV).
  void write_damage_probabilities(JsonWriter &json, const RealizationRunner &runner,
                                  const Exceedances &e);

  /// The Monte Carlo at each PGA level of a fragility analysis.
  struct FragilityLevels
  {
    std::vector<double>      levels;      // g: the levels done (rank 0)
    std::vector<Exceedances> counts;      // at each of them (rank 0)
    /// Each level's realizations (rank 0), kept only when they went to no
    /// file (results in memory); after an interruption, the interrupted
    /// level's realizations done last (its level: `interrupted_level`), as
    /// a run into files keeps them for the next to resume from
    std::vector<MonteCarloTable> tables;
    double                       interrupted_level = 0; // g
    bool                     interrupted = false; // on every rank
  };

  /// The folder of a fragility level's realizations: "pga_<a>g".
  std::string fragility_level_folder(double level);

  /// Runs `parameters.realizations_per_level` realizations at each PGA level
  /// in turn (amplitudes scaled by level / reference_pga) over the ranks of
  /// `comm`, each level in directory/pga_<a>g/realizations.csv (resumed as
  /// run_realizations does; an empty `directory`: no file, each level's
  /// table kept in `tables`); stops after a level that was interrupted.
  /// Rank 0 counts the exceedances of `drift_limits` at the levels done.
  FragilityLevels run_fragility_levels(RealizationRunner &runner,
                                       const FragilityParameters &parameters,
                                       const std::vector<double> &drift_limits,
                                       double reference_pga, const std::string &directory,
                                       MPI_Comm comm, Progress &progress);

  /// One fragility curve: the observed exceedances at each level and the
  /// lognormal maximum-likelihood fit (statistics.h).
  struct FragilityCurve
  {
    std::string                      name; // "pounding" or "drift_<limit>"
    std::vector<ProbabilityEstimate> observed;
    LognormalFragility               fit;
  };

  /// The curve of pounding (with gaps) and one per drift limit, fitted over
  /// the levels done.
  std::vector<FragilityCurve> fit_fragility_curves(const FragilityLevels     &levels,
                                                   const std::vector<double> &drift_limits,
                                                   bool                       has_gaps);
} // namespace poundfe

#endif
