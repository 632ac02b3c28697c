// The map from an input entry's path to the built model's numbers
// (dynamics/model_parameter.h), and the realization of a model with
// sampled parameters: each value is written where the model builder
// (model/model_builder.cc) put the entry's value, so a realization equals
// the model built from a file with that value (tests/dynamics/
// test_model_parameters.cc checks exactly that).
#include <poundfe/dynamics/model_parameter.h>
#include <poundfe/dynamics/modal_damping_assembly.h>
#include <poundfe/model/floor_mass.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <stdexcept>

namespace poundfe
{
  namespace
  {
    using Kind = ModelParameter::Kind;

    const std::string known_paths =
      "Building b/Storey stiffnesses[i], Building b/Storey damping[i], Building b/Storey yield "
      "drifts[i], Building b/Hinges/Yield moment, Building b/Damping/Damping ratio, "
      "Building b/Floor masses[i], Model/Separations[i], Contact/Stiffness, Contact/Damping, Friction/Static coefficient, "
      "Friction/Kinetic coefficient, Links/Viscous dampers[i]";

    /// Indices in model.links of the storeys of building b, bottom to top.
    std::vector<unsigned int>
    storeys_of(const Model &model, const unsigned int b)
    {
      std::vector<unsigned int> result;
      for (unsigned int l = 0; l < model.links.size(); ++l)
        if (model.links[l].building == b)
          result.push_back(l);
      return result;
    }

    /// Indices in model.gaps of the gaps between building b and b + 1 (not barriers).
    std::vector<unsigned int>
    gaps_after(const Model &model, const unsigned int b)
    {
      std::vector<unsigned int> result;
      for (unsigned int g = 0; g < model.gaps.size(); ++g)
        {
          const Gap &gap = model.gaps[g];
          if (gap.nodes[0] >= 0 && gap.nodes[1] >= 0 && gap.buildings[0] == b)
            result.push_back(g);
        }
      return result;
    }

    /// Indices in model.building_links of the viscous dampers.
    std::vector<unsigned int>
    viscous_dampers(const Model &model)
    {
      std::vector<unsigned int> result;
      for (unsigned int l = 0; l < model.building_links.size(); ++l)
        if (model.building_links[l].law.kind == LinkKind::viscous)
          result.push_back(l);
      return result;
    }

    /// Indices in model.building_links of the dampers `p` names (all, or one).
    std::vector<unsigned int>
    named_dampers(const ModelParameter &p, const Model &model)
    {
      const std::vector<unsigned int> all = viscous_dampers(model);
      return p.entry < 0 ? all : std::vector<unsigned int>{all.at(p.entry)};
    }

    /// Indices in model.links of the storeys `p` names (all, or one).
    std::vector<unsigned int>
    named_storeys(const ModelParameter &p, const Model &model)
    {
      const std::vector<unsigned int> all = storeys_of(model, p.building);
      return p.entry < 0 ? all : std::vector<unsigned int>{all.at(p.entry)};
    }

    /// Floors of building b that `p` names (all, or one).
    std::vector<const Floor *>
    named_floors(const ModelParameter &p, const Model &model)
    {
      const std::vector<Floor> &floors = model.buildings[p.building].floors;
      if (p.entry >= 0)
        return {&floors.at(p.entry)};
      std::vector<const Floor *> result;
      for (const Floor &f : floors)
        result.push_back(&f);
      return result;
    }

    /// Shares m / n_joints of a floor mass at each floor's joints, as the
    /// model builder lumps it (every joint has its NodalMass:
    /// model_parameter() checks it), and sets again the effective mass of
    /// each gap whose m_e is of the floors' masses (one equal to
    /// floor_effective_mass to the last bit: Contact/Effective mass not
    /// given, or given equal to it), as the builder does.
    void
    write_floor_masses(const ModelParameter &p, const double value, Model &model)
    {
      std::vector<bool> of_floors;
      for (const Gap &gap : model.gaps)
        of_floors.push_back(!gap.in_plan && gap.effective_mass == floor_effective_mass(model, gap));
      for (const Floor *floor : named_floors(p, model))
        for (NodalMass &m : model.masses)
          if (std::find(floor->nodes.begin(), floor->nodes.end(), m.node) != floor->nodes.end())
            m.mass = value / floor->nodes.size();
      for (unsigned int g = 0; g < model.gaps.size(); ++g)
        if (of_floors[g])
          model.gaps[g].effective_mass = floor_effective_mass(model, model.gaps[g]);
      if (!model.gaps.empty()) // as the builder: the law's default
        model.contact.effective_mass = model.gaps.front().effective_mass;
    }

