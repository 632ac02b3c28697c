// Stopping a long command cleanly on Ctrl-C or a batch system's SIGTERM:
// the first SIGINT or SIGTERM only sets a flag, which the command polls at
// its safe points (between realizations, between levels) to finish its
// files and exit; a second one (of either kind) kills as usual.
#ifndef poundfe_base_interruption_h
#define poundfe_base_interruption_h

namespace poundfe
{
  /// Catches the first SIGINT or SIGTERM (the handler then restores the
  /// default action of both). A signal ignored at start-up (e.g. SIGINT in a
  /// background job of a script) stays ignored.
  void install_interruption_handlers();

  /// Whether SIGINT or SIGTERM has arrived. Async-signal-safe to call.
  bool interruption_requested();

  /// The exit status of a command stopped early: 128 + the signal, as a shell
  /// reports a process killed by it (130 for SIGINT, 143 for SIGTERM); 130
  /// when this process received none (an MPI rank stopped by another).
  int interrupted_exit_status();
} // namespace poundfe

#endif
