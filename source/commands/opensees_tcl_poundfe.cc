// poundfe's additions to an OpenSees script, in the namespace poundfe::
// (poundfe::report is opensees_command.cc's):
//   poundfe::energy on | off        the energy balance of the transient analyses
//   poundfe::energy                 from the `on` (or the last reset) on
//   poundfe::impacts on | off       the contact episodes of the gap elements
//   poundfe::impacts ?-file F.csv?  from the `on` (or the last reset) on
//   poundfe::stepCutting on N | off a failed step of `analyze n dt` tried
//                                   again in halved sub-steps, N halvings at most
//   poundfe::locateEvents on ?R? | off | query
//                                   a transient step of `analyze n dt` in which
//                                   a gap's contact starts or ends redone in
//                                   halves down to dt/2^R (R 1 to 12, 4 when
//                                   not given: Contact/Event refinement's
//                                   range and default); query: R, 0 when off
// (opensees/opensees_energy.h gives the equations). A gap element is a
// zeroLength or twoNodeLink row whose material is a gap law (ElasticPPGap,
// ImpactMaterial, Hertzdamp, JankowskiImpact, ViscoelasticGap, or a MinMax,
// Parallel or Series material of one, nested or not: its first such
// component); it is in contact while that gap law's force is not zero, its
// force then the row's; its penetration is the gap law's deformation past
// `gap` along the gap's sign (ElasticPPGap with gap 0: Fy's; the others:
// compression). Both are off until the script turns them on: nothing is
// observed, and nothing paid, before; `reset` starts them again and `wipe`
// turns them off. Their vectors (offsets, masses, modes, gap rows) are
// kept from one `analyze` to the next while the model stays the same.
#include <poundfe/output/atomic_file.h>