    void
    require_in_range(const ModelParameter &p, const double value)
    {
      const bool zero_allowed = p.can_be_zero();
      if (!(zero_allowed ? value >= 0 : value > 0) || !std::isfinite(value))
        throw std::invalid_argument("'" + p.path + "' cannot take the sampled value " +
                                    std::to_string(value) + " (it must be " +
                                    (zero_allowed ? ">= 0" : "> 0") +
                                    "; choose a distribution that stays in range, e.g. "
                                    "lognormal or truncated normal)");
    }

    /// Writes `value` into the model; the checks of model_parameter() hold.
    void
    write(const ModelParameter &p, const double value, Model &model)
    {
      switch (p.kind)
        {
          case Kind::storey_stiffness:
            require_in_range(p, value);
            for (const unsigned int l : named_storeys(p, model))
              model.links[l].stiffness = model.links[l].hysteresis.stiffness = value;
            return;
          case Kind::storey_damping:
            require_in_range(p, value);
            for (const unsigned int l : named_storeys(p, model))
              model.links[l].damping = value;
            return;
          case Kind::storey_yield_drift:
            require_in_range(p, value);
            for (const unsigned int l : named_storeys(p, model))
              model.links[l].hysteresis.yield_deformation = value;
            return;
          case Kind::floor_mass:
            require_in_range(p, value);
            write_floor_masses(p, value, model);
            return;
          case Kind::hinge_yield_moment:
            require_in_range(p, value);
            for (Hinge &hinge : model.hinges)
              if (hinge.building == p.building)
                hinge.law.yield_deformation = value / hinge.law.stiffness;
            return;
          case Kind::damping_ratio:
            require_in_range(p, value);
            model.buildings[p.building].damping.damping_ratio = value;
            return;
          case Kind::separation:
            require_in_range(p, value);
            for (const unsigned int g : gaps_after(model, p.building))
              model.gaps[g].initial_gap = value;
            return;
          case Kind::contact_stiffness:
            require_in_range(p, value);
            model.contact.stiffness = value;
            return;
          case Kind::contact_damping:
            require_in_range(p, value);
            model.contact.damping = value;
            return;
          case Kind::static_friction:
          case Kind::kinetic_friction:
            require_in_range(p, value);
            for (FrictionSurface &surface : model.friction_surfaces)
              (p.kind == Kind::static_friction ? surface.law.static_coefficient :
                                                 surface.law.kinetic_coefficient) = value;
            return;
          case Kind::link_damping:
            require_in_range(p, value);
            for (const unsigned int l : named_dampers(p, model))
              model.building_links[l].law.damping = value;
            return;
        }
    }

    /// Building b of "Building b/..." (0-based), checked against the model.
    unsigned int
    building_index(const std::string &path, const std::string &number, const Model &model)
    {
      const unsigned long b = std::stoul(number);
      if (b < 1 || b > model.buildings.size())
        throw std::invalid_argument("'" + path + "': the model has buildings 1.." +
                                    std::to_string(model.buildings.size()));
      return b - 1;
    }

    /// Whether the floors `p` names can take a sampled mass: a 2D model (a
    /// 3D floor has a polar moment too), no friction surfaces (their stick
    /// damping is fitted to the mass once), a mass at every joint.
    void
    check_floor_masses(const ModelParameter &p, const Model &model)
    {
      const Building &building = model.buildings[p.building];
      if (p.entry >= int(building.floors.size()))
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' has floors 1.." + std::to_string(building.floors.size()));
      if (model.dimension != 2)
        throw std::invalid_argument("'" + p.path + "': random floor masses are for 2D models "
                                    "(a 3D floor has a polar moment of inertia too)");
      if (!model.friction_surfaces.empty())
        throw std::invalid_argument("'" + p.path + "': random floor masses are not available "
                                    "with friction surfaces (their stick damping is fitted to "
                                    "the mass once)");
      for (const Floor *floor : named_floors(p, model))
        for (const unsigned int node : floor->nodes)
          if (std::none_of(model.masses.begin(), model.masses.end(),
                           [node](const NodalMass &m) { return m.node == node; }))
            throw std::invalid_argument("'" + p.path + "': a floor of building '" +
                                        building.name + "' has no floor mass in the input");
    }

