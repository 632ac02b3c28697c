// The section and beam-column commands of OpenSees scripts in the plane,
// with OpenSees 3.8's argument syntax:
//   section Elastic tag E A Iz
//   section Fiber tag { patch rect|quad|circ ...; layer straight|circ ...; fiber y z A mat }
//     (sections/fibre_generators.h: the fibres exactly as OpenSees places
//     them; the reference axis at the area centroid, as FiberSection2d)
//   section Aggregator tag mat1 dof1 <mat2 dof2 ...> <-section baseTag>
//     (dofs P and Mz, in 3D also My and T, every dof given; an Elastic
//     base holds them all, so with it no dof can be given)
//   beamIntegration Lobatto|Legendre tag secTag N
//   beamIntegration HingeRadau tag secI lpI secJ lpJ secInterior
//   element forceBeamColumn tag i j transfTag integrationTag <-mass rho> <-iter maxIter tol>
//   element forceBeamColumn tag i j nIP secTag transfTag <-integration Lobatto|Legendre>
//       <-mass rho> <-iter maxIter tol>
//   element nonlinearBeamColumn tag i j nIP secTag transfTag <-mass rho> <-iter maxIter tol>
//   element dispBeamColumn tag i j transfTag integrationTag <-mass rho>
//   element dispBeamColumn tag i j nIP secTag transfTag <-integration Legendre|Lobatto> <-mass rho>
// with the mass lumped, rho L/2 on each node's translations (OpenSees's
// default). The force-based element iterates as OpenSees's
// ForceBeamColumn2d (elements/beam_column.h: OpenSeesIteration; -iter sets
// its maxIter and tol, 10 and 1e-12 by default).
#include <poundfe/sections/aggregator_section.h>
#include <poundfe/sections/elastic_section.h>
#include <poundfe/sections/fibre_generators.h>

#include "opensees_tcl.h"

namespace poundfe
{
  namespace opensees_tcl
  {
    namespace
    {
      using opensees::ScriptError;

      opensees::Domain &
      plane_domain(Session &s, const std::string &what)
      {
        opensees::Domain &d = s.domain;
        if (d.ndf == 0)
          throw ScriptError("no model yet: the script must call 'model basic -ndm N' first");
        if (d.ndm != 2 || d.ndf != 3)
          unsupported(what + " outside -ndm 2 -ndf 3");
        return d;
      }

      void
      add_section(opensees::Domain &d, const int tag, std::shared_ptr<const SectionLaw> section)
      {
        if (!d.sections.emplace(tag, std::move(section)).second)
          throw ScriptError("section " + std::to_string(tag) + " exists already");
      }

      /// The plane or 3D (-ndm 3 -ndf 6) domain of a section or beam-column.
      opensees::Domain &
      frame_domain(Session &s, const std::string &what)
      {
        opensees::Domain &d = s.domain;
        if (d.ndm == 3 && d.ndf == 6)
          return d;
        return plane_domain(s, what);
      }

