// Where an entry of `Building <i>` acts (the tag of its help text) and the
// refusal of an entry the user wrote where it has no effect
// (model/entry_scope.h; doc/user-guide.md, "Entries without effect").
#include <poundfe/model/entry_scope.h>
#include <poundfe/model/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <climits>
#include <functional>
#include <sstream>

namespace poundfe
{
  std::optional<EntryScope>
  parse_entry_scope(const std::string &help)
  {
    const std::string text = trimmed(help);
    const std::size_t close = text.find(']');
    if (text.empty() || text[0] != '[' || close == std::string::npos)
      return std::nullopt;
    EntryScope scope;
    scope.tag = text.substr(1, close - 1);
    std::string rest = scope.tag;
    if (rest.rfind("3D", 0) == 0)
      {
        scope.only_3d = true;
        rest.erase(0, 2);
      }
    std::istringstream words(rest);
    for (std::string word; std::getline(words, word, ',');)
      {
        word = trimmed(word); // "[3D]" has none: every Type
        const std::vector<std::string> types = building_type_names().names();
        if (word == "fibre")
          scope.only_fibre = true;
        else
          {
            AssertThrow(std::find(types.begin(), types.end(), word) != types.end(),
                        dealii::ExcMessage("the help tag [" + scope.tag + "] has the word '" +
                                           word + "': neither a Type, 3D nor fibre"));
            scope.types.push_back(building_type_names().value(word));
          }
      }
    return scope;
  }

  namespace
  {
    /// The help of every entry of `listing` (deal.II's PRM listing: '#'
    /// lines of help, then 'set Entry = value'), by its path.
    std::map<std::string, std::string>
    helps_of_listing(const std::string &listing)
    {
      std::map<std::string, std::string> helps;
      std::vector<std::string>           sections;
      std::string                        help;
      std::istringstream                 in(listing);
      for (std::string raw; std::getline(in, raw);)
        {
          const std::string line = trimmed(raw);
          if (line.rfind("#", 0) == 0)
            help += " " + trimmed(line.substr(1));
          else if (line.rfind("subsection ", 0) == 0)
            sections.push_back(trimmed(line.substr(11)));
          else if (line == "end" && !sections.empty())
            sections.pop_back();
          else if (line.rfind("set ", 0) == 0)
            {
              std::string path;
              for (const std::string &s : sections)
                path += s + "/";
              helps[path + trimmed(line.substr(4, line.find('=') - 4))] = help;
            }
          if (line.rfind("#", 0) != 0)
            help.clear();
        }
      return helps;
    }
  } // namespace

  const std::map<std::string, EntryScope> &
  building_entry_scopes()
  {
    static const std::map<std::string, EntryScope> scopes = [] {
      BuildingParameters       building; // outlives prm: its entries are bound to it
      dealii::ParameterHandler prm;
      building.declare(prm);
      std::ostringstream listing;
      prm.print_parameters(listing, dealii::ParameterHandler::PRM);
      std::map<std::string, EntryScope> tagged;
      for (const auto &[path, help] : helps_of_listing(listing.str()))
        if (std::optional<EntryScope> scope = parse_entry_scope(help))
          tagged.emplace(path, *scope);
      return tagged;
    }();
    return scopes;
  }

  namespace
  {
    /// "frame or mesh" of a scope's Types.
    std::string
    types_text(const std::vector<BuildingType> &types)
    {
      std::string text;
      for (std::size_t i = 0; i < types.size(); ++i)
        text += (i == 0 ? "" : i + 1 == types.size() ? " or " : ", ") +
                building_type_names().name(types[i]);
      return text;
    }
  } // namespace

  std::string
  entry_without_effect(const EntryScope &scope, const BuildingParameters &building,
                       const unsigned int dimension)
  {
    const bool type_fits = scope.types.empty() ||
                           std::find(scope.types.begin(), scope.types.end(), building.type) !=
                             scope.types.end();
    const bool dimension_fits = !scope.only_3d || dimension == 3;
    const bool fibre_fits     = !scope.only_fibre || building.fibre();
    if (type_fits && dimension_fits && fibre_fits)
      return "";
    std::string fixes;
    const auto  fix = [&](const std::string &text) { fixes += (fixes.empty() ? "" : " and ") + text; };
    if (!type_fits)
      fix("set Type = " + types_text(scope.types));
    if (!dimension_fits)
      fix("set Model/Dimension = 3");
    if (!fibre_fits)
      fix("set Member model = fibre");
    const std::string kind = (dimension == 3 ? "3D " : "2D ") +
                             building_type_names().name(building.type) +
                             (scope.only_fibre && !fibre_fits ? " building with Member model = " +
                                                                  building.member_model :
                                                                " building");
    return "has no effect on a " + kind + ": it is a [" + scope.tag + "] entry (" +
           (scope.types.empty() ? std::string("every Type") : "Type = " + types_text(scope.types)) +
           (scope.only_3d ? ", Model/Dimension = 3" : "") +
           (scope.only_fibre ? ", Member model = fibre" : "") + "); remove it, or " + fixes;
  }