    /// The parameter of a "Building b/ENTRY" path.
    ModelParameter
    building_parameter(ModelParameter p, const std::string &entry, const bool indexed,
                       const Model &model)
    {
      const std::string &name    = model.buildings[p.building].name;
      const auto         storeys = storeys_of(model, p.building);
      if (entry == "Storey stiffnesses" || entry == "Storey damping" ||
          entry == "Storey yield drifts")
        {
          p.kind = entry == "Storey stiffnesses" ? Kind::storey_stiffness :
                   entry == "Storey damping"     ? Kind::storey_damping :
                                                   Kind::storey_yield_drift;
          if (storeys.empty())
            throw std::invalid_argument("'" + p.path + "': building '" + name +
                                        "' is not a shear building (no storey springs)");
          if (p.entry >= int(storeys.size()))
            throw std::invalid_argument("'" + p.path + "': building '" + name + "' has storeys 1.." +
                                        std::to_string(storeys.size()));
          if (p.kind == Kind::storey_yield_drift)
            for (const unsigned int l : named_storeys(p, model))
              if (!model.links[l].hysteretic)
                throw std::invalid_argument("'" + p.path + "': a storey of building '" + name +
                                            "' is elastic (no yield drift in the input)");
          return p;
        }
      if (entry == "Floor masses")
        {
          p.kind = Kind::floor_mass;
          check_floor_masses(p, model);
          return p;
        }
      const bool scalar = entry == "Hinges/Yield moment" || entry == "Damping/Damping ratio";
      if (scalar && indexed)
        throw std::invalid_argument("'" + p.path + "': '" + entry + "' takes no [entry]");
      if (entry == "Hinges/Yield moment")
        {
          p.kind = Kind::hinge_yield_moment;
          if (std::none_of(model.hinges.begin(), model.hinges.end(),
                           [&](const Hinge &h) { return h.building == p.building; }))
            throw std::invalid_argument("'" + p.path + "': building '" + name + "' has no hinges");
          return p;
        }
      if (entry == "Damping/Damping ratio")
        {
          p.kind = Kind::damping_ratio;
          if (model.buildings[p.building].damping.kind != RayleighDamping::Kind::modes)
            throw std::invalid_argument("'" + p.path + "': building '" + name +
                                        "' has no Rayleigh damping fitted at modes "
                                        "(Damping/Type = modes)");
          return p;
        }
      throw std::invalid_argument("'" + p.path + "' is not a parameter poundfe can vary (" +
                                  known_paths + ")");
    }
  } // namespace

  bool
  ModelParameter::enters_linear_part() const
  {
    return kind == Kind::storey_stiffness || kind == Kind::storey_damping ||
           kind == Kind::damping_ratio || kind == Kind::floor_mass;
  }

  bool
  ModelParameter::can_be_zero() const
  {
    return kind == Kind::storey_damping || kind == Kind::separation ||
           kind == Kind::contact_damping || kind == Kind::static_friction ||
           kind == Kind::kinetic_friction || kind == Kind::link_damping;
  }

  ModelParameter
  model_parameter(const std::string &path, const Model &model)
  {
    static const std::regex with_entry(R"(^\s*(.*?)\s*\[\s*([0-9]+)\s*\]\s*$)");
    static const std::regex building(R"(^Building ([0-9]+)/(.+)$)");
    ModelParameter p;
    p.path            = path;
    std::string entry = path;
    std::smatch match;
    const bool  indexed = std::regex_match(path, match, with_entry);
    if (indexed)
      {
        entry   = match[1];
        p.entry = std::stoi(match[2]) - 1;
        if (p.entry < 0)
          throw std::invalid_argument("'" + path + "': entries count from 1");
      }
    if (std::regex_match(entry, match, building))
      {
        p.building = building_index(path, match[1], model);
        return building_parameter(p, match[2], indexed, model);
      }
    const auto no_entry = [&]() {
      if (indexed)
        throw std::invalid_argument("'" + path + "': '" + entry + "' takes no [entry]");
    };
    if (entry == "Model/Separations")
      {
        p.kind     = Kind::separation;
        p.building = indexed ? p.entry : 0;
        if (p.building + 1 >= model.buildings.size() ||
            gaps_after(model, p.building).empty())
          throw std::invalid_argument("'" + path + "': no gaps between building " +
                                      std::to_string(p.building + 1) + " and " +
                                      std::to_string(p.building + 2));
        return p;
      }
    if (entry == "Contact/Stiffness" || entry == "Contact/Damping")
      {
        no_entry();
        p.kind = entry == "Contact/Stiffness" ? Kind::contact_stiffness : Kind::contact_damping;
        if (model.gaps.empty())
          throw std::invalid_argument("'" + path + "': the model has no contact (Contact/Law)");
        return p;
      }
    if (entry == "Friction/Static coefficient" || entry == "Friction/Kinetic coefficient")
      {
        no_entry();
        p.kind = entry == "Friction/Static coefficient" ? Kind::static_friction :
                                                          Kind::kinetic_friction;
        if (model.friction_surfaces.empty())
          throw std::invalid_argument("'" + path + "': the model has no friction surfaces");
        return p;
      }
    if (entry == "Links/Viscous dampers")
      {
        p.kind = Kind::link_damping;
        const std::size_t n = viscous_dampers(model).size();
        if (n == 0)
          throw std::invalid_argument("'" + path + "': the model has no viscous dampers "
                                      "(Links/Viscous dampers)");
        if (p.entry >= int(n))
          throw std::invalid_argument("'" + path + "': the model has viscous dampers 1.." +
                                      std::to_string(n));
        return p;
      }
    throw std::invalid_argument("'" + path + "' is not a parameter poundfe can vary (" +
                                known_paths + ")");
  }

