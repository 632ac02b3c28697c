// The model-building commands of OpenSees scripts, with OpenSees 3.8's
// argument syntax: wipe, model, node, fix, mass, equalDOF, rigidLink, rigidDiaphragm, geomTransf,
// element, uniaxialMaterial, timeSeries, pattern, load, sp, eleLoad, loadConst, setTime,
// rayleigh, recorder (Node, Element, Drift, EnvelopeNode, EnvelopeElement).
// An option or type poundfe lacks is an error naming it.
#include <poundfe/laws/material_registry.h>
#include <poundfe/laws/opensees_dead_bands.h>
#include <poundfe/laws/viscous_damper.h>

#include <poundfe/opensees/opensees_section_links.h>

#include "opensees_tcl.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <set>

namespace poundfe
{
  namespace opensees_tcl
  {
    namespace
    {
      using opensees::ScriptError;

      std::string
      text_of(const int value)
      {
        return std::to_string(value);
      }

      opensees::Domain &
      model_domain(Session &session)
      {
        if (session.domain.ndf == 0)
          throw ScriptError("no model yet: the script must call 'model basic -ndm N' first");
        return session.domain;
      }

      /// The model and analysis wiped also when a recorder's file fails
      /// (Session::finish_recorders), whose error then follows.
      void
      wipe(Session &s)
      {
        std::exception_ptr failure;
        try
          {
            s.finish_recorders();
          }
        catch (...)
          {
            failure = std::current_exception();
          }
        if (s.analysis)
          {
            s.counts.steps += s.analysis->counts.steps;
            s.counts.iterations += s.analysis->counts.iterations;
            s.counts.factorizations += s.analysis->counts.factorizations;
            s.counts.failed_steps += s.analysis->counts.failed_steps;
          }
        s.analysis.reset();
        s.domain.clear();
        s.options        = opensees::AnalysisOptions();
        s.has_test = s.has_algorithm = false;
        s.has_static_integrator = s.has_transient_integrator = false;
        s.reactions.clear();
        s.current_pattern = -1;
        s.open_fibres.reset();
        s.fibres = nullptr;
        s.link_materials.clear();
        stop_observers(s);
        s.max_cuts     = 0;
        s.event_levels = 0;
        s.printed_elements.clear();
        s.printed_sections.clear();
        s.node_vectors = Session::NodeVectors();
        if (failure)
          std::rethrow_exception(failure);
      }

      void
      model(Session &s, Words &w)
      {
        const std::string type = w.word("the model builder");
        if (type != "basic" && type != "Basic" && type != "BasicBuilder")
          unsupported("model " + type);
        unsigned int ndm = 0, ndf = 0;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option == "-ndm")
              ndm = w.integer("-ndm");
            else if (option == "-ndf")
              ndf = w.integer("-ndf");
            else
              unsupported("model option '" + option + "'");
          }
        if (ndm < 1 || ndm > 3)
          throw ScriptError("-ndm must be 1, 2 or 3");
        if (ndf == 0)
          ndf = ndm == 1 ? 1 : ndm == 2 ? 3 : 6;
        const bool known = (ndm == 1 && ndf == 1) || (ndm == 2 && (ndf == 2 || ndf == 3)) ||
                           (ndm == 3 && (ndf == 3 || ndf == 6));
        if (!known)
          unsupported("-ndm " + text_of(ndm) + " -ndf " + text_of(ndf));
        s.domain.ndm = ndm;
        s.domain.ndf = ndf;
      }

      std::vector<double>
      exactly(Words &w, const unsigned int n, const char *what)
      {
        std::vector<double> values;
        for (unsigned int i = 0; i < n; ++i)
          values.push_back(w.real(what));
        return values;
      }