      /// In 3D the section's torsional rigidity GJ (FiberSection3d's -GJ).
      /// FiberSection2d/3d::Print's fields: its fibres in OpenSees's order
      /// (the fiber commands', then the patches', then the layers'), each
      /// at (y, z) (z 0 in the plane) with its area and material, and the
      /// sectionRepr of the commands (FiberSectionRepr::Print: patches,
      /// layers, then fibres at (-y, z), as UniaxialFiber2d/3d keep them).
      Printed
      fibre_section_printed(Session &s, const FibreGeometry &geometry, const double torsion)
      {
        const bool space = s.domain.ndm == 3;
        Printed    printed{space ? "FiberSection3d" : "FiberSection2d", {}};
        if (space)
          printed.fields.emplace_back("torsion", json_number(torsion));
        const auto lines = [](const std::vector<std::string> &objects) {
          std::string text = "[\n";
          for (std::size_t i = 0; i < objects.size(); ++i)
            text += (i ? ",\n" : "") + objects[i];
          return text + "\n\t\t\t]";
        };
        const Session::FibrePrint &record = s.fibre_print;
        std::vector<std::string>   fibres;
        for (const int kind : {0, 1, 2})
          for (std::size_t i = 0; i < geometry.fibres.size(); ++i)
            if (record.kinds.at(i) == kind)
              {
                const Fibre &f = geometry.fibres[i];
                fibres.push_back("\t\t\t\t{\"coord\": " + json_numbers({f.y, space ? f.z : 0.0}) +
                                 ", \"area\": " + json_number(f.area) + ", \"material\": \"" +
                                 geometry.materials[f.material].name + "\"}");
              }
        std::vector<std::string> repr = record.repr[1];
        repr.insert(repr.end(), record.repr[2].begin(), record.repr[2].end());
        repr.insert(repr.end(), record.repr[0].begin(), record.repr[0].end());
        printed.fields.emplace_back("fibers", lines(fibres));
        printed.fields.emplace_back("sectionRepr", lines(repr));
        return printed;
      }

      void
      add_fibre_section(Session &s, const int tag, const FibreGeometry &geometry,
                        const double torsion)
      {
        opensees::Domain &d = s.domain;
        if (geometry.fibres.empty())
          throw ScriptError("section Fiber " + std::to_string(tag) + " has no fibre");
        add_section(d, tag, std::make_shared<FibreSection>(geometry, d.ndm == 3 ? 4 : 2, torsion));
        s.printed_sections[tag] = fibre_section_printed(s, geometry, torsion);
        s.fibre_print           = Session::FibrePrint();
      }

      void
      fibre_section(Session &s, opensees::Domain &d, Words &w, const int tag)
      {
        double torsion = 0;
        if (w.peek() == "-GJ" && d.ndm != 3)
          unsupported("section Fiber -GJ in the plane");
        if (w.peek() == "-GJ")
          {
            w.word("-GJ");
            torsion = w.real("GJ");
          }
        else if (d.ndm == 3)
          throw ScriptError("a 3D section Fiber needs -GJ (poundfe has no -torsion)");
        if (w.done() && s.without_bodies) // OpenSeesPy: the fibres follow it
          {
            if (d.sections.count(tag))
              throw ScriptError("section " + std::to_string(tag) + " exists already");
            s.open_fibres  = std::make_shared<FibreGeometry>();
            s.fibre_print  = Session::FibrePrint();
            s.open_section = tag;
            s.open_torsion = torsion;
            s.fibres       = s.open_fibres.get();
            return;
          }
        const std::string body = w.word("the section's body");
        if (!w.done())
          unsupported("section Fiber option '" + w.peek() + "'");
        FibreGeometry geometry;
        s.fibre_print  = Session::FibrePrint();
        s.fibres       = &geometry;
        const int code = Tcl_Eval(w.interp, body.c_str());
        s.fibres       = nullptr;
        if (code != TCL_OK)
          throw ScriptError(Tcl_GetStringResult(w.interp));
        add_fibre_section(s, tag, geometry, torsion);
      }

      /// Aggregator: mat dof pairs (P, Mz), then -section base.
      /// The script's material `tag` for a section; a material of other
      /// materials or one that needs the analysis' time step (ViscousDamper)
      /// is for zeroLength and truss elements only.
      const MaterialParameters &
      section_material(const opensees::Domain &d, const int tag)
      {
        const auto        it = d.materials.find(tag);
        const std::string type =
          it != d.materials.end()         ? it->second.material :
          d.combined_materials.count(tag) ? d.combined_materials.at(tag).type :
                                            "";
        if (type.empty())
          throw ScriptError("uniaxialMaterial " + std::to_string(tag) + " does not exist");
        if (it == d.materials.end() || type == "ViscousDamper")
          throw ScriptError("uniaxialMaterial " + std::to_string(tag) + " is a " + type +
                            ": in zeroLength, twoNodeLink and truss elements only");
        return it->second;
      }

