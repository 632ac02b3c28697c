// The domain's own commands of an OpenSees script: `reset` (OpenSees's
// resetModel in tcl/commands.cpp: Domain::revertToStart, which reverts
// every node and element to its start, restarts the recorders and sets the
// time to 0, and the transient integrator's revertToStart; poundfe::energy
// and poundfe::impacts start again too), and `remove` of elements, nodes,
// fixities, multi-point constraints (Domain::removeMP_Constraints: every tie
// of a constrained node) and time series (removeObject there).
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
        restart_observers(s);
      }

      /// A word after the last one remove takes (as the other removes).
      void
      no_more_words(Words &w, const std::string &what)
      {
        if (!w.done())
          unsupported("remove " + what + " word '" + w.peek() + "'");
      }

      /// ScriptError when a recorder records the node (or the element).
      void
      check_recorders(const Session &s, const int tag, const bool node)
      {
        for (std::size_t i = 0; i < s.recorders.size(); ++i)
          if (node ? s.recorders[i]->records_node(tag) : s.recorders[i]->records_element(tag))
            throw ScriptError(std::string(node ? "node " : "element ") + std::to_string(tag) +
                              " is recorded by recorder " + std::to_string(s.recorder_tags[i]) +
                              " (remove the recorder first)");
      }

      /// remove sp node dof: the fixity of `fix` (OpenSees's
      /// Domain::removeSP_Constraint with no pattern).
      void
      remove_fixity(Session &s, Words &w)
      {
        const int node = w.integer("the node's tag");
        const int dof  = w.integer("the DOF");
        if (!w.done())
          unsupported("remove sp node dof patternTag (OpenSees 3.8 leaves a pattern's sp in place)");
        // a node or DOF that does not exist: nothing to remove, as OpenSees's
        const auto n = s.domain.nodes.find(node);
        if (n == s.domain.nodes.end() || dof < 1 ||
            dof > static_cast<int>(n->second.fixed.size()))
          return;
        n->second.fixed[dof - 1] = false;
        s.domain.changed = true;
      }
    } // namespace

    bool
    remove_model_object(Session &s, Words &w, const std::string &what)
    {
      if (what == "element" || what == "ele")
        {
          const int tag = w.integer("the element's tag");
          no_more_words(w, what);
          check_recorders(s, tag, false);
          s.domain.remove_element(tag);
          s.printed_elements.erase(tag);
        }
      else if (what == "node")
        {
          const int tag = w.integer("the node's tag");
          no_more_words(w, what);
          check_recorders(s, tag, true);
          s.domain.remove_node(tag);
          s.reactions.erase(tag);
        }
      else if (what == "sp" || what == "SPconstraint")
        {
          if (w.left() == 1)
            unsupported("remove sp spTag (poundfe's sp have no tags: remove sp node dof)");
          remove_fixity(s, w);
        }
      else if (what == "mp" || what == "MPconstraint")
        {
          if (w.peek() == "-tag")
            unsupported("remove mp -tag mpTag (poundfe's mp have no tags: remove mp cNode)");
          const int tag = w.integer("the constrained node's tag");
          if (!w.done()) // OpenSees 3.8 would ignore the whole command
            throw ScriptError("'" + w.peek() + "' after the node: remove mp takes the constrained "
                              "node only (OpenSees 3.8 removes all its constraints)");
          s.domain.remove_ties_of(tag);
        }
      else if (what == "timeSeries" || what == "TimeSeries")
        {
          const int tag = w.integer("the series' tag");
          no_more_words(w, what);
          // the patterns and recorders that took it keep it, as OpenSees's copies
          s.domain.series.erase(tag);
        }
      else
        return false;
      return true;
    }

    void
    define_domain_commands(Tcl_Interp *interp, Session &session)
    {
      define(interp, session, "reset", reset);
    }
  } // namespace opensees_tcl
} // namespace poundfe
