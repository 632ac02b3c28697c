// `print` and `printModel` of an OpenSees script (OpenSees 3.8's
// printModel in tcl/commands.cpp): `-JSON` writes the model in OpenSees's
// JSON layout (Domain::Print with OPS_PRINT_PRINTMODEL_JSON: the simulation
// header, then "properties" with uniaxialMaterials, ndMaterials, sections
// and crdTransformations, then "geometry" with nodes and elements, each
// object's fields as its class's Print(s, 25000) writes them); without it
// the text of Print(s, 0): a node's lines as Node::Print's, an element in
// poundfe's layout of the same fields as its JSON (doc/user-guide.md).
// -file: JSON replaces the file, text is appended to it (as OpenSees's
// OVERWRITE and APPEND). A run's first print to a path (and every JSON)
// writes a new file through a temporary renamed into place; a later text
// print to the file this run made appends to it in place (one write of the
// text: n appends cost what they write, not n^2), so a run never mixes its
// file with an earlier run's.
#include <poundfe/base/exceptions.h>
#include <poundfe/base/lean_assert.h>
#include <poundfe/laws/hysteretic.h>
#include <poundfe/laws/material_registry.h>
#include <poundfe/output/atomic_file.h>

#include "opensees_tcl.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <filesystem>
#include <set>
#include <sstream>

namespace poundfe
{
  namespace opensees_tcl
  {
    std::string
    json_number(const double value)
    {
      char text[32];
      return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
    }

    namespace
    {
      /// "[a, b, ...]" of each value's text.
      template <typename Value, typename Text>
      std::string
      json_array(const std::vector<Value> &values, const Text &text_of_value)
      {
        std::string text = "[";
        for (std::size_t i = 0; i < values.size(); ++i)
          text += (i ? ", " : "") + text_of_value(values[i]);
        return text + "]";
      }
    } // namespace

    std::string
    json_numbers(const std::vector<double> &values)
    {
      return json_array(values, json_number);
    }

    std::string
    json_tag(const int tag)
    {
      return "\"" + std::to_string(tag) + "\"";
    }

    std::string
    json_tags(const std::vector<int> &tags)
    {
      return json_array(tags, json_tag);
    }

    std::string
    json_strings(const std::vector<std::string> &texts)
    {
      return json_array(texts, [](const std::string &text) { return "\"" + text + "\""; });
    }

    namespace
    {
      using opensees::ScriptError;
      using Fields = std::vector<std::pair<std::string, std::string>>;

      /// The value of a material's parameter, its registered default when
      /// the script left it out.
      double
      parameter(const MaterialParameters &p, const std::string &name)
      {
        const auto it = p.values.find(name);
        if (it != p.values.end())
          return it->second;
        for (const MaterialParameter &m : material_type(p.material).parameters)
          if (m.name == name)
            return m.default_value;
        Assert(false, dealii::ExcMessage("no parameter " + name + " of " + p.material));
        return 0;
      }

      /// HystereticMaterial's Print fields: each envelope point with the
      /// slope up to it, as its setEnvelope computes them (the two-point
      /// form's middle point halfway, as its constructor puts it), the
      /// damage's energyA as the constructor sums it.
      Fields
      hysteretic_fields(const MaterialParameters &p)
      {
        const bool two_points = p.values.count("s3p") == 0;
        Fields     fields;
        double     energy = 0;
        for (const char *side : {"p", "n"})
          {
            // the negative side as given (negative values), as OpenSees prints it
            const HystereticEnvelope e = hysteretic_envelope(p.values, side);
            const double m1 = e.s1, r1 = e.e1, m2 = e.s2, r2 = e.e2, m3 = e.s3, r3 = e.e3;
            const double slopes[] = {m1 / r1, (m2 - m1) / (r2 - r1), (m3 - m2) / (r3 - r2)};
            const double points[][2] = {{m1, r1}, {m2, r2}, {m3, r3}};
            for (int i = 0; i < 3; ++i)
              {
                const std::string n = std::to_string(i + 1) + side;
                fields.emplace_back("s" + n, json_number(points[i][0]));
                fields.emplace_back("e" + n, json_number(points[i][1]));
                fields.emplace_back("E" + n, json_number(slopes[i]));
              }
            energy += two_points ? r1 * m1 + (r3 - r1) * (m3 + m1) :
                                   r1 * m1 + (r2 - r1) * (m2 + m1) + (r3 - r2) * (m3 + m2);
          }
        const auto value = [&](const char *name) { return json_number(parameter(p, name)); };
        fields.insert(fields.end(), {{"pinchX", value("pinchX")}, {"pinchY", value("pinchY")},
                                     {"damfc1", value("damage1")}, {"damfc2", value("damage2")},
                                     {"energyA", json_number(0.5 * energy)},
                                     {"beta", value("beta")}});
        return fields;
      }

