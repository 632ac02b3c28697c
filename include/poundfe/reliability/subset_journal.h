// What makes Subset Simulation resumable: a journal of every model run,
// subset_runs.csv (level, sample, response, completed). The algorithm is
// deterministic given the responses: level 0's samples come from the
// stream (seed, i), each chain's proposals from the stream (seed, level,
// chain), and the seeds of a level from the order of its responses. So a
// run that replays the algorithm and takes each response it finds in the
// journal instead of running the model again reaches exactly the state
// where the interrupted run stopped, and goes on from there; the estimate
// is bit-identical to an uninterrupted run's. Each rank appends its own
// runs to subset_runs.rank<k>.csv (one synced line per run: a kill leaves
// complete lines and at most one partial line, which is dropped); the
// journal is merged into subset_runs.csv when a run starts and when it
// ends, so it resumes on any number of ranks.
#ifndef poundfe_reliability_subset_journal_h
#define poundfe_reliability_subset_journal_h

#include <poundfe/reliability/subset.h>

#include <mpi.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace poundfe
{
  class AppendFile;

  /// The settings a journal's responses depend on (its first line): a
  /// journal of other settings is refused, not mixed in.
  std::string subset_journal_settings(const SubsetSettings &settings, unsigned int n_variables,
                                      double threshold);

  /// The journal files an earlier run left in `directory` (their names):
  /// a command keeps them when it prepares the directory.
  std::vector<std::string> subset_journal_files(const std::string &directory);

  class SubsetRunsFile : public SubsetJournal
  {
  public:
    /// Reads the journal an earlier run left in `directory` (every rank
    /// calls it; rank 0 reads and merges, then broadcasts). Throws InputError
    /// naming the file when it was written for other settings. An empty
    /// `directory`: no file read or written, the runs kept in memory (one
    /// rank; results in memory) for text().
    SubsetRunsFile(const std::string &directory, const std::string &settings, MPI_Comm comm);
    ~SubsetRunsFile() override;

    bool find(unsigned int level, unsigned int sample, double &response) const override;
    void record(unsigned int level, unsigned int sample, double response) override;

    /// The model run about to be recorded did not complete (its response is
    /// that of the state it reached).
    void mark_failed() { last_failed = true; }

    /// Runs the earlier runs left (found in the journal when this one began).
    std::size_t n_resumed() const { return earlier.size(); }

    /// Merges every rank's runs into subset_runs.csv (collective); returns
    /// the number of runs that did not complete, on rank 0.
    unsigned long finish();
    /// After finish(), on rank 0: the text subset_runs.csv holds (a journal
    /// in memory: what it would hold).
    std::string text() const;

  private:
    using Key = std::pair<unsigned int, unsigned int>; // (level, sample)
    struct Entry
    {
      double response  = 0;
      bool   completed = true;
    };

    const std::string           directory;
    const std::string           settings;
    const MPI_Comm              comm;
    std::map<Key, Entry>        earlier; // the same on every rank
    std::map<Key, Entry>        kept;    // this run's, in memory (no directory)
    std::unique_ptr<AppendFile> out;     // this rank's runs
    bool                        last_failed = false;

    std::string rank_file(unsigned int rank) const;
    void        merge(); // rank 0: every journal file into subset_runs.csv
  };
} // namespace poundfe

#endif