      /// section Aggregator; its Print fields (SectionAggregator's: the
      /// -section, the materials and their dof).
      Printed
      aggregator_section(opensees::Domain &d, Words &w, const int tag)
      {
        Printed printed{"SectionAggregator", {}};
        std::vector<std::pair<int, std::string>> laws;
        while (!w.done() && w.peek() != "-section")
          {
            const int mat = w.integer("a material's tag");
            laws.emplace_back(mat, w.word("the material's dof"));
          }
        // the resultants' order of poundfe's sections: N, Mz (, My, T in space)
        const std::vector<std::string> names =
          d.ndm == 3 ? std::vector<std::string>{"P", "Mz", "My", "T"} :
                       std::vector<std::string>{"P", "Mz"};
        SectionVector rigidity(names.size());
        rigidity.setConstant(std::numeric_limits<double>::quiet_NaN());
        if (!w.done())
          {
            w.word("-section");
            const int  base = w.integer("the base section");
            printed.fields.emplace_back("section", json_tag(base));
            const auto it   = d.sections.find(base);
            if (it == d.sections.end())
              throw ScriptError("section " + std::to_string(base) + " does not exist");
            if (!dynamic_cast<const ElasticSection *>(it->second.get()))
              unsupported("section Aggregator on a base section other than Elastic");
            if (it->second->n_resultants() != names.size())
              throw ScriptError("section " + std::to_string(base) + " is not a " +
                                (d.ndm == 3 ? "3D" : "plane") + " section");
            rigidity = it->second->initial_tangent().diagonal();
          }
        if (!w.done())
          unsupported("section Aggregator option '" + w.peek() + "'");
        auto section = std::make_shared<AggregatorSection>(rigidity);
        std::vector<bool> has(names.size(), false);
        for (const auto &[mat, dof] : laws)
          {
            const auto at = std::find(names.begin(), names.end(), dof);
            if (at == names.end())
              unsupported("section Aggregator dof '" + dof + "'" +
                          (d.ndm == 3 ? "" : " in the plane") + " (it takes " +
                          (d.ndm == 3 ? "P, Mz, My and T)" : "P and Mz)"));
            const unsigned int r = at - names.begin();
            // OpenSees 3.8 would hold two resultants of the code, in series in
            // a forceBeamColumn and in parallel in a dispBeamColumn
            if (!std::isnan(rigidity[r]))
              throw ScriptError("section Aggregator " + std::to_string(tag) + ": dof " + dof +
                                " is in the -section already (OpenSees 3.8 then has two " + dof +
                                " resultants: in series in forceBeamColumn, in parallel in "
                                "dispBeamColumn)");
            if (has[r])
              throw ScriptError("section Aggregator " + std::to_string(tag) + ": dof " + dof +
                                " given twice");
            const MaterialParameters parameters = section_material(d, mat);
            section->set_law(r, [parameters]() { return make_material(parameters); });
            has[r] = true;
          }
        for (unsigned int r = 0; r < names.size(); ++r)
          if (!has[r] && std::isnan(rigidity[r]))
            unsupported("section Aggregator without " + names[r] +
                        " and without an Elastic -section");
        add_section(d, tag, section);
        std::vector<int>         tags;
        std::vector<std::string> dofs;
        for (const auto &[mat, dof] : laws)
          {
            tags.push_back(mat);
            dofs.push_back(dof);
          }
        printed.fields.emplace_back("materials", json_tags(tags));
        printed.fields.emplace_back("dof", json_strings(dofs));
        return printed;
      }