      /// OpenSees's class name and Print fields of a uniaxial material;
      /// the type word alone for the kinds whose fields poundfe does not
      /// write (doc/user-guide.md lists them).
      Printed
      material_printed(const MaterialParameters &p)
      {
        const auto value = [&](const char *name) { return json_number(parameter(p, name)); };
        const std::string &type = p.material;
        if (type == "Elastic")
          return {"ElasticMaterial",
                  {{"Epos", value("E")},
                   {"Eneg", json_number(p.values.count("Eneg") ? p.values.at("Eneg") :
                                                                 p.values.at("E"))},
                   {"eta", value("eta")}}};
        if (type == "ElasticPP")
          {
            const double epsy_p = p.values.at("epsyP");
            const double epsy_n = p.values.count("epsyN") ? p.values.at("epsyN") : -epsy_p;
            return {"ElasticPPMaterial",
                    {{"E", value("E")}, {"epsyp", json_number(epsy_p)},
                     {"epsyn", json_number(epsy_n)}, {"eps0", value("eps0")}}};
          }
        if (type == "ElasticPPGap")
          return {"EPPGap",
                  {{"E", value("E")}, {"eta", value("eta")}, {"fy", value("Fy")},
                   {"gap", value("gap")}, {"damageFlag", p.values.count("damage") ? "1" : "0"}}};
        if (type == "Steel01")
          {
            // OpenSees's Steel01 of three values holds a2 = a4 = 55 where
            // poundfe's takes 1: with a1 = a3 = 0 neither hardens isotropically
            const std::string a_default = p.values.count("a1") ? "" : "55";
            return {"Steel01",
                    {{"E", value("E0")}, {"fy", value("fy")}, {"b", value("b")},
                     {"a1", value("a1")}, {"a2", a_default.empty() ? value("a2") : a_default},
                     {"a3", value("a3")}, {"a4", a_default.empty() ? value("a4") : a_default}}};
          }
        if (type == "Steel02")
          return {"Steel02",
                  {{"E", value("E0")}, {"fy", value("fy")}, {"b", value("b")},
                   {"R0", value("R0")}, {"cR1", value("cR1")}, {"cR2", value("cR2")},
                   {"a1", value("a1")}, {"a2", value("a2")}, {"a3", value("a3")},
                   {"a4", value("a4")}, {"sigini", "0"}}};
        if (type == "Hysteretic")
          return {"HystereticMaterial", hysteretic_fields(p)};
        return {type, {}};
      }

      /// The same of Parallel, Series and MinMax (Parallel's factors as a
      /// list of their own, where OpenSees 3.8 closes the object before them).
      Printed
      combined_printed(const opensees::CombinedMaterial &c)
      {
        if (c.type == "MinMax")
          return {"MinMaxMaterial",
                  {{"material", json_tag(c.components.at(0))},
                   {"epsMin", json_number(c.min_strain)},
                   {"epsMax", json_number(c.max_strain)}}};
        Printed printed{c.type + "Material", {{"materials", json_tags(c.components)}}};
        if (!c.factors.empty())
          printed.fields.emplace_back("factors", json_numbers(c.factors));
        return printed;
      }

      /// {"name": ..., "type": ..., fields...} on a line of its own.
      std::string
      json_object(const std::string &name, const Printed &printed, const Fields &first = {})
      {
        std::string text = "\t\t\t{\"name\": " + name + ", \"type\": \"" + printed.type + "\"";
        for (const Fields *fields : {&first, &printed.fields})
          for (const auto &[key, value] : *fields)
            text += ", \"" + key + "\": " + value;
        return text + "}";
      }

      /// `"key": [` the objects, one a line, `]` (an empty line when there
      /// is none, as OpenSees's).
      std::string
      json_list(const std::string &key, const std::vector<std::string> &objects,
                const std::string &indent)
      {
        std::string text = indent + "\"" + key + "\": [\n";
        for (std::size_t i = 0; i < objects.size(); ++i)
          text += (i ? ",\n" : "") + objects[i];
        return text + "\n" + indent + "]";
      }

