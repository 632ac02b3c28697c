// A time history with the standard observers: the peaks and the response
// range, and with an output directory the input's recorders, the floor
// spectra, the VTU series and the run's report (RunSummary).
#ifndef poundfe_report_run_outputs_h
#define poundfe_report_run_outputs_h

#include <poundfe/report/run_parameters.h>

#include <mpi.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace poundfe
{
  class MemoryResults;

  struct RunOptions
  {
    std::string output_directory; // empty: no files at all (benchmarks, tests)
    std::string linear_solver;    // empty: the input's choice
    bool        csv   = true;     // the recorders of the input (Output/Recorders)
    bool        vtu   = true;
    bool        plots = true;
    bool        progress      = false; // steps, rate and ETA on a terminal
    bool        interruptible = false; // SIGINT/SIGTERM end the run after the current step
    /// Where notes on the run's set-up go (e.g. VTU frames widened to keep
    /// within Output/Maximum VTU frames); nullptr: nowhere.
    std::ostream *console = nullptr;
    /// The caller's own observers, after the standard ones (e.g. the Python
    /// module's callback every N steps).
    Observers observers;
    /// The recorders' tables and the summary's texts kept here instead of
    /// files (output/table_writer.h; Python's results in memory): with an
    /// empty output_directory, the observers of a run with one, without VTU
    /// and plots; nothing is written.
    MemoryResults *memory = nullptr;
  };

  /// What a run with the standard observers reports to its caller.
  struct RunResult
  {
    RunStatus           status;
    IterationStatistics statistics;
    EnergyBalance       energy;
    double              max_energy_error   = 0;
    unsigned int        n_nonlinear_elements = 0;
    std::size_t         n_impacts          = 0;
    /// Where the response left the model's range (output/response_range.h).
    std::vector<std::string> warnings;
  };

  /// A time history with the standard observers: peaks, and with an output
  /// directory the input's recorders, the VTU series and the summary
  /// (summary.json, impacts.csv, profiles, plots).
  RunResult run_time_history(const Analysis &analysis, const RunParameters &parameters,
                             const Excitation &excitation, const RunOptions &options);
  /// The same over the ranks of `communicator`, the model partitioned by
  /// building (Time integration/Partition = buildings; theory §3.5d):
  /// `analysis` is this rank's part (prepare_rank_analysis), which the run
  /// takes over. The same time loop (TimeHistory) over a PartitionedStepper
  /// (dynamics/partitioned_stepper.h): each rank steps its own buildings;
  /// after every accepted (sub)step each rank replays the elements it
  /// observes through its own values and ghosts (integration/replayed_stepper.h)
  /// and runs the standard observers on its part; the recorders' rows and field frames
  /// go to rank 0 summed by owner, and the peaks, logs and work are merged
  /// there at the end (observation by rank: base/rank_merge.h), so rank 0
  /// writes the files of a one-process run and the other ranks write
  /// nothing. The summary's whole-model modes are not computed (each
  /// building's are). `options.observers` must be empty. Collective;
  /// InputError on every rank for what a partitioned run refuses (friction
  /// surfaces, initial conditions, a recorder's bad entry, ...). The full
  /// result on rank 0; on the others the status and the integrator's figures.
  RunResult run_partitioned_time_history(Analysis &analysis, const RunParameters &parameters,
                                         const RunOptions &options, MPI_Comm communicator);
} // namespace poundfe

#endif
