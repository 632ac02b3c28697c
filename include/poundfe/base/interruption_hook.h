// A function the SIGINT/SIGTERM handler (interruption.h) calls after it
// sets the flag: for a loop that polls no flag, the OpenSees interpreter's
// Tcl (opensees_command.cc: Tcl_AsyncMark, which Tcl provides for signal
// handlers, and Tcl then unwinds the script at its next safe point).
// Implemented in interruption.cc, beside the handler.
#ifndef poundfe_base_interruption_hook_h
#define poundfe_base_interruption_hook_h

namespace poundfe
{
  /// The hook the handler calls (async-signal-safe, as the handler is);
  /// nullptr: none. One at a time: it replaces the one before.
  void set_interruption_hook(void (*hook)());
} // namespace poundfe

#endif