      void
      section(Session &s, Words &w)
      {
        const std::string type = w.word("the section's type");
        opensees::Domain &d = frame_domain(s, "section " + type);
        const int tag = w.integer("the section's tag");
        if (type == "Elastic" && d.ndm == 3)
          {
            const double E = w.real("E"), A = w.real("A"), Iz = w.real("Iz"), Iy = w.real("Iy"),
                         G = w.real("G"), J = w.real("J");
            if (!w.done())
              unsupported("section Elastic with shear (alphaY alphaZ)");
            if (!(E > 0 && A > 0 && Iz > 0 && Iy > 0 && G > 0 && J > 0))
              throw ScriptError("section Elastic needs E, A, Iz, Iy, G, J > 0");
            add_section(d, tag, std::make_shared<ElasticSection>(E * A, E * Iz, E * Iy, G * J));
            s.printed_sections[tag] = {"ElasticSection3d",
                                       {{"E", json_number(E)}, {"G", json_number(G)},
                                        {"A", json_number(A)}, {"Jx", json_number(J)},
                                        {"Iy", json_number(Iy)}, {"Iz", json_number(Iz)}}};
          }
        else if (type == "Elastic")
          {
            const double E = w.real("E"), A = w.real("A"), I = w.real("Iz");
            if (!w.done())
              unsupported("section Elastic with shear (G alphaY)");
            if (!(E > 0 && A > 0 && I > 0))
              throw ScriptError("section Elastic needs E, A, Iz > 0");
            add_section(d, tag, std::make_shared<ElasticSection>(E * A, E * I));
            s.printed_sections[tag] = {"ElasticSection2d", {{"E", json_number(E)},
                                                            {"A", json_number(A)},
                                                            {"Iz", json_number(I)}}};
          }
        else if (type == "Fiber" || type == "fiberSec")
          {
            fibre_section(s, d, w, tag);
          }
        else if (type == "Aggregator")
          {
            s.printed_sections[tag] = aggregator_section(d, w, tag);
          }
        else
          unsupported("section " + type);
      }

      /// The index in the section of the script's material `tag`.
      unsigned int
      fibre_material(Session &s, const int tag)
      {
        const MaterialParameters &law = section_material(s.domain, tag);
        const std::string name = std::to_string(tag);
        for (unsigned int i = 0; i < s.fibres->materials.size(); ++i)
          if (s.fibres->materials[i].name == name)
            return i;
        SectionMaterial material;
        material.name = name;
        material.law  = law;
        return s.fibres->add_material(material);
      }

      FibreGeometry &
      open_section(Session &s, const Words &w)
      {
        if (!s.fibres)
          throw ScriptError(w.name + (s.without_bodies ? " needs a section Fiber before it" :
                                                         " belongs in the body of a section Fiber"));
        return *s.fibres;
      }

      SectionPoint
      point(Words &w)
      {
        SectionPoint p;
        p.y = w.real("y");
        p.z = w.real("z");
        return p;
      }

      /// The fibres a command has just added, and its sectionRepr object
      /// (kind: 0 fiber, 1 patch, 2 layer; FibrePrint).
      void
      note_fibres(Session &s, const FibreGeometry &g, const int kind, const std::string &fields)
      {
        s.fibre_print.kinds.resize(g.fibres.size(), kind);
        s.fibre_print.repr[kind].push_back("\t\t\t\t{" + fields + "}");
      }

      std::string
      repr_point(const SectionPoint &p)
      {
        return json_numbers({p.y, p.z});
      }