      std::vector<std::string>
      material_objects(const Session &s)
      {
        // OpenSees keeps every uniaxial material in one map by tag
        std::map<int, Printed> all;
        for (const auto &[tag, p] : s.domain.materials)
          all[tag] = material_printed(p);
        for (const auto &[tag, c] : s.domain.combined_materials)
          all[tag] = combined_printed(c);
        std::vector<std::string> objects;
        for (const auto &[tag, printed] : all)
          objects.push_back(json_object(json_tag(tag), printed));
        return objects;
      }

      std::vector<std::string>
      section_objects(const Session &s)
      {
        std::vector<std::string> objects;
        for (const auto &[tag, printed] : s.printed_sections)
          if (s.domain.sections.count(tag) != 0)
            objects.push_back(json_object(json_tag(tag), printed));
        return objects;
      }

      std::vector<std::string>
      transformation_objects(const Session &s)
      {
        const opensees::Domain  &d = s.domain;
        std::vector<std::string> objects;
        for (const auto &[tag, kind] : d.transformations)
          {
            const std::string name = kind == Transformation::pdelta       ? "PDelta" :
                                     kind == Transformation::corotational ? "Corot" :
                                                                            "Linear";
            Printed printed{name + (d.ndm == 3 ? "CrdTransf3d" : "CrdTransf2d"), {}};
            if (d.ndm == 3)
              {
                const auto &v = d.vecxz.at(tag);
                printed.fields = {{"vecInLocXZPlane", json_numbers({v[0], v[1], v[2]})}};
              }
            objects.push_back(json_object(json_tag(tag), printed));
          }
        return objects;
      }

      bool
      has_mass(const opensees::Node &n)
      {
        for (const double m : n.mass)
          if (m != 0)
            return true;
        return false;
      }

      std::vector<std::string>
      geometry_objects(const Session &s, const bool nodes)
      {
        std::vector<std::string> objects;
        if (nodes)
          for (const auto &[tag, n] : s.domain.nodes)
            {
              std::string text = "\t\t\t{\"name\": " + std::to_string(tag) +
                                 ", \"ndf\": " + std::to_string(n.fixed.size()) +
                                 ", \"crd\": " + json_numbers(n.coordinates);
              if (has_mass(n))
                text += ", \"mass\": " + json_numbers(n.mass);
              objects.push_back(text + "}");
            }
        else
          for (const auto &[tag, element] : s.domain.elements)
            {
              const Printed &printed = s.printed_elements.at(tag);
              const std::string nodes =
                json_array(element->node_tags, [](const int n) { return std::to_string(n); });
              objects.push_back(json_object(std::to_string(tag), printed, {{"nodes", nodes}}));
            }
        return objects;
      }

      /// The model in OpenSees's JSON layout (SimulationInformation::Print
      /// and Domain::Print with flag 25000).
      std::string
      model_json(const Session &s)
      {
        return "{\n\"StructuralAnalysisModel\": {\n\t\"BIM\": \"unknown\",\n"
               "\t\"description\": \"\",\n\t\"engineer\": \"\",\n\t\"units\": {\n"
               "\t\t\"force\": \"\",\n\t\t\"length\": \"\",\n\t\t\"time\": \"\",\n"
               "\t\t\"temperature\": \"\"\n\t},\n"
               "\t\"properties\": {\n" +
               json_list("uniaxialMaterials", material_objects(s), "\t\t") + ",\n" +
               json_list("ndMaterials", {}, "\t\t") + ",\n" +
               json_list("sections", section_objects(s), "\t\t") + ",\n" +
               json_list("crdTransformations", transformation_objects(s), "\t\t") +
               "\n\t},\n\t\"geometry\": {\n" + json_list("nodes", geometry_objects(s, true), "\t\t") +
               ",\n" + json_list("elements", geometry_objects(s, false), "\t\t") +
               "\n\t}\n}\n}\n";
      }

      /// OpenSees's Vector text: each value and a space, then a line end.
      void
      vector_text(std::ostream &out, const std::vector<double> &values)
      {
        for (const double v : values)
          out << v << ' ';
        out << '\n';
      }

