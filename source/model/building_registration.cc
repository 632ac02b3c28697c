// The parameters of a building's storeys and floors (model/parameter_registry.h):
//   Building b/Storey stiffnesses[i]   k of storey i (K; C through Rayleigh); of a 3D
//                                      shear building: k/2 on each of the default
//                                      four planes of storey i
//   Building b/Storey damping[i]       storey dashpot c (C)
//   Building b/Storey yield drifts[i]  Bouc-Wen u_y of storey i (3D: of its four planes)
//   Building b/Plan/Resisting planes/k[i], u_y[i]
//                                      k, u_y of typed plane i of a 3D shear building,
//                                      in every storey (K; nonlinear)
//   Building b/Floor masses[i]         mass of floor i, in equal shares at its joints
//                                      (M; K_G under P-Delta; modes, Rayleigh and modal
//                                      C; the gaps' effective masses m1 m2/(m1 + m2));
//                                      in 3D also the floor's polar moment
//                                      J = m (L_x^2 + L_y^2)/12 when Plan/Polar moments
//                                      is not given, and a 3D frame's vertical masses
//   Building b/Plan/Polar moments[i]   the typed polar moment of floor i of a 3D
//                                      building with rigid slabs (M)
// each written where the model builder (model_builder.cc, plan_builder.cc's
// storey_planes and add_plane_links, floor_mass.cc) puts it.
#include <poundfe/model/floor_mass.h>
#include <poundfe/model/parameter_registry.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace poundfe::building_registration
{
  namespace
  {
    const ModelParameter::Range positive{0, false, std::numeric_limits<double>::infinity()};
    const ModelParameter::Range non_negative{0, true, std::numeric_limits<double>::infinity()};

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

    /// Indices in model.links of the storeys `p` names (all, or one; none
    /// of a 3D shear building, whose storeys are planes: named_planes).
    std::vector<unsigned int>
    named_storeys(const ModelParameter &p, const Model &model)
    {
      const std::vector<unsigned int> all = storeys_of(model, p.building);
      return p.entry < 0 || all.empty() ? all : std::vector<unsigned int>{all.at(p.entry)};
    }

    /// The resisting planes of building b (a 3D shear building) `p` names:
    /// those of its storey (`by_plane` false) or its typed plane in every
    /// storey; all when p.entry < 0 (of a const model: read only).
    template <typename ModelType>
    auto
    named_planes(const ModelParameter &p, ModelType &model, const bool by_plane = false)
    {
      std::vector<decltype(&model.plane_links.front())> result;
      for (auto &link : model.plane_links)
        {
          const unsigned int index = by_plane ? link.plane : link.storey;
          if (link.building == p.building && (p.entry < 0 || int(index) == p.entry + 1))
            result.push_back(&link);
        }
      return result;
    }

    bool
    has_planes(const ModelParameter &p, const Model &model)
    {
      return std::any_of(model.plane_links.begin(), model.plane_links.end(),
                         [&](const PlaneLink &l) { return l.building == p.building; });
    }

    /// A storey entry of a 3D shear building whose planes are the default
    /// four per storey (Plan/Resisting planes not typed): k/2 on each plane
    /// (plan_builder.cc's storey_planes), u_y of each; it has no storey dashpots.
    void
    check_plane_storeys(const ModelParameter &p, const Model &model, const bool damping,
                        const bool yield)
    {
      const Building &building = model.buildings[p.building];
      if (damping)
        refuse_parameter(p, ": building '" + building.name +
                              "' is a 3D shear building, whose storeys have no dashpots");
      if (!p.inputs)
        refuse_parameter(p, " needs the input the model was built from (whether its "
                            "resisting planes are typed)");
      if (!p.inputs->model.buildings[p.building].plan.planes.empty())
        refuse_parameter(p, ": building '" + building.name +
                              "' has its Plan/Resisting planes typed (each with its k "
                              "and u_y), which the storey entries do not set (vary "
                              "Plan/Resisting planes/k[i] or u_y[i])");
      if (p.entry >= int(building.floors.size()))
        refuse_parameter(p, ": building '" + building.name + "' has storeys 1.." +
                              std::to_string(building.floors.size()));
      if (yield)
        for (const PlaneLink *link : named_planes(p, model))
          if (!link->hysteretic)
            refuse_parameter(p, ": a storey of building '" + building.name +
                                  "' is elastic (no yield drift in the input)");
    }

    /// The checks of a storey entry (`damping`: Storey damping, `yield`:
    /// Storey yield drifts).
    void
    check_storeys(const ModelParameter &p, const Model &model, const bool damping,
                  const bool yield)
    {
      if (has_planes(p, model))
        return check_plane_storeys(p, model, damping, yield);
      const std::string &name    = model.buildings[p.building].name;
      const auto         storeys = storeys_of(model, p.building);
      if (storeys.empty())
        refuse_parameter(p, ": building '" + name + "' is not a shear building (no storey "
                              "springs)");
      if (p.entry >= int(storeys.size()))
        refuse_parameter(p, ": building '" + name + "' has storeys 1.." +
                              std::to_string(storeys.size()));
      if (yield)
        for (const unsigned int l : named_storeys(p, model))
          if (!model.links[l].hysteretic)
            refuse_parameter(p, ": a storey of building '" + name +
                                  "' is elastic (no yield drift in the input)");
    }

    ParameterRegistration
    storey_entry(const std::string &name, const ModelParameter::Range range,
                 const unsigned int touches)
    {
      ParameterRegistration r;
      r.name        = name;
      r.of_building = true;
      r.takes_index = true;
      r.range       = range;
      r.touches     = touches;
      const bool damping = name == "Storey damping", yield = name == "Storey yield drifts";
      r.resolve = [damping, yield](ModelParameter &p, const Model &model) {
        check_storeys(p, model, damping, yield);
      };
      return r;
    }

    /// "Plan/Resisting planes/FIELD[i]" of a 3D shear building whose planes
    /// are typed: FIELD k or u_y of plane i (as listed) in every storey
    /// (plan_builder.cc's storey_planes gives each storey the typed list).
    void
    check_resisting_planes(const ModelParameter &p, const Model &model, const bool yield)
    {
      const Building &building = model.buildings[p.building];
      if (!has_planes(p, model))
        refuse_parameter(p, ": building '" + building.name +
                              "' is not a 3D shear building (no resisting planes)");
      if (!p.inputs)
        refuse_parameter(p, " needs the input the model was built from (whether its "
                            "resisting planes are typed)");
      const std::size_t n = p.inputs->model.buildings[p.building].plan.planes.size();
      if (n == 0)
        refuse_parameter(p, ": building '" + building.name + "' has no typed Plan/Resisting "
                              "planes: its default four planes per storey follow Storey "
                              "stiffnesses and Storey yield drifts (vary those)");
      if (p.entry >= int(n))
        refuse_parameter(p, ": building '" + building.name + "' has resisting planes 1.." +
                              std::to_string(n));
      if (yield)
        for (const PlaneLink *link : named_planes(p, model, true))
          if (!link->hysteretic)
            refuse_parameter(p, ": plane " + std::to_string(link->plane) + " of building '" +
                                  building.name + "' is elastic (no u_y in the input)");
    }

    /// Entries that place nodes: the model's geometry, which a realization
    /// does not move.
    const std::vector<std::string> geometry_entries = {
      "Storey heights", "Bay widths", "Number of storeys", "Number of bays",
      "Elements per member", "Drawing width", "Bay widths y", "Number of bays y",
      "Set-backs", "Column angle", "Diaphragm", "Mesh file", "Group ids",
      "Plan/Plan dimensions", "Plan/Position", "Plan/Rotation", "Plan/Mass eccentricity",
      "Plan/Accidental eccentricity", "Plan/Accidental eccentricity ratio",
      "Plan/Resisting planes"};

    void
    explain_geometry(const ModelParameter &p, const std::string &entry, const bool of_building,
                     bool, const Model &)
    {
      if (!of_building)
        return;
      if (std::find(geometry_entries.begin(), geometry_entries.end(), entry) !=
          geometry_entries.end())
        refuse_parameter(p, " is the model's geometry (where its nodes are), which a "
                            "realization does not move; vary a stiffness or a mass instead");
      const std::string planes = "Plan/Resisting planes/";
      if (entry.rfind(planes, 0) != 0)
        return;
      const std::string field = entry.substr(planes.size());
      if (field == "x" || field == "y" || field == "angle")
        refuse_parameter(p, " is the model's geometry (where the plane acts), which a "
                            "realization does not move; vary k or u_y");
      refuse_parameter(p, ": name a field of the typed planes, "
                          "'Plan/Resisting planes/FIELD[i]' with FIELD one of k, u_y");
    }

    void
    storeys(ParameterRegistry &registry)
    {
      ParameterRegistration k = storey_entry("Storey stiffnesses", positive, ModelParameter::stiffness);
      k.get = [](const ModelParameter &p, const Model &model) {
        if (!model.plane_links.empty() && !named_planes(p, model).empty()) // 3D: k/2 a plane
          return 2 * named_planes(p, model).front()->stiffness;
        return model.links[named_storeys(p, model).front()].stiffness;
      };
      k.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        for (const unsigned int l : named_storeys(p, model))
          model.links[l].stiffness = model.links[l].hysteresis.stiffness = value;
        for (PlaneLink *plane : named_planes(p, model)) // 3D: four planes, k/2 each
          plane->stiffness = plane->hysteresis.stiffness = 0.5 * value;
      };
      registry.add(k);

      ParameterRegistration c = storey_entry("Storey damping", non_negative, ModelParameter::damping);
      c.get = [](const ModelParameter &p, const Model &model) {
        return model.links[named_storeys(p, model).front()].damping;
      };
      c.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        for (const unsigned int l : named_storeys(p, model))
          model.links[l].damping = value;
      };
      registry.add(c);

      ParameterRegistration uy =
        storey_entry("Storey yield drifts", positive, ModelParameter::nonlinear_only);
      uy.get = [](const ModelParameter &p, const Model &model) {
        if (!model.plane_links.empty() && !named_planes(p, model).empty())
          return named_planes(p, model).front()->hysteresis.yield_deformation;
        return model.links[named_storeys(p, model).front()].hysteresis.yield_deformation;
      };
      uy.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        for (const unsigned int l : named_storeys(p, model))
          model.links[l].hysteresis.yield_deformation = value;
        for (PlaneLink *plane : named_planes(p, model))
          plane->hysteresis.yield_deformation = value;
      };
      registry.add(uy);
    }

    /// Plan/Resisting planes/k and u_y, as add_plane_links sets a typed plane.
    void
    resisting_planes(ParameterRegistry &registry)
    {
      for (const bool yield : {false, true})
        {
          ParameterRegistration r;
          r.name        = yield ? "Plan/Resisting planes/u_y" : "Plan/Resisting planes/k";
          r.of_building = true;
          r.takes_index = true;
          r.family      = "Plan/Resisting planes";
          r.label       = "u_y";
          r.range       = positive;
          r.touches     = yield ? ModelParameter::nonlinear_only : ModelParameter::stiffness;
          r.resolve     = [yield](ModelParameter &p, const Model &model) {
            check_resisting_planes(p, model, yield);
          };
          r.get = [yield](const ModelParameter &p, const Model &model) {
            const PlaneLink &plane = *named_planes(p, model, true).front();
            return yield ? plane.hysteresis.yield_deformation : plane.stiffness;
          };
          r.set = [yield](const ModelParameter &p, const double value, Model &model,
                          ModelInputs &) {
            for (PlaneLink *plane : named_planes(p, model, true))
              if (yield)
                plane->hysteresis.yield_deformation = value;
              else
                plane->stiffness = plane->hysteresis.stiffness = value;
          };
          registry.add(r);
        }
      registry.add_explanation(explain_geometry);
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

    /// The effective mass of `gap` as the builder sets it from the floors'
    /// masses: m1 m2/(m1 + m2) of the two floor nodes of a contact in plan
    /// (model/plan_builder.cc), floor_effective_mass otherwise.
    double
    builder_effective_mass(const Model &model, const Gap &gap)
    {
      if (!gap.in_plan)
        return floor_effective_mass(model, gap);
      std::array<double, 2> m{{0, 0}};
      for (unsigned int k = 0; k < 2; ++k)
        for (const NodalMass &mass : model.masses)
          if (int(mass.node) == gap.nodes[k])
            m[k] += mass.mass;
      return m[0] * m[1] / (m[0] + m[1]);
    }

    /// The vertical masses (DofMass) of the joints of a 3D frame's floor:
    /// on the joints' (uz, rx, ry) nodes of building b at the floor's level.
    std::vector<DofMass *>
    joint_vertical_masses(Model &model, const unsigned int b, const Floor &floor)
    {
      std::vector<DofMass *> result;
      for (DofMass &m : model.dof_masses)
        {
          const Node &node = model.nodes[m.dof / n_dofs_per_node];
          if (node.joint_translation_z && node.building == b &&
              std::abs(node.position.y - floor.level) <= 1e-9 * std::max(1.0, std::abs(floor.level)))
            result.push_back(&m);
        }
      return result;
    }

    /// Shares m / n_joints of a floor mass at each floor's joints, as the
    /// model builder lumps it (every joint has its NodalMass: check_floors);
    /// a 3D floor's polar moment J = m c (c = (L_x^2 + L_y^2)/12 unless
    /// Plan/Polar moments is given) keeps its c, and a 3D frame's joints
    /// their vertical masses m / n_joints. Sets again the effective mass of
    /// each gap whose m_e is of the floors' masses (one equal to what the
    /// builder computes to the last bit: Contact/Effective mass not given,
    /// or given equal to it), as the builder does.
    void
    write_floor_masses(const ModelParameter &p, const double value, Model &model)
    {
      const bool polar_follows =
        !p.inputs || p.inputs->model.buildings[p.building].plan.polar_moments.empty();
      std::vector<bool> of_floors;
      for (const Gap &gap : model.gaps)
        of_floors.push_back(gap.effective_mass == builder_effective_mass(model, gap));
      for (const Floor *floor : named_floors(p, model))
        {
          const double before = floor_mass(model, *floor);
          for (NodalMass &m : model.masses)
            if (std::find(floor->nodes.begin(), floor->nodes.end(), m.node) != floor->nodes.end())
              {
                m.mass = value / floor->nodes.size();
                if (polar_follows)
                  m.polar_moment = m.polar_moment / before * value;
              }
          const std::vector<DofMass *> vertical = joint_vertical_masses(model, p.building, *floor);
          for (DofMass *m : vertical)
            m->mass = value / vertical.size();
        }
      for (unsigned int g = 0; g < model.gaps.size(); ++g)
        if (of_floors[g])
          model.gaps[g].effective_mass = builder_effective_mass(model, model.gaps[g]);
      if (!model.gaps.empty()) // as the builder: the law's default
        model.contact.effective_mass = model.gaps.front().effective_mass;
    }

    /// Whether the floors `p` names can take a set mass: a mass at every
    /// joint; in 3D the input (whether Plan/Polar moments is typed).
    void
    check_floors(const ModelParameter &p, const Model &model)
    {
      const Building &building = model.buildings[p.building];
      if (p.entry >= int(building.floors.size()))
        refuse_parameter(p, ": building '" + building.name + "' has floors 1.." +
                              std::to_string(building.floors.size()));
      if (model.dimension != 2 && !p.inputs)
        refuse_parameter(p, ": a 3D floor mass needs the input the model was built from "
                            "(its polar moment follows it)");
      for (const Floor *floor : named_floors(p, model))
        for (const unsigned int node : floor->nodes)
          if (std::none_of(model.masses.begin(), model.masses.end(),
                           [node](const NodalMass &m) { return m.node == node; }))
            refuse_parameter(p, ": a floor of building '" + building.name +
                                  "' has no floor mass in the input");
    }

    /// "Plan/Polar moments[i]" of a 3D building whose input types them (a
    /// polar moment not typed follows its floor's mass, as Floor masses
    /// does), on a rigid slab (one node per floor carries its mass).
    void
    check_polar_moments(const ModelParameter &p, const Model &model)
    {
      const Building &building = model.buildings[p.building];
      if (model.dimension != 3)
        refuse_parameter(p, " is an entry of a 3D building (Model/Dimension = 3)");
      if (!p.inputs)
        refuse_parameter(p, " needs the input the model was built from (whether its polar "
                            "moments are typed)");
      if (p.inputs->model.buildings[p.building].plan.polar_moments.empty())
        refuse_parameter(p, ": building '" + building.name + "' has no Plan/Polar moments: "
                            "its floors' polar moments follow their masses (vary Floor "
                            "masses, or type Plan/Polar moments to make them random)");
      check_floors(p, model);
      for (const Floor *floor : named_floors(p, model))
        if (floor->nodes.size() != 1)
          refuse_parameter(p, ": building '" + building.name +
                                "' has no rigid slabs (Diaphragm = none): each joint "
                                "carries its share of the floor mass, no polar moment");
    }

    void
    floors(ParameterRegistry &registry)
    {
      ParameterRegistration m;
      m.name        = "Floor masses";
      m.of_building = true;
      m.takes_index = true;
      m.range       = positive;
      m.touches     = ModelParameter::mass;
      m.resolve     = check_floors;
      m.get         = [](const ModelParameter &p, const Model &model) {
        return floor_mass(model, *named_floors(p, model).front());
      };
      m.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        write_floor_masses(p, value, model);
      };
      m.follow_up = refit_contact_damping; // the gaps' effective masses changed
      registry.add(m);

      ParameterRegistration j;
      j.name        = "Plan/Polar moments";
      j.of_building = true;
      j.takes_index = true;
      j.range       = positive;
      j.touches     = ModelParameter::mass;
      j.resolve     = check_polar_moments;
      j.get         = [](const ModelParameter &p, const Model &model) {
        for (const NodalMass &mass : model.masses)
          if (mass.node == named_floors(p, model).front()->nodes.front())
            return mass.polar_moment;
        return 0.0;
      };
      j.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        for (const Floor *floor : named_floors(p, model))
          for (NodalMass &mass : model.masses)
            if (mass.node == floor->nodes.front()) // the slab's node (check_polar_moments)
              mass.polar_moment = value;
      };
      registry.add(j);
    }
  } // namespace
} // namespace poundfe::building_registration

namespace poundfe
{
  void
  register_storey_parameters(ParameterRegistry &registry)
  {
    building_registration::storeys(registry);
    building_registration::resisting_planes(registry);
  }

  void
  register_floor_parameters(ParameterRegistry &registry)
  {
    building_registration::floors(registry);
  }
} // namespace poundfe
