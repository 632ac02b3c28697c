#include <poundfe/base/numbers.h>
#include <poundfe/dynamics/initial_conditions.h>

#include <deal.II/base/parameter_handler.h>

#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  namespace
  {
    const std::string section = "Initial conditions/";

    /// The largest initial displacement or velocity (m, rad, m/s, rad/s):
    /// far beyond any building's motion, and a state of 1e308 would end as
    /// a numerical failure instead of a named entry.
    constexpr double largest_initial_value = 1e3;
    const char *const initial_value_why = "beyond any building's motion, in m, rad, m/s or rad/s";

    /// The numbers of `text` (blank-separated), each finite; fails on the
    /// first word that is not one.
    std::vector<double>
    finite_numbers(const InputFile &input, const std::string &path, const std::string &text)
    {
      std::istringstream  words(text);
      std::vector<double> values;
      std::string         word;
      while (words >> word)
        {
          const std::optional<double> value = parse_number(word);
          if (!value)
            input.fail(path, "'" + word + "' is not a finite number (in '" + trimmed(text) + "')");
          input.at_most(path, *value, largest_initial_value, "", initial_value_why);
          values.push_back(*value);
        }
      return values;
    }

    /// One 'building: values' entry: the building's text and its values
    /// (empty `values` and `uniform` set for 'all v').
    struct FloorEntry
    {
      std::string         building;
      std::vector<double> values;
      bool                uniform = false;
    };

    FloorEntry
    floor_entry(const InputFile &input, const std::string &path, const std::string &text)
    {
      const std::size_t colon = text.find(':');
      if (colon == std::string::npos || trimmed(text.substr(0, colon)).empty())
        input.fail(path, "'" + trimmed(text) +
                           "' is not 'building: one value per floor' or 'building: all value'");
      FloorEntry  entry;
      entry.building   = trimmed(text.substr(0, colon));
      std::string rest = trimmed(text.substr(colon + 1));
      if (rest.rfind("all", 0) == 0 && (rest.size() == 3 || std::isspace(rest[3])))
        {
          entry.uniform = true;
          rest          = rest.substr(3);
        }
      entry.values = finite_numbers(input, path, rest);
      if (entry.values.empty() || (entry.uniform && entry.values.size() != 1))
        input.fail(path, "'" + trimmed(text) + "' needs " +
                           (entry.uniform ? "one value after 'all'" : "a value per floor"));
      return entry;
    }

    /// One 'index = value' entry.
    std::pair<long, double>
    equation_entry(const InputFile &input, const std::string &path, const std::string &text)
    {
      const std::size_t equals = text.find('=');
      if (equals == std::string::npos)
        input.fail(path, "'" + trimmed(text) + "' is not 'equation index = value'");
      const std::optional<unsigned long> index =
        parse_count(text.substr(0, equals), std::numeric_limits<unsigned int>::max());
      const std::vector<double> value = finite_numbers(input, path, text.substr(equals + 1));
      if (!index || value.size() != 1)
        input.fail(path, "'" + trimmed(text) +
                           "' is not 'equation index = value' (index an integer >= 0)");
      return {static_cast<long>(*index), value[0]};
    }

    /// Building b of a name or a 1-based number.
    unsigned int
    building_of(const InputFile &input, const std::string &path, const Model &model,
                const std::string &text)
    {
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        if (model.buildings[b].name == text || std::to_string(b + 1) == text)
          return b;
      input.fail(path, "there is no building '" + text + "' (the model has " +
                         std::to_string(model.buildings.size()) +
                         "; give a building's name or number)");
    }

    /// Sets ux of every node of every floor the entries name; a building
    /// named twice (by name or number) is refused: one of the two would
    /// silently win.
    void
    set_floors(const InputFile &input, const std::string &entry, const Model &model,
               const std::vector<std::string> &entries, Vector &x)
    {
      const std::string        path = section + entry;
      std::vector<std::string> given(model.buildings.size());
      for (const std::string &text : entries)
        {
          const FloorEntry   e     = floor_entry(input, path, text);
          const unsigned int b     = building_of(input, path, model, e.building);
          if (!given[b].empty())
            input.fail(path, "building '" + model.buildings[b].name + "' is given twice ('" +
                               given[b] + "' and '" + trimmed(text) + "'): give it once");
          given[b] = trimmed(text);
          const auto        &floor = model.buildings[b].floors;
          if (!e.uniform && e.values.size() != floor.size())
            input.fail(path, "building '" + model.buildings[b].name + "' has " +
                               std::to_string(floor.size()) + " floors, " +
                               std::to_string(e.values.size()) + " values are given ('" +
                               trimmed(text) + "'; 'all value' sets every floor)");
          for (unsigned int f = 0; f < floor.size(); ++f)
            for (const unsigned int node : floor[f].nodes)
              if (const int eq = model.equation(Model::dof(node, Component::ux)); eq >= 0)
                x[eq] = e.uniform ? e.values[0] : e.values[f];
        }
    }

    void
    set_equations(const InputFile &input, const std::string &entry, const Model &model,
                  const std::vector<std::string> &entries, Vector &x)
    {
      const std::string path = section + entry;
      std::vector<bool> given(model.n_equations(), false);
      for (const std::string &text : entries)
        {
          const auto [index, value] = equation_entry(input, path, text);
          if (index >= long(model.n_equations()))
            input.fail(path, "there is no equation " + std::to_string(index) +
                               ": the model has " + std::to_string(model.n_equations()) +
                               " (numbered from 0)");
          if (given[index])
            input.fail(path, "equation " + std::to_string(index) +
                               " is given twice: give it once");
          given[index] = true;
          x[index]     = value;
        }
    }
  } // namespace

  void
  InitialConditionParameters::declare(dealii::ParameterHandler &prm)
  {
    const auto list = Patterns::List(Patterns::Anything(), 0, 100000, ";");
    prm.enter_subsection("Initial conditions");
    prm.add_parameter("Floor displacements", floor_displacements,
                      "Displacement at t = 0 of the floors of buildings, relative to the "
                      "ground: 'building: u1 u2 ... uN' (a value per floor, bottom to top; "
                      "ux of every node of the floor) or 'building: all u' (every floor), "
                      "building by name or number, ';' between buildings. Empty: at rest. "
                      "Unit: m.",
                      list);
    prm.add_parameter("Floor velocities", floor_velocities,
                      "Velocity at t = 0 of the floors, as Floor displacements. Unit: m/s.",
                      list);
    prm.add_parameter("Equation displacements", equation_displacements,
                      "Displacement at t = 0 of single equations (free DOFs, numbered from 0 "
                      "building by building; a shear building's floors bottom to top): "
                      "'index = value', ';' between them; applied after Floor displacements. "
                      "Unit: m (rad on a rotation).",
                      list);
    prm.add_parameter("Equation velocities", equation_velocities,
                      "Velocity at t = 0 of single equations, as Equation displacements. "
                      "Unit: m/s (rad/s on a rotation).",
                      list);
    prm.add_parameter("State", state,
                      "The whole state at t = 0, y0 = [u0; v0]: the displacement of every "
                      "equation, then its velocity (2 values per equation; e.g. '3, 0' for "
                      "an oscillator). Not with the other entries. Unit: per field.");
    prm.leave_subsection();
  }

  void
  InitialConditionParameters::finalize(const InputFile &input) const
  {
    for (const double x : state)
      if (!std::isfinite(x))
        input.fail(section + "State", "every value must be finite, got " + number_text(x));
      else
        input.at_most(section + "State", x, largest_initial_value, "", initial_value_why);
    if (!state.empty() && !(floor_displacements.empty() && floor_velocities.empty() &&
                            equation_displacements.empty() && equation_velocities.empty()))
      input.fail(section + "State",
                 "gives the whole state: leave the Floor and Equation entries empty");
    for (const auto &[entry, texts] :
         {std::pair{"Floor displacements", &floor_displacements},
          std::pair{"Floor velocities", &floor_velocities}})
      for (const std::string &text : *texts)
        floor_entry(input, section + entry, text);
    for (const auto &[entry, texts] :
         {std::pair{"Equation displacements", &equation_displacements},
          std::pair{"Equation velocities", &equation_velocities}})
      for (const std::string &text : *texts)
        equation_entry(input, section + entry, text);
  }

  bool
  InitialConditionParameters::at_rest() const
  {
    return state.empty() && floor_displacements.empty() && floor_velocities.empty() &&
           equation_displacements.empty() && equation_velocities.empty();
  }

  InitialState
  initial_state(const InitialConditionParameters &parameters, const Model &model,
                const InputFile &input)
  {
    const unsigned int n = model.n_equations();
    InitialState       s{Vector::Zero(n), Vector::Zero(n)};
    if (!parameters.state.empty())
      {
        if (parameters.state.size() != 2 * n)
          input.fail(section + "State",
                     "needs 2 x " + std::to_string(n) + " = " + std::to_string(2 * n) +
                       " values (the displacement, then the velocity, of each of the model's " +
                       std::to_string(n) + " equations), got " +
                       std::to_string(parameters.state.size()));
        for (unsigned int i = 0; i < n; ++i)
          {
            s.displacement[i] = parameters.state[i];
            s.velocity[i]     = parameters.state[n + i];
          }
        return s;
      }
    set_floors(input, "Floor displacements", model, parameters.floor_displacements,
               s.displacement);
    set_floors(input, "Floor velocities", model, parameters.floor_velocities, s.velocity);
    set_equations(input, "Equation displacements", model, parameters.equation_displacements,
                  s.displacement);
    set_equations(input, "Equation velocities", model, parameters.equation_velocities,
                  s.velocity);
    return s;
  }
} // namespace poundfe