      void
      patch(Session &s, Words &w)
      {
        FibreGeometry    &g    = open_section(s, w);
        const std::string type = w.word("the patch's type");
        const int          tag = w.integer("the material's tag");
        const unsigned int m   = fibre_material(s, tag);
        const int          n1 = w.integer("the first number of cells"),
                  n2          = w.integer("the second number of cells");
        if (n1 < 1 || n2 < 1)
          throw ScriptError("the numbers of cells must be >= 1");
        // QuadPatch::Print and CircPatch::Print (a rect is a quad there)
        const std::string head = "\"material\": " + std::to_string(tag) + ", \"divisions\": ";
        std::string       repr;
        if (type == "rect" || type == "rectangular" || type == "quad" || type == "quadr")
          {
            std::array<SectionPoint, 4> v;
            const bool                  rect = type == "rect" || type == "rectangular";
            for (unsigned int k = 0; k < (rect ? 2u : 4u); ++k)
              v[rect ? 2 * k : k] = point(w);
            if (rect)
              {
                v[1] = {v[2].y, v[0].z};
                v[3] = {v[0].y, v[2].z};
                add_rect_patch(g, m, n1, n2, v[0], v[2]);
              }
            else
              add_quad_patch(g, m, n1, n2, v);
            repr = "\"type\": \"quad\", " + head + json_numbers({1.0 * n1, 1.0 * n2}) +
                   ", \"vertices\": [" + repr_point(v[0]) + ", " + repr_point(v[1]) + ", " +
                   repr_point(v[2]) + ", " + repr_point(v[3]) + "]";
          }
        else if (type == "circ")
          {
            const SectionPoint c   = point(w);
            const double       r_i = w.real("rInt"), r_e = w.real("rExt");
            double             a0 = 0, a1 = 360;
            if (!w.done())
              {
                a0 = w.real("the start angle");
                a1 = w.real("the end angle");
              }
            add_circ_patch(g, m, n1, n2, c, r_i, r_e, a0, a1);
            repr = "\"type\": \"circ\", " + head + json_numbers({1.0 * n2, 1.0 * n1}) +
                   ", \"center\": " + repr_point(c) + ", \"radii\": " + json_numbers({r_i, r_e}) +
                   ", \"angles\": " + json_numbers({a0, a1});
          }
        else
          unsupported("patch " + type);
        if (!w.done())
          unsupported("patch " + type + " option '" + w.peek() + "'");
        note_fibres(s, g, 1, repr);
      }

      void
      layer(Session &s, Words &w)
      {
        FibreGeometry     &g    = open_section(s, w);
        const std::string  type = w.word("the layer's type");
        const int          tag  = w.integer("the material's tag");
        const unsigned int m    = fibre_material(s, tag);
        const int          n    = w.integer("the number of bars");
        const double       area = w.real("the bar's area");
        if (n < 1)
          throw ScriptError("the number of bars must be >= 1");
        // StraightReinfLayer::Print and CircReinfLayer::Print (whose stray
        // comma before "area" OpenSees 3.8 writes is left out)
        const std::string head = "\"material\": " + std::to_string(tag) +
                                 ", \"area\": " + json_number(area) +
                                 ", \"nReinfBars\": " + std::to_string(n) + ", ";
        if (type == "straight")
          {
            const SectionPoint a = point(w), b = point(w);
            add_straight_layer(g, m, n, area, a, b);
            note_fibres(s, g, 2,
                        "\"type\": \"layerStraight\", " + head + "\"start\": " + repr_point(a) +
                          ", \"end\": " + repr_point(b));
          }
        else if (type == "circ")
          {
            const SectionPoint c = point(w);
            const double       r = w.real("the radius");
            double             a0 = 0, a1 = 360;
            if (!w.done())
              {
                a0 = w.real("the start angle");
                a1 = w.real("the end angle");
              }
            add_circ_layer(g, m, n, area, c, r, a0, a1);
            // CircReinfLayer's constructor: a full circle ends a bar short of it
            const double end = a1 - a0 >= 360 ? a0 + 360.0 - 360.0 / n : a1;
            note_fibres(s, g, 2,
                        "\"type\": \"layerCirc\", " + head + "\"center\": " + repr_point(c) +
                          ", \"radius\": " + json_number(r) + ", \"angles\": " +
                          json_numbers({a0, end}));
          }
        else
          unsupported("layer " + type);
        if (!w.done())
          unsupported("layer " + type + " option '" + w.peek() + "'");
      }