#include "opensees_tcl.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace poundfe
{
  namespace opensees_tcl
  {
    namespace
    {
      /// The gap of material `tag` into g (gap and direction); false when
      /// it is not a gap law.
      bool
      gap_of(const opensees::Domain &d, const int tag, opensees::GapRow &g, const unsigned int depth = 0)
      {
        static const std::set<std::string> gap_laws{"ElasticPPGap", "ImpactMaterial", "Hertzdamp",
                                                    "JankowskiImpact", "ViscoelasticGap"};
        if (const auto m = d.materials.find(tag); m != d.materials.end())
          {
            if (gap_laws.count(m->second.material) == 0)
              return false;
            const auto  &values = m->second.values;
            const double gap    = values.count("gap") ? values.at("gap") : 0.0;
            const double fy     = values.count("Fy") ? values.at("Fy") : -1.0;
            g.gap               = gap;
            g.direction         = gap != 0 ? (gap > 0 ? 1.0 : -1.0) :
                                  m->second.material == "ElasticPPGap" && fy > 0 ? 1.0 :
                                                                                  -1.0;
            return true;
          }
        const auto c = d.combined_materials.find(tag);
        if (c == d.combined_materials.end() || depth > 8)
          return false;
        const std::vector<int> &parts = c->second.components;
        for (unsigned int i = 0; i < parts.size(); ++i)
          if (gap_of(d, parts[i], g, depth + 1))
            {
              g.path.insert(g.path.begin(), i); // outermost first
              return true;
            }
        return false;
      }

      std::vector<opensees::GapRow>
      gap_rows(Session &s)
      {
        std::vector<opensees::GapRow> rows;
        for (const auto &[tag, materials] : s.link_materials)
          {
            const auto e = s.domain.elements.find(tag);
            if (e == s.domain.elements.end() || !opensees::link_rows(*e->second))
              continue;
            for (unsigned int m = 0; m < materials.size(); ++m)
              {
                opensees::GapRow g;
                g.element = tag;
                g.row     = m;
                if (gap_of(s.domain, materials[m], g))
                  rows.push_back(g);
              }
          }
        return rows;
      }

      /// A Tcl dict of names and values (a list: Python's poundfe.opensees
      /// makes it a dict).
      Tcl_Obj *
      dict_of(const std::vector<std::pair<const char *, Tcl_Obj *>> &entries)
      {
        Tcl_Obj *list = Tcl_NewListObj(0, nullptr);
        for (const auto &[name, value] : entries)
          {
            Tcl_ListObjAppendElement(nullptr, list, Tcl_NewStringObj(name, -1));
            Tcl_ListObjAppendElement(nullptr, list, value);
          }
        return list;
      }

      Tcl_Obj *
      real(const double value)
      {
        return Tcl_NewDoubleObj(value);
      }

      /// `on` or `off` (true: the command was a setting, done), or nothing
      /// (a query; ScriptError while `observer` is off).
      template <typename Observer>
      bool
      set_observer(Words &w, std::optional<Observer> &observer, const std::string &name)
      {
        const std::string state = w.done() ? "" : w.peek();
        if (state == "on" || state == "off")
          {
            w.word("on or off");
            if (!w.done())
              throw opensees::ScriptError("unknown word '" + w.peek() + "' after " + state);
            if (state == "off")
              observer.reset();
            else if (!observer)
              observer.emplace();
            return true;
          }
        if (!observer)
          throw opensees::ScriptError("it is off: 'poundfe::" + name +
                                      " on' before the analysis turns it on");
        return false;
      }

      void
      energy(Session &s, Words &w)
      {
        if (set_observer(w, s.energy, "energy"))
          return;
        if (!w.done())
          throw opensees::ScriptError("unknown option '" + w.peek() +
                                      "' (poundfe::energy takes none, or on or off)");
        const opensees::EnergyTerms t = s.energy->terms();
        Tcl_SetObjResult(w.interp, dict_of({{"input", real(t.input)},
                                            {"kinetic", real(t.kinetic)},
                                            {"elements", real(t.elements)},
                                            {"damping", real(t.damping)},
                                            {"contact", real(t.contact)},
                                            {"residual", real(t.residual)},
                                            {"relative_residual", real(t.relative_residual)}}));
      }

      void
      impacts(Session &s, Words &w)
      {
        if (set_observer(w, s.impacts, "impacts"))
          return;
        std::string file;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option != "-file")
              throw opensees::ScriptError("unknown option '" + option +
                                          "' (poundfe::impacts takes -file F, or on or off)");
            file = w.word("the file's name after -file");
            if (file.empty())
              throw opensees::ScriptError("an empty file name after -file");
          }
        if (!file.empty())
          write_file_atomically(file, s.impacts->csv());
        Tcl_Obj *list = Tcl_NewListObj(0, nullptr);
        for (const Impact &i : s.impacts->impacts())
          Tcl_ListObjAppendElement(
            nullptr, list,
            dict_of({{"element", Tcl_NewIntObj(s.impacts->rows()[i.element].element)},
                     {"start_time", real(i.start_time)},
                     {"end_time", real(i.end_time)},
                     {"peak_force", real(i.peak_force)},
                     {"impulse", real(i.impulse)},
                     {"max_penetration", real(i.max_penetration)},
                     {"max_penetration_time", real(i.max_penetration_time)}}));
        Tcl_ConvertToType(nullptr, list, Tcl_GetObjType("list"));
        Tcl_SetObjResult(w.interp, list);
      }

      /// What the observers' vectors depend on besides the domain's changes
      /// since the last analyze (Domain::changed: nodes, masses, elements,
      /// constraints, damping): the analysis, the modes and modal damping,
      /// the patterns and the gap elements' materials.
      std::vector<std::size_t>
      observed_model(const Session &s)
      {
        const opensees::Domain &d = s.domain;
        return {reinterpret_cast<std::size_t>(s.analysis.get()),
                d.modal_stamp,
                d.nodes.size(),
                d.elements.size(),
                d.patterns.size(),
                d.lumped_masses.size(),
                d.consistent_masses.size(),
                s.link_materials.size()};
      }

      void
      step_cutting(Session &s, Words &w)
      {
        const std::string state = w.word("on or off");
        if (state == "off")
          s.max_cuts = 0;
        else if (state == "on")
          {
            const int cuts = w.integer("the most halvings");
            if (cuts < 1 || cuts > 30)
              throw opensees::ScriptError("the most halvings must be 1 to 30, got " +
                                          std::to_string(cuts));
            s.max_cuts = cuts;
          }
        else
          throw opensees::ScriptError("'" + state + "' where on or off is due");
        if (!w.done())
          throw opensees::ScriptError("unknown word '" + w.peek() + "' after " + state);
      }

      /// Contact/Event refinement's default and largest value
      /// (integration/time_integration_parameters.cc), which `poundfe run`
      /// applies to the same events.
      constexpr int default_event_levels = 4, max_event_levels = 12;

      void
      locate_events(Session &s, Words &w)
      {
        const std::string state = w.word("on, off or query");
        if (state == "query")
          Tcl_SetObjResult(w.interp, Tcl_NewIntObj(static_cast<int>(s.event_levels)));
        else if (state == "off")
          s.event_levels = 0;
        else if (state == "on")
          {
            const int levels = w.done() ? default_event_levels : w.integer("the most halvings");
            if (levels < 1 || levels > max_event_levels)
              throw opensees::ScriptError("the most halvings must be 1 to " +
                                          std::to_string(max_event_levels) + ", got " +
                                          std::to_string(levels));
            s.event_levels = levels;
          }
        else
          throw opensees::ScriptError("'" + state + "' where on, off or query is due");
        if (!w.done())
          throw opensees::ScriptError("unknown word '" + w.peek() + "' after " + state);
      }
    } // namespace

    void
    begin_locating(Session &s)
    {
      const bool locate         = s.event_levels > 0 && s.analysis->options().transient;
      s.analysis->event_levels = s.event_levels;
      s.analysis->events       = locate ? &s.contact_events : nullptr;
      if (locate) // the gaps anew: the model may have changed since the last analyze
        s.contact_events.watch(s.domain, gap_rows(s));
    }

    void
    begin_observing(Session &s)
    {
      if (!s.energy && !s.impacts)
        return;
      std::vector<std::size_t> model = observed_model(s);
      if (!s.domain.changed && model == s.observed_model)
        {
          if (s.energy)
            s.energy->resume(s.domain);
          if (s.impacts)
            s.impacts->resume(s.domain);
          return;
        }
      s.observed_model = std::move(model);
      const std::vector<opensees::GapRow> rows = gap_rows(s);
      std::vector<int>                    contact;
      for (const opensees::GapRow &g : rows)
        if (contact.empty() || contact.back() != g.element)
          contact.push_back(g.element);
      if (s.energy)
        s.energy->begin(s.domain, contact);
      if (s.impacts)
        s.impacts->begin(s.domain, rows);
    }

    void
    observe_step(Session &s)
    {
      if (s.energy)
        s.energy->step(s.domain);
      if (s.impacts)
        s.impacts->step(s.domain);
    }

    void
    restart_observers(Session &s)
    {
      if (s.energy)
        s.energy.emplace();
      if (s.impacts)
        s.impacts.emplace();
      s.observed_model.clear();
    }

    void
    stop_observers(Session &s)
    {
      s.energy.reset();
      s.impacts.reset();
      s.observed_model.clear();
    }

    void
    define_poundfe_commands(Tcl_Interp *interp, Session &session)
    {
      define(interp, session, "poundfe::energy", energy);
      define(interp, session, "poundfe::impacts", impacts);
      define(interp, session, "poundfe::stepCutting", step_cutting);
      define(interp, session, "poundfe::locateEvents", locate_events);
    }
  } // namespace opensees_tcl
} // namespace poundfe
