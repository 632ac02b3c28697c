// Placing the `Springs` and `Friction` sections' elements at floor nodes.
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/model/model_builder.h>

#include <cmath>
#include <istream>
#include <sstream>
#include <vector>

namespace poundfe
{
  unsigned int
  read_building(const InputFile &input, const Model &model, const std::string &token,
                const std::string &path, const std::string &entry)
  {
    std::vector<std::string> names;
    for (const Building &b : model.buildings)
      names.push_back(b.name);
    return read_building(input, names, token, path, entry);
  }

  unsigned int
  read_building(const InputFile &input, const std::vector<std::string> &names,
                const std::string &token, const std::string &path, const std::string &entry)
  {
    const unsigned int n = names.size();
    if (const std::optional<unsigned long> number = parse_count(token, n))
      {
        if (*number >= 1)
          return *number - 1;
      }
    else if (!parse_number(token))
      {
        std::vector<unsigned int> named;
        for (unsigned int b = 0; b < n; ++b)
          if (names[b] == token)
            named.push_back(b);
        if (named.size() == 1)
          return named.front();
        if (named.size() > 1)
          throw InputError(input.file, input.line_of(path), path,
                           "'" + entry + "': buildings " + std::to_string(named[0] + 1) +
                             " and " + std::to_string(named[1] + 1) + " are both named '" +
                             token + "'; give the building's number");
      }
    std::string listed;
    for (unsigned int b = 0; b < n; ++b)
      listed += (b == 0 ? "'" : ", '") + names[b] + "'";
    throw InputError(input.file, input.line_of(path), path,
                     "'" + entry + "': building must be 1.." + std::to_string(n) +
                       " or a Name (" + listed + "), got '" + token + "'");
  }

  FloorNode
  read_floor_node(const InputFile &input, const Model &model, std::istream &fields,
                  const std::string &path, const std::string &entry, const std::string &form)
  {
    const int    line = input.line_of(path);
    std::string  building_field;
    unsigned int floor = 0, node = 0;
    if (!read_number(read_number(fields >> building_field, floor), node))
      throw InputError(input.file, line, path, "'" + entry + "': expected '" + form + "'");
    const unsigned int building = read_building(input, model, building_field, path, entry) + 1;
    const Building    &b        = model.buildings[building - 1];
    if (floor < 1 || floor > b.floors.size())
      throw InputError(input.file, line, path,
                       "'" + entry + "': floor must be 1.." + std::to_string(b.floors.size()) +
                         " (the base is supported)");
    const Floor &f = b.floors[floor - 1];
    if (node >= f.nodes.size())
      throw InputError(input.file, line, path,
                       "'" + entry + "': node must be 0.." + std::to_string(f.nodes.size() - 1));
    return {f.nodes[node], building - 1, floor, node,
            b.name + " floor " + std::to_string(floor) + " node " + std::to_string(node)};
  }

  namespace
  {
    bool
    blank(const std::string &entry)
    {
      return entry.find_first_not_of(" \t") == std::string::npos;
    }

    /// The node of 'building floor node ...' whose ux is free.
    FloorNode
    free_ux_node(const InputFile &input, const Model &model, std::istream &fields,
                 const std::string &path, const std::string &entry, const std::string &form)
    {
      const FloorNode at = read_floor_node(input, model, fields, path, entry, form);
      if (model.equation(Model::dof(at.node, Component::ux)) < 0)
        throw InputError(input.file, input.line_of(path), path,
                         "'" + entry + "': the node's ux is fixed");
      return at;
    }

    /// "<building>_F<floor>.<node>_<suffix>", e.g. "A3_F1.0_friction".
    std::string
    element_label(const Model &model, const FloorNode &at, const std::string &suffix)
    {
      return model.buildings[at.building].name + "_F" + std::to_string(at.floor) + "." +
             std::to_string(at.index) + "_" + suffix;
    }

