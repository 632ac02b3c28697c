// The domain's own commands of an OpenSees script: `reset` (OpenSees's
// resetModel in tcl/commands.cpp: Domain::revertToStart, which reverts
// every node and element to its start, restarts the recorders and sets the
// time to 0, and the transient integrator's revertToStart).
#include "opensees_tcl.h"

namespace poundfe
{
  namespace opensees_tcl
  {
    namespace
    {
      using opensees::ScriptError;

      void
      reset(Session &s, Words &w)
      {
        if (!w.done())
          throw ScriptError("takes no words, '" + w.peek() + "' given");
        // OpenSees 3.8's HHT has no revertToStart (IncrementalIntegrator's
        // prints an error and keeps its state): its next step would start
        // from the state before the reset
        if (s.analysis && s.analysis->options().transient && s.analysis->options().alpha != 1)
          unsupported("reset with integrator HHT");
        s.domain.revert_to_start();
        for (auto &recorder : s.recorders)
          recorder->restart();
      }
    } // namespace

    void
    define_domain_commands(Tcl_Interp *interp, Session &session)
    {
      define(interp, session, "reset", reset);
    }
  } // namespace opensees_tcl
} // namespace poundfe