  void
  refuse_entries_without_effect(const InputFile &input, const ModelParameters &model)
  {
    const std::map<std::string, EntryScope> &scopes = building_entry_scopes();
    std::string                              path, problem;
    int                                      first_line = INT_MAX;
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const std::string s = "Building " + std::to_string(b + 1) + "/";
        for (const auto &[written, line] : input.lines)
          {
            if (written.rfind(s, 0) != 0)
              continue;
            const auto scope = scopes.find(written.substr(s.size()));
            if (scope == scopes.end())
              continue;
            const std::string why =
              entry_without_effect(scope->second, model.buildings[b], model.dimension);
            const int order = line > 0 ? line : INT_MAX - 1; // JSON keys, overrides: after lines
            if (!why.empty() && order < first_line)
              {
                path = written, problem = why, first_line = order;
              }
          }
      }
    if (!problem.empty())
      input.fail(path, problem);
  }

  namespace
  {
    /// An entry (or, ending in '/', every entry of a subsection but its
    /// `Type`) of `Building <i>` and why another entry's value leaves it
    /// without effect on a building of a model of that dimension (empty:
    /// it acts).
    struct ConditionalEntry
    {
      std::string path;
      std::function<std::string(const BuildingParameters &, unsigned int dimension)> why;
    };

    /// Typed Plan/Resisting planes of a 3D shear building: they replace the
    /// perimeter planes made from the storey entries.
    bool
    typed_planes(const BuildingParameters &b, const unsigned int dimension)
    {
      return dimension == 3 && b.type == BuildingType::shear && !b.plan.planes.empty();
    }

    /// Whether the building has a Bouc-Wen element: a hinge of a frame or
    /// mesh, a storey (or plane) with a yield drift of a shear building.
    bool
    has_bouc_wen(const BuildingParameters &b, const unsigned int dimension)
    {
      if (b.type != BuildingType::shear)
        return !b.hinge_locations.empty() && !b.fibre();
      if (typed_planes(b, dimension))
        return std::any_of(b.plan.planes.begin(), b.plan.planes.end(),
                           [](const PlaneEntry &plane) { return plane.yield_drift > 0; });
      return std::any_of(b.storey_yield_drifts.begin(), b.storey_yield_drifts.end(),
                         [](const double u_y) { return u_y > 0; });
    }

    /// A Damping entry used by Damping/Type = `user` alone.
    ConditionalEntry
    damping_entry(const std::string &entry, const RayleighDamping::Kind user)
    {
      return {"Damping/" + entry, [user](const BuildingParameters &b, unsigned int) {
                const auto &names = damping_type_names();
                return b.damping_type == user ?
                         std::string() :
                         "Damping/Type = " + names.name(b.damping_type) +
                           " does not use it (Type = " + names.name(user) + " does)";
              }};
    }

    /// The entries whose effect depends on another entry's value.
    const std::vector<ConditionalEntry> &
    conditional_entries()
    {
      using Kind = RayleighDamping::Kind;
      const auto planes_replace = [](const BuildingParameters &b, const unsigned int dimension) {
        return typed_planes(b, dimension) ?
                 std::string("Plan/Resisting planes are typed: each plane has its own "
                             "stiffness and yield drift (remove this entry, or the planes)") :
                 std::string();
      };
      static const std::vector<ConditionalEntry> entries{
        {"Storey stiffnesses", planes_replace},
        {"Storey yield drifts", planes_replace},
        {"Bouc-Wen/",
         [](const BuildingParameters &b, const unsigned int dimension) {
           return has_bouc_wen(b, dimension) ?
                    std::string() :
                    b.type == BuildingType::shear ?
                    std::string("the building has no hysteretic storey (no yield drift above 0)") :
                    std::string("the building has no hinge (Hinges/Locations is empty)");
         }},
        {"Hinges/",
         [](const BuildingParameters &b, unsigned int) {
           return b.type == BuildingType::shear || !b.hinge_locations.empty() ?
                    std::string() :
                    std::string("the building has no hinge (Hinges/Locations is empty)");
         }},
        {"Foundation/",
         [](const BuildingParameters &b, unsigned int) {
           return b.foundation.enabled() ? std::string() :
                                           std::string("Foundation/Type = none: a fixed base");
         }},
        damping_entry("Damping ratio", Kind::modes),
        damping_entry("Modes", Kind::modes),
        damping_entry("a0", Kind::coefficients),
        damping_entry("a1", Kind::coefficients),
        damping_entry("Modal ratios", Kind::modal),
        damping_entry("Bands", Kind::bands),
        damping_entry("Damped modes", Kind::bands)};
      return entries;
    }

    /// Whether `entry` (a path below `Building <i>/`) is `path` of a
    /// ConditionalEntry, or an entry of its subsection other than Type.
    bool
    conditional_entry_matches(const std::string &path, const std::string &entry)
    {
      if (path.back() != '/')
        return entry == path;
      return entry.rfind(path, 0) == 0 && entry.find('/', path.size()) == std::string::npos &&
             entry != path + "Type";
    }
  } // namespace

  std::vector<std::string>
  warn_entries_without_effect(const InputFile &input, const ModelParameters &model)
  {
    std::vector<std::pair<int, std::string>> found; // (line order, warning)
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const std::string s = "Building " + std::to_string(b + 1) + "/";
        for (const auto &[written, line] : input.lines)
          {
            if (written.rfind(s, 0) != 0)
              continue;
            const std::string entry = written.substr(s.size());
            for (const ConditionalEntry &c : conditional_entries())
              if (conditional_entry_matches(c.path, entry))
                if (const std::string why = c.why(model.buildings[b], model.dimension); !why.empty())
                  found.emplace_back(line > 0 ? line : INT_MAX, // JSON keys, overrides: after lines
                                     input.warning(written, "has no effect: " + why));
          }
      }
    std::stable_sort(found.begin(), found.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    std::vector<std::string> warnings;
    for (auto &[order, warning] : found)
      warnings.push_back(std::move(warning));
    return warnings;
  }
} // namespace poundfe