    /// Reads the spring's numbers after the node; throws on a bad entry.
    void
    read_spring_law(const InputFile &input, std::istream &fields, const std::string &path,
                    const std::string &entry, SpringLawParameters &law)
    {
      const int   line = input.line_of(path);
      std::string rest;
      if (law.kind == SpringKind::sd)
        {
          if (!read_number(read_number(read_number(fields, law.stiffness), law.length),
                           law.height) ||
              (fields >> rest))
            throw InputError(input.file, line, path,
                             "'" + entry + "': expected 'building floor node K L H'");
          if (!(law.stiffness > 0 && law.length >= 0 && law.height >= 0) ||
              !std::isfinite(law.stiffness + law.length + law.height))
            throw InputError(input.file, line, path,
                             "'" + entry + "': K must be positive, L and H zero or positive");
          return;
        }
      if (!read_number(read_number(fields, law.stiffness), law.cubic) || (fields >> rest))
        throw InputError(input.file, line, path,
                         "'" + entry + "': expected 'building floor node k1 k3'");
      if (!(law.stiffness > 0) || !std::isfinite(law.stiffness + law.cubic))
        throw InputError(input.file, line, path,
                         "'" + entry + "': k1 must be positive and k3 finite");
    }
  } // namespace

  void
  add_springs(Model &model, const SpringParameters &springs, const InputFile &input)
  {
    for (const auto &[entries, kind] : {std::pair{&springs.sd, SpringKind::sd},
                                        std::pair{&springs.cubic, SpringKind::cubic}})
      {
        const std::string path = kind == SpringKind::sd ? "Springs/SD springs" : "Springs/Cubic springs";
        const std::string form = kind == SpringKind::sd ? "building floor node K L H" :
                                                          "building floor node k1 k3";
        for (const std::string &entry : *entries)
          {
            if (blank(entry))
              continue;
            std::istringstream fields(entry);
            const FloorNode    at = free_ux_node(input, model, fields, path, entry, form);
            Spring             spring;
            spring.node     = at.node;
            spring.building = at.building;
            spring.law.kind = kind;
            read_spring_law(input, fields, path, entry, spring.law);
            spring.label = element_label(model, at, kind == SpringKind::sd ? "sd" : "cubic");
            model.springs.push_back(spring);
          }
      }
  }

  void
  check_storeys_held(const Model &model, const InputFile &input)
  {
    std::vector<unsigned int> storey_of_building(model.buildings.size(), 0);
    for (const StoreyLink &link : model.links)
      {
        const unsigned int storey = ++storey_of_building[link.building];
        if (link.stiffness > 0)
          continue;
        bool held = false;
        for (const Spring &spring : model.springs)
          held = held || spring.node == link.nodes[1];
        const std::string path =
          "Building " + std::to_string(link.building + 1) + "/Storey stiffnesses";
        if (!held || link.hysteretic)
          input.fail(path, "storey " + std::to_string(storey) + " of '" +
                             model.buildings[link.building].name + "' has zero stiffness" +
                             (link.hysteretic ? " but yields (Bouc-Wen)" :
                                                " and no spring (Springs) holds its floor"));
      }
  }

  const Spring *
  sd_spring_at(const Model &model, const unsigned int node)
  {
    const Spring *sd = nullptr;
    for (const Spring &spring : model.springs)
      if (spring.node == node && spring.law.kind == SpringKind::sd)
        sd = &spring;
    return sd;
  }

  void
  take_sd_reaction(NormalForce &normal, const SpringLawParameters &sd)
  {
    normal.sd_reaction  = true;
    normal.sd_stiffness = sd.stiffness;
    normal.sd_length    = sd.length;
    normal.sd_height    = sd.height;
  }

  void
  add_friction_surfaces(Model &model, const FrictionParameters &friction, const InputFile &input)
  {
    const std::string path = "Friction/Surfaces";
    for (const std::string &entry : friction.surfaces)
      {
        if (blank(entry))
          continue;
        std::istringstream fields(entry);
        const FloorNode at = free_ux_node(input, model, fields, path, entry, "building floor node");
        std::string     rest;
        if (fields >> rest)
          throw InputError(input.file, input.line_of(path), path,
                           "'" + entry + "': expected 'building floor node'");
        FrictionSurface surface;
        surface.node     = at.node;
        surface.building = at.building;
        surface.law      = friction.law;
        surface.label    = element_label(model, at, "friction");
        if (friction.normal_force_from_sd_spring)
          {
            const Spring *sd = sd_spring_at(model, at.node);
            if (!sd)
              throw InputError(input.file, input.line_of("Friction/Normal force from SD spring"),
                               "Friction/Normal force from SD spring",
                               "'" + entry + "' has no SD spring at its node (Springs/SD springs)");
            take_sd_reaction(surface.law.normal, sd->law);
          }
        model.friction_surfaces.push_back(surface);
      }
  }
} // namespace poundfe
