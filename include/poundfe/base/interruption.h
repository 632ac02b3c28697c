// Stopping a long command cleanly on Ctrl-C or a batch system's SIGTERM:
// the first SIGINT or SIGTERM only sets a flag, which the command polls at
// its safe points (between realizations, between levels) to finish its
// files and exit; a second one (of either kind) kills as usual.
// A command with no results worth finishing early (modal, spectrum, sweep,
// ...) instead turns on stops at safe points: the file layer (every
// AtomicFile write, each plot) and the long loops then throw Interrupted,
// which unwinds (removing the uncommitted temporaries) to the command's
// guard (commands/command_guard.h), which writes the summary.
#ifndef poundfe_base_interruption_h
#define poundfe_base_interruption_h

#include <exception>

namespace poundfe
{
  /// Thrown by throw_if_interrupted(): a signal stopped the command.
  class Interrupted : public std::exception
  {
  public:
    const char *what() const noexcept override { return "interrupted by a signal"; }
  };

  /// Thrown by a step observer to end a time history at the step it
  /// observes as if interrupted (the Python module's Ctrl-C, which Python
  /// catches itself): the run finishes every observer's files, its summary
  /// says "interrupted", and the caller learns it from the run's status.
  class RunStopped : public std::exception
  {
  public:
    const char *what() const noexcept override { return "interrupted"; }
  };

  /// Catches the first SIGINT or SIGTERM (the handler then restores the
  /// default action of both), also where the signal was ignored at start-up
  /// (SIGINT in a background job of a script without job control): every
  /// command stops alike however it was started. Called again (after
  /// MPI_Init, whose PETSc installs handlers of its own), it installs the
  /// handler again, unless a signal came.
  void install_interruption_handlers();

  /// Whether SIGINT or SIGTERM has arrived, or request_stop() was called.
  /// Async-signal-safe to call.
  bool interruption_requested();

  /// Stops the command's loops at their next safe point as a signal would
  /// (interruption_requested() turns true; no signal, so the handlers and
  /// interrupted_exit_status() stay as they are): for a failure found on one
  /// MPI rank inside a collective loop, which every rank must leave at the
  /// same point before it is reported. request_stop(false) withdraws it
  /// once the loop is left (a library process goes on).
  void request_stop(bool stop = true);

  /// The exit status of a command stopped early: 128 + the signal, as a shell
  /// reports a process killed by it (130 for SIGINT, 143 for SIGTERM); 130
  /// when this process received none (an MPI rank stopped by another).
  int interrupted_exit_status();

  /// Whether throw_if_interrupted() throws once a signal has arrived (off
  /// at start: a command that finishes its own files keeps control).
  void set_stop_at_safe_points(bool stop);

  /// Throws Interrupted when a signal has arrived and stops at safe points
  /// are on; a cheap flag test, for every file write and every time step.
  void throw_if_interrupted();
} // namespace poundfe

#endif
