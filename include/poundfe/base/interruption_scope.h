// SIGINT and SIGTERM caught for the length of one command inside a process
// that goes on afterwards (Python): the command stops as the command line's
// does on a signal (interruption.h), and the process's own handlers (Python
// raises KeyboardInterrupt from its own) come back at the end. Implemented
// in interruption.cc, beside the handler it installs.
#ifndef poundfe_base_interruption_scope_h
#define poundfe_base_interruption_scope_h

namespace poundfe
{
  /// While alive, the command line's handlers of SIGINT and SIGTERM (the
  /// first stops the command at its next safe point, a second one kills, as
  /// on the command line); at its end, the handlers there before are back
  /// and the signal is forgotten, so that a later command starts afresh.
  class InterruptionScope
  {
  public:
    InterruptionScope();
    ~InterruptionScope();
    InterruptionScope(const InterruptionScope &)            = delete;
    InterruptionScope &operator=(const InterruptionScope &) = delete;

    /// The signal that came in the scope so far, 0: none.
    int signal() const;
  };
} // namespace poundfe

#endif
