// Where an entry of `Building <i>` acts (the tag of its help text) and the
// refusal of an entry the user wrote where it has no effect
// (model/entry_scope.h; doc/user-guide.md, "Entries without effect").
#include <poundfe/model/entry_scope.h>
#include <poundfe/model/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <climits>
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
} // namespace poundfe