      void
      node(Session &s, Words &w)
      {
        opensees::Domain &d = model_domain(s);
        opensees::Node    n;
        n.tag         = w.integer("the node's tag");
        n.coordinates = exactly(w, d.ndm, "a coordinate");
        n.mass.assign(d.ndf, 0.0);
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option != "-mass")
              unsupported("node option '" + option + "'");
            n.mass = exactly(w, d.ndf, "a mass");
          }
        n.element_mass.assign(d.ndf, 0.0);
        n.fixed.assign(d.ndf, false);
        n.disp.assign(d.ndf, 0.0);
        n.vel = n.accel = n.disp;
        if (!d.nodes.emplace(n.tag, n).second)
          throw ScriptError("node " + text_of(n.tag) + " exists already");
        if (d.rayleigh.alpha_m != 0)
          d.node_alpha_m[n.tag] = 0.0; // undamped until the next rayleigh (made_undamped)
        d.changed = true;
      }

      void
      fix(Session &s, Words &w)
      {
        opensees::Domain &d    = model_domain(s);
        opensees::Node   &n    = d.node(w.integer("the node's tag"));
        const auto        flag = exactly(w, d.ndf, "a fixity (0 or 1)");
        if (!w.done())
          unsupported("fix with more than ndf = " + text_of(d.ndf) + " values");
        for (unsigned int k = 0; k < d.ndf; ++k)
          if (flag[k] != 0)
            {
              if (n.fixed[k])
                throw ScriptError("node " + text_of(n.tag) + " DOF " + text_of(k + 1) +
                                  " is fixed already");
              n.fixed[k] = true;
            }
        d.changed = true;
      }

      /// fixX|fixY|fixZ coordinate flags... <-tol tol>: `fix` on every node
      /// within tol (1e-10) of the coordinate along the axis, a DOF fixed
      /// already left as it is (Domain::addSP_Constraint(axis, ...)).
      void
      fix_at_coordinate(Session &s, Words &w, const unsigned int axis)
      {
        opensees::Domain &d          = model_domain(s);
        const double      coordinate = w.real("the coordinate");
        std::vector<int>  flags      = w.integers("a fixity (0 or 1)");
        double            tolerance  = 1e-10;
        if (w.peek() == "-tol")
          {
            w.word("-tol");
            tolerance = w.real("the tolerance");
          }
        if (!w.done())
          unsupported(w.name + " word '" + w.peek() + "'");
        if (flags.empty() || flags.size() > d.ndf)
          throw ScriptError("needs 1 to ndf = " + text_of(d.ndf) + " fixities, got " +
                            text_of(flags.size()));
        if (axis >= d.ndm)
          throw ScriptError("the model has no axis " + text_of(axis + 1) + " (-ndm " +
                            text_of(d.ndm) + ")");
        for (auto &[tag, node] : d.nodes)
          if (std::fabs(node.coordinates[axis] - coordinate) <= tolerance)
            for (std::size_t k = 0; k < flags.size(); ++k)
              node.fixed[k] = node.fixed[k] || flags[k] == 1;
        d.changed = true;
      }

      void
      mass(Session &s, Words &w)
      {
        opensees::Domain &d = model_domain(s);
        opensees::Node   &n = d.node(w.integer("the node's tag"));
        n.mass              = exactly(w, d.ndf, "a mass");
        if (!w.done())
          unsupported("mass with more than ndf = " + text_of(d.ndf) + " values");
        d.changed = true;
      }

      void
      equal_dof(Session &s, Words &w)
      {
        opensees::Domain  &d = model_domain(s);
        opensees::EqualDof e;
        e.retained    = d.node(w.integer("the retained node")).tag;
        e.constrained = d.node(w.integer("the constrained node")).tag;
        if (e.retained == e.constrained)
          throw ScriptError("the retained and the constrained node are the same");
        while (!w.done())
          {
            const int dof = w.integer("a DOF");
            if (dof < 1 || dof > static_cast<int>(d.ndf))
              throw ScriptError("DOF " + text_of(dof) + " is not one of 1 to ndf");
            e.dofs.push_back(dof - 1);
          }
        if (e.dofs.empty())
          throw ScriptError("missing the DOFs");
        d.equal_dofs.push_back(e);
        d.changed = true;
      }

      std::pair<std::string, int> calling_line(Tcl_Interp *interp);

      /// The "file:line" of the command being run ("" outside a file).
      std::string
      command_place(Tcl_Interp *interp)
      {
        const auto [file, line] = calling_line(interp);
        return line > 0 ? std::filesystem::path(file).filename().string() + ":" + text_of(line) :
                          std::string();
      }

      /// rigidLink bar|beam rNode cNode: OpenSees's RigidBar, the
      /// translations of cNode equal to rNode's (an identity constraint, as
      /// equalDOF 1..ndm), or RigidBeam, every DOF of cNode tied to rNode's
      /// by the rigid offset (opensees::RigidTie with beam set).
      void
      rigid_link(Session &s, Words &w)
      {
        opensees::Domain &d    = model_domain(s);
        const std::string type = w.word("the link's type");
        if (type != "bar" && type != "beam")
          unsupported("rigidLink " + type);
        const bool three = d.ndm == 3 && d.ndf == 6;
        if (type == "beam" && d.ndf != d.ndm && !three && (d.ndm != 2 || d.ndf != 3))
          throw ScriptError("rigidLink beam needs -ndf equal to -ndm, or -ndm 2 -ndf 3, or "
                            "-ndm 3 -ndf 6 (this model: -ndm " + text_of(d.ndm) + " -ndf " +
                            text_of(d.ndf) + ")");
        const int retained    = d.node(w.integer("the retained node")).tag;
        const int constrained = d.node(w.integer("the constrained node")).tag;
        if (!w.done())
          throw ScriptError("'" + w.peek() + "' after the constrained node: rigidLink " + type +
                            " takes two nodes");
        if (retained == constrained)
          throw ScriptError("the retained and the constrained node are the same");
        if (type == "beam")
          {
            opensees::RigidTie tie;
            tie.beam        = true;
            tie.retained    = retained;
            tie.constrained = {constrained};
            tie.where       = command_place(w.interp);
            d.rigid_ties.push_back(tie);
          }
        else
          {
            opensees::EqualDof e;
            e.retained    = retained;
            e.constrained = constrained;
            for (unsigned int k = 0; k < std::min(d.ndm, d.ndf); ++k)
              e.dofs.push_back(k);
            d.equal_dofs.push_back(e);
          }
        d.changed = true;
      }

      /// rigidDiaphragm perpDirn rNode cNode1 cNode2 ... (3D, -ndf 6); its
      /// file and line kept for the errors its constraints meet at analyze.
      void
      rigid_diaphragm(Session &s, Words &w)
      {
        opensees::Domain &d = model_domain(s);
        if (d.ndm != 3 || d.ndf != 6)
          unsupported("rigidDiaphragm outside -ndm 3 -ndf 6");
        const int perpendicular = w.integer("perpDirn");
        if (perpendicular < 1 || perpendicular > 3)
          throw ScriptError("perpDirn " + text_of(perpendicular) + " is not 1, 2 or 3");
        opensees::RigidTie diaphragm;
        diaphragm.perpendicular = perpendicular - 1;
        diaphragm.retained      = d.node(w.integer("the retained node")).tag;
        for (const int c : w.integers("a constrained node"))
          {
            if (d.node(c).tag == diaphragm.retained)
              throw ScriptError("the retained node " + text_of(c) + " is among the constrained");
            diaphragm.constrained.push_back(c);
          }
        if (!w.done())
          throw ScriptError("'" + w.peek() + "' is not a node's tag");
        diaphragm.where = command_place(w.interp);
        d.rigid_ties.push_back(diaphragm);
        d.changed = true;
      }

      void
      geom_transf(Session &s, Words &w)
      {
        opensees::Domain &d    = model_domain(s);
        const std::string type = w.word("the transformation's type");
        if (type != "Linear" && type != "PDelta" && type != "Corotational")
          unsupported("geomTransf " + type);
        const int tag = w.integer("the transformation's tag");
        if (d.ndm == 3)
          {
            const std::vector<double> v = exactly(w, 3, "a component of vecxz");
            d.vecxz[tag]                = {{v[0], v[1], v[2]}};
          }
        if (!w.done())
          unsupported("geomTransf option '" + w.peek() + "'");
        const Transformation kind = type == "PDelta"       ? Transformation::pdelta :
                                    type == "Corotational" ? Transformation::corotational :
                                                             Transformation::linear;
        if (!d.transformations.emplace(tag, kind).second)
          throw ScriptError("geomTransf " + text_of(tag) + " exists already");
      }

      void
      elastic_beam_column(opensees::Domain &d, Words &w, Printed &printed)
      {
        const bool three = d.ndm == 3 && d.ndf == 6;
        if ((d.ndm != 2 || d.ndf != 3) && !three)
          unsupported("element elasticBeamColumn with -ndm " + text_of(d.ndm) + " -ndf " +
                      text_of(d.ndf));
        const int          tag = w.integer("the element's tag");
        std::array<int, 2> nodes{{w.integer("node i"), w.integer("node j")}};
        opensees::ElasticSection3d section;
        section.A = w.real("A"), section.E = w.real("E");
        if (three)
          {
            section.G = w.real("G"), section.J = w.real("J");
            section.Iy = w.real("Iy");
          }
        section.Iz         = w.real("Iz");
        const int transf   = w.integer("the transformation's tag");
        double rho        = 0;     // mass per length
        bool   consistent = false; // -cMass (the last of -lMass and -cMass)
        while (w.peek() == "-mass" || w.peek() == "-lMass" || w.peek() == "-cMass")
          {
            const std::string option = w.word("an option");
            if (option == "-mass")
              rho = w.real("the mass per length");
            else
              consistent = option == "-cMass";
          }
        if (!w.done())
          unsupported("element elasticBeamColumn option '" + w.peek() + "'");
        const auto t = d.transformations.find(transf);
        if (t == d.transformations.end())
          throw ScriptError("geomTransf " + text_of(transf) + " does not exist");
        // ElasticBeam3d's twists take J/A of the axial mass
        const auto mass = consistent ? consistent_beam_mass(d, tag, nodes, rho,
                                                            three ? section.J / section.A : 0.0,
                                                            transf, !three) :
                                       std::nullopt;
        if (three)
          add_element(d, opensees::make_elastic_beam_3d(d, tag, nodes, section, t->second,
                                                        d.vecxz.at(transf)));
        else
          add_element(d, opensees::make_elastic_beam_2d(d, tag, nodes, section.A, section.E,
                                                        section.Iz, t->second));
        add_member_mass(d, tag, nodes, rho, mass);
        for (auto &m : d.lumped_masses)
          m.ground_load_twice |= m.element == tag && !three;
        // ElasticBeam2d and ElasticBeam3d::Print's fields (release: 0, both ends fixed)
        printed.type = three ? "ElasticBeam3d" : "ElasticBeam2d";
        printed.fields = {{"E", json_number(section.E)}};
        if (three)
          printed.fields.emplace_back("G", json_number(section.G));
        printed.fields.emplace_back("A", json_number(section.A));
        if (three)
          printed.fields.insert(printed.fields.end(), {{"Jx", json_number(section.J)},
                                                       {"Iy", json_number(section.Iy)}});
        printed.fields.insert(printed.fields.end(), {{"Iz", json_number(section.Iz)},
                                                     {"massperlength", json_number(rho)}});
        if (three)
          printed.fields.insert(printed.fields.end(), {{"releasez", "0"}, {"releasey", "0"}});
        else
          printed.fields.emplace_back("release", "0");
        printed.fields.emplace_back("crdTransformation", json_tag(transf));
      }

      void
      zero_length_option(Words &w, const std::string &option, opensees::ZeroLengthData &z)
      {
        if (option == "-mat")
          z.materials = w.integers("a material's tag");
        else if (option == "-dir")
          z.directions = w.integers("a direction");
        else if (option == "-doRayleigh")
          {
            int flag = 1;
            if (!w.done() && w.peek()[0] != '-')
              flag = w.integer("the -doRayleigh flag");
            if (flag != 0 && flag != 1)
              unsupported("element zeroLength -doRayleigh " + text_of(flag));
            z.rayleigh = flag == 1;
          }
        else if (option == "-orient")
          {
            for (double &x : z.x)
              x = w.real("a component of x");
            for (double &y : z.y)
              y = w.real("a component of yp");
          }
        else
          unsupported("element zeroLength option '" + option + "'");
      }

      /// [[row 0], [row 1], [row 2]].
      std::string
      json_rows(const Eigen::Matrix3d &rows)
      {
        std::string matrix = "[";
        for (int i = 0; i < 3; ++i)
          matrix += (i ? ", " : "") + json_numbers({rows(i, 0), rows(i, 1), rows(i, 2)});
        return matrix + "]";
      }

      /// The transMatrix of ZeroLength and ZeroLengthSection::Print: the
      /// rows x, y = (x cross yp) cross x, x cross yp, each of unit length
      /// (their setUp).
      std::string
      trans_matrix(const std::array<double, 3> &x_given, const std::array<double, 3> &yp)
      {
        using V   = Eigen::Vector3d;
        const V x = V(x_given[0], x_given[1], x_given[2]);
        const V z = x.cross(V(yp[0], yp[1], yp[2]));
        Eigen::Matrix3d rows;
        rows << x.normalized().transpose(), z.cross(x).normalized().transpose(),
          z.normalized().transpose();
        return json_rows(rows);
      }

      /// ZeroLength::Print's fields: its materials, the names of their
      /// directions and its transMatrix.
      std::vector<std::pair<std::string, std::string>>
      zero_length_fields(const opensees::ZeroLengthData &z, const unsigned int ndm)
      {
        std::string names = "[";
        for (std::size_t i = 0; i < z.directions.size(); ++i)
          {
            // OpenSees keeps direction 3 of a 2D model as 6 (Mz)
            const int dof = z.directions[i] == 3 && ndm == 2 ? 6 : z.directions[i];
            const char *const all[] = {"P", "Vy", "Vz", "T", "My", "Mz"};
            names += (i ? ", \"" : "\"") + std::string(dof >= 1 && dof <= 6 ? all[dof - 1] : "") + "\"";
          }
        return {{"materials", json_tags(z.materials)}, {"dof", names + "]"},
                {"transMatrix", trans_matrix(z.x, z.y)}};
      }

      /// zeroLength; its tag and -mat tags.
      std::pair<int, std::vector<int>>
      zero_length(opensees::Domain &d, Words &w, Printed &printed)
      {
        const int                tag = w.integer("the element's tag");
        opensees::ZeroLengthData z;
        z.nodes = {{w.integer("node i"), w.integer("node j")}};
        while (!w.done())
          zero_length_option(w, w.word("an option"), z);
        if (z.materials.empty() || z.materials.size() != z.directions.size())
          throw ScriptError("zeroLength " + text_of(tag) +
                            " needs as many -dir directions as -mat materials, at least one");
        add_element(d, opensees::make_zero_length(d, tag, z));
        printed = {"ZeroLength", zero_length_fields(z, d.ndm)};
        return {tag, z.materials};
      }

      /// "'word'" for the word where something is due, or the line's end.
      std::string
      where_due(const Words &w)
      {
        return w.done() ? std::string("the end of the line") : "'" + w.peek() + "'";
      }

      /// The values of a twoNodeLink's option taking one of `counts` numbers
      /// (ascending); the word where the next is due, or the first in excess,
      /// named when their number is none of them.
      std::vector<double>
      link_option_values(Words &w, const std::string &link, const std::string &option,
                         const std::vector<std::size_t> &counts, const std::string &model = "")
      {
        std::vector<std::string> texts;
        double                   value;
        while (!w.done() && Tcl_GetDouble(nullptr, w.peek().c_str(), &value) == TCL_OK)
          texts.push_back(w.word("a value"));
        using std::to_string;
        std::string takes = "takes " + to_string(counts[0]);
        if (counts.size() > 1)
          takes += " or " + to_string(counts[1]);
        takes += (counts.back() == 1 ? " value" : " values") + model;
        const std::size_t n = texts.size();
        if (n > counts.back())
          throw ScriptError(link + ": '" + texts[counts.back()] + "' is value " +
                            to_string(counts.back() + 1) + " of " + option + ", which " + takes);
        if (std::find(counts.begin(), counts.end(), n) == counts.end())
          throw ScriptError(link + ": " + where_due(w) + " where value " + to_string(n + 1) +
                            " of " + option + " is due (" + option + " " + takes + ")");
        std::vector<double> values;
        for (const std::string &text : texts)
          {
            Tcl_GetDouble(nullptr, text.c_str(), &value);
            if (!std::isfinite(value))
              throw ScriptError(link + ": " + option + " value '" + text + "' is not finite");
            values.push_back(value);
          }
        return values;
      }

      /// -mat's tags and -dir's directions, one for each, the word where
      /// one is missing or the first in excess named.
      void
      link_materials_and_directions(Words &w, const std::string &link,
                                    opensees::TwoNodeLinkData &data)
      {
        if (w.done() || w.peek() != "-mat")
          throw ScriptError(link + ": " + where_due(w) + " where -mat is due");
        w.word("-mat");
        data.materials = w.integers("a material's tag");
        if (data.materials.empty())
          throw ScriptError(link + ": " + where_due(w) + " where a material's tag is due");
        if (w.done() || (w.peek() != "-dir" && w.peek() != "-dof"))
          throw ScriptError(link + ": " + where_due(w) + " where a material's tag or -dir is due");
        w.word("-dir");
        const std::size_t n = data.materials.size();
        while (data.directions.size() < n && !w.done() && w.peek()[0] != '-')
          data.directions.push_back(w.integer("a direction"));
        if (data.directions.size() < n)
          throw ScriptError(link + ": " + where_due(w) + " where the direction of material " +
                            text_of(data.materials[data.directions.size()]) + " is due");
        int excess;
        if (!w.done() && Tcl_GetInt(nullptr, w.peek().c_str(), &excess) == TCL_OK)
          throw ScriptError(link + ": direction '" + w.peek() + "' has no material (-mat gives " +
                            std::to_string(n) + ")");
      }

      /// twoNodeLink tag i j -mat m1 m2 ... -dir d1 d2 ... <-orient <x1 x2 x3>
      /// yp1 yp2 yp3> <-pDelta ratios> <-shearDist ratios> <-doRayleigh> <-mass m>
      /// (OpenSees's order: -mat, then -dir, then the options). A bad word is
      /// named, as is the word where a missing value is due.
      /// TwoNodeLink::Print's fields (OPS_PRINT_PRINTMODEL_JSON).
      std::vector<std::pair<std::string, std::string>>
      two_node_link_fields(const opensees::Domain &d, const int tag,
                           const opensees::TwoNodeLinkData &data)
      {
        static const char *const names[] = {"P", "Vy", "Vz", "T", "My", "Mz"};
        std::vector<std::string> dofs;
        for (const int direction : data.directions)
          dofs.push_back(names[direction - 1]);
        std::vector<double> shear{0.5, 0.5}, ratios(4, 0.0);
        std::copy(data.shear_distance.begin(), data.shear_distance.end(), shear.begin());
        std::copy(data.p_delta.begin(), data.p_delta.end(), ratios.end() - data.p_delta.size());
        double                                           length = 0;
        std::vector<std::pair<std::string, std::string>> fields{
          {"materials", json_tags(data.materials)},
          {"dof", json_strings(dofs)},
          {"sDratios", json_numbers(shear)}};
        if (!data.p_delta.empty())
          fields.emplace_back("Mratios", json_numbers(ratios));
        fields.insert(fields.end(),
                      {{"transMatrix", json_rows(opensees::two_node_link_axes(d, tag, data, length))},
                       {"addRayleigh", data.rayleigh ? "1" : "0"},
                       {"mass", json_number(data.mass)}});
        return fields;
      }

      /// twoNodeLink; its tag and -mat tags, its Print fields into `printed`.
      std::pair<int, std::vector<int>>
      two_node_link(opensees::Domain &d, Words &w, Printed &printed)
      {
        const int                 tag = w.integer("the element's tag");
        const std::string         link = "twoNodeLink " + text_of(tag);
        opensees::TwoNodeLinkData data;
        data.nodes = {{w.integer("node i"), w.integer("node j")}};
        link_materials_and_directions(w, link, data);
        const std::size_t ratios = d.ndm == 2 ? 2 : 4, distances = d.ndm == 2 ? 1 : 2;
        const std::string model = " in -ndm " + text_of(static_cast<int>(d.ndm));
        std::set<std::string> given;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option[0] == '-' && !given.insert(option).second)
              throw ScriptError(link + ": " + option + " given twice");
            if (option == "-orient")
              data.orient = link_option_values(w, link, option, {3, 6});
            else if (option == "-pDelta")
              data.p_delta = link_option_values(w, link, option, {ratios}, model);
            else if (option == "-shearDist")
              data.shear_distance = link_option_values(w, link, option, {distances}, model);
            else if (option == "-doRayleigh")
              data.rayleigh = true;
            else if (option == "-mass")
              data.mass = link_option_values(w, link, option, {1})[0];
            else if (option[0] != '-')
              throw ScriptError(link + ": '" + option + "' where an option is due");
            else
              unsupported("element twoNodeLink option '" + option + "'");
          }
        if (data.mass < 0)
          throw ScriptError(link + ": -mass must not be negative");
        add_element(d, opensees::make_two_node_link(d, tag, data));
        add_node_masses(d, tag, data.nodes, 0.5 * data.mass); // TwoNodeLink::getMass
        printed.fields = two_node_link_fields(d, tag, data);
        return {tag, data.materials};
      }

      /// The length of a member between its nodes' coordinates (CorotTruss's
      /// Lo, whatever the nodes' displacements).
      double
      member_length(const opensees::Domain &d, const std::array<int, 2> &nodes)
      {
        const auto &a = d.node(nodes[0]).coordinates, &b = d.node(nodes[1]).coordinates;
        double      L2 = 0;
        for (unsigned int k = 0; k < std::min(a.size(), b.size()); ++k)
          L2 += (b[k] - a[k]) * (b[k] - a[k]);
        return std::sqrt(L2);
      }

      /// The member's length when it is made, on nodes that may have moved
      /// (the transformations' and Truss's initial displacements).
      double
      moved_member_length(const opensees::Domain &d, const std::array<int, 2> &nodes)
      {
        const opensees::Node &i = d.node(nodes[0]), &j = d.node(nodes[1]);
        double                L2 = 0;
        for (unsigned int k = 0; k < std::min(i.coordinates.size(), j.coordinates.size()); ++k)
          {
            const double moved =
              k < std::min(i.disp.size(), j.disp.size()) ? j.disp[k] - i.disp[k] : 0;
            L2 += std::pow(j.coordinates[k] - i.coordinates[k] + moved, 2);
          }
        return std::sqrt(L2);
      }

      /// A truss's consistent mass (Truss and CorotTruss::getMass with
      /// cMass): rho L/6 [2 1; 1 2] on each of its ends' ndm translations,
      /// L the member's length (Truss's from its moved nodes, CorotTruss's Lo).
      void
      add_consistent_truss_mass(opensees::Domain &d, const int element,
                                const std::array<int, 2> &nodes, const double rho,
                                const double length, const bool load_in_reaction)
      {
        if (rho == 0)
          return;
        const double       m   = rho * length / 6.0;
        const unsigned int ndf = d.ndf;
        opensees::Matrix   M   = opensees::Matrix::Zero(2 * ndf, 2 * ndf);
        for (unsigned int i = 0; i < std::min(d.ndm, ndf); ++i)
          {
            M(i, i) = M(ndf + i, ndf + i) = 2.0 * m;
            M(i, ndf + i) = M(ndf + i, i) = m;
          }
        d.consistent_masses.push_back({element, {nodes[0], nodes[1]}, M, load_in_reaction});
        d.changed = true;
      }

      /// A 0|1 flag's value (-doRayleigh, -cMass), the option named when
      /// it is neither.
      bool
      flag_value(Words &w, const std::string &element, const std::string &option)
      {
        const int flag = w.integer(("the " + option + " flag").c_str());
        if (flag != 0 && flag != 1)
          throw ScriptError(element + ": " + option + " takes 0 or 1, not " + text_of(flag));
        return flag == 1;
      }

      /// The words of truss and corotTruss: tag i j A matTag <-rho r>
      /// <-cMass 0|1> <-doRayleigh 0|1>; `unknown` refuses another option.
      struct TrussWords
      {
        int                tag = 0;
        std::array<int, 2> nodes{};
        double             area = 0, rho = 0;
        int                material = 0;
        bool               rayleigh = false, consistent = false;
      };
      TrussWords
      truss_words(Words &w, const std::string &type,
                  const std::function<void(const std::string &, const std::string &)> &unknown)
      {
        TrussWords t;
        t.tag                  = w.integer("the element's tag");
        const std::string name = type + " " + text_of(t.tag);
        t.nodes                = {{w.integer("node i"), w.integer("node j")}};
        t.area                 = w.real("A");
        t.material             = w.integer("the material's tag");
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option == "-rho")
              t.rho = w.real("the mass per length");
            else if (option == "-cMass")
              t.consistent = flag_value(w, name, option);
            else if (option == "-doRayleigh")
              t.rayleigh = flag_value(w, name, option);
            else
              unknown(name, option);
          }
        return t;
      }

      /// Truss and CorotTruss::Print's fields.
      std::vector<std::pair<std::string, std::string>>
      truss_fields(const TrussWords &t)
      {
        return {{"A", json_number(t.area)}, {"massperlength", json_number(t.rho)},
                {"material", json_tag(t.material)}};
      }

      /// truss tag i j A matTag <-rho rho> <-cMass 0|1> <-doRayleigh 0|1>
      void
      truss(opensees::Domain &d, Words &w, Printed &printed)
      {
        const TrussWords t = truss_words(w, "truss", [](const std::string &, const std::string &o) {
          unsupported("element truss option '" + o + "'");
        });
        add_element(d, opensees::make_truss(d, t.tag, t.nodes, t.area, t.material, t.rayleigh));
        if (d.ndm == 2 && t.consistent)
          add_consistent_truss_mass(d, t.tag, t.nodes, t.rho, moved_member_length(d, t.nodes),
                                    true);
        else if (d.ndm == 2)
          add_lumped_mass(d, t.tag, t.nodes, t.rho);
        else if (t.rho != 0)
          unsupported("element truss -rho outside -ndm 2");
        printed = {"Truss", truss_fields(t)};
      }

      /// zeroLengthSection tag i j secTag <-orient x1 x2 x3 yp1 yp2 yp3>
      /// <-doRayleigh <0|1>> (Rayleigh-damped by default, as OpenSees's);
      /// in 2D, OpenSeesPy's -orient x1 x2 x3 too (`python`: y across x);
      /// Tcl wants all six values, as OpenSees 3.8's Tcl command.
      void
      zero_length_section(opensees::Domain &d, Words &w, const bool python, Printed &printed)
      {
        const int                       tag  = w.integer("the element's tag");
        const std::string               name = "zeroLengthSection " + text_of(tag);
        opensees::ZeroLengthSectionData z;
        z.nodes    = {{w.integer("node i"), w.integer("node j")}};
        z.section  = w.integer("the section's tag");
        z.rayleigh = true;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option == "-orient")
              {
                for (double &x : z.x)
                  x = w.real("a component of x");
                double value;
                const bool x_alone =
                  w.done() || Tcl_GetDouble(nullptr, w.peek().c_str(), &value) != TCL_OK;
                if (x_alone && !(python && d.ndm == 2))
                  throw ScriptError(name + ": not enough parameters after -orient (x1 x2 x3 "
                                           "yp1 yp2 yp3)");
                if (x_alone)
                  z.y = {{-z.x[1], z.x[0], 0.0}};
                else
                  for (double &y : z.y)
                    y = w.real("a component of yp");
              }
            else if (option == "-doRayleigh")
              z.rayleigh = w.done() || w.peek()[0] == '-' || flag_value(w, name, option);
            else
              unsupported("element zeroLengthSection option '" + option + "'");
          }
        add_element(d, opensees::make_zero_length_section(d, tag, z));
        printed.fields = {{"section", json_tag(z.section)}, {"transMatrix", trans_matrix(z.x, z.y)}};
      }

      /// corotTruss tag i j A matTag <-rho r> <-cMass 0|1> <-doRayleigh 0|1>:
      /// -rho lumped (rho L/2 on each end's translations) or consistent.
      void
      corot_truss(opensees::Domain &d, Words &w, Printed &printed)
      {
        const TrussWords t =
          truss_words(w, "corotTruss", [](const std::string &name, const std::string &option) {
            throw ScriptError("invalid option " + option + " in: element " + name +
                              " $iNode $jNode $A $matTag <-rho $rho> <-cMass $flag> "
                              "<-doRayleigh $flag>");
          });
        add_element(d, opensees::make_corot_truss(d, t.tag, t.nodes, t.area, t.material,
                                                  t.rayleigh));
        // CorotTruss::getResistingForce does not subtract its inertia load:
        // the reactions leave it out (add_node_masses, not add_lumped_mass)
        if (t.consistent)
          add_consistent_truss_mass(d, t.tag, t.nodes, t.rho, member_length(d, t.nodes), false);
        else
          add_node_masses(d, t.tag, t.nodes, 0.5 * t.rho * member_length(d, t.nodes));
        printed.fields = truss_fields(t);
      }

      /// The node vectors OpenSees's element makes as it is created.
      void
      note_node_vectors(Session &s, const int tag)
      {
        const std::vector<int> &nodes = s.domain.elements.at(tag)->node_tags;
        const std::string      &type  = s.printed_elements.at(tag).type;
        s.node_vectors.displacements.insert(nodes.begin(), nodes.end());
        if (type == "Truss" || type == "CorotTruss" || type == "ZeroLength" ||
            type == "TwoNodeLink")
          s.node_vectors.velocities.insert(nodes.begin(), nodes.end());
      }

      void
      element(Session &s, Words &w)
      {
        opensees::Domain &d    = model_domain(s);
        const std::string type = w.word("the element's type");
        int               tag  = 0;
        Tcl_GetInt(nullptr, w.peek().c_str(), &tag);
        Printed printed{type == "corotTruss" || type == "CorotTruss" ? "CorotTruss" :
                        type == "zeroLengthSection"                   ? "ZeroLengthSection" :
                                                                        "TwoNodeLink",
                        {}};
        if (type == "elasticBeamColumn")
          elastic_beam_column(d, w, printed);
        else if (type == "zeroLength")
          {
            const auto [link_tag, materials] = zero_length(d, w, printed);
            s.link_materials[link_tag]       = materials;
          }
        else if (type == "truss")
          truss(d, w, printed);
        else if (type == "zeroLengthSection")
          zero_length_section(d, w, s.without_bodies, printed);
        else if (type == "corotTruss" || type == "CorotTruss")
          corot_truss(d, w, printed);
        else if (type == "twoNodeLink")
          {
            const auto [link_tag, materials] = two_node_link(d, w, printed);
            s.link_materials[link_tag]       = materials;
          }
        else if (type == "forceBeamColumn" || type == "nonlinearBeamColumn" ||
                 type == "dispBeamColumn")
          beam_column_element(s, w, type);
        else
          unsupported("element " + type);
        s.printed_elements.emplace(tag, printed); // a beam-column's own already there
        note_node_vectors(s, tag);
      }

      /// A material's positional parameters in OpenSees's order, with the
      /// numbers of values OpenSees accepts.
      struct MaterialSyntax
      {
        const char                *name;
        std::vector<const char *> parameters;
        std::vector<std::size_t>  counts;
      };

      const std::vector<MaterialSyntax> &
      material_syntaxes()
      {
        static const std::vector<MaterialSyntax> syntaxes = {
          {"Elastic", {"E", "eta", "Eneg"}, {1, 2, 3}},
          {"ElasticPP", {"E", "epsyP", "epsyN", "eps0"}, {2, 3, 4}},
          {"ElasticPPGap", {"E", "Fy", "gap", "eta"}, {3, 4}},
          {"ImpactMaterial", {"K1", "K2", "Delta_y", "gap"}, {4}},
          {"Hertzdamp", {"Kh", "xiNorm", "gap", "n"}, {3, 4}},
          {"JankowskiImpact", {"Kh", "xi", "mEff", "gap", "n"}, {4, 5}},
          {"ViscoelasticGap", {"K", "C", "gap"}, {3}},
          {"Viscous", {"C", "alpha", "minVel"}, {2, 3}},
          {"ViscousDamper",
           {"K", "C", "Alpha", "LGap", "NM", "RelTol", "AbsTol", "MaxHalf"},
           {3, 4, 8}},
          {"BoucWen",
           {"alpha", "ko", "n", "gamma", "beta", "Ao", "deltaA", "deltaNu", "deltaEta", "tolerance",
            "maxNumIter"},
           {9, 10, 11}},
          {"Steel01", {"fy", "E0", "b", "a1", "a2", "a3", "a4"}, {3, 7}},
          {"Steel02", {"fy", "E0", "b", "R0", "cR1", "cR2", "a1", "a2", "a3", "a4"}, {3, 6, 10}},
          {"Concrete01", {"fpc", "epsc0", "fpcu", "epscu"}, {4}},
          {"Concrete02", {"fpc", "epsc0", "fpcu", "epscu", "lambda", "ft", "Ets"}, {7}},
        };
        return syntaxes;
      }

      /// OpenSees's usage line: "Name tag p1 p2 <p3 <p4>>", the optional
      /// parameters nested by the counts the material takes.
      std::string
      usage_of(const MaterialSyntax &m)
      {
        std::string text = std::string(m.name) + " tag";
        std::size_t i = 0, open = 0;
        for (const std::size_t count : m.counts)
          {
            if (i > 0)
              text += " <", ++open;
            for (; i < count; ++i)
              text += (text.back() == '<' ? "" : " ") + std::string(m.parameters[i]);
          }
        if (std::string(m.name) == "ElasticPPGap")
          text += " <damage>";
        return text + std::string(open, '>');
      }

      /// OpenSees's EPPGapMaterial takes Fy and gap of opposite signs with a
      /// warning (and strain 0 then past the yield strain): so does poundfe.
      void
      warn_eppgap_signs(std::ostream &warnings, const MaterialParameters &p)
      {
        if (p.values.at("Fy") * p.values.at("gap") < 0)
          warnings << "EPPGapMaterial::EPPGapMaterial -- Alternate signs on fy and gap "
                      "encountered, continuing anyway\n";
      }

      /// Hysteretic: s1p e1p s2p e2p <s3p e3p> s1n e1n s2n e2n <s3n e3n>
      /// pinchX pinchY damage1 damage2 <beta>.
      MaterialParameters
      hysteretic_parameters(const std::vector<double> &v)
      {
        const bool three = v.size() == 16 || v.size() == 17;
        if (!three && v.size() != 12 && v.size() != 13)
          throw ScriptError("Hysteretic takes 12, 13, 16 or 17 values, got " +
                            text_of(v.size()));
        MaterialParameters p{"Hysteretic", {}};
        std::size_t        i = 0;
        for (const char *side : {"p", "n"})
          for (const char *point : {"1", "2", "3"})
            if (*point != '3' || three)
              {
                p.values[std::string("s") + point + side] = v[i++];
                p.values[std::string("e") + point + side] = v[i++];
              }
        for (const char *name : {"pinchX", "pinchY", "damage1", "damage2", "beta"})
          if (i < v.size())
            p.values[name] = v[i++];
        return p;
      }

      /// Series ... -iter maxIter tol (OpenSees reads -iter's numbers only
      /// after the components).
      void
      series_iterations(opensees::CombinedMaterial &c, Words &w)
      {
        if (w.left() < 2)
          throw ScriptError("want: uniaxialMaterial Series tag tag1 tag2 ... <-iter maxIter tol>");
        const int max_iterations = w.integer("-iter's maxIter");
        // Every pass costs a trial of each material: a bound keeps a
        // mistyped count from stalling the analysis.
        if (max_iterations < 1 || max_iterations > 1000)
          throw ScriptError("Series -iter: maxIter must be from 1 to 1000");
        c.max_iterations = max_iterations;
        c.tolerance      = w.real("-iter's tol");
        if (!(c.tolerance > 0))
          throw ScriptError("Series -iter: tol must be > 0");
      }

      /// Parallel tag tag1 tag2 ... <-factors f1 f2 ...>; Series tag tag1
      /// tag2 ... <-iter maxIter tol>; MinMax tag other <-min eps> <-max
      /// eps>: the components must exist already, as in OpenSees (which
      /// copies them there).
      opensees::CombinedMaterial
      combined_material(const opensees::Domain &d, const std::string &type, Words &w)
      {
        opensees::CombinedMaterial c{type, w.integers("a material's tag"), {}};
        if (c.components.empty() || (type == "MinMax" && c.components.size() != 1))
          throw ScriptError(type + " takes " + (type == "MinMax" ? "one material" : "materials"));

        for (const int component : c.components)
          if (d.materials.count(component) == 0 && d.combined_materials.count(component) == 0)
            throw ScriptError("uniaxialMaterial " + text_of(component) + " does not exist");
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (type == "Parallel" && option == "-factors")
              {
                c.factors = w.numbers("a factor");
                if (c.factors.size() != c.components.size())
                  throw ScriptError("Parallel -factors takes one factor a material");
              }
            else if (type == "Series" && option == "-iter")
              series_iterations(c, w);
            else if (type == "MinMax" && (option == "-min" || option == "-Min" || option == "-MIN"))
              c.min_strain = w.real("the smallest strain");
            else if (type == "MinMax" && (option == "-max" || option == "-Max" || option == "-MAX"))
              c.max_strain = w.real("the largest strain");
            else
              unsupported("uniaxialMaterial " + type + " option '" + option + "'");
          }
        return c;
      }

      void
      uniaxial_material(Session &s, Words &w)
      {
        opensees::Domain  &d    = model_domain(s);
        const std::string  type = w.word("the material's type");
        const int          tag  = w.integer("the material's tag");
        if (d.materials.count(tag) != 0 || d.combined_materials.count(tag) != 0)
          throw ScriptError("uniaxialMaterial " + text_of(tag) + " exists already");
        if (type == "Parallel" || type == "Series" || type == "MinMax")
          {
            d.combined_materials.emplace(tag, combined_material(d, type, w));
            return;
          }
        const MaterialSyntax *syntax = nullptr;
        if (type != "Hysteretic")
          {
            const auto &all = material_syntaxes();
            const auto  it  = std::find_if(all.begin(), all.end(), [&](const MaterialSyntax &m) {
              return m.name == type;
            });
            if (it == all.end())
              unsupported("uniaxialMaterial " + type);
            syntax = &*it;
          }
        const std::vector<double> values = w.numbers("a parameter");
        MaterialParameters        p{type, {}};
        if (type == "ElasticPPGap" && w.peek() == "damage")
          {
            w.word("damage");
            p.values["damage"] = 1;
          }
        // a word where a number may still follow is a bad number, not an option
        const std::size_t most = syntax ? syntax->counts.back() : 17;
        if (!w.done() && values.size() < most)
          throw ScriptError("'" + w.peek() + "' is not a number");
        if (!w.done())
          unsupported("uniaxialMaterial " + type + " option '" + w.peek() + "'");
        if (type == "Hysteretic")
          p = hysteretic_parameters(values);
        else
          {
            const auto &counts = syntax->counts;
            if (std::find(counts.begin(), counts.end(), values.size()) == counts.end())
              throw ScriptError(type + " does not take " + text_of(values.size()) +
                                " values: want uniaxialMaterial " + usage_of(*syntax));
            for (std::size_t i = 0; i < values.size(); ++i)
              p.values[syntax->parameters[i]] = values[i];
            if (type == "ElasticPPGap")
              warn_eppgap_signs(s.warnings, p);
            // OpenSees's Steel02(tag, Fy, E0, b) takes R0 = 15, where
            // poundfe's law defaults to 20 (cR1 and cR2 agree)
            if (type == "Steel02" && values.size() == 3)
              p.values["R0"] = 15.0;
            // OpenSees's ElasticPP takes a given epsyN of 0 as no compressive
            // strength (a tension-only bar); poundfe's law reads +0 as not
            // given (symmetric) and -0 as given
            if (type == "ElasticPP" && values.size() >= 3 && values[2] == 0)
              p.values["epsyN"] = -0.0;
            if (type == "ViscousDamper" && p.values.at("Alpha") < 0)
              {
                s.warnings << "ViscousDamper::ViscousDamper -- Alpha < 0.0, setting to 1.0\n";
                p.values["Alpha"] = 1;
              }
          }
        // OpenSees 3.8's laws skip strain changes below DBL_EPSILON: a
        // script's numbers are OpenSees's with them
        if (type == "Concrete01" || type == "Concrete02" || type == "Steel02" ||
            type == "Hysteretic")
          p.values[opensees_dead_band_entry] = 1;
        // the law's own checks, now at the script's line
        if (type == "ViscousDamper")
          make_viscous_damper(p.values, d.time_step);
        else
          make_material(p);
        if (!d.materials.emplace(tag, p).second)
          throw ScriptError("uniaxialMaterial " + text_of(tag) + " exists already");
      }

      /// The numbers of a -filePath file up to its first word that is not a
      /// number (OpenSees reads that far: a PEER record's "End Data" line),
      /// with a warning naming what follows them.
      std::vector<double>
      read_path_file(const std::string &name, std::ostream &warnings)
      {
        std::ifstream in(name);
        if (!in)
          throw ScriptError("the file '" + name + "' cannot be read");
        std::vector<double> values{std::istream_iterator<double>(in),
                                   std::istream_iterator<double>()};
        if (!in.eof())
          {
            in.clear();
            std::string word;
            in >> word;
            warnings << "WARNING timeSeries Path: '" << name << "' holds '" << word
                     << "' after its " << values.size()
                     << " values; the rest of the file is not read (as OpenSees)\n";
          }
        if (values.empty())
          throw ScriptError("the file '" + name + "' holds no number");
        return values;
      }

      /// A list of numbers: one list word or, as OpenSeesPy gives them, the
      /// numbers as words of their own.
      std::vector<double>
      number_list(Words &w, const char *what)
      {
        std::vector<double> values;
        Tcl_Obj            *list = Tcl_NewStringObj(w.word(what).c_str(), -1);
        Tcl_IncrRefCount(list);
        int       n = 0;
        Tcl_Obj **items;
        const int ok = Tcl_ListObjGetElements(w.interp, list, &n, &items);
        for (int i = 0; ok == TCL_OK && i < n; ++i)
          {
            double v;
            if (Tcl_GetDoubleFromObj(nullptr, items[i], &v) != TCL_OK)
              {
                const std::string item = Tcl_GetString(items[i]);
                Tcl_DecrRefCount(list);
                throw ScriptError(std::string(what) + " holds '" + item + "', not a number");
              }
            values.push_back(v);
          }
        Tcl_DecrRefCount(list);
        if (n == 1)
          for (const double v : w.numbers(what))
            values.push_back(v);
        return values;
      }

      /// A Path series' options besides its values and factor (OpenSees's
      /// OPS_PathSeries).
      struct PathOptions
      {
        std::vector<double> times; // -time or -fileTime
        bool times_from_file = false, values_from_file = false; // -fileTime, -filePath
        bool                use_last = false, prepend_zero = false;
        double              start_time = 0;
      };

      /// A Path series as OpenSees's OPS_PathSeries makes it: with -dt a
      /// PathSeries (-useLast, -prependZero, -startTime), else with times a
      /// PathTimeSeries, which takes none of the three (with a warning).
      void
      finish_path(opensees::TimeSeries &series, const PathOptions &path, std::ostream &warnings)
      {
        if (series.values.empty())
          throw ScriptError("a Path series needs -values or -filePath");
        if (series.dt > 0 && !path.times.empty())
          throw ScriptError("a Path series takes -dt or -time (-fileTime), not both");
        if (series.dt > 0)
          {
            if (path.prepend_zero)
              series.values.insert(series.values.begin(), 0.0);
            series.use_last   = path.use_last;
            series.start_time = path.start_time;
            return;
          }
        if (path.times.empty())
          throw ScriptError("a Path series needs -dt > 0, -time or -fileTime");
        if (path.times_from_file != path.values_from_file) // OPS_PathSeries's choices
          throw ScriptError("a Path series takes -time with -values or -fileTime with -filePath "
                            "(OpenSees 3.8: choice of options for path series is invalid)");
        if (path.times.size() != series.values.size())
          throw ScriptError("a Path series has " + std::to_string(path.times.size()) +
                            " times and " + std::to_string(series.values.size()) +
                            " values (they must be as many)");
        for (std::size_t i = 1; i < path.times.size(); ++i)
          if (path.times[i] < path.times[i - 1])
            throw ScriptError("a Path series' times must not decrease (time " +
                              std::to_string(i + 1) + " is before time " + std::to_string(i) +
                              ")");
        if (path.use_last || path.prepend_zero || path.start_time != 0)
          warnings << "WARNING timeSeries Path: -useLast, -prependZero and -startTime are "
                      "ignored with -time or -fileTime (OpenSees 3.8's PathTimeSeries)\n";
        series.times = path.times;
      }

      /// The options of a Path, Linear or Constant series (after its tag).
      std::shared_ptr<opensees::TimeSeries>
      series_options(const std::string &type, Words &w, std::ostream &warnings)
      {
        using Kind = opensees::TimeSeries::Kind;
        auto series  = std::make_shared<opensees::TimeSeries>();
        series->kind = type == "Path" || type == "Series" ? Kind::path :
                       type == "Linear"                   ? Kind::linear :
                       type == "Trig"                     ? Kind::trig :
                                                            Kind::constant;
        if (series->kind == Kind::trig)
          {
            series->start  = w.real("tStart");
            series->finish = w.real("tEnd");
            series->period = w.real("the period");
            if (!(series->period > 0))
              throw ScriptError("the period must be > 0");
          }
        PathOptions path;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option == "-factor" || option == "-fact")
              series->factor = w.real("-factor");
            else if (series->kind == Kind::trig && (option == "-shift" || option == "-phaseShift"))
              series->shift = w.real("-shift");
            else if (series->kind == Kind::trig && option == "-zeroShift")
              series->zero_shift = w.real("-zeroShift");
            else if (series->kind == Kind::path && option == "-dt")
              series->dt = w.real("-dt");
            else if (series->kind == Kind::path && option == "-values")
              series->values = number_list(w, "-values"), path.values_from_file = false;
            else if (series->kind == Kind::path && option == "-time")
              path.times = number_list(w, "-time"), path.times_from_file = false;
            else if (series->kind == Kind::path && option == "-filePath")
              series->values          = read_path_file(w.word("the file"), warnings),
              path.values_from_file   = true;
            else if (series->kind == Kind::path && option == "-fileTime")
              path.times = read_path_file(w.word("the file"), warnings),
              path.times_from_file = true;
            else if (series->kind == Kind::path && option == "-useLast")
              path.use_last = true;
            else if (series->kind == Kind::path && option == "-prependZero")
              path.prepend_zero = true;
            else if (series->kind == Kind::path && (option == "-startTime" || option == "-tStart"))
              path.start_time = w.real(option.c_str());
            else
              unsupported("timeSeries " + type + " option '" + option + "'");
          }
        if (series->kind == Kind::path)
          finish_path(*series, path, warnings);
        return series;
      }

      void
      time_series(Session &s, Words &w)
      {
        opensees::Domain &d    = model_domain(s);
        const std::string type = w.word("the series' type");
        if (type != "Path" && type != "Linear" && type != "Constant" && type != "Trig")
          unsupported("timeSeries " + type);
        const int tag = w.integer("the series' tag");
        if (!d.series.emplace(tag, series_options(type, w, s.warnings)).second)
          throw ScriptError("timeSeries " + text_of(tag) + " exists already");
      }

      /// A pattern's series: a tag, or one given in line ("Linear",
      /// "Constant", "Series -dt 0.01 -filePath f -factor g").
      std::shared_ptr<opensees::TimeSeries>
      pattern_series(Session &s, Tcl_Interp *interp, const std::string &text)
      {
        int tag;
        if (Tcl_GetInt(nullptr, text.c_str(), &tag) == TCL_OK)
          {
            const auto it = s.domain.series.find(tag);
            if (it == s.domain.series.end())
              throw ScriptError("timeSeries " + text_of(tag) + " does not exist");
            return it->second;
          }
        Tcl_Obj *list = Tcl_NewStringObj(text.c_str(), -1);
        Tcl_IncrRefCount(list);
        int       n = 0;
        Tcl_Obj **items;
        if (Tcl_ListObjGetElements(interp, list, &n, &items) != TCL_OK || n == 0)
          {
            Tcl_DecrRefCount(list);
            throw ScriptError("'" + text + "' is neither a series' tag nor a series");
          }
        Words             inline_words(interp, n, items);
        const std::string type = inline_words.name;
        if (type != "Path" && type != "Series" && type != "Linear" && type != "Constant" &&
            type != "Trig")
          unsupported("time series '" + type + "'");
        auto series = series_options(type, inline_words, s.warnings);
        Tcl_DecrRefCount(list);
        return series;
      }

      void
      uniform_excitation(Session &s, Words &w, opensees::Pattern &p)
      {
        const opensees::Domain &d = s.domain;
        p.uniform_excitation      = true;
        const int direction       = w.integer("the direction");
        if (direction < 1 || direction > static_cast<int>(d.ndf))
          throw ScriptError("direction " + text_of(direction) + " is not one of 1 to ndf");
        p.direction = direction - 1;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option == "-accel")
              p.series = pattern_series(s, w.interp, w.word("the acceleration series"));
            else if (option == "-fact" || option == "-factor")
              p.factor = w.real("-fact");
            else
              unsupported("pattern UniformExcitation option '" + option + "'");
          }
        if (!p.series)
          throw ScriptError("UniformExcitation needs -accel");
      }

      /// The file and line of the running command (`info frame -1` from
      /// here: the command's frame), {"", 0} when it is not in a file.
      std::pair<std::string, int>
      calling_line(Tcl_Interp *interp)
      {
        std::pair<std::string, int> where{"", 0};
        Tcl_InterpState saved = Tcl_SaveInterpState(interp, TCL_OK);
        if (Tcl_Eval(interp, "info frame -1") == TCL_OK)
          {
            Tcl_Obj *frame = Tcl_GetObjResult(interp), *value = nullptr;
            Tcl_Obj *key   = Tcl_NewStringObj("file", -1);
            Tcl_IncrRefCount(key);
            if (Tcl_DictObjGet(nullptr, frame, key, &value) == TCL_OK && value)
              where.first = Tcl_GetString(value);
            Tcl_DecrRefCount(key);
            key = Tcl_NewStringObj("line", -1);
            Tcl_IncrRefCount(key);
            if (Tcl_DictObjGet(nullptr, frame, key, &value) == TCL_OK && value &&
                !where.first.empty())
              Tcl_GetIntFromObj(nullptr, value, &where.second);
            Tcl_DecrRefCount(key);
          }
        Tcl_RestoreInterpState(interp, saved);
        return where;
      }

      void
      pattern(Session &s, Words &w)
      {
        opensees::Domain &d    = model_domain(s);
        const std::string type = w.word("the pattern's type");
        opensees::Pattern p;
        p.tag = w.integer("the pattern's tag");
        if (d.patterns.count(p.tag))
          throw ScriptError("pattern " + text_of(p.tag) + " exists already");
        if (type == "UniformExcitation")
          {
            uniform_excitation(s, w, p);
            d.patterns.emplace(p.tag, p);
            return;
          }
        if (type != "Plain")
          unsupported("pattern " + type);
        p.series = pattern_series(s, w.interp, w.word("the series"));
        if (w.peek() == "-fact" || w.peek() == "-factor")
          {
            w.word("-fact");
            p.factor = w.real("-fact");
          }
        if (w.done() && s.without_bodies) // OpenSeesPy: the loads follow it
          {
            d.patterns.emplace(p.tag, p);
            s.current_pattern = p.tag;
            return;
          }
        const std::string body = w.word("the pattern's body");
        if (!w.done())
          unsupported("pattern Plain option '" + w.peek() + "'");
        d.patterns.emplace(p.tag, p);
        const auto [file, line] = calling_line(w.interp);
        s.current_pattern       = p.tag;
        const int code          = Tcl_Eval(w.interp, body.c_str());
        s.current_pattern       = -1;
        if (code != TCL_OK)
          {
            const std::string message = w.name + ": " + Tcl_GetStringResult(w.interp);
            if (line > 0) // the body's line in the file: its line in the body, from the brace's
              s.body_error = {message, file, line + Tcl_GetErrorLine(w.interp) - 1};
            throw ScriptError(message);
          }
      }

      /// The Plain pattern a load goes to: the one whose body runs (OpenSeesPy:
      /// the last one defined).
      opensees::Pattern &
      current_pattern(Session &s, const char *what)
      {
        if (s.current_pattern < 0)
          throw ScriptError(std::string(what) +
                            (s.without_bodies ? " needs a Plain pattern before it" :
                                                " belongs in the body of a Plain pattern"));
        return s.domain.patterns.at(s.current_pattern);
      }

      void
      load(Session &s, Words &w)
      {
        opensees::Domain  &d       = model_domain(s);
        opensees::Pattern &pattern = current_pattern(s, "a load");
        opensees::NodalLoad l;
        l.node   = d.node(w.integer("the node's tag")).tag;
        l.values = exactly(w, d.ndf, "a load value");
        if (!w.done())
          unsupported("load option '" + w.peek() + "'");
        pattern.loads.push_back(l);
      }

      /// sp node dof value: the DOF (1-based) imposed at value times the
      /// pattern's factor.
      void
      imposed_displacement(Session &s, Words &w)
      {
        opensees::Domain             &d       = model_domain(s);
        opensees::Pattern            &pattern = current_pattern(s, "an sp");
        opensees::ImposedDisplacement sp;
        const opensees::Node         &node = d.node(w.integer("the node's tag"));
        const int                     dof  = w.integer("the DOF");
        if (dof < 1 || dof > int(d.ndf))
          throw ScriptError("sp: DOF " + std::to_string(dof) + " outside 1.." +
                            std::to_string(d.ndf));
        if (node.fixed[dof - 1])
          throw ScriptError("sp: node " + std::to_string(node.tag) + " DOF " +
                            std::to_string(dof) + " is fixed");
        sp.node  = node.tag;
        sp.dof   = dof - 1;
        sp.value = w.real("the imposed displacement");
        if (!w.done())
          unsupported("sp option '" + w.peek() + "'");
        pattern.imposed.push_back(sp);
        d.changed = true;
      }

      /// eleLoad (-ele tag ... | -range first last) -type -beamUniform Wy <Wx>
      /// (in 3D: Wy Wz <Wx>).
      void
      element_load(Session &s, Words &w)
      {
        opensees::Domain  &d       = model_domain(s);
        opensees::Pattern &pattern = current_pattern(s, "an eleLoad");
        std::vector<int>  tags;
        const std::string how = w.word("-ele or -range");
        if (how == "-ele")
          while (!w.done() && w.peek() != "-type")
            tags.push_back(w.integer("an element's tag"));
        else if (how == "-range")
          {
            const int first = w.integer("the first element"), last = w.integer("the last element");
            for (const auto &[tag, element] : d.elements)
              if (tag >= first && tag <= last)
                tags.push_back(tag);
          }
        else
          unsupported("eleLoad " + how);
        if (w.word("-type") != "-type")
          throw ScriptError("eleLoad: -type expected after the elements");
        const std::string type = w.word("the load's type");
        if (type != "-beamUniform")
          unsupported("eleLoad -type " + type);
        opensees::BeamUniformLoad load;
        load.wy = w.real("Wy");
        if (d.ndm == 3)
          load.wz = w.real("Wz");
        load.wx = w.done() ? 0.0 : w.real("Wx");
        if (!w.done())
          unsupported(d.ndm == 3 ? "eleLoad -beamUniform with more than Wy, Wz and Wx" :
                                   "eleLoad -beamUniform with more than Wy and Wx");
        for (const int tag : tags)
          {
            const auto it = d.elements.find(tag);
            if (it == d.elements.end())
              throw ScriptError("element " + std::to_string(tag) + " does not exist");
            if (!it->second->takes_beam_loads())
              unsupported("eleLoad on element " + std::to_string(tag) +
                          " (only elasticBeamColumn in the plane, and forceBeamColumn and "
                          "dispBeamColumn, on a Linear or PDelta transformation take it)");
            load.element = tag;
            pattern.beam_loads.push_back(load);
          }
      }

      void
      load_const(Session &s, Words &w)
      {
        opensees::Domain &d = model_domain(s);
        for (auto &[tag, p] : d.patterns)
          if (!p.constant)
            {
              p.constant_factor = p.load_factor(d.time);
              p.constant        = true;
            }
        if (w.peek() == "-time")
          {
            w.word("-time");
            d.time = w.real("the time");
          }
        if (!w.done())
          unsupported("loadConst option '" + w.peek() + "'");
      }

      void
      rayleigh(Session &s, Words &w)
      {
        opensees::RayleighFactors &r = model_domain(s).rayleigh;
        r.alpha_m                     = w.real("alphaM");
        r.beta_k                      = w.real("betaK");
        r.beta_k_init                 = w.real("betaKinit");
        r.beta_k_committed            = w.real("betaKcomm");
        if (!w.done())
          unsupported("rayleigh with more than 4 values");
        // OpenSees's Domain::setRayleighDampingFactors sets every element's
        // and node's: a region's factors are gone
        model_domain(s).element_rayleigh.clear();
        model_domain(s).node_alpha_m.clear();
        model_domain(s).changed = true;
        // OpenSees's K_c starts as the element's tangent now (after gravity:
        // the gravity state's, not the virgin one); every commit renews it
        if (r.beta_k_committed != 0)
          for (auto &[tag, element] : model_domain(s).elements)
            element->committed_tangent = element->tangent();
      }

      opensees::NodeRecorderSpec::Response
      recorder_response(const std::string &word)
      {
        using Response = opensees::NodeRecorderSpec::Response;
        if (word == "disp")
          return Response::disp;
        if (word == "vel")
          return Response::vel;
        if (word == "accel")
          return Response::accel;
        if (word == "reaction")
          return Response::reaction;
        unsupported("recorder Node response '" + word + "'");
      }

      /// The options of every recorder's output (-file, -time, -precision,
      /// -dT, -rTolDt, -closeOnWrite but in an Envelope) into its spec;
      /// false for any other word.
      bool
      output_option(Words &w, const std::string &option, opensees::OutputSpec &r,
                    const std::string &type)
      {
        if (option == "-file")
          r.file = w.word("the file");
        else if (option == "-time")
          r.time = true;
        else if (option == "-precision")
          r.precision = w.integer("-precision");
        else if (option == "-dT" || option == "-rTolDt")
          {
            const double value = w.real(option.c_str());
            if (value < 0)
              throw ScriptError(option + " must be >= 0");
            (option == "-dT" ? r.interval : r.interval_tolerance) = value;
          }
        // -closeOnWrite is taken and has nothing to do: the file is whole
        // when the script ends either way (an Envelope's rows would be
        // written at each change, then again at the end)
        else if (option != "-closeOnWrite" || type.compare(0, 8, "Envelope") == 0)
          return false;
        return true;
      }

      /// -timeSeries: a series' tag for each DOF (0 or -1: none).
      std::vector<std::shared_ptr<const opensees::TimeSeries>>
      recorder_series(const opensees::Domain &d, Words &w)
      {
        std::vector<std::shared_ptr<const opensees::TimeSeries>> series;
        for (const int tag : w.integers("a series' tag"))
          {
            const auto it = d.series.find(tag);
            if (tag != 0 && tag != -1 && it == d.series.end())
              throw ScriptError("timeSeries " + text_of(tag) + " does not exist");
            series.push_back(tag == 0 || tag == -1 ? nullptr : it->second);
          }
        if (series.empty())
          throw ScriptError("-timeSeries needs a series' tag for each DOF");
        return series;
      }

      void
      recorder_option(opensees::Domain &d, Words &w, const std::string &option,
                      opensees::NodeRecorderSpec &r, const std::string &type)
      {
        if (output_option(w, option, r, type))
          return;
        if (option == "-node")
          for (const int tag : w.integers("a node's tag"))
            r.nodes.push_back(d.node(tag).tag);
        else if (option == "-nodeRange")
          {
            const int first = w.integer("the first node"), last = w.integer("the last node");
            for (auto it = d.nodes.lower_bound(first); it != d.nodes.end() && it->first <= last;
                 ++it)
              r.nodes.push_back(it->first);
          }
        else if (option == "-dof")
          for (const int dof : w.integers("a DOF"))
            {
              if (dof < 1 || dof > static_cast<int>(d.ndf))
                throw ScriptError("DOF " + text_of(dof) + " is not one of 1 to ndf");
              r.dofs.push_back(dof - 1);
            }
        else if (option == "-timeSeries")
          r.series = recorder_series(d, w);
        else
          unsupported("recorder " + type + " option '" + option + "'");
      }

      /// recorder Element: -file, -time, -precision, -ele, -eleRange, then
      /// the response's words (each element checked to have it).
      void
      element_recorder(Session &s, Words &w, const std::string &type)
      {
        const opensees::Domain       &d = s.domain;
        opensees::ElementRecorderSpec r;
        while (!w.done() && r.response.empty())
          {
            const std::string word = w.word("an option");
            if (output_option(w, word, r, type))
              continue;
            if (word == "-ele")
              r.elements = w.integers("an element's tag");
            else if (word == "-eleRange")
              {
                const int first = w.integer("the first element"),
                          last  = w.integer("the last element");
                for (auto it = d.elements.lower_bound(first);
                     it != d.elements.end() && it->first <= last; ++it)
                  r.elements.push_back(it->first);
              }
            else if (word[0] == '-')
              unsupported("recorder " + type + " option '" + word + "'");
            else
              r.response.push_back(word);
          }
        while (!w.done())
          r.response.push_back(w.word("the response"));
        if (r.file.empty())
          unsupported("recorder " + type + " without -file");
        if (r.elements.empty() || r.response.empty())
          throw ScriptError("recorder " + type +
                            " needs elements (-ele, -eleRange) and a response");
        for (const int tag : r.elements)
          {
            const auto it = d.elements.find(tag);
            if (it == d.elements.end())
              throw ScriptError("element " + text_of(tag) + " does not exist");
            it->second->response(r.response);
          }
        if (type == "Element")
          s.recorders.push_back(std::make_unique<opensees::ElementRecorder>(r));
        else
          s.recorders.push_back(std::make_unique<opensees::EnvelopeElementRecorder>(r));
      }

      /// recorder Drift: -iNode, -jNode (as many), -dof, -perpDirn (1-based,
      /// defaults 1 and 2) and the output's options.
      void
      drift_recorder(Session &s, Words &w)
      {
        const opensees::Domain     &d = s.domain;
        opensees::DriftRecorderSpec r;
        int                         dof = 1, perpendicular = 2;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (output_option(w, option, r, "Drift"))
              continue;
            if (option == "-iNode" || option == "-iNodes" || option == "-jNode" ||
                option == "-jNodes")
              for (const int tag : w.integers("a node's tag"))
                (option[1] == 'i' ? r.i_nodes : r.j_nodes).push_back(d.node(tag).tag);
            else if (option == "-dof")
              dof = w.integer("-dof");
            else if (option == "-perpDirn")
              perpendicular = w.integer("-perpDirn");
            else
              unsupported("recorder Drift option '" + option + "'");
          }
        if (r.file.empty())
          unsupported("recorder Drift without -file");
        if (r.i_nodes.empty() || r.i_nodes.size() != r.j_nodes.size())
          throw ScriptError("recorder Drift needs as many -jNode as -iNode nodes, one at least");
        if (dof < 1 || dof > static_cast<int>(d.ndf))
          throw ScriptError("-dof " + text_of(dof) + " is not one of 1 to ndf");
        if (perpendicular < 1 || perpendicular > static_cast<int>(d.ndm))
          throw ScriptError("-perpDirn " + text_of(perpendicular) + " is not one of 1 to ndm");
        r.dof           = dof - 1;
        r.perpendicular = perpendicular - 1;
        auto recorder = std::make_unique<opensees::DriftRecorder>(r, d);
        if (!recorder->has_pairs())
          s.warnings << "DriftRecorder::initialize() - no valid nodes or perpendicular direction\n";
        s.recorders.push_back(std::move(recorder));
      }

      void
      recorder(Session &s, Words &w)
      {
        opensees::Domain &d    = model_domain(s);
        const std::string type = w.word("the recorder's type");
        if (type == "Element" || type == "EnvelopeElement")
          return element_recorder(s, w, type);
        if (type == "Drift")
          return drift_recorder(s, w);
        if (type != "Node" && type != "EnvelopeNode")
          unsupported("recorder " + type);
        opensees::NodeRecorderSpec r;
        bool                       has_response = false;
        while (!w.done())
          {
            const std::string word = w.word("an option");
            if (word[0] == '-')
              recorder_option(d, w, word, r, type);
            else if (!has_response)
              {
                r.response   = recorder_response(word);
                has_response = true;
              }
            else
              unsupported("recorder " + type + " word '" + word + "' after the response");
          }
        if (r.file.empty())
          unsupported("recorder " + type + " without -file");
        if (!has_response || r.nodes.empty() || r.dofs.empty())
          throw ScriptError("recorder " + type + " needs nodes, -dof and a response");
        // OpenSees takes the first tags, one a DOF (fewer: it reads past them)
        if (!r.series.empty() && r.series.size() < r.dofs.size())
          throw ScriptError("-timeSeries gives " + text_of(r.series.size()) + " series for " +
                            text_of(r.dofs.size()) + " DOFs");
        if (!r.series.empty())
          r.series.resize(r.dofs.size());
        if (type == "Node")
          s.recorders.push_back(std::make_unique<opensees::NodeRecorder>(r));
        else
          s.recorders.push_back(std::make_unique<opensees::EnvelopeNodeRecorder>(r));
      }
      /// remove recorders | recorder tag | loadPattern tag | pattern tag
      /// (OpenSees's `remove`): a recorder removed writes its file.
      void
      remove(Session &s, Words &w)
      {
        const std::string what = w.word("what to remove");
        const auto        done = [&]() {
          if (!w.done())
            unsupported("remove " + what + " word '" + w.peek() + "'");
        };
        if (what == "recorders")
          {
            done();
            s.finish_recorders();
          }
        else if (what == "recorder")
          {
            const int tag = w.integer("the recorder's tag");
            done();
            const auto it = std::find(s.recorder_tags.begin(), s.recorder_tags.end(), tag);
            if (it == s.recorder_tags.end())
              throw ScriptError("recorder " + text_of(tag) + " does not exist");
            const std::size_t i = it - s.recorder_tags.begin();
            s.finish_recorders(i, i + 1);
          }
        else if (what == "loadPattern" || what == "pattern")
          {
            opensees::Domain &d   = model_domain(s);
            const int         tag = w.integer("the pattern's tag");
            done();
            d.patterns.erase(tag);
            d.changed = true;
          }
        else if (!remove_model_object(s, w, what))
          unsupported("remove " + what);
      }
    } // namespace

    void
    add_element(opensees::Domain &d, std::unique_ptr<opensees::Element> element)
    {
      const int tag = element->tag;
      // An element takes the model's -ndf DOFs at each node; a node made
      // under another -ndf would leave it reading past the node's DOFs
      // (OpenSees 3.8 warns "differing dof at ends" and stops at analyze).
      std::string node_dofs;
      std::size_t n_node_dofs = 0;
      for (const int n : element->node_tags)
        {
          const std::size_t ndf = d.node(n).fixed.size();
          n_node_dofs += ndf;
          node_dofs += (node_dofs.empty() ? "node " : ", node ") + text_of(n) + " has " +
                       text_of(static_cast<int>(ndf));
        }
      if (n_node_dofs != element->n_dofs())
        throw ScriptError("element " + text_of(tag) + " takes " +
                          text_of(static_cast<int>(element->n_dofs())) +
                          " DOFs (-ndf " + text_of(static_cast<int>(d.ndf)) +
                          " at each node) but " + node_dofs +
                          ": nodes of differing dof at the element's ends");
      if (!d.elements.emplace(tag, std::move(element)).second)
        throw ScriptError("element " + text_of(tag) + " exists already");
      if (has_factors(d.rayleigh))
        d.element_rayleigh[tag] = opensees::RayleighFactors(); // see made_undamped
      d.changed = true;
    }

    bool
    has_factors(const opensees::RayleighFactors &f)
    {
      return f.alpha_m != 0 || f.beta_k != 0 || f.beta_k_init != 0 || f.beta_k_committed != 0;
    }

    void
    add_lumped_mass(opensees::Domain &d, const int element, const std::array<int, 2> &nodes,
                    const double rho)
    {
      add_node_masses(d, element, nodes, 0.5 * rho * moved_member_length(d, nodes));
      // a member's getResistingForce subtracts its inertia load (rho != 0):
      // the reactions take it
      for (auto &m : d.lumped_masses)
        m.load_in_reaction |= m.element == element;
    }

    std::optional<opensees::Domain::ConsistentMass>
    consistent_beam_mass(const opensees::Domain &d, const int element,
                         const std::array<int, 2> &nodes, const double rho,
                         const double torsion_ratio, const int transf,
                         const bool ground_load_twice)
    {
      if (rho == 0)
        return std::nullopt;
      if (d.transformations.at(transf) == Transformation::corotational)
        unsupported("element " + text_of(element) + " -cMass on geomTransf Corotational");
      for (const int n : nodes)
        for (const double u : d.node(n).disp)
          if (u != 0)
            unsupported("element " + text_of(element) + " -cMass on node " + text_of(n) +
                        ", which has moved");
      const bool three = d.ndm == 3;
      opensees::Domain::ConsistentMass m;
      m.element = element;
      m.nodes   = {nodes[0], nodes[1]};
      m.matrix  = opensees::beam_consistent_mass(d, element, nodes, rho, torsion_ratio,
                                                 three ? &d.vecxz.at(transf) : nullptr);
      // a member's getResistingForce subtracts its inertia load
      m.load_in_reaction  = true;
      m.ground_load_twice = ground_load_twice;
      return m;
    }

    void
    add_member_mass(opensees::Domain &d, const int element, const std::array<int, 2> &nodes,
                    const double rho, const std::optional<opensees::Domain::ConsistentMass> &mass)
    {
      if (!mass)
        return add_lumped_mass(d, element, nodes, rho);
      d.consistent_masses.push_back(*mass);
      d.changed = true;
    }

    void
    add_node_masses(opensees::Domain &d, const int element, const std::array<int, 2> &nodes,
                    const double m)
    {
      if (m == 0)
        return;
      for (const int n : nodes)
        {
          for (unsigned int k = 0; k < std::min(d.ndm, d.ndf); ++k)
            d.node(n).element_mass[k] += m;
          d.lumped_masses.push_back({element, n, m, false, false});
        }
      d.changed = true;
    }

    void
    define_model_commands(Tcl_Interp *interp, Session &session)
    {
      define(interp, session, "wipe", [](Session &s, Words &w) {
        if (!w.done())
          unsupported("wipe option '" + w.peek() + "'");
        wipe(s);
      });
      define(interp, session, "model", model);
      define(interp, session, "node", node);
      define(interp, session, "fix", fix);
      for (unsigned int axis = 0; axis < 3; ++axis)
        define(interp, session, std::string("fix") + "XYZ"[axis],
               [axis](Session &s, Words &w) { fix_at_coordinate(s, w, axis); });
      define(interp, session, "remove", remove);
      define(interp, session, "mass", mass);
      define(interp, session, "equalDOF", equal_dof);
      define(interp, session, "rigidDiaphragm", rigid_diaphragm);
      define(interp, session, "rigidLink", rigid_link);
      define(interp, session, "geomTransf", geom_transf);
      define(interp, session, "element", element);
      define(interp, session, "uniaxialMaterial", uniaxial_material);
      define(interp, session, "timeSeries", time_series);
      define(interp, session, "pattern", pattern);
      define(interp, session, "load", load);
      define(interp, session, "sp", imposed_displacement);
      define(interp, session, "eleLoad", element_load);
      define(interp, session, "loadConst", load_const);
      define(interp, session, "setTime", [](Session &s, Words &w) {
        model_domain(s).time = w.real("the time");
      });
      define(interp, session, "rayleigh", rayleigh);
      define(interp, session, "recorder", [](Session &s, Words &w) {
        recorder(s, w);
        if (!s.writer) // the lines' text made and written off the stepping thread
          s.writer = std::make_shared<OutputQueue>(output_writer_threaded());
        s.recorders.back()->set_queue(s.writer);
        // OpenSees's recorders are numbered from 0 in the order made, over
        // the whole run (Recorder::lastRecorderTag)
        s.recorder_tags.push_back(s.next_recorder_tag++);
        Tcl_SetObjResult(w.interp, Tcl_NewIntObj(s.recorder_tags.back()));
      });
      define(interp, session, "record", [](Session &s, Words &) { s.record(); });
    }
  } // namespace opensees_tcl
} // namespace poundfe