      void
      fiber(Session &s, Words &w)
      {
        FibreGeometry     &g    = open_section(s, w);
        const SectionPoint p    = point(w);
        const double       area = w.real("the area");
        const int          tag  = w.integer("the material's tag");
        add_fibre(g, fibre_material(s, tag), p, area);
        if (!w.done())
          unsupported("fiber option '" + w.peek() + "'");
        // UniaxialFiber2d/3d::Print: they keep -y
        note_fibres(s, g, 0,
                    "\"type\": \"fiber\", \"material\": " + std::to_string(tag) +
                      ", \"area\": " + json_number(area) + ", \"coord\": " +
                      json_numbers({-p.y, s.domain.ndm == 3 ? p.z : 0.0}));
      }

      void
      beam_integration(Session &s, Words &w)
      {
        const std::string type = w.word("the rule's type");
        opensees::Domain &d    = frame_domain(s, "beamIntegration " + type);
        const int         tag  = w.integer("the rule's tag");
        using Kind             = opensees::IntegrationSpec::Kind;
        opensees::IntegrationSpec r;
        if (type == "Lobatto" || type == "Legendre")
          {
            r.kind     = type == "Lobatto" ? Kind::lobatto : Kind::legendre;
            r.section  = w.integer("the section's tag");
            r.n_points = w.integer("the number of points");
          }
        else if (type == "HingeRadau")
          {
            r.kind           = Kind::hinge_radau;
            r.section_i      = w.integer("secTagI");
            r.hinge_length_i = w.real("lpI");
            r.section_j      = w.integer("secTagJ");
            r.hinge_length_j = w.real("lpJ");
            r.section        = w.integer("secTagInterior");
          }
        else
          unsupported("beamIntegration " + type);
        if (!w.done())
          unsupported("beamIntegration " + type + " option '" + w.peek() + "'");
        for (const int section : {r.section, r.section_i, r.section_j})
          if (section != 0 && d.sections.count(section) == 0)
            throw ScriptError("section " + std::to_string(section) + " does not exist");
        if (!d.integrations.emplace(tag, r).second)
          throw ScriptError("beamIntegration " + std::to_string(tag) + " exists already");
      }

