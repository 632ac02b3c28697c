// poundfe's additions to an OpenSees script, in the namespace poundfe::
// (poundfe::report is opensees_command.cc's):
//   poundfe::energy                 the energy balance of the transient analyses
//   poundfe::impacts ?-file F.csv?  the contact episodes of the gap elements
//   poundfe::stepCutting on N | off a failed step of `analyze n dt` tried
//                                   again in halved sub-steps, N halvings at most
// (opensees/opensees_energy.h gives the equations). A gap element is a
// zeroLength or twoNodeLink row whose material is a gap law (ElasticPPGap,
// ImpactMaterial, Hertzdamp, JankowskiImpact, ViscoelasticGap, or a MinMax
// or Parallel material of one); its penetration is its deformation past
// `gap` along the gap's sign (ElasticPPGap with gap 0: Fy's; the others:
// compression).
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
        if (c == d.combined_materials.end() || depth > 8 ||
            (c->second.type != "MinMax" && c->second.type != "Parallel"))
          return false;
        return std::any_of(c->second.components.begin(), c->second.components.end(),
                           [&](const int part) { return gap_of(d, part, g, depth + 1); });
      }

      std::vector<opensees::GapRow>
      gap_rows(Session &s)
      {
        std::vector<opensees::GapRow> rows;
        for (const auto &[tag, materials] : s.link_materials)
          {
            const auto e = s.domain.elements.find(tag);
            if (e == s.domain.elements.end() || !e->second->uniaxial_rows())
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

      /// A Tcl dict of names and numbers (a list: Python's poundfe.opensees
      /// makes it a dict).
      Tcl_Obj *
      dict_of(const std::vector<std::pair<const char *, double>> &entries)
      {
        Tcl_Obj *list = Tcl_NewListObj(0, nullptr);
        for (const auto &[name, value] : entries)
          {
            Tcl_ListObjAppendElement(nullptr, list, Tcl_NewStringObj(name, -1));
            Tcl_ListObjAppendElement(nullptr, list, Tcl_NewDoubleObj(value));
          }
        return list;
      }

      void
      energy(Session &s, Words &w)
      {
        if (!w.done())
          throw opensees::ScriptError("unknown option '" + w.peek() + "' (poundfe::energy takes none)");
        const opensees::EnergyTerms t = s.energy.terms();
        Tcl_SetObjResult(w.interp, dict_of({{"input", t.input},
                                            {"kinetic", t.kinetic},
                                            {"elements", t.elements},
                                            {"damping", t.damping},
                                            {"contact", t.contact},
                                            {"residual", t.residual},
                                            {"relative_residual", t.relative_residual}}));
      }

      void
      impacts(Session &s, Words &w)
      {
        std::string file;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option != "-file")
              throw opensees::ScriptError("unknown option '" + option +
                                          "' (poundfe::impacts takes -file F)");
            file = w.word("the file's name after -file");
          }
        if (!file.empty())
          write_file_atomically(file, s.impacts.csv());
        Tcl_Obj *list = Tcl_NewListObj(0, nullptr);
        for (const Impact &i : s.impacts.impacts())
          Tcl_ListObjAppendElement(
            nullptr, list,
            dict_of({{"element", s.impacts.rows()[i.element].element},
                     {"start_time", i.start_time},
                     {"end_time", i.end_time},
                     {"peak_force", i.peak_force},
                     {"impulse", i.impulse},
                     {"max_penetration", i.max_penetration},
                     {"max_penetration_time", i.max_penetration_time}}));
        Tcl_ConvertToType(nullptr, list, Tcl_GetObjType("list"));
        Tcl_SetObjResult(w.interp, list);
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
    } // namespace

    void
    begin_observing(Session &s)
    {
      const std::vector<opensees::GapRow> rows = gap_rows(s);
      std::vector<int>                    contact;
      for (const opensees::GapRow &g : rows)
        if (contact.empty() || contact.back() != g.element)
          contact.push_back(g.element);
      s.energy.begin(s.domain, contact);
      s.impacts.begin(s.domain, rows);
    }

    void
    observe_step(Session &s)
    {
      s.energy.step(s.domain);
      s.impacts.step(s.domain);
    }

    void
    define_poundfe_commands(Tcl_Interp *interp, Session &session)
    {
      define(interp, session, "poundfe::energy", energy);
      define(interp, session, "poundfe::impacts", impacts);
      define(interp, session, "poundfe::stepCutting", step_cutting);
    }
  } // namespace opensees_tcl
} // namespace poundfe
