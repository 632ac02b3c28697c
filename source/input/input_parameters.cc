#include <poundfe/input/input_parameters.h>
#include <poundfe/input/override_origin.h>
#include <poundfe/input/parameter_text.h>
#include <poundfe/input/unknown_path.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>
#include <poundfe/base/numbers.h>
#include <poundfe/model/section_shorthands.h>

#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace poundfe
{
  namespace
  {
    using dealii::ParameterHandler;

    std::string
    collapse_whitespace(const std::string &text)
    {
      std::string out;
      bool        space = false;
      for (const char c : text)
        if (std::isspace(static_cast<unsigned char>(c)))
          space = !out.empty();
        else
          {
            if (space)
              out += ' ';
            out += c;
            space = false;
          }
      return out;
    }

    /// deal.II's names of its patterns, in the words a user expects.
    std::string
    plain_patterns(std::string text)
    {
      static const std::pair<const char *, const char *> names[] = {
        {"[List of <[Double -MAX_DOUBLE...MAX_DOUBLE (inclusive)]> of length "
         "0...4294967295 (inclusive)]",
         "a comma-separated list of numbers"},
        {"[Double -MAX_DOUBLE...MAX_DOUBLE (inclusive)]", "a number"},
        {"[Bool]", "true or false"}};
      for (const auto &[deal_ii, plain] : names)
        for (std::size_t at; (at = text.find(deal_ii)) != std::string::npos;)
          text.replace(at, std::string(deal_ii).size(), plain);
      return text;
    }

    /// The entry "set" on line `line` of the parameter file (empty when
    /// none is: a JSON file, a line of an included file).
    std::string
    entry_on_line(const InputFile &p, const int line)
    {
      if (line > 0)
        for (const auto &[path, at] : p.lines)
          if (at == line)
            return path;
      return "";
    }

    /// The entry set on `line` of `file`, a .prm file the input includes
    /// (its name as the include names it: from the working directory, or
    /// the input's), its paths as written there; "" when it cannot be read.
    std::string
    entry_on_included_line(const InputFile &p, const std::string &file, const int line)
    {
      for (const std::string &name : {file, (std::filesystem::path(p.directory) / file).string()})
        {
          std::ifstream in(name);
          if (!in)
            continue;
          std::ostringstream text;
          text << in.rdbuf();
          try
            {
              InputFile included;
              included.lines = prepare_prm_text(file, text.str()).lines;
              return entry_on_line(included, line);
            }
          catch (const InputError &)
            {
              return "";
            }
        }
      return "";
    }

    /// Every entry of `prm` as (path, value), from deal.II's short PRM
    /// listing ("subsection S", "set E = V", "end"), in declaration order.
    std::vector<std::pair<std::string, std::string>>
    flattened_values(const ParameterHandler &prm)
    {
      std::ostringstream listing;
      prm.print_parameters(listing, ParameterHandler::OutputStyle(ParameterHandler::ShortPRM |
                                                                  ParameterHandler::KeepDeclarationOrder));
      std::vector<std::pair<std::string, std::string>> values;
      std::vector<std::string>                         sections;
      std::istringstream                               in(listing.str());
      for (std::string line; std::getline(in, line);)
        {
          const std::string text = trimmed(line);
          if (text.rfind("subsection ", 0) == 0)
            sections.push_back(trimmed(text.substr(11)));
          else if (text == "end" && !sections.empty())
            sections.pop_back();
          else if (text.rfind("set ", 0) == 0)
            {
              const std::size_t equals = text.find('=');
              std::string       path;
              for (const std::string &s : sections)
                path += s + "/";
              path += trimmed(text.substr(4, equals - 4));
              values.emplace_back(path, equals == std::string::npos ? "" : trimmed(text.substr(equals + 1)));
            }
        }
      return values;
    }

    /// The path of every entry of `prm`, in declaration order.
    std::vector<std::string>
    declared_paths(const ParameterHandler &prm)
    {
      std::vector<std::string> paths;
      for (const auto &[path, value] : flattened_values(prm))
        paths.push_back(path);
      return paths;
    }

    /// deal.II's words for an entry or subsection of a file that is not
    /// declared, in the reader's own (unknown_path.h, the same as for an
    /// override) where the path is known: `parameter`, the entry set on the
    /// line, or the subsection path deal.II names ('.' between its parts).
    std::string
    reworded_unknown_path(const ParameterHandler &prm, const std::string &text,
                          const std::string &parameter)
    {
      static const std::string entry   = "No entry with name <";
      static const std::string json    = "You can't ask for entry <";
      static const std::string section = "There is no such subsection to be entered: ";
      if ((text.rfind(entry, 0) == 0 || text.rfind(json, 0) == 0) && !parameter.empty())
        return unknown_path_problem(declared_paths(prm), parameter, false);
      if (text.rfind(section, 0) == 0)
        {
          std::string path = text.substr(section.size());
          std::replace(path.begin(), path.end(), '.', '/');
          return unknown_path_problem(declared_paths(prm), path, true);
        }
      return text;
    }

    /// deal.II's JSON reader names an undeclared entry alone ("You can't ask
    /// for entry <E> ..."): the path of the file's first entry E that is not
    /// declared ("" when there is none, or the text is another).
    std::string
    undeclared_json_path(const ParameterHandler &prm, const InputFile &p, const std::string &text)
    {
      static const std::string json = "You can't ask for entry <";
      const std::size_t        end  = text.find('>', json.size());
      if (text.rfind(json, 0) != 0 || end == std::string::npos)
        return "";
      const std::string              name     = text.substr(json.size(), end - json.size());
      const std::vector<std::string> declared = declared_paths(prm);
      for (const auto &[path, line] : p.lines)
        if (path.size() > name.size() && path.compare(path.size() - name.size(), name.size(), name) == 0 &&
            path[path.size() - name.size() - 1] == '/' &&
            std::find(declared.begin(), declared.end(), path) == declared.end())
          return path;
      return "";
    }

    /// deal.II's messages carry "Line <n> of file <f>:" (sometimes without
    /// the closing '>'): turn them into ours, blaming file f, which is an
    /// included file when the error is in one, and naming the entry set on
    /// that line of the parameter file (a value its pattern refuses), so
    /// that a caller can say where the entry was set (Python's Model).
    [[noreturn]] void
    rethrow_parse_error(const ParameterHandler &prm, const InputFile &p,
                        const dealii::ExceptionBase &e)
    {
      const std::string &file = p.file;
      std::ostringstream info;
      e.print_info(info);
      std::string       text = collapse_whitespace(info.str());
      std::string       blamed = file;
      int               line   = 0;
      const std::size_t where  = text.find("Line <");
      const std::size_t of     = text.find("> of file <", where);
      if (where != std::string::npos && of != std::string::npos)
        {
          const std::string digits = text.substr(where + 6, of - where - 6);
          line = std::atoi(digits.substr(0, 9).c_str());
          const std::size_t name  = of + 11;
          const std::size_t close = std::min(text.find(">", name), text.find(": ", name));
          const std::size_t rest  = close == std::string::npos ? text.size() : close;
          blamed                  = text.substr(name, rest - name);
          std::size_t after       = rest;
          while (after < text.size() && (text[after] == '>' || text[after] == ':' ||
                                         text[after] == ' '))
            ++after;
          text = text.substr(0, where) + text.substr(after);
        }
      if (text.empty())
        text = collapse_whitespace(e.what());
      const bool        here      = blamed.empty() || blamed == file;
      std::string       parameter = here ? entry_on_line(p, line) : entry_on_included_line(p, blamed, line);
      if (parameter.empty() && here)
        parameter = undeclared_json_path(prm, p, text);
      throw InputError(here ? file : blamed, line, parameter,
                       plain_patterns(reworded_unknown_path(prm, text, parameter)));
    }

    /// An override's path taken apart: "A/B/Entry:k" is sections {A, B},
    /// entry "Entry" and field k (0: the whole value).
    struct OverridePath
    {
      std::vector<std::string> sections;
      std::string              entry;
      unsigned int             field = 0;
    };

    OverridePath
    split_override_path(const InputFile &p, const std::string &path)
    {
      OverridePath split;
      std::string  rest  = path;
      const auto   colon = path.rfind(':');
      if (colon != std::string::npos && colon + 1 < path.size() &&
          path.find_first_not_of("0123456789", colon + 1) == std::string::npos)
        {
          rest        = path.substr(0, colon);
          split.field = std::atoi(path.substr(colon + 1, 6).c_str());
          if (split.field == 0)
            p.fail(path, "override: fields count from 1");
        }
      for (std::size_t slash; (slash = rest.find('/')) != std::string::npos;
           rest.erase(0, slash + 1))
        split.sections.push_back(rest.substr(0, slash));
      split.entry = rest;
      if (split.sections.empty() || split.entry.empty())
        p.fail(path, "override: a path is 'Section/.../Entry' or 'Section/.../Entry:k'");
      return split;
    }

    /// `list` ("f1 f2 ...; item 2; ...") with field k of the first item set to `value`.
    std::string
    replace_field(const InputFile &p, const std::string &path, const std::string &list,
                  const unsigned int k, const std::string &value)
    {
      const std::size_t semicolon = list.find(';');
      std::istringstream        first(list.substr(0, semicolon));
      std::vector<std::string>  fields{std::istream_iterator<std::string>(first), {}};
      if (k > fields.size())
        p.fail(path, "override: the first item '" + collapse_whitespace(list.substr(0, semicolon)) +
                       "' has " + std::to_string(fields.size()) + " fields, not " +
                       std::to_string(k));
      fields[k - 1] = value;
      std::string out;
      for (const std::string &f : fields)
        out += (out.empty() ? "" : " ") + f;
      return semicolon == std::string::npos ? out : out + list.substr(semicolon);
    }

    /// Set one override in `prm` (at its top level). With `skip_undeclared`
    /// (the first pass, which declares only the number of buildings) a path
    /// not declared is left alone; otherwise it is an InputError in the
    /// file reader's words (unknown_path.h). (A failed value leaves `prm`
    /// inside the sections: it is thrown away then.)
    void
    apply_override(ParameterHandler &prm, InputFile &p, const ParameterOverride &o,
                   const bool skip_undeclared)
    {
      const OverridePath split = split_override_path(p, o.path);
      std::string        path;
      for (const std::string &section : split.sections)
        path += section + "/";
      path += split.entry;
      // looked up, not left to prm.get, which gives "" for an undeclared
      // entry in a release build of deal.II (its check is an Assert)
      const std::vector<std::string> paths    = declared_paths(prm);
      const bool                     declared = std::find(paths.begin(), paths.end(), path) != paths.end();
      if (declared)
        {
          for (const std::string &section : split.sections)
            prm.enter_subsection(section);
          try
            {
              const std::string current = prm.get(split.entry);
              prm.set(split.entry, split.field == 0 ?
                                     o.value :
                                     replace_field(p, o.path, current, split.field, o.value));
            }
          catch (const dealii::ExceptionBase &e)
            {
              std::ostringstream info;
              e.print_info(info);
              p.fail(o.path, "override value '" + o.value + "' is not allowed: " +
                               collapse_whitespace(info.str()));
            }
          for (std::size_t i = 0; i < split.sections.size(); ++i)
            prm.leave_subsection();
        }
      if (!declared)
        {
          if (skip_undeclared)
            return;
          p.fail(path, unknown_path_problem(paths, path, false));
        }
      // written, but not on a line of the file any more (model/entry_scope.h)
      p.lines[path] = 0;
    }

    /// Parse `text` (a prepared .prm text, or JSON) into `prm`, then the overrides.
    void
    parse(ParameterHandler &prm, InputFile &p, const std::string &text, const bool json,
          const std::vector<ParameterOverride> &overrides, const bool skip_undefined)
    {
      try
        {
          std::istringstream in(text);
          if (json)
            prm.parse_input_from_json(in, skip_undefined);
          else
            prm.parse_input(in, p.file, "", skip_undefined);
        }
      catch (const dealii::ExceptionBase &e)
        {
          rethrow_parse_error(prm, p, e);
        }
      for (const ParameterOverride &o : overrides)
        apply_override(prm, p, o, skip_undefined);
    }
  } // namespace

  void
  InputParameters::declare(ParameterHandler &prm)
  {
    model.declare(prm);
    ground_motion.declare(prm);
    prm.enter_subsection("Contact");
    contact.declare(prm);
    time_integration.declare_event_refinement(prm);
    prm.leave_subsection();
    prm.enter_subsection("Springs");
    springs.declare(prm);
    prm.leave_subsection();
    prm.enter_subsection("Friction");
    friction.declare(prm);
    prm.leave_subsection();
    prm.enter_subsection("Links");
    contact.links.declare(prm);
    prm.leave_subsection();
    prm.enter_subsection("Bumpers");
    contact.bumpers.declare(prm);
    prm.leave_subsection();
    nodal_forces.declare(prm);
    time_integration.declare(prm);
    initial_conditions.declare(prm);
    output.declare(prm);
    modal.declare(prm);
    monte_carlo.declare(prm);
    subset.declare(prm);
    fragility.declare(prm);
    stationary_pdf.declare(prm);
    reliability.declare(prm);
    random_parameters.declare(prm);
    sweep.declare(prm);
    bifurcation.declare(prm);
    site_hazard.declare(prm);
    drift_limits.declare(prm);
    section_limits.declare(prm);
    separation.declare(prm);
    mitigation.declare(prm);
    spectrum.declare(prm);
    sections.declare(prm);
    moment_curvature.declare(prm);
    pushover.declare(prm);
    ida.declare(prm);
    msa.declare(prm);
    selection.declare(prm);
  }

  void
  InputParameters::finalize()
  {
    for (BuildingParameters &building : model.buildings)
      {
        building.hysteresis.theta          = time_integration.hysteresis_theta();
        building.hysteresis.tolerance      = time_integration.law_tolerance;
        building.hysteresis.max_iterations = time_integration.law_max_iterations;
      }
    output.finalize(*this);
    model.sections = sections; // what fibre buildings name
    apply_section_shorthands(*this, values, model);
    model.finalize(*this);
    ground_motion.check(*this, time_integration.newmark.time_step);
    time_integration.check(*this);
    // only a .prm file says whether the entry was given (JSON: no lines)
    time_integration.newmark.lu_when_nonsymmetric =
      time_integration.linear_solver == "eigen-ldlt" && line_of("Time integration/Linear solver") == 0;
    initial_conditions.finalize(*this);
    check_stochastic_samples();
    check_contact();
    contact.links.check(*this);
    contact.bumpers.finalize(*this, contact.law);
    friction.check(*this);
    monte_carlo.check(*this);
    subset.check(*this, model);
    reliability.check(*this);
    random_parameters.check(*this);
    // rigid contact's e is the input's, read once: a random one would refit
    // only a penalty law's damping
    if (time_integration.contact_model == ContactModel::nonsmooth)
      for (const std::string &path : random_parameters.paths)
        if (path == "Contact/Coefficient of restitution")
          fail("Random parameters/Variables",
               "Contact/Coefficient of restitution is not a random parameter of rigid contact "
               "(Contact/Model = nonsmooth) yet: sweep it instead");
    fragility.check(*this);
    stationary_pdf.check(*this, time_integration.newmark.time_step);
    sweep.check(*this);
    distinct("Sweep/Values", sweep.values()); // a value twice: the same run twice
    bifurcation.check(*this);
    site_hazard.check(*this);
    drift_limits.finalize(*this);
    section_limits.finalize(*this);
    separation.check(*this, model.buildings.size());
    mitigation.check(*this);
    spectrum.check(*this);
    sections.check(*this);
    moment_curvature.check(*this, sections);
    pushover.finalize(*this, model.buildings.size(), spectrum.target != DesignSpectrum::none);
    ida.check(*this);
    msa.check(*this);
    selection.check(*this);
  }

  void
  InputParameters::check_contact()
  {
    time_integration.restitution = contact.restitution;
    if (time_integration.contact_model != ContactModel::nonsmooth)
      {
        contact.check(*this);
        return;
      }
    // rigid contact takes e = 0 (a plastic impact), which no law's damping
    // formula does: the law's checks see e = 1 then (its damping is unused)
    if (!(contact.restitution >= 0 && contact.restitution <= 1))
      fail("Contact/Coefficient of restitution",
           "must lie in [0, 1] with Contact/Model = nonsmooth, got " +
             number_text(contact.restitution));
    if (contact.law == "none")
      fail("Contact/Model", "nonsmooth acts at the gaps, and Contact/Law = none makes none: "
                            "name a law (its force parameters are unused)");
    // what Moreau-Jean's stepper does not take yet, refused before anything
    // is built (time_history.cc refuses the rest with the model at hand)
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      if (model.buildings[b].fibre())
        fail("Contact/Model", "nonsmooth does not take fibre members yet: Building " +
                                std::to_string(b + 1) + " has Member model = fibre");
    if (model.gravity_analysis.enabled)
      fail("Contact/Model", "nonsmooth does not take a gravity analysis first "
                            "(Model/Gravity analysis) yet");
    if (time_integration.moreau_jean.friction_coefficient > 0 && model.dimension != 3)
      fail("Contact/Friction coefficient",
           "acts along contacts in plan (Model/Dimension = 3), where the slabs slide along the "
           "edge they touch; a 2D gap closes along one direction only, with no sliding to resist");
    if (!friction.surfaces.empty())
      fail("Contact/Model", "nonsmooth does not take friction surfaces yet (Friction/Surfaces; "
                            "Contact/Friction coefficient is friction along rigid contacts "
                            "in plan)");
    ContactParameters checked = contact;
    checked.restitution       = std::max(checked.restitution, 1e-3);
    checked.check(*this);
  }

  void
  InputParameters::check_stochastic_samples() const
  {
    if (!ground_motion.is_stochastic() && nodal_forces.white_noise.empty())
      return;
    const double interval  = ground_motion.held_interval(time_integration.newmark.time_step);
    const double n_samples = ground_motion.duration / interval;
    if (!(n_samples <= time_integration.max_steps))
      fail("Ground motion/Stochastic/Duration",
           "needs " + count_text(n_samples) + " samples of " + number_text(interval) +
             " s to last " + number_text(ground_motion.duration) +
             " s, more than Time integration/Maximum number of steps = " +
             std::to_string(time_integration.max_steps) + " (raise it if the run is meant)");
  }

  namespace
  {
    /// Every entry path a JSON parameter text writes, at line 0 (a JSON
    /// file has no line index): the entries the user wrote, as a .prm
    /// file's set lines are (model/entry_scope.h).
    void
    index_json_entries(const boost::property_tree::ptree &tree, const std::string &section,
                       std::map<std::string, int> &lines)
    {
      for (const auto &[key, child] : tree)
        if (child.empty())
          lines.emplace(section + key, 0);
        else
          index_json_entries(child, section + key + "/", lines);
    }

    /// The number k of the first key "Building k" of a JSON text with k >
    /// n_buildings, and its line; "" if there is none.
    std::string
    building_beyond(const std::string &text, const unsigned int n_buildings, int &line)
    {
      const std::string key = "\"Building ";
      for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + 1))
        {
          const std::size_t digits = at + key.size();
          const std::size_t end    = text.find_first_not_of("0123456789", digits);
          if (end == digits || end == std::string::npos || text[end] != '"' || end - digits > 9)
            continue;
          if (std::stoul(text.substr(digits, end - digits)) > n_buildings)
            {
              line = 1 + std::count(text.begin(), text.begin() + at, '\n');
              return text.substr(digits, end - digits);
            }
        }
      return "";
    }
  } // namespace

  std::vector<std::pair<std::string, std::string>>
  resume_inputs(const InputParameters &input, const std::string &command)
  {
    // entries that change how many realizations run or how they are
    // reported, never what one realization computes
    const auto neutral = [](const std::string &path) {
      for (const char *section : {"Output/", "Drift limits/", "Section limits/"})
        if (path.rfind(section, 0) == 0)
          return true;
      for (const char *entry : {"Monte Carlo/Realizations", "Fragility/Realizations per level",
                                "Fragility/PGA levels", "Stationary PDF/Number of realizations"})
        if (path == entry)
          return true;
      return false;
    };
    std::vector<std::pair<std::string, std::string>> inputs{{"command", command}};
    for (const auto &entry : input.values)
      if (!neutral(entry.first))
        inputs.push_back(entry);
    return inputs;
  }

  namespace
  {
    /// The extension of a parameter file's name, .prm or .json.
    std::string
    parameter_file_extension(const std::string &file)
    {
      const std::string extension = std::filesystem::path(file).extension().string();
      if (extension != ".prm" && extension != ".json")
        throw InputError(file, 0, "", "parameter files end in .prm or .json");
      return extension;
    }

    /// Reads the text of a parameter file into the lines of its entries
    /// (for messages) and, for .prm files, the text deal.II parses.
    void
    index_parameter_text(const std::string &file, const std::string &extension, std::string &text,
                         InputParameters &p)
    {
      if (extension == ".prm")
        {
          PrmText prm = prepare_prm_text(file, text);
          p.lines     = std::move(prm.lines);
          text        = std::move(prm.text);
          return;
        }
      check_json_text(file, text);
      std::istringstream          json(text);
      boost::property_tree::ptree tree;
      try
        {
          boost::property_tree::read_json(json, tree);
        }
      catch (const boost::property_tree::json_parser_error &)
        {
          // deal.II's parser reports the fault with its line below
        }
      index_json_entries(tree, "", p.lines);
    }

    /// The number of a building beyond the `n_buildings` declared that
    /// deal.II's "no such subsection" message names, or an empty string.
    std::string
    undeclared_building_number(const std::string &problem, const unsigned int n_buildings)
    {
      const std::string undeclared = "There is no such subsection to be entered: Building ";
      if (problem.rfind(undeclared, 0) != 0)
        return {};
      // its number alone, beyond the buildings declared
      const std::string rest   = problem.substr(undeclared.size());
      const std::size_t digits = std::min(rest.find_first_not_of("0123456789"), rest.size());
      if (digits > 0 && digits <= 9 &&
          (digits == rest.size() || rest[digits] == '/' || rest[digits] == ' ') &&
          std::stoul(rest.substr(0, digits)) > n_buildings)
        return rest.substr(0, digits);
      return {};
    }

    /// Rethrows `e` as the message that a building beyond the number
    /// declared is given, if that is its cause (deal.II's words for it in
    /// .prm files, or a "Building <k>" key whose entries it cannot find in
    /// JSON); rethrows `e` unchanged otherwise. Called inside its catch.
    [[noreturn]] void
    rethrow_as_building_beyond_declared(const InputError &e, const std::string &text,
                                        const bool json, const unsigned int n_buildings)
    {
      std::string building = undeclared_building_number(e.problem(), n_buildings);
      int         line     = e.line();
      // JSON has the building's key on a line of its own, and no one
      // entry of it is to blame: the key's line, no parameter
      if (json)
        {
          int               key_line = 0;
          const std::string beyond   = building_beyond(text, n_buildings, key_line);
          if (building.empty())
            building = beyond;
          if (!beyond.empty())
            line = key_line;
        }
      if (building.empty())
        throw;
      throw InputError(e.file(), line, json ? std::string() : e.parameter(),
                       "'Building " + building + "' is given, but Model/Number of buildings is " +
                         std::to_string(n_buildings) + " (raise it, or remove the section)");
    }

    /// The text of a parameter file `file` in `directory` (the one against
    /// which its relative file names are taken), read and checked.
    InputParameters
    read_parameter_input(const std::string &file, const std::string &directory, std::string text,
                         const std::vector<ParameterOverride> &overrides,
                         const std::size_t                     n_named)
    {
      const std::string extension = parameter_file_extension(file);
      const bool        json      = extension == ".json";
      InputParameters   p;
      p.file      = file;
      p.directory = directory;
      p.overrides = overrides;
      index_parameter_text(file, extension, text, p);

      // First pass: only the numbers of buildings and of cross-sections, which
      // shape the declarations.
      unsigned int n_buildings = 1, n_sections = 0;
      {
        ParameterHandler prm;
        ModelParameters::declare_number_of_buildings(prm, n_buildings);
        SectionsParameters::declare_number_of_sections(prm, n_sections);
        parse(prm, p, text, json, overrides, true);
      }
      p.model.buildings.resize(n_buildings);
      p.sections.sections.resize(n_sections);
      ParameterHandler prm;
      p.declare(prm);
      try
        {
          parse(prm, p, text, json, overrides, false);
        }
      catch (const InputError &e)
        {
          rethrow_as_building_beyond_declared(e, text, json, n_buildings);
        }
      p.values = flattened_values(prm);
      try
        {
          p.finalize();
        }
      catch (const InputError &e)
        {
          throw with_override_origin(e, overrides, n_named);
        }
      return p;
    }
  } // namespace

  std::string
  override_origin(const ParameterOverride &o)
  {
    return " (--set '" + o.path + "=" + o.value + "')";
  }

  InputError
  with_override_origin(const InputError &error, const std::vector<ParameterOverride> &overrides,
                       const std::size_t n_named)
  {
    if (error.line() > 0 || error.parameter().empty())
      return error;
    const auto entry = [](const std::string &path) { return path.substr(0, path.find(':')); };
    for (std::size_t i = overrides.size(); i-- > 0;)
      if (entry(overrides[i].path) == error.parameter())
        {
          const std::string origin = override_origin(overrides[i]);
          if (i >= n_named || error.problem().find(origin) != std::string::npos)
            return error; // a command's own override, or named already
          return InputError(error.file(), 0, error.parameter(), error.problem() + origin);
        }
    return error;
  }

  InputError
  with_override_origin(const InputError &error, const std::vector<ParameterOverride> &overrides)
  {
    return with_override_origin(error, overrides, overrides.size());
  }

  InputParameters
  read_parameters(const std::string &file, const std::vector<ParameterOverride> &overrides,
                  const std::size_t n_named)
  {
    check_input_file(file, "parameter file");
    parameter_file_extension(file);
    return read_parameter_input(file, std::filesystem::path(file).parent_path().string(),
                                read_input_text(file), overrides, n_named);
  }

  InputParameters
  read_parameters(const std::string &file, const std::vector<ParameterOverride> &overrides)
  {
    return read_parameters(file, overrides, overrides.size());
  }

  InputParameters
  read_parameter_text(const std::string &name, const std::string &text,
                      const std::vector<ParameterOverride> &overrides)
  {
    return read_parameter_input(name, "", text, overrides, overrides.size());
  }

  InputParameters
  read_parameters(const std::string &file)
  {
    return read_parameters(file, {});
  }

  void
  print_parameters(std::ostream &out)
  {
    InputParameters p;
    p.model.buildings.resize(1);
    p.sections.sections.resize(1);
    ParameterHandler prm;
    p.declare(prm);
    out << "# poundfe parameters, in the order the program declares them. 'Building 1'\n"
        << "# stands for every 'Building <i>', i = 1 .. Number of buildings ('Section 1'\n"
        << "# for every 'Section <k>' of Sections); its entries\n"
        << "# tagged [frame], [shear] or [mesh] apply only to buildings of that Type,\n"
        << "# untagged ones to every Type. Each entry says its unit ('Unit: -' for\n"
        << "# names, choices and switches). Lists are comma separated.\n";
    const auto style = ParameterHandler::PRM | ParameterHandler::KeepDeclarationOrder;
    prm.print_parameters(out, ParameterHandler::OutputStyle(style));
  }
} // namespace poundfe