      /// The nodes of a fix, equalDOF or rigidDiaphragm: OpenSees's
      /// constraints ask for their displacements as they are made. Found
      /// once per print, so that printing every node stays linear.
      std::set<int>
      constrained_nodes(const Session &s)
      {
        std::set<int> nodes;
        for (const auto &[tag, node] : s.domain.nodes)
          if (std::find(node.fixed.begin(), node.fixed.end(), true) != node.fixed.end())
            nodes.insert(tag);
        for (const opensees::EqualDof &e : s.domain.equal_dofs)
          nodes.insert({e.retained, e.constrained});
        for (const opensees::RigidTie &d : s.domain.rigid_ties)
          {
            nodes.insert(d.retained);
            nodes.insert(d.constrained.begin(), d.constrained.end());
          }
        return nodes;
      }

      /// Node::Print(s, 0): OpenSees's lines before any analysis (after
      /// one OpenSees adds its DOF numbers, unbalanced load and
      /// reaction, which poundfe does not write: doc/user-guide.md).
      void
      node_text(std::ostream        &out,
                const Session       &s,
                const opensees::Node &n,
                const std::set<int> &constrained)
      {
        const Session::NodeVectors &made = s.node_vectors;
        out << "\n Node: " << n.tag << "\n\tCoordinates  : ";
        vector_text(out, n.coordinates);
        if (made.analysed || made.displacements.count(n.tag) != 0 ||
            constrained.count(n.tag) != 0)
          {
            out << "\tDisps: ";
            vector_text(out, n.disp);
          }
        if (made.transient_analysed || made.velocities.count(n.tag) != 0)
          {
            out << "\tVelocities   : ";
            vector_text(out, n.vel);
          }
        if (made.transient_analysed)
          {
            out << "\tcommitAccels: ";
            vector_text(out, n.accel);
          }
        if (has_mass(n))
          {
            out << "\tMass : \n";
            for (std::size_t i = 0; i < n.mass.size(); ++i)
              {
                std::vector<double> row(n.mass.size(), 0.0);
                row[i] = n.mass[i];
                vector_text(out, row);
              }
            const double alpha = s.domain.alpha_m_of(n.tag);
            out << "\n\t Rayleigh Factor: alphaM: " << alpha << "\n\t Rayleigh Forces: ";
            std::vector<double> forces(n.mass.size());
            for (std::size_t i = 0; i < forces.size(); ++i)
              forces[i] = 0.0 - alpha * n.mass[i] * n.vel[i]; // -alphaM M v, +0 for a zero mass
            vector_text(out, forces);
          }
        out << '\n';
      }

      /// An element's fields, one a line (poundfe's layout).
      void
      element_text(std::ostream &out, const Session &s, const int tag)
      {
        out << "\nElement: " << tag << " " << s.printed_elements.at(tag).type << "\n\tnodes:";
        for (const int n : s.domain.elements.at(tag)->node_tags)
          out << ' ' << n;
        out << '\n';
        for (const auto &[key, value] : s.printed_elements.at(tag).fields)
          out << '\t' << key << ": " << value << '\n';
      }

      /// What `print` was asked for: the file ("": the warnings stream),
      /// JSON, and the nodes and elements (all of them when the list is
      /// empty; neither: the whole domain).
      struct PrintRequest
      {
        std::string      file;
        bool             json = false, nodes = false, elements = false;
        std::vector<int> tags;
      };

      PrintRequest
      print_request(Words &w)
      {
        PrintRequest r;
        while (!w.done() && !r.nodes && !r.elements)
          {
            const std::string word = w.word("an option");
            if (word == "-ele" || word == "ele" || word == "-node" || word == "node")
              {
                r.nodes = word == "-node" || word == "node";
                r.elements = !r.nodes;
                if (!w.done() && (w.peek() == "flag" || w.peek() == "-flag"))
                  unsupported("print " + word + " flag");
                r.tags = w.integers("a tag");
                if (!w.done())
                  throw ScriptError("'" + w.peek() + "' is not a tag");
              }
            else if (word == "-JSON")
              r.json = true;
            else if (word == "-file" || word == "file")
              r.file = w.word("the file's name");
            else if (word[0] == '-' || word == "integrator" || word == "algorithm")
              unsupported("print " + word);
            else
              r.file = word; // OpenSees's `print <filename>`
          }
        return r;
      }

      /// The text of the nodes (elements) asked for, every one when none is.
      void
      objects_text(std::ostream &out, const Session &s, const PrintRequest &r)
      {
        std::vector<int> tags = r.tags;
        if (tags.empty() && r.nodes)
          for (const auto &node : s.domain.nodes)
            tags.push_back(node.first);
        if (tags.empty() && r.elements)
          for (const auto &element : s.domain.elements)
            tags.push_back(element.first);
        const std::set<int> constrained = r.nodes ? constrained_nodes(s) : std::set<int>();
        for (const int tag : tags)
          {
            if (r.nodes && s.domain.nodes.count(tag) == 0)
              throw ScriptError("node " + std::to_string(tag) + " does not exist");
            if (r.elements && s.domain.elements.count(tag) == 0)
              throw ScriptError("element " + std::to_string(tag) + " does not exist");
            if (r.nodes)
              node_text(out, s, s.domain.nodes.at(tag), constrained);
            else
              element_text(out, s, tag);
          }
      }