      /// The options after the element's tags: -mass rho, -lMass and
      /// -cMass (dispBeamColumn's consistent mass) and the old syntax's
      /// -integration.
      void
      beam_column_options(Words &w, const std::string &type, double &rho, bool &consistent,
                          opensees::IntegrationSpec &rule, const bool old_syntax,
                          OpenSeesIteration &iteration)
      {
        using Kind = opensees::IntegrationSpec::Kind;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option == "-mass")
              rho = w.real("the mass per length");
            // OpenSees 3.8's ForceBeamColumn2d/3d read -cMass and keep their
            // mass lumped
            else if (option == "-lMass" || option == "-cMass")
              consistent = option == "-cMass" && type == "dispBeamColumn";
            else if (option == "-iter" && type != "dispBeamColumn")
              {
                const int n         = w.integer("maxIter");
                iteration.tolerance = w.real("tol");
                if (n < 1 || !(iteration.tolerance > 0))
                  throw ScriptError("-iter needs maxIter >= 1 and tol > 0");
                iteration.max_iterations = n;
              }
            else if (option == "-integration" && old_syntax)
              {
                const std::string name = w.word("the integration's type");
                if (name != "Lobatto" && name != "Legendre")
                  unsupported("-integration " + name);
                rule.kind = name == "Lobatto" ? Kind::lobatto : Kind::legendre;
              }
            else
              unsupported("element " + type + " option '" + option + "'");
          }
      }
      /// ForceBeamColumn2d/3d and DispBeamColumn2d/3d::Print's fields: the
      /// section of each integration point (HingeRadau: I, the interior
      /// four times, J, as OpenSees's), the integration's own Print.
      Printed
      beam_column_printed(const std::string &type, const unsigned int ndm,
                          const opensees::IntegrationSpec &rule, const double rho,
                          const int transf)
      {
        using Kind = opensees::IntegrationSpec::Kind;
        std::vector<int> sections(rule.n_points, rule.section);
        std::string integration = rule.kind == Kind::lobatto ? "{\"type\": \"Lobatto\"}" :
                                                               "{\"type\": \"Legendre\"}";
        if (rule.kind == Kind::hinge_radau)
          {
            sections = {rule.section_i, rule.section, rule.section,
                        rule.section,   rule.section, rule.section_j};
            integration = "{\"type\": \"HingeRadau\", \"lpI\": " +
                          json_number(rule.hinge_length_i) +
                          ", \"lpJ\": " + json_number(rule.hinge_length_j) + "}";
          }
        return {(type == "dispBeamColumn" ? "DispBeamColumn" : "ForceBeamColumn") +
                  std::string(ndm == 3 ? "3d" : "2d"),
                {{"sections", json_tags(sections)},
                 {"integration", integration},
                 {"massperlength", json_number(rho)},
                 {"crdTransformation", json_tag(transf)}}};
      }
    } // namespace

    void
    beam_column_element(Session &s, Words &w, const std::string &type)
    {
      opensees::Domain  &d   = frame_domain(s, "element " + type);
      const int          tag = w.integer("the element's tag");
      std::array<int, 2> nodes{{w.integer("node i"), w.integer("node j")}};
      const std::vector<int> numbers = w.integers("a tag");
      const bool old_syntax = type == "nonlinearBeamColumn" || numbers.size() == 3;
      if (numbers.size() != (old_syntax ? 3u : 2u))
        throw ScriptError("element " + type + " " + std::to_string(tag) +
                          " needs transfTag integrationTag, or nIP secTag transfTag");
      using Kind = opensees::IntegrationSpec::Kind;
      opensees::IntegrationSpec rule;
      int                       transf = numbers[0];
      if (old_syntax)
        {
          rule.n_points = numbers[0];
          rule.section  = numbers[1];
          transf        = numbers[2];
          rule.kind     = type == "dispBeamColumn" ? Kind::legendre : Kind::lobatto;
        }
      else
        {
          const auto it = d.integrations.find(numbers[1]);
          if (it == d.integrations.end())
            throw ScriptError("beamIntegration " + std::to_string(numbers[1]) +
                              " does not exist");
          rule = it->second;
        }
      double            rho        = 0;
      bool              consistent = false;
      OpenSeesIteration iteration;
      beam_column_options(w, type, rho, consistent, rule, old_syntax, iteration);
      const auto t = d.transformations.find(transf);
      if (t == d.transformations.end())
        throw ScriptError("geomTransf " + std::to_string(transf) + " does not exist");
      const auto kind = type == "dispBeamColumn" ? opensees::BeamColumnKind::displacement_based :
                                                   opensees::BeamColumnKind::force_based;
      // DispBeamColumn3d's consistent mass has no torsional part
      const auto mass =
        consistent ? consistent_beam_mass(d, tag, nodes, rho, 0.0, transf, false) : std::nullopt;
      if (d.ndm == 3)
        add_element(d, opensees::make_beam_column_3d(d, tag, nodes, kind, t->second,
                                                     d.vecxz.at(transf), rule, iteration));
      else
        add_element(d,
                    opensees::make_beam_column_2d(d, tag, nodes, kind, t->second, rule, iteration));
      add_member_mass(d, tag, nodes, rho, mass);
      s.printed_elements[tag] = beam_column_printed(type, d.ndm, rule, rho, transf);
    }

    void
    close_open_section(Session &s)
    {
      if (!s.open_fibres)
        return;
      const std::shared_ptr<FibreGeometry> geometry = std::move(s.open_fibres);
      s.open_fibres.reset();
      s.fibres = nullptr;
      add_fibre_section(s, s.open_section, *geometry, s.open_torsion);
    }

    void
    define_section_commands(Tcl_Interp *interp, Session &session)
    {
      define(interp, session, "section", section);
      define(interp, session, "patch", patch);
      define(interp, session, "layer", layer);
      define(interp, session, "fiber", fiber);
      define(interp, session, "beamIntegration", beam_integration);
    }
  } // namespace opensees_tcl
} // namespace poundfe
