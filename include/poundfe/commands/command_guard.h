// What every command leaves when it stops early. A command that writes
// files runs inside guard_command(), which guarantees, whatever stops it:
//  - SIGINT/SIGTERM (base/interruption.h): a command that does not finish
//    its own files on a signal (modal, ground-motion, spectrum, sweep,
//    bifurcation, site-hazard) stops at the next safe point (a file write,
//    a plot, a time step); its uncommitted temporaries are removed and
//    summary.json says "status": "interrupted"; exit status 128 + signal.
//  - a file that cannot be written (OutputError: a full disk, an
//    unwritable path): temporaries removed, summary.json says "status":
//    "failed" with the OS reason in "message"; exit status 1.
//  - a numerical failure (NumericalError) after the output has begun: the
//    same with the failure in "message"; exit status 2, the files written
//    so far kept.
//  - before the body runs: the command's output directory is named
//    (expect_output_directory), so its first file removes the earlier
//    run's files, whatever the command;
//  - after it returns: figures gnuplot did not draw turn summary.json's
//    "completed" into "completed with warnings", with "missing_figures".
// The summary lists in "files" the complete files the command left. When
// even summary.json cannot be written, stderr says so. The commands whose
// row has CommandRule::own_interruption (run, montecarlo, subset, ...)
// handle a signal themselves (they write their results so far); the guard
// covers their output errors. The summary's name is the row's `summary`.
// Bad input (InputError) passes untouched: nothing written.
#ifndef poundfe_commands_command_guard_h
#define poundfe_commands_command_guard_h

#include <functional>
#include <string>

namespace poundfe
{
  struct Command;
  struct InputParameters;

  struct GuardedCommand
  {
    /// The command's row: its name, how it stops on a signal
    /// (CommandRule::own_interruption: it polls interruption_requested()
    /// and finishes its files itself; otherwise it stops at safe points)
    /// and the summary it leaves.
    const Command         &command;
    const InputParameters &input;
    std::string            directory; // the output directory
    /// This process writes the files (rank 0 of an MPI command).
    bool writes = true;
  };

  /// Runs `body` (the command) and returns its exit status, or that of a
  /// signal (after writing the summary); rethrows OutputError and
  /// NumericalError after writing the summary (main reports them).
  int guard_command(const GuardedCommand &command, const std::function<int()> &body);
} // namespace poundfe

#endif