      /// Domain::Print(s, 0)'s opening lines, its nodes and elements.
      void
      domain_text(std::ostream &out, const Session &s)
      {
        out << "Current Domain Information\n\tCurrent Time: " << s.domain.time
            << "\n\tCommitted Time: " << s.domain.time
            << "\nNODE DATA: NumNodes: " << s.domain.nodes.size() << "\n";
        objects_text(out, s, {"", false, true, false, {}});
        out << "ELEMENT DATA: NumEle: " << s.domain.elements.size() << "\n";
        objects_text(out, s, {"", false, false, true, {}});
      }

      /// The device and inode of the file at `path`; nullopt when there is
      /// none.
      std::optional<std::pair<unsigned long long, unsigned long long>>
      file_identity(const std::string &path)
      {
        struct stat status;
        if (::stat(path.c_str(), &status) != 0)
          return std::nullopt;
        return std::pair<unsigned long long, unsigned long long>(status.st_dev, status.st_ino);
      }

      /// `text` after what the file holds, in one write(2).
      void
      append_in_place(const std::string &path, const std::string &text)
      {
        const int descriptor = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
        if (descriptor < 0)
          throw OutputError("open", path, errno);
        std::size_t written = 0;
        while (written < text.size())
          {
            const ssize_t n = ::write(descriptor, text.data() + written, text.size() - written);
            if (n < 0 && errno == EINTR)
              continue;
            if (n < 0)
              {
                const int error = errno;
                ::close(descriptor);
                throw OutputError("write", path, error);
              }
            written += static_cast<std::size_t>(n);
          }
        if (::close(descriptor) != 0)
          throw OutputError("close", path, errno);
      }

      /// The path a print writes for `file`: a symbolic link's target
      /// (OpenSees writes through the link; a renamed temporary would
      /// replace the link itself), followed link by link, also when the
      /// last one dangles. A path that names a device or a FIFO, through
      /// links or not, stays as it is: AtomicFile writes it in place.
      std::string
      print_target(const std::string &file)
      {
        namespace fs = std::filesystem;
        std::error_code error;
        const fs::file_status followed = fs::status(file, error);
        if (fs::exists(followed) && !fs::is_regular_file(followed))
          return file;
        fs::path path = file;
        for (int links = 0; links < 40 && fs::is_symlink(path, error); ++links) // ELOOP's 40
          {
            const fs::path target = fs::read_symlink(path, error);
            if (error)
              break;
            path = target.is_relative() ? path.parent_path() / target : target;
          }
        return path.string();
      }

      /// The text into the file (through a link: its target): appended to
      /// the file this run made there, else (and for JSON) a new file in its
      /// place.
      void
      write_file(Session &s, const std::string &file, const std::string &text, const bool append)
      {
        const std::filesystem::path parent = std::filesystem::path(file).parent_path();
        if (!parent.empty() && !std::filesystem::is_directory(parent))
          throw ScriptError("cannot write '" + file + "': the directory '" + parent.string() +
                            "' does not exist");
        const std::string target   = print_target(file);
        const auto        existing = file_identity(target);
        if (append && existing && s.print_files.count(*existing) > 0)
          return append_in_place(target, text);
        write_file_atomically(target, text);
        if (const auto made = file_identity(target))
          s.print_files.insert(*made);
      }

      void
      print(Session &s, Words &w)
      {
        const PrintRequest r = print_request(w);
        std::ostringstream out;
        if (r.json && !r.nodes && !r.elements)
          out << model_json(s);
        else if (r.nodes || r.elements)
          objects_text(out, s, r);
        else
          domain_text(out, s);
        if (r.file.empty())
          s.warnings << out.str();
        else
          write_file(s, r.file, out.str(), !r.json);
      }
    } // namespace

    void
    define_print_commands(Tcl_Interp *interp, Session &session)
    {
      define(interp, session, "print", print);
      define(interp, session, "printModel", print);
    }
  } // namespace opensees_tcl
} // namespace poundfe