  double
  model_parameter_value(const ModelParameter &p, const Model &model)
  {
    switch (p.kind)
      {
        case Kind::storey_stiffness:
          return model.links[named_storeys(p, model).front()].stiffness;
        case Kind::storey_damping:
          return model.links[named_storeys(p, model).front()].damping;
        case Kind::storey_yield_drift:
          return model.links[named_storeys(p, model).front()].hysteresis.yield_deformation;
        case Kind::floor_mass:
          return floor_mass(model, *named_floors(p, model).front());
        case Kind::hinge_yield_moment:
          for (const Hinge &h : model.hinges)
            if (h.building == p.building)
              return h.law.yield_deformation * h.law.stiffness;
          break;
        case Kind::damping_ratio:
          return model.buildings[p.building].damping.damping_ratio;
        case Kind::separation:
          return model.gaps[gaps_after(model, p.building).front()].initial_gap;
        case Kind::contact_stiffness:
          return model.contact.stiffness;
        case Kind::contact_damping:
          return model.contact.damping;
        case Kind::static_friction:
          return model.friction_surfaces.front().law.static_coefficient;
        case Kind::kinetic_friction:
          return model.friction_surfaces.front().law.kinetic_coefficient;
        case Kind::link_damping:
          return model.building_links[named_dampers(p, model).front()].law.damping;
      }
    return 0;
  }

  ModelRealization::ModelRealization(const Analysis &base, std::vector<ModelParameter> parameters,
                                     const Eigensolver eigensolver_)
    : working(base)
    , targets(std::move(parameters))
    , eigensolver(eigensolver_)
  {
    for (const ModelParameter &p : targets)
      linear = linear || p.enters_linear_part();
  }

  void
  ModelRealization::apply(const std::vector<double> &values)
  {
    AssertDimension(values.size(), targets.size());
    bool matrices_changed = false; // M or K: the modes change
    for (unsigned int i = 0; i < targets.size(); ++i)
      {
        write(targets[i], values[i], working.model);
        matrices_changed = matrices_changed || targets[i].kind == Kind::storey_stiffness ||
                           targets[i].kind == Kind::floor_mass;
      }
    if (linear)
      assemble_linear_part(matrices_changed);
  }

  void
  ModelRealization::assemble_linear_part(const bool matrices_changed)
  {
    const Model &model = working.model;
    if (matrices_changed)
      {
        // M and K as prepare_analysis assembles them (with P-Delta, K_G of
        // the unchanged gravity loads on the new K_E)
        LinearSystem fresh = assemble_mass_and_stiffness(model);
        working.system.mass                = std::move(fresh.mass);
        working.system.stiffness           = std::move(fresh.stiffness);
        working.system.geometric_stiffness = std::move(fresh.geometric_stiffness);
      }
    LinearSystem &system = working.system;
    std::vector<std::array<double, 2>> coefficients = system.rayleigh;
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const RayleighDamping &d = model.buildings[b].damping;
        if (d.kind != RayleighDamping::Kind::modes && !d.is_modal())
          continue;
        Modes &modes = working.building_modes[b];
        if (matrices_changed)
          {
            const auto range = model.equation_range(b);
            modes = compute_modes(block(system.mass, range), block(system.stiffness, range),
                                  system.influence.segment(range[0], range[1] - range[0]),
                                  modes.n_modes(), eigensolver);
          }
        if (d.kind == RayleighDamping::Kind::modes)
          coefficients[b] = rayleigh_coefficients(d.damping_ratio, modes.omega[d.first_mode - 1],
                                                  modes.omega[d.second_mode - 1]);
      }
    assemble_damping(model, coefficients, system);
    assemble_modal_damping(working); // modal buildings: from their new modes
  }
} // namespace poundfe
