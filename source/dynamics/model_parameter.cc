// The map from an input entry's path to the built model's numbers
// (dynamics/model_parameter.h), and the realization of a model with
// sampled parameters: each value is written where the model builder
// (model/model_builder.cc) put the entry's value, so a realization equals
// the model built from a file with that value (tests/dynamics/
// test_model_parameters.cc checks exactly that).
#include <poundfe/base/numbers.h>
#include <poundfe/dynamics/model_parameter.h>
#include <poundfe/model/plan_builder.h>
#include <poundfe/dynamics/modal_damping_assembly.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/model/floor_mass.h>
#include <poundfe/model/frame_foundation.h>
#include <poundfe/model/model_builder.h>
#include <poundfe/model/plan_foundation.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <regex>
#include <stdexcept>
#include <type_traits>

namespace poundfe
{
  namespace
  {
    using Kind = ModelParameter::Kind;

    const std::string known_paths =
      "Building b/Storey stiffnesses[i], Building b/Storey damping[i], Building b/Storey yield "
      "drifts[i], Building b/Hinges/Yield moment, Building b/Damping/Damping ratio, "
      "Building b/Floor masses[i], Model/Separations[i], Contact/Barriers/gap[i], "
      "Contact/Stiffness, Contact/Damping, Friction/Static coefficient, "
      "Friction/Kinetic coefficient, Links/Viscous dampers[i] (c), Links/LIST/FIELD[i] "
      "(Viscous dampers/c, alpha; Kelvin-Voigt links/k, c, alpha; Maxwell links/k, c; "
      "Elastic-plastic links/k, Fy, r; Soil coupling/k, c; Rocking soil coupling/k, c), "
      "Springs/SD springs/K[i] (L, H), Springs/Cubic springs/k1[i] (k3), Bumpers/Stiffness, "
      "Bumpers/Thickness, Building b/Column E[i] (A, I, "
      "mass per length), Building b/Beam E[i] (A, I, mass per length), Building b/Hinges/"
      "Stiffness, Building b/Hinges/Stiffness factor, Building b/Hinges/Yield rotation, "
      "Building b/Bouc-Wen/alpha (A, beta, gamma, n, delta A, delta nu, delta eta), "
      "Building b/Damping/a0, Building b/Damping/a1, Building b/Damping/Modal ratios[i], "
      "3D frames: Building b/Column E[i] (G, A, I, Iz, J, Avy, Avz, mass per length), Building "
      "b/Beam E[i] (the same), meshes: Building b/Group E[i] (A, I, mass per length; 3D: G, "
      "Iz, J too), 3D: Building b/Plan/Polar moments[i] (typed ones), Building "
      "b/Plan/Resisting planes/k[i] (u_y; typed ones), Building "
      "b/Foundation/ENTRY (Shear-wave velocity, Soil density, Poisson ratio, Length, Width, "
      "Embedment, Horizontal stiffness, Rocking stiffness, Vertical stiffness, their dampings, "
      "Mass, Rotary inertia; 3D: the y, x and torsional ones, Rotary inertia x, Polar inertia), "
      "Contact/Coefficient of restitution, Friction/Stribeck velocity (Belt velocity, Normal "
      "force, Normal force per displacement, per velocity, per velocity cubed, Stick stiffness, "
      "Regularization velocity)";

    const double infinity = std::numeric_limits<double>::infinity();

    /// The section entries of a 3D frame's columns and beams (I: Iy).
    const std::vector<std::pair<std::string, double Section3D::*>> section_3d_entries = {
      {"E", &Section3D::youngs_modulus},    {"G", &Section3D::shear_modulus},
      {"A", &Section3D::area},              {"I", &Section3D::second_moment_y},
      {"Iz", &Section3D::second_moment_z},  {"J", &Section3D::torsion_constant},
      {"Avy", &Section3D::shear_area_y},    {"Avz", &Section3D::shear_area_z},
      {"mass per length", &Section3D::mass_per_length}};

    /// A numeric entry of an input struct: its name, where it is, the
    /// values it can take.
    template <typename Struct>
    struct NumericEntry
    {
      const char *name;
      double &(*at)(Struct &);
      ModelParameter::Range range;
    };

    /// The entries of the Friction section a realization can vary besides
    /// the two coefficients.
    const std::vector<NumericEntry<FrictionLawParameters>> friction_entries = {
      {"Stribeck velocity", [](FrictionLawParameters &l) -> double & { return l.stribeck_velocity; },
       {0, true, infinity}},
      {"Belt velocity", [](FrictionLawParameters &l) -> double & { return l.belt_velocity; },
       {-maximum_belt_velocity, true, maximum_belt_velocity}},
      {"Normal force", [](FrictionLawParameters &l) -> double & { return l.normal.constant; },
       {0, true, infinity}},
      {"Normal force per displacement",
       [](FrictionLawParameters &l) -> double & { return l.normal.per_displacement; },
       {-infinity, true, infinity}},
      {"Normal force per velocity",
       [](FrictionLawParameters &l) -> double & { return l.normal.per_velocity; },
       {-infinity, true, infinity}},
      {"Normal force per velocity cubed",
       [](FrictionLawParameters &l) -> double & { return l.normal.per_velocity_cubed; },
       {-infinity, true, infinity}},
      {"Stick stiffness", [](FrictionLawParameters &l) -> double & { return l.stick_stiffness; },
       {0, false, infinity}},
      {"Regularization velocity",
       [](FrictionLawParameters &l) -> double & { return l.regularization_velocity; },
       {0, false, infinity}}};

    const ModelParameter::Range positive{0, false, infinity}, non_negative{0, true, infinity};

    /// A field of the entries of a `Links` or `Springs` list: the list, the
    /// field's name in the entries' form, where the builder puts it in the
    /// law (model/building_links.cc, model/springs_and_friction.cc) and the
    /// values it accepts there.
    struct ListField
    {
      const char                   *list;
      const char                   *name;
      double LinkLawParameters::*   link;
      double SpringLawParameters::* spring;
      ModelParameter::Range         range;
    };

    const ModelParameter::Range exponent_range{0, false, 1}, hardening_range{0, true, 1, false};
    const std::vector<ListField> list_fields = {
      // c = 0: a damper without force, the mitigation study's bare case
      {"Links/Viscous dampers", "c", &LinkLawParameters::damping, nullptr, non_negative},
      {"Links/Viscous dampers", "alpha", &LinkLawParameters::exponent, nullptr, exponent_range},
      {"Links/Kelvin-Voigt links", "k", &LinkLawParameters::stiffness, nullptr, non_negative},
      {"Links/Kelvin-Voigt links", "c", &LinkLawParameters::damping, nullptr, positive},
      {"Links/Kelvin-Voigt links", "alpha", &LinkLawParameters::exponent, nullptr, exponent_range},
      {"Links/Maxwell links", "k", &LinkLawParameters::stiffness, nullptr, positive},
      {"Links/Maxwell links", "c", &LinkLawParameters::damping, nullptr, positive},
      {"Links/Elastic-plastic links", "k", &LinkLawParameters::stiffness, nullptr, positive},
      {"Links/Elastic-plastic links", "Fy", &LinkLawParameters::yield_force, nullptr, positive},
      {"Links/Elastic-plastic links", "r", &LinkLawParameters::hardening, nullptr, hardening_range},
      {"Links/Soil coupling", "k", &LinkLawParameters::stiffness, nullptr, non_negative},
      {"Links/Soil coupling", "c", &LinkLawParameters::damping, nullptr, non_negative},
      {"Links/Rocking soil coupling", "k", &LinkLawParameters::stiffness, nullptr, non_negative},
      {"Links/Rocking soil coupling", "c", &LinkLawParameters::damping, nullptr, non_negative},
      {"Springs/SD springs", "K", nullptr, &SpringLawParameters::stiffness, positive},
      {"Springs/SD springs", "L", nullptr, &SpringLawParameters::length, non_negative},
      {"Springs/SD springs", "H", nullptr, &SpringLawParameters::height, non_negative},
      {"Springs/Cubic springs", "k1", nullptr, &SpringLawParameters::stiffness, positive},
      {"Springs/Cubic springs", "k3", nullptr, &SpringLawParameters::cubic,
       {-infinity, true, infinity}}};

    const ListField &
    list_field_of(const ModelParameter &p)
    {
      return *std::find_if(list_fields.begin(), list_fields.end(), [&p](const ListField &f) {
        return f.list == p.list && f.link == p.link_field && f.spring == p.spring_field;
      });
    }

    /// Which foundations have an entry: those from the soil (gazetas, cone),
    /// typed ones (given), every one; `three_d` only in 3D, `vertical` only
    /// with a vertical part (frames); `matrices`: it enters K or M.
    struct FoundationEntry
    {
      NumericEntry<FoundationParameters> entry;
      enum
      {
        soil,
        typed,
        any
      } of;
      bool three_d, vertical, matrices;
    };

#define POUNDFE_FOUNDATION_FIELD(expression) \
  [](FoundationParameters &f) -> double & { return f.expression; }
    const std::vector<FoundationEntry> foundation_entries = {
      {{"Shear-wave velocity", POUNDFE_FOUNDATION_FIELD(soil.shear_wave_velocity), positive},
       FoundationEntry::soil, false, false, true},
      {{"Soil density", POUNDFE_FOUNDATION_FIELD(soil.density), positive},
       FoundationEntry::soil, false, false, true},
      {{"Poisson ratio", POUNDFE_FOUNDATION_FIELD(soil.poisson_ratio), {0, false, 0.5}},
       FoundationEntry::soil, false, false, true},
      {{"Length", POUNDFE_FOUNDATION_FIELD(geometry.length), positive},
       FoundationEntry::soil, false, false, true},
      {{"Width", POUNDFE_FOUNDATION_FIELD(geometry.width), positive},
       FoundationEntry::soil, false, false, true},
      {{"Embedment", POUNDFE_FOUNDATION_FIELD(geometry.embedment), non_negative},
       FoundationEntry::soil, false, false, true},
      {{"Horizontal stiffness", POUNDFE_FOUNDATION_FIELD(given.horizontal_stiffness), positive},
       FoundationEntry::typed, false, false, true},
      {{"Rocking stiffness", POUNDFE_FOUNDATION_FIELD(given.rocking_stiffness), positive},
       FoundationEntry::typed, false, false, true},
      {{"Vertical stiffness", POUNDFE_FOUNDATION_FIELD(given.vertical_stiffness), positive},
       FoundationEntry::typed, false, true, true},
      {{"Horizontal damping", POUNDFE_FOUNDATION_FIELD(given.horizontal_damping), non_negative},
       FoundationEntry::typed, false, false, false},
      {{"Rocking damping", POUNDFE_FOUNDATION_FIELD(given.rocking_damping), non_negative},
       FoundationEntry::typed, false, false, false},
      {{"Vertical damping", POUNDFE_FOUNDATION_FIELD(given.vertical_damping), non_negative},
       FoundationEntry::typed, false, true, false},
      {{"Horizontal stiffness y", POUNDFE_FOUNDATION_FIELD(given_3d.sway_stiffness[1]),
        positive},
       FoundationEntry::typed, true, false, true},
      {{"Rocking stiffness x", POUNDFE_FOUNDATION_FIELD(given_3d.rocking_stiffness[0]),
        positive},
       FoundationEntry::typed, true, false, true},
      {{"Torsional stiffness", POUNDFE_FOUNDATION_FIELD(given_3d.torsional_stiffness), positive},
       FoundationEntry::typed, true, false, true},
      {{"Horizontal damping y", POUNDFE_FOUNDATION_FIELD(given_3d.sway_damping[1]),
        non_negative},
       FoundationEntry::typed, true, false, false},
      {{"Rocking damping x", POUNDFE_FOUNDATION_FIELD(given_3d.rocking_damping[0]),
        non_negative},
       FoundationEntry::typed, true, false, false},
      {{"Torsional damping", POUNDFE_FOUNDATION_FIELD(given_3d.torsional_damping),
        non_negative},
       FoundationEntry::typed, true, false, false},
      {{"Mass", POUNDFE_FOUNDATION_FIELD(mass), positive}, FoundationEntry::any, false, false,
       true},
      {{"Rotary inertia", POUNDFE_FOUNDATION_FIELD(rotary_inertia), positive},
       FoundationEntry::any, false, false, true},
      {{"Rotary inertia x", POUNDFE_FOUNDATION_FIELD(rotary_inertia_x), positive},
       FoundationEntry::any, true, false, true},
      {{"Polar inertia", POUNDFE_FOUNDATION_FIELD(polar_inertia), positive},
       FoundationEntry::any, true, false, true}};
#undef POUNDFE_FOUNDATION_FIELD

    const NumericEntry<FrictionLawParameters> &
    friction_entry_of(double &(*at)(FrictionLawParameters &))
    {
      return *std::find_if(friction_entries.begin(), friction_entries.end(),
                           [at](const auto &e) { return e.at == at; });
    }

    const FoundationEntry &
    foundation_entry_of(double &(*at)(FoundationParameters &))
    {
      return *std::find_if(foundation_entries.begin(), foundation_entries.end(),
                           [at](const FoundationEntry &e) { return e.entry.at == at; });
    }

    /// The section entries of a generated frame's columns and beams.
    const std::vector<std::pair<std::string, double Section::*>> section_entries = {
      {"E", &Section::youngs_modulus},
      {"A", &Section::area},
      {"I", &Section::second_moment},
      {"mass per length", &Section::mass_per_length}};

    /// The entries of a building's Bouc-Wen subsection.
    const std::vector<std::pair<std::string, double BoucWenParameters::*>> bouc_wen_entries = {
      {"alpha", &BoucWenParameters::alpha},         {"A", &BoucWenParameters::A},
      {"beta", &BoucWenParameters::beta},           {"gamma", &BoucWenParameters::gamma},
      {"n", &BoucWenParameters::n},                 {"delta A", &BoucWenParameters::delta_A},
      {"delta nu", &BoucWenParameters::delta_nu},   {"delta eta", &BoucWenParameters::delta_eta}};

    /// Entries that place nodes: the model's geometry, which a realization
    /// does not move.
    const std::vector<std::string> geometry_entries = {
      "Storey heights", "Bay widths", "Number of storeys", "Number of bays",
      "Elements per member", "Drawing width", "Bay widths y", "Number of bays y",
      "Set-backs", "Column angle", "Diaphragm", "Mesh file", "Group ids",
      "Plan/Plan dimensions", "Plan/Position", "Plan/Rotation", "Plan/Mass eccentricity",
      "Plan/Accidental eccentricity", "Plan/Accidental eccentricity ratio",
      "Plan/Resisting planes"};

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

    /// Indices in model.gaps of the Contact/Barriers entries `p` names (all,
    /// or one): the gaps with a barrier side (-1), in the order listed
    /// (model_builder.cc adds them so, after the gaps between buildings).
    std::vector<unsigned int>
    named_barriers(const ModelParameter &p, const Model &model)
    {
      std::vector<unsigned int> all;
      for (unsigned int g = 0; g < model.gaps.size(); ++g)
        if (model.gaps[g].nodes[0] < 0 || model.gaps[g].nodes[1] < 0)
          all.push_back(g);
      return p.entry < 0 || all.empty() ? all : std::vector<unsigned int>{all.at(p.entry)};
    }

    /// Indices in model.building_links (a `Links` list) or model.springs (a
    /// `Springs` list) of the entries of `list`, in the order listed.
    std::vector<unsigned int>
    list_members(const Model &model, const std::string &list)
    {
      std::vector<unsigned int> result;
      if (list.rfind("Links/", 0) == 0)
        {
          for (unsigned int l = 0; l < model.building_links.size(); ++l)
            if (model.building_links[l].entry == list)
              result.push_back(l);
          return result;
        }
      const SpringKind kind = list == "Springs/SD springs" ? SpringKind::sd : SpringKind::cubic;
      for (unsigned int s = 0; s < model.springs.size(); ++s)
        if (model.springs[s].law.kind == kind)
          result.push_back(s);
      return result;
    }

    /// The entries of its list that `p` names (all, or one).
    std::vector<unsigned int>
    named_list_members(const ModelParameter &p, const Model &model)
    {
      const std::vector<unsigned int> all = list_members(model, p.list);
      return p.entry < 0 ? all : std::vector<unsigned int>{all.at(p.entry)};
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
    /// those of its storey (a storey entry) or its typed plane in every
    /// storey (resisting_plane); all when p.entry < 0.
    template <typename ModelType> // of a const model: read only
    auto
    named_planes(const ModelParameter &p, ModelType &model)
    {
      std::vector<decltype(&model.plane_links.front())> result;
      for (auto &link : model.plane_links)
        {
          const unsigned int index = p.kind == Kind::resisting_plane ? link.plane : link.storey;
          if (link.building == p.building && (p.entry < 0 || int(index) == p.entry + 1))
            result.push_back(&link);
        }
      return result;
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
    /// model builder lumps it (every joint has its NodalMass:
    /// model_parameter() checks it); a 3D floor's polar moment J = m c
    /// (c = (L_x^2 + L_y^2)/12 unless Plan/Polar moments is given) keeps its
    /// c, and a 3D frame's joints their vertical masses m / n_joints. Sets
    /// again the effective mass of each gap whose m_e is of the floors'
    /// masses (one equal to what the builder computes to the last bit:
    /// Contact/Effective mass not given, or given equal to it), as the
    /// builder does.
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

    void
    require_in_range(const ModelParameter &p, const double value)
    {
      const ModelParameter::Range r = p.range();
      // beyond 1e150 in size the builder refuses the entry, or the K or M
      // it enters (dynamics/analysis.cc), whatever the parameter's range
      if (!(r.lower_included ? value >= r.lower : value > r.lower) ||
          !(r.upper_included ? value <= r.upper : value < r.upper) ||
          !(std::abs(value) <= largest_model_value))
        {
          std::string range;
          if (std::isfinite(r.lower))
            range += (r.lower_included ? ">= " : "> ") + number_text(r.lower) + " and ";
          if (std::isfinite(r.upper))
            range += (r.upper_included ? "<= " : "< ") + number_text(r.upper) + " and ";
          range += "at most 1e150 in size";
          throw std::invalid_argument("'" + p.path + "' cannot take the sampled value " +
                                      number_text(value) + " (it must be " + range +
                                      "; choose a distribution that stays in range, e.g. "
                                      "lognormal or truncated normal)");
        }
    }

    /// The building of hinge h in the order of HingeOrigin: model.hinges,
    /// then model.hinges_3d.
    unsigned int
    hinge_building(const Model &model, const unsigned int h)
    {
      return h < model.hinges.size() ? model.hinges[h].building :
                                       model.hinges_3d[h - model.hinges.size()].building;
    }

    /// The origin of `hinge` (an element of model.hinges) under `p`.
    const HingeOrigin &
    origin_of(const ModelParameter &p, const Model &model, const Hinge &hinge)
    {
      Assert(p.hinges && p.hinges->size() == model.hinges.size() + model.hinges_3d.size(),
             dealii::ExcMessage("a section or hinge parameter needs the hinges' origins"));
      return (*p.hinges)[&hinge - model.hinges.data()];
    }

    /// Sets a hinge's k and, for a hinge whose u_y comes from its yield
    /// moment, u_y = M_y / k with M_y = k u_y before (the builder's M_y to
    /// rounding).
    void
    set_hinge_stiffness(BoucWenParameters &law, const HingeOrigin &origin, const double stiffness)
    {
      if (origin.yield_from_moment)
        law.yield_deformation = law.stiffness * law.yield_deformation / stiffness;
      law.stiffness = stiffness;
    }

    void
    set_hinge_stiffness(Hinge &hinge, const HingeOrigin &origin, const double stiffness)
    {
      set_hinge_stiffness(hinge.law, origin, stiffness);
    }

    /// 6 E I / L of the member that carries `hinge` (k / factor in the builder).
    double
    section_stiffness(const Model &model, const Hinge &hinge)
    {
      const Member &member = model.members[hinge.member];
      return 6 * member.section.youngs_modulus * member.section.second_moment /
             member.member_length;
    }

    /// Whether `member` (a Member or a Member3D) is one `p` names: a column
    /// of storey i (group 2i - 1) or a beam of floor i (group 2i) of its
    /// generated frame, or a member of a mesh's group `p.group`; without
    /// [i], all of them.
    template <typename MemberType>
    bool
    named_member(const ModelParameter &p, const MemberType &member)
    {
      if (member.building != p.building)
        return false;
      if (p.member_kind == MemberKind::other) // a mesh's group (all without [i])
        return p.entry < 0 || int(member.group) == p.group;
      const int group = 2 * p.entry + (p.member_kind == MemberKind::column ? 1 : 2);
      return member.kind == p.member_kind && (p.entry < 0 || int(member.group) == group);
    }

    double
    length_of(const Member3D &member)
    {
      return std::hypot(member.ends[1][0] - member.ends[0][0], member.ends[1][1] - member.ends[0][1],
                        member.ends[1][2] - member.ends[0][2]);
    }

    /// 6 E I / L of the member that carries a 3D hinge (I about its axis).
    double
    section_stiffness_3d(const Model &model, const Hinge3D &hinge)
    {
      const Member3D &member = model.members_3d[hinge.member];
      return 6 * member.section.youngs_modulus *
             (hinge.slot == 0 ? member.section.second_moment_y : member.section.second_moment_z) /
             length_of(member);
    }

    /// A hinge of a building, of a 2D frame (model.hinges) or of a 3D one
    /// (model.hinges_3d, one per bending axis): its law, the index of its
    /// origin (HingeOrigin: those of model.hinges, then of hinges_3d) and
    /// 6 E I / L of its member about its axis (k / factor in the builder).
    template <typename Law> // BoucWenParameters, const or not
    struct BuildingHinge
    {
      Law         *law;
      unsigned int origin;
      double       section_stiffness;
    };

    /// The hinges of building b, 2D and 3D (of a const model: read only).
    template <typename ModelType>
    auto
    hinges_of(ModelType &model, const unsigned int b)
    {
      using Law = std::remove_reference_t<decltype((model.hinges.front().law))>;
      std::vector<BuildingHinge<Law>> result;
      for (unsigned int h = 0; h < model.hinges.size(); ++h)
        if (model.hinges[h].building == b)
          result.push_back({&model.hinges[h].law, h, section_stiffness(model, model.hinges[h])});
      for (unsigned int h = 0; h < model.hinges_3d.size(); ++h)
        if (model.hinges_3d[h].building == b)
          result.push_back({&model.hinges_3d[h].law, unsigned(model.hinges.size() + h),
                            section_stiffness_3d(model, model.hinges_3d[h])});
      return result;
    }

    /// The Bouc-Wen laws of building b: its hinges' (2D; 3D: one per bending
    /// axis), its hysteretic storeys' and its hysteretic resisting planes'
    /// (a 3D shear building's; of a const model: read only).
    template <typename ModelType>
    auto
    bouc_wen_laws_of(ModelType &model, const unsigned int b)
    {
      std::vector<decltype(hinges_of(model, b).front().law)> laws;
      for (const auto &hinge : hinges_of(model, b))
        laws.push_back(hinge.law);
      for (auto &link : model.links)
        if (link.building == b && link.hysteretic)
          laws.push_back(&link.hysteresis);
      for (auto &link : model.plane_links)
        if (link.building == b && link.hysteretic)
          laws.push_back(&link.hysteresis);
      return laws;
    }

    /// Whether building b has a bidirectional (Park-Wen-Ang) Bouc-Wen law:
    /// biaxial 3D hinges or paired resisting planes; that law needs n >= 2
    /// and has no degradation (laws/bidirectional_bouc_wen.h).
    bool
    has_bidirectional_bouc_wen(const Model &model, const unsigned int b)
    {
      return std::any_of(model.hinges_3d.begin(), model.hinges_3d.end(),
                         [b](const Hinge3D &h) { return h.building == b && h.biaxial; }) ||
             std::any_of(model.plane_links.begin(), model.plane_links.end(),
                         [b](const PlaneLink &l) { return l.building == b && l.partner >= 0; });
    }

    /// The origin of a hinge of hinges_of under `p`.
    template <typename Law>
    const HingeOrigin &
    origin_of(const ModelParameter &p, const Model &model, const BuildingHinge<Law> &hinge)
    {
      Assert(p.hinges && p.hinges->size() == model.hinges.size() + model.hinges_3d.size(),
             dealii::ExcMessage("a hinge parameter needs the hinges' origins"));
      (void)model; // for the Assert
      return (*p.hinges)[hinge.origin];
    }

    /// The section value of the named 3D members; a hinge whose k is
    /// f 6 E I / L of its member keeps its f (as write_member_section).
    void
    write_member_section_3d(const ModelParameter &p, const double value, Model &model)
    {
      const bool bending = p.section_3d == &Section3D::youngs_modulus ||
                           p.section_3d == &Section3D::second_moment_y ||
                           p.section_3d == &Section3D::second_moment_z;
      Assert(p.hinges && p.hinges->size() == model.hinges.size() + model.hinges_3d.size(),
             dealii::ExcMessage("a section parameter needs the hinges' origins"));
      std::vector<Hinge3D *> following;
      std::vector<double>    factors;
      for (unsigned int h = 0; h < model.hinges_3d.size(); ++h)
        {
          Hinge3D &hinge = model.hinges_3d[h];
          if (bending && named_member(p, model.members_3d[hinge.member]) &&
              (*p.hinges)[model.hinges.size() + h].stiffness_from_section)
            {
              following.push_back(&hinge);
              factors.push_back(hinge.law.stiffness / section_stiffness_3d(model, hinge));
            }
        }
      for (Member3D &member : model.members_3d)
        if (named_member(p, member))
          member.section.*p.section_3d = value;
      for (std::size_t h = 0; h < following.size(); ++h)
        set_hinge_stiffness(following[h]->law,
                            (*p.hinges)[model.hinges.size() + (following[h] - model.hinges_3d.data())],
                            factors[h] * section_stiffness_3d(model, *following[h]));
    }

    /// The section value of the named members; a hinge whose k is f 6 E I / L
    /// of its member keeps its f = k / (6 E I / L) of before.
    void
    write_member_section(const ModelParameter &p, const double value, Model &model)
    {
      const bool bending =
        p.section == &Section::youngs_modulus || p.section == &Section::second_moment;
      std::vector<Hinge *> following;
      std::vector<double>  factors;
      for (Hinge &hinge : model.hinges)
        if (bending && named_member(p, model.members[hinge.member]) &&
            origin_of(p, model, hinge).stiffness_from_section)
          {
            following.push_back(&hinge);
            factors.push_back(hinge.law.stiffness / section_stiffness(model, hinge));
          }
      for (Member &member : model.members)
        if (named_member(p, member))
          member.section.*p.section = value;
      for (std::size_t h = 0; h < following.size(); ++h)
        set_hinge_stiffness(*following[h], origin_of(p, model, *following[h]),
                            factors[h] * section_stiffness(model, *following[h]));
    }

    /// beta + gamma > 0 and beta >= |gamma| or gamma >= |beta|, as the input
    /// checks them (model/parameters.cc).
    void
    require_bouc_wen_shape(const ModelParameter &p, const BoucWenParameters &h)
    {
      if (!(h.beta + h.gamma > 0) || !(h.beta >= std::abs(h.gamma) || h.gamma >= std::abs(h.beta)))
        throw std::invalid_argument("'" + p.path + "': the sampled value gives beta = " +
                                    number_text(h.beta) + ", gamma = " + number_text(h.gamma) +
                                    ", which need beta + gamma > 0 and beta >= |gamma| or "
                                    "gamma >= |beta|");
    }

    void
    write_bouc_wen_shape(const ModelParameter &p, const double value, Model &model)
    {
      for (BoucWenParameters *law : bouc_wen_laws_of(model, p.building))
        {
          law->*p.shape = value;
          require_bouc_wen_shape(p, *law);
        }
    }

    /// The parameters of a building's hinges and its damping coefficients.
    void
    write_hinge_or_damping(const ModelParameter &p, const double value, Model &model)
    {
      RayleighDamping &damping = model.buildings[p.building].damping;
      switch (p.kind)
        {
          case Kind::hinge_yield_moment:
            for (const auto &hinge : hinges_of(model, p.building))
              hinge.law->yield_deformation = value / hinge.law->stiffness;
            return;
          case Kind::hinge_stiffness:
            for (const auto &hinge : hinges_of(model, p.building))
              set_hinge_stiffness(*hinge.law, origin_of(p, model, hinge), value);
            return;
          case Kind::hinge_stiffness_factor:
            for (const auto &hinge : hinges_of(model, p.building))
              if (origin_of(p, model, hinge).stiffness_from_section)
                set_hinge_stiffness(*hinge.law, origin_of(p, model, hinge),
                                    value * hinge.section_stiffness);
            return;
          case Kind::hinge_yield_rotation:
            for (const auto &hinge : hinges_of(model, p.building))
              if (!origin_of(p, model, hinge).yield_from_moment)
                hinge.law->yield_deformation = value;
            return;
          case Kind::rayleigh_a0:
            damping.a0 = value;
            return;
          case Kind::rayleigh_a1:
            damping.a1 = value;
            return;
          case Kind::modal_ratio:
            for (unsigned int i = 0; i < damping.modal_ratios.size(); ++i)
              if (p.entry < 0 || int(i) == p.entry)
                damping.modal_ratios[i] = value;
            return;
          default:
            Assert(false, dealii::ExcInternalError());
        }
    }

    /// Writes `value` into the model, or, for a value the builder maps
    /// (a foundation's entry, the restitution), into `inputs` (the working
    /// copy of the input sections; ModelRealization::apply maps them); the
    /// checks of model_parameter() hold.
    /// The storeys of a shear building and the resisting planes of a 3D one (write()).
    void
    write_storey_or_plane(const ModelParameter &p, const double value, Model &model)
    {
      switch (p.kind)
        {
          case Kind::storey_stiffness:
            for (const unsigned int l : named_storeys(p, model))
              model.links[l].stiffness = model.links[l].hysteresis.stiffness = value;
            for (PlaneLink *plane : named_planes(p, model)) // 3D: four planes, k/2 each
              plane->stiffness = plane->hysteresis.stiffness = 0.5 * value;
            return;
          case Kind::resisting_plane: // as add_plane_links sets a typed plane
            for (PlaneLink *plane : named_planes(p, model))
              if (p.plane_yield_drift)
                plane->hysteresis.yield_deformation = value;
              else
                plane->stiffness = plane->hysteresis.stiffness = value;
            return;
          case Kind::storey_damping:
            for (const unsigned int l : named_storeys(p, model))
              model.links[l].damping = value;
            return;
          case Kind::storey_yield_drift:
            for (const unsigned int l : named_storeys(p, model))
              model.links[l].hysteresis.yield_deformation = value;
            for (PlaneLink *plane : named_planes(p, model))
              plane->hysteresis.yield_deformation = value;
            return;
          default:
            Assert(false, dealii::ExcInternalError());
        }
    }

    /// The gaps, the contact and friction laws, the links, springs and bumpers (write()).
    void
    write_contact_or_device(const ModelParameter &p, const double value, Model &model)
    {
      switch (p.kind)
        {
          case Kind::separation:
            for (const unsigned int g : gaps_after(model, p.building))
              model.gaps[g].initial_gap = value;
            return;
          case Kind::barrier_gap:
            for (const unsigned int g : named_barriers(p, model))
              model.gaps[g].initial_gap = value;
            return;
          case Kind::contact_stiffness:
            model.contact.stiffness = value;
            return;
          case Kind::contact_damping:
            model.contact.damping = value;
            return;
          case Kind::static_friction:
          case Kind::kinetic_friction:
            for (FrictionSurface &surface : model.friction_surfaces)
              (p.kind == Kind::static_friction ? surface.law.static_coefficient :
                                                 surface.law.kinetic_coefficient) = value;
            return;
          case Kind::link_entry:
            for (const unsigned int l : named_list_members(p, model))
              model.building_links[l].law.*p.link_field = value;
            return;
          case Kind::spring_entry: // an SD reaction in N follows in apply
            for (const unsigned int s : named_list_members(p, model))
              model.springs[s].law.*p.spring_field = value;
            return;
          case Kind::bumper_entry: // t <= the gaps is checked in apply
            model.bumper.*p.bumper_field = value;
            return;
          default:
            Assert(false, dealii::ExcInternalError());
        }
    }

    void
    write(const ModelParameter &p, const double value, Model &model, ModelInputs &inputs)
    {
      require_in_range(p, value);
      switch (p.kind)
        {
          case Kind::member_section_3d:
            write_member_section_3d(p, value, model);
            return;
          case Kind::friction_entry:
            for (FrictionSurface &surface : model.friction_surfaces)
              {
                p.friction(surface.law) = value;
                if (std::string(friction_entry_of(p.friction).name) == "Stick stiffness")
                  surface.automatic_stick_stiffness = false;
              }
            return;
          case Kind::contact_restitution:
            inputs.contact.restitution = value;
            return;
          case Kind::foundation_entry:
            p.foundation(inputs.model.buildings[p.building].foundation) = value;
            return;
          case Kind::storey_stiffness:
          case Kind::resisting_plane:
          case Kind::storey_damping:
          case Kind::storey_yield_drift:
            write_storey_or_plane(p, value, model);
            return;
          case Kind::floor_mass:
            write_floor_masses(p, value, model);
            return;
          case Kind::polar_moment:
            for (const Floor *floor : named_floors(p, model))
              for (NodalMass &m : model.masses)
                if (m.node == floor->nodes.front()) // the slab's node (model_parameter())
                  m.polar_moment = value;
            return;
          case Kind::damping_ratio:
            model.buildings[p.building].damping.damping_ratio = value;
            return;
          case Kind::separation:
          case Kind::barrier_gap:
          case Kind::contact_stiffness:
          case Kind::contact_damping:
          case Kind::static_friction:
          case Kind::kinetic_friction:
          case Kind::link_entry:
          case Kind::spring_entry:
          case Kind::bumper_entry:
            write_contact_or_device(p, value, model);
            return;
          case Kind::member_section:
            write_member_section(p, value, model);
            return;
          case Kind::bouc_wen_shape:
            write_bouc_wen_shape(p, value, model);
            return;
          case Kind::hinge_yield_moment:
          case Kind::hinge_stiffness:
          case Kind::hinge_stiffness_factor:
          case Kind::hinge_yield_rotation:
          case Kind::rayleigh_a0:
          case Kind::rayleigh_a1:
          case Kind::modal_ratio:
            write_hinge_or_damping(p, value, model);
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

    /// "Storey stiffnesses[i]" or "Storey yield drifts[i]" of a 3D shear
    /// building whose planes are the default four per storey (Plan/Resisting
    /// planes not typed): k/2 on each plane (plan_builder.cc's storey_planes),
    /// u_y of each; it has no storey dashpots.
    ModelParameter
    plane_storey_parameter(ModelParameter p, const Model &model)
    {
      const Building &building = model.buildings[p.building];
      if (p.kind == Kind::storey_damping)
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' is a 3D shear building, whose storeys have no dashpots");
      if (!p.inputs)
        throw std::invalid_argument("'" + p.path + "' needs the input the model was built "
                                    "from (whether its resisting planes are typed)");
      if (!p.inputs->model.buildings[p.building].plan.planes.empty())
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' has its Plan/Resisting planes typed (each with its k "
                                    "and u_y), which the storey entries do not set (vary "
                                    "Plan/Resisting planes/k[i] or u_y[i])");
      if (p.entry >= int(building.floors.size()))
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' has storeys 1.." + std::to_string(building.floors.size()));
      if (p.kind == Kind::storey_yield_drift)
        for (const PlaneLink *link : named_planes(p, model))
          if (!link->hysteretic)
            throw std::invalid_argument("'" + p.path + "': a storey of building '" +
                                        building.name + "' is elastic (no yield drift in the "
                                        "input)");
      return p;
    }

    /// "Plan/Resisting planes/FIELD[i]" of a 3D shear building whose planes
    /// are typed: FIELD k or u_y of plane i (as listed) in every storey
    /// (plan_builder.cc's storey_planes gives each storey the typed list).
    ModelParameter
    resisting_plane_parameter(ModelParameter p, const std::string &field, const Model &model)
    {
      const Building &building = model.buildings[p.building];
      if (field == "x" || field == "y" || field == "angle")
        throw std::invalid_argument("'" + p.path + "' is the model's geometry (where the plane "
                                    "acts), which a realization does not move; vary k or u_y");
      if (field != "k" && field != "u_y")
        throw std::invalid_argument("'" + p.path + "': name a field of the typed planes, "
                                    "'Plan/Resisting planes/FIELD[i]' with FIELD one of k, u_y");
      p.kind              = Kind::resisting_plane;
      p.plane_yield_drift = field == "u_y";
      if (std::none_of(model.plane_links.begin(), model.plane_links.end(),
                       [&](const PlaneLink &l) { return l.building == p.building; }))
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' is not a 3D shear building (no resisting planes)");
      if (!p.inputs)
        throw std::invalid_argument("'" + p.path + "' needs the input the model was built "
                                    "from (whether its resisting planes are typed)");
      const std::size_t n = p.inputs->model.buildings[p.building].plan.planes.size();
      if (n == 0)
        throw std::invalid_argument(
          "'" + p.path + "': building '" + building.name + "' has no typed Plan/Resisting "
          "planes: its default four planes per storey follow Storey stiffnesses and Storey "
          "yield drifts (vary those)");
      if (p.entry >= int(n))
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' has resisting planes 1.." + std::to_string(n));
      if (p.plane_yield_drift)
        for (const PlaneLink *link : named_planes(p, model))
          if (!link->hysteretic)
            throw std::invalid_argument("'" + p.path + "': plane " +
                                        std::to_string(link->plane) + " of building '" +
                                        building.name + "' is elastic (no u_y in the input)");
      return p;
    }

    /// Whether the floors `p` names can take a sampled mass: a mass at
    /// every joint; in 3D the input (whether Plan/Polar moments is typed).
    void
    check_floor_masses(const ModelParameter &p, const Model &model)
    {
      const Building &building = model.buildings[p.building];
      if (p.entry >= int(building.floors.size()))
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' has floors 1.." + std::to_string(building.floors.size()));
      if (model.dimension != 2 && !p.inputs)
        throw std::invalid_argument("'" + p.path + "': a 3D floor mass needs the input the "
                                    "model was built from (its polar moment follows it)");
      for (const Floor *floor : named_floors(p, model))
        for (const unsigned int node : floor->nodes)
          if (std::none_of(model.masses.begin(), model.masses.end(),
                           [node](const NodalMass &m) { return m.node == node; }))
            throw std::invalid_argument("'" + p.path + "': a floor of building '" +
                                        building.name + "' has no floor mass in the input");
    }

    /// A 3D section entry needs the hinges' origins (its hinges' k follows
    /// E and I as the builder set it).
    void
    require_hinge_origins(const ModelParameter &p, const Model &model)
    {
      if (!p.hinges || p.hinges->size() != model.hinges.size() + model.hinges_3d.size())
        throw std::invalid_argument("'" + p.path + "': a 3D section needs the hinges' "
                                    "origins (hinge_origins)");
    }

    /// "Column E[i]" ... "Beam mass per length[i]" of a 3D frame (`which`:
    /// the word after Column or Beam).
    ModelParameter
    section_3d_parameter(ModelParameter p, const bool column, const std::string &which,
                         const Model &model)
    {
      const auto found = std::find_if(section_3d_entries.begin(), section_3d_entries.end(),
                                      [&](const auto &e) { return e.first == which; });
      if (found == section_3d_entries.end())
        throw std::invalid_argument("'" + p.path + "' is not a parameter poundfe can vary (" +
                                    known_paths + ")");
      require_hinge_origins(p, model);
      p.kind        = Kind::member_section_3d;
      p.member_kind = column ? MemberKind::column : MemberKind::beam;
      p.section_3d  = found->second;
      return p;
    }

    /// "Group E[i]" ... "Group mass per length[i]" of a mesh building: the
    /// members of its i-th group id (3D: Group G, Iz and J too; its
    /// members have no shear areas, Euler-Bernoulli).
    ModelParameter
    mesh_section_parameter(ModelParameter p, const std::string &which, const Model &model)
    {
      const Building &building = model.buildings[p.building];
      const bool      three_d  = model.dimension == 3;
      const auto      found    = std::find_if(section_entries.begin(), section_entries.end(),
                                      [&](const auto &e) { return e.first == which; });
      const auto found_3d = std::find_if(section_3d_entries.begin(), section_3d_entries.end(),
                                         [&](const auto &e) { return e.first == which; });
      if (three_d ? found_3d == section_3d_entries.end() : found == section_entries.end())
        throw std::invalid_argument("'" + p.path + "' is not a parameter poundfe can vary (" +
                                    known_paths + ")");
      if (building.type != BuildingType::mesh)
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' is not a mesh building (Type = mesh)");
      if (which == "Avy" || which == "Avz")
        throw std::invalid_argument("'" + p.path + "': the members of a 3D mesh building have "
                                    "no shear areas (Euler-Bernoulli; Group " + which +
                                    " is no entry)");
      if (!p.inputs)
        throw std::invalid_argument("'" + p.path + "': a mesh group needs the input the "
                                    "model was built from (its Group ids)");
      const std::vector<unsigned int> &ids = p.inputs->model.buildings[p.building].group_ids;
      if (p.entry >= int(ids.size()))
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' has groups 1.." + std::to_string(ids.size()));
      p.member_kind = MemberKind::other;
      p.group       = p.entry < 0 ? -1 : int(ids[p.entry]);
      if (three_d)
        {
          require_hinge_origins(p, model);
          p.kind       = Kind::member_section_3d;
          p.section_3d = found_3d->second;
          return p;
        }
      p.kind    = Kind::member_section;
      p.section = found->second;
      return p;
    }

    /// "Plan/Polar moments[i]" of a 3D building whose input types them (a
    /// polar moment not typed follows its floor's mass, as Floor masses
    /// does), on a rigid slab (one node per floor carries its mass).
    ModelParameter
    polar_moment_parameter(ModelParameter p, const Model &model)
    {
      const Building &building = model.buildings[p.building];
      p.kind                   = Kind::polar_moment;
      if (model.dimension != 3)
        throw std::invalid_argument("'" + p.path + "' is an entry of a 3D building "
                                    "(Model/Dimension = 3)");
      if (!p.inputs)
        throw std::invalid_argument("'" + p.path + "' needs the input the model was built "
                                    "from (whether its polar moments are typed)");
      if (p.inputs->model.buildings[p.building].plan.polar_moments.empty())
        throw std::invalid_argument(
          "'" + p.path + "': building '" + building.name + "' has no Plan/Polar moments: its "
          "floors' polar moments follow their masses (vary Floor masses, or type Plan/Polar "
          "moments to make them random)");
      check_floor_masses(p, model);
      for (const Floor *floor : named_floors(p, model))
        if (floor->nodes.size() != 1)
          throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                      "' has no rigid slabs (Diaphragm = none): each joint "
                                      "carries its share of the floor mass, no polar moment");
      return p;
    }

    /// "Column E[i]" ... "Beam mass per length[i]" of a generated frame.
    ModelParameter
    section_parameter(ModelParameter p, const std::string &entry, const Model &model)
    {
      const Building &building = model.buildings[p.building];
      const bool      column   = entry.rfind("Column ", 0) == 0;
      const std::string which  = entry.substr(column ? 7 : 5);
      if (building.type == BuildingType::frame && model.dimension == 3)
        {
          if (p.entry >= int(building.floors.size()))
            throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                        "' has " + (column ? "storeys" : "floors") + " 1.." +
                                        std::to_string(building.floors.size()));
          return section_3d_parameter(p, column, which, model);
        }
      const auto        found  = std::find_if(section_entries.begin(), section_entries.end(),
                                      [&](const auto &e) { return e.first == which; });
      if (found == section_entries.end())
        throw std::invalid_argument("'" + p.path + "' is not a parameter poundfe can vary (" +
                                    known_paths + ")");
      if (building.type != BuildingType::frame)
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' is not a generated frame (Type = frame)");
      if (p.entry >= int(building.floors.size()))
        throw std::invalid_argument("'" + p.path + "': building '" + building.name + "' has " +
                                    (column ? "storeys" : "floors") + " 1.." +
                                    std::to_string(building.floors.size()));
      p.kind        = Kind::member_section;
      p.member_kind = column ? MemberKind::column : MemberKind::beam;
      p.section     = found->second;
      return p;
    }

    /// "Damping/Modal ratios[i]" of a building with modal damping.
    ModelParameter
    modal_ratio_parameter(ModelParameter p, const Model &model)
    {
      const Building &building = model.buildings[p.building];
      p.kind                   = Kind::modal_ratio;
      if (building.damping.kind != RayleighDamping::Kind::modal)
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' has no modal damping (Damping/Type = modal)");
      if (p.entry >= int(building.damping.modal_ratios.size()))
        throw std::invalid_argument("'" + p.path + "': building '" + building.name +
                                    "' has modal ratios 1.." +
                                    std::to_string(building.damping.modal_ratios.size()));
      return p;
    }

    /// "Hinges/ENTRY": the building's hinges must have what the entry sets
    /// (checked when `p.hinges` is known).
    ModelParameter
    hinge_parameter(ModelParameter p, const std::string &entry, const Model &model)
    {
      const std::string &name = model.buildings[p.building].name;
      if (entry == "Yield moment")
        p.kind = Kind::hinge_yield_moment;
      else if (entry == "Stiffness")
        p.kind = Kind::hinge_stiffness;
      else if (entry == "Stiffness factor")
        p.kind = Kind::hinge_stiffness_factor;
      else if (entry == "Yield rotation")
        p.kind = Kind::hinge_yield_rotation;
      else
        throw std::invalid_argument("'" + p.path + "' is not a parameter poundfe can vary (" +
                                    known_paths + ")");
      bool any = false, from_section = false, from_rotation = false;
      for (unsigned int h = 0; h < model.hinges.size() + model.hinges_3d.size(); ++h)
        if (hinge_building(model, h) == p.building)
          {
            any = true;
            if (p.hinges)
              {
                from_section  = from_section || (*p.hinges)[h].stiffness_from_section;
                from_rotation = from_rotation || !(*p.hinges)[h].yield_from_moment;
              }
          }
      if (!any)
        throw std::invalid_argument("'" + p.path + "': building '" + name + "' has no hinges");
      if (p.hinges && p.kind == Kind::hinge_stiffness_factor && !from_section)
        throw std::invalid_argument("'" + p.path + "': the hinges of building '" + name +
                                    "' have a given Hinges/Stiffness (the factor is unused)");
      if (p.hinges && p.kind == Kind::hinge_yield_rotation && !from_rotation)
        throw std::invalid_argument("'" + p.path + "': the hinges of building '" + name +
                                    "' yield at their Hinges/Yield moment (the rotation is "
                                    "unused)");
      return p;
    }

    /// "Bouc-Wen/ENTRY": the building must have a Bouc-Wen element.
    ModelParameter
    bouc_wen_parameter(ModelParameter p, const std::string &entry, const Model &model)
    {
      const auto found = std::find_if(bouc_wen_entries.begin(), bouc_wen_entries.end(),
                                      [&](const auto &e) { return e.first == entry; });
      if (found == bouc_wen_entries.end())
        throw std::invalid_argument("'" + p.path + "' is not a parameter poundfe can vary (" +
                                    known_paths + ")");
      const std::string &name = model.buildings[p.building].name;
      if (bouc_wen_laws_of(model, p.building).empty())
        throw std::invalid_argument("'" + p.path + "': building '" + name +
                                    "' has no Bouc-Wen hinges, hysteretic storeys or "
                                    "hysteretic resisting planes");
      p.kind          = Kind::bouc_wen_shape;
      p.shape         = found->second;
      p.bidirectional = has_bidirectional_bouc_wen(model, p.building);
      if (p.bidirectional &&
          (p.shape == &BoucWenParameters::delta_A || p.shape == &BoucWenParameters::delta_nu ||
           p.shape == &BoucWenParameters::delta_eta))
        throw std::invalid_argument("'" + p.path + "': the Bouc-Wen law of building '" + name +
                                    "' is bidirectional (Hinges/Biaxial interaction = true or "
                                    "Plan/Storey law = bidirectional Bouc-Wen), which has no "
                                    "degradation");
      return p;
    }

    /// "Foundation/ENTRY" of building b's compliant foundation: an entry
    /// its Type uses (the soil's for gazetas and cone, the typed springs
    /// and dashpots for given), in 3D the 3D ones, the vertical ones under
    /// a frame.
    ModelParameter
    foundation_parameter(ModelParameter p, const std::string &entry, const Model &model)
    {
      const std::string &name  = model.buildings[p.building].name;
      const auto         found = std::find_if(foundation_entries.begin(), foundation_entries.end(),
                                      [&](const FoundationEntry &e) { return e.entry.name == entry; });
      if (found == foundation_entries.end())
        throw std::invalid_argument("'" + p.path + "' is not a parameter poundfe can vary (" +
                                    known_paths + ")");
      const auto foundation = std::find_if(model.foundations.begin(), model.foundations.end(),
                                           [&](const Foundation &f) { return f.building == p.building; });
      if (foundation == model.foundations.end())
        throw std::invalid_argument("'" + p.path + "': building '" + name +
                                    "' has no compliant foundation (Foundation/Type = none)");
      if (!p.inputs)
        throw std::invalid_argument("'" + p.path + "': a foundation entry needs the input the "
                                    "model was built from");
      const FoundationParameters &input = p.inputs->model.buildings[p.building].foundation;
      const bool given = input.type == FoundationType::given;
      const bool vertical = std::any_of(foundation->parts.begin(), foundation->parts.end(),
                                        [](const FoundationPart &part) { return part.name == "_vertical"; });
      if (found->of == FoundationEntry::soil && given)
        throw std::invalid_argument("'" + p.path + "': building '" + name + "' has its springs "
                                    "and dashpots typed in (Foundation/Type = given), not from "
                                    "the soil");
      if (found->of == FoundationEntry::typed && !given)
        throw std::invalid_argument("'" + p.path + "': building '" + name + "' has its springs "
                                    "and dashpots from the soil (Foundation/Type = " +
                                    foundation_type_names().name(input.type) +
                                    "); vary the soil's entries");
      if (found->three_d && model.dimension != 3)
        throw std::invalid_argument("'" + p.path + "' is an entry of a 3D foundation "
                                    "(Model/Dimension = 3)");
      if (found->vertical && !vertical)
        throw std::invalid_argument("'" + p.path + "': the foundation of building '" + name +
                                    "' has no vertical spring (a shear building's)");
      if (entry == "Embedment" && input.type == FoundationType::cone)
        throw std::invalid_argument("'" + p.path + "': the cones are for surface foundations "
                                    "(Embedment = 0)");
      p.kind                = Kind::foundation_entry;
      p.foundation          = found->entry.at;
      p.foundation_matrices = found->matrices;
      return p;
    }

    /// "LIST/FIELD" of a `Links` or `Springs` list (its entry p.entry, or
    /// every one): a list and field of list_fields, and the model has it.
    ModelParameter
    list_entry_parameter(ModelParameter p, const std::string &list, const std::string &field,
                         const Model &model)
    {
      std::string      fields;
      const ListField *found = nullptr;
      for (const ListField &f : list_fields)
        if (f.list == list)
          {
            fields += (fields.empty() ? "" : ", ") + std::string(f.name);
            if (f.name == field)
              found = &f;
          }
      if (fields.empty())
        throw std::invalid_argument("'" + p.path + "' is not a parameter poundfe can vary (" +
                                    known_paths + ")");
      if (!found)
        throw std::invalid_argument("'" + p.path + "': name a field of the entries of '" + list +
                                    "', '" + list + "/FIELD[i]' with FIELD one of " + fields);
      const std::size_t n    = list_members(model, list).size();
      const std::string what = list.substr(list.find('/') + 1);
      if (n == 0)
        throw std::invalid_argument("'" + p.path + "': the model has no entries of '" + list +
                                    "'");
      if (p.entry >= int(n))
        throw std::invalid_argument("'" + p.path + "': the model has " + what + " 1.." +
                                    std::to_string(n));
      p.kind         = found->link ? Kind::link_entry : Kind::spring_entry;
      p.list         = list;
      p.link_field   = found->link;
      p.spring_field = found->spring;
      return p;
    }

    /// "Bumpers/Stiffness" or "Bumpers/Thickness" of the bumper in every gap.
    ModelParameter
    bumper_parameter(ModelParameter p, const std::string &entry, const Model &model)
    {
      if (model.bumper.law == BumperLaw::none)
        throw std::invalid_argument("'" + p.path + "': the gaps have no bumper (Bumpers/Law = "
                                    "none)");
      const bool stiffness = entry == "Bumpers/Stiffness";
      if (stiffness && model.bumper.law == BumperLaw::table)
        throw std::invalid_argument("'" + p.path + "': a table bumper's force comes from its "
                                    "Bumpers/Table, not a stiffness");
      p.kind         = Kind::bumper_entry;
      p.bumper_field = stiffness ? &BumperParameters::stiffness : &BumperParameters::thickness;
      return p;
    }

    /// "Contact/Barriers/gap[i]": the gap of barrier i (its building, floor
    /// and side place it).
    ModelParameter
    barrier_parameter(ModelParameter p, const std::string &entry, const Model &model)
    {
      if (entry != "Contact/Barriers/gap")
        throw std::invalid_argument("'" + p.path + "': the barriers' random field is their gap, "
                                    "'Contact/Barriers/gap[i]' (building, floor and side "
                                    "place a barrier)");
      p.kind                = Kind::barrier_gap;
      const std::size_t n   = named_barriers(ModelParameter{}, model).size();
      if (n == 0)
        throw std::invalid_argument("'" + p.path + "': the model has no Contact/Barriers");
      if (p.entry >= int(n))
        throw std::invalid_argument("'" + p.path + "': the model has barriers 1.." +
                                    std::to_string(n));
      return p;
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
          if (std::any_of(model.plane_links.begin(), model.plane_links.end(),
                          [&](const PlaneLink &l) { return l.building == p.building; }))
            return plane_storey_parameter(p, model);
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
      if (entry == "Plan/Polar moments")
        return polar_moment_parameter(p, model);
      if (entry.rfind("Plan/Resisting planes/", 0) == 0)
        return resisting_plane_parameter(p, entry.substr(22), model);
      if (entry.rfind("Column ", 0) == 0 || entry.rfind("Beam ", 0) == 0)
        return section_parameter(p, entry, model);
      if (entry.rfind("Group ", 0) == 0)
        return mesh_section_parameter(p, entry.substr(6), model);
      if (entry.rfind("Foundation/", 0) == 0)
        {
          if (indexed)
            throw std::invalid_argument("'" + p.path + "': '" + entry + "' takes no [entry]");
          return foundation_parameter(p, entry.substr(11), model);
        }
      if (entry == "Damping/Modal ratios")
        return modal_ratio_parameter(p, model);
      if (std::find(geometry_entries.begin(), geometry_entries.end(), entry) !=
          geometry_entries.end())
        throw std::invalid_argument("'" + p.path + "' is the model's geometry (where its nodes "
                                    "are), which a realization does not move; vary a "
                                    "stiffness or a mass instead");
      const bool scalar = entry.rfind("Hinges/", 0) == 0 || entry.rfind("Bouc-Wen/", 0) == 0 ||
                          entry == "Damping/a0" || entry == "Damping/a1" ||
                          entry == "Damping/Damping ratio";
      if (!scalar)
        throw std::invalid_argument("'" + p.path + "' is not a parameter poundfe can vary (" +
                                    known_paths + ")");
      // an entry it knows, of one value (an unknown one says so first)
      const ModelParameter known =
        entry.rfind("Hinges/", 0) == 0   ? hinge_parameter(p, entry.substr(7), model) :
        entry.rfind("Bouc-Wen/", 0) == 0 ? bouc_wen_parameter(p, entry.substr(9), model) :
                                           p;
      if (indexed)
        throw std::invalid_argument("'" + p.path + "': '" + entry + "' takes no [entry]");
      if (entry.rfind("Hinges/", 0) == 0 || entry.rfind("Bouc-Wen/", 0) == 0)
        return known;
      if (entry == "Damping/a0" || entry == "Damping/a1")
        {
          p.kind = entry == "Damping/a0" ? Kind::rayleigh_a0 : Kind::rayleigh_a1;
          if (model.buildings[p.building].damping.kind != RayleighDamping::Kind::coefficients)
            throw std::invalid_argument("'" + p.path + "': building '" + name +
                                        "' has no given Rayleigh coefficients "
                                        "(Damping/Type = coefficients)");
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
      Assert(false, dealii::ExcInternalError());
      return p;
    }
  } // namespace

  bool
  ModelParameter::enters_matrices() const
  {
    return kind == Kind::storey_stiffness || kind == Kind::floor_mass ||
           kind == Kind::polar_moment || kind == Kind::member_section || kind == Kind::hinge_stiffness ||
           kind == Kind::hinge_stiffness_factor || kind == Kind::member_section_3d ||
           (kind == Kind::foundation_entry && foundation_matrices) ||
           (kind == Kind::spring_entry && spring_field == &SpringLawParameters::stiffness) ||
           (kind == Kind::resisting_plane && !plane_yield_drift);
  }

  bool
  ModelParameter::enters_mass() const
  {
    // a 3D member's rotary inertias are rho I with rho = m / A
    return kind == Kind::floor_mass || kind == Kind::polar_moment ||
           (kind == Kind::member_section && section == &Section::mass_per_length) ||
           (kind == Kind::member_section_3d && section_3d != &Section3D::youngs_modulus &&
            section_3d != &Section3D::shear_modulus && section_3d != &Section3D::torsion_constant &&
            section_3d != &Section3D::shear_area_y && section_3d != &Section3D::shear_area_z) ||
           (kind == Kind::foundation_entry && foundation_matrices);
  }

  bool
  ModelParameter::enters_linear_part() const
  {
    return enters_matrices() || kind == Kind::storey_damping || kind == Kind::damping_ratio ||
           kind == Kind::rayleigh_a0 || kind == Kind::rayleigh_a1 || kind == Kind::modal_ratio;
  }

  ModelParameter::Range
  ModelParameter::range() const
  {
    if (kind == Kind::friction_entry)
      return friction_entry_of(friction).range;
    if (kind == Kind::foundation_entry)
      return foundation_entry_of(foundation).entry.range;
    if (kind == Kind::contact_restitution)
      return {0, false, 1};
    if (kind == Kind::link_entry || kind == Kind::spring_entry)
      return list_field_of(*this).range;
    if (kind == Kind::bumper_entry) // a bumper of zero thickness is the bare contact
      return {0, bumper_field == &BumperParameters::thickness, infinity};
    if (kind == Kind::bouc_wen_shape)
      {
        if (shape == &BoucWenParameters::alpha)
          return {0, true, 1};
        if (shape == &BoucWenParameters::n) // Park-Wen-Ang's interaction needs n >= 2
          return {bidirectional ? 2.0 : 1.0, true, infinity};
        if (shape == &BoucWenParameters::beta || shape == &BoucWenParameters::gamma)
          return {-infinity, true, infinity}; // their sum and order are checked
        return {0, shape != &BoucWenParameters::A, infinity};
      }
    const bool zero = kind == Kind::storey_damping || kind == Kind::separation ||
                      kind == Kind::barrier_gap ||
                      kind == Kind::contact_damping || kind == Kind::static_friction ||
                      kind == Kind::kinetic_friction ||
                      kind == Kind::rayleigh_a0 || kind == Kind::rayleigh_a1 ||
                      kind == Kind::modal_ratio ||
                      (kind == Kind::member_section && section == &Section::mass_per_length) ||
                      (kind == Kind::member_section_3d &&
                       section_3d == &Section3D::mass_per_length);
    return {0, zero, infinity};
  }

  bool
  ModelParameter::can_be_zero() const
  {
    const Range r = range();
    return r.lower < 0 || (r.lower == 0 && r.lower_included);
  }

  namespace
  {
    /// The value of a hinge or Bouc-Wen parameter: that of the building's
    /// first hinge that has it (else its first hysteretic storey's).
    double
    hinge_or_storey_value(const ModelParameter &p, const Model &model)
    {
      if (p.kind == Kind::bouc_wen_shape)
        {
          const auto laws = bouc_wen_laws_of(model, p.building);
          return laws.empty() ? 0 : laws.front()->*p.shape;
        }
      for (const auto &h : hinges_of(model, p.building))
        switch (p.kind)
          {
            case Kind::hinge_stiffness:
              return h.law->stiffness;
            case Kind::hinge_stiffness_factor:
              if (origin_of(p, model, h).stiffness_from_section)
                return h.law->stiffness / h.section_stiffness;
              break;
            case Kind::hinge_yield_rotation:
              if (!origin_of(p, model, h).yield_from_moment)
                return h.law->yield_deformation;
              break;
            default:
              Assert(false, dealii::ExcInternalError());
          }
      return 0;
    }
    /// An entry that names one model-wide parameter refuses "[i]".
    void
    refuse_entry(const ModelParameter &p, const std::string &entry, const bool indexed)
    {
      if (indexed)
        throw std::invalid_argument("'" + p.path + "': '" + entry + "' takes no [entry]");
    }

    /// Contact/Stiffness, Damping, Coefficient of restitution and the
    /// Friction/ entries; nothing when `entry` is none of them.
    std::optional<ModelParameter>
    contact_or_friction_parameter(ModelParameter p, const std::string &entry, const bool indexed,
                                  const Model &model)
    {
      if (entry == "Contact/Stiffness" || entry == "Contact/Damping")
        {
          refuse_entry(p, entry, indexed);
          p.kind = entry == "Contact/Stiffness" ? Kind::contact_stiffness : Kind::contact_damping;
          if (model.gaps.empty())
            throw std::invalid_argument("'" + p.path +
                                        "': the model has no contact (Contact/Law)");
          return p;
        }
      if (entry == "Friction/Static coefficient" || entry == "Friction/Kinetic coefficient")
        {
          refuse_entry(p, entry, indexed);
          p.kind = entry == "Friction/Static coefficient" ? Kind::static_friction :
                                                            Kind::kinetic_friction;
          if (model.friction_surfaces.empty())
            throw std::invalid_argument("'" + p.path + "': the model has no friction surfaces");
          return p;
        }
      if (entry == "Contact/Coefficient of restitution")
        {
          refuse_entry(p, entry, indexed);
          p.kind = Kind::contact_restitution;
          if (model.gaps.empty())
            throw std::invalid_argument("'" + p.path +
                                        "': the model has no contact (Contact/Law)");
          if (!p.inputs)
            throw std::invalid_argument("'" + p.path +
                                        "' needs the input the model was built from");
          const ContactParameters &contact = p.inputs->contact;
          if (!contact_law_is_damped(contact.law) ||
              contact.damping_from == ContactDampingFrom::given)
            throw std::invalid_argument("'" + p.path + "': the contact damping does not come from "
                                        "the restitution (an undamped law, or Contact/Damping "
                                        "from = given)");
          return p;
        }
      if (entry.rfind("Friction/", 0) == 0)
        {
          const auto found = std::find_if(friction_entries.begin(), friction_entries.end(),
                                          [&](const auto &e) { return entry.substr(9) == e.name; });
          if (found != friction_entries.end())
            {
              refuse_entry(p, entry, indexed);
              p.kind     = Kind::friction_entry;
              p.friction = found->at;
              if (model.friction_surfaces.empty())
                throw std::invalid_argument("'" + p.path + "': the model has no friction surfaces");
              return p;
            }
        }
      return std::nullopt;
    }
  } // namespace

  std::vector<HingeOrigin>
  hinge_origins(const Model &model, const ModelParameters &input)
  {
    // as insert_hinges (model/model_builder.cc) reads the entries: the
    // hinge's member group's place in Groups (0 without Groups)
    // (3D frames: frame_building_3d.cc's add_hinge, the same reading)
    std::vector<HingeOrigin> origins;
    const auto origin = [&](const unsigned int building, const unsigned int group) {
      const BuildingParameters &b  = input.buildings[building];
      const auto         at = std::find(b.hinge_groups.begin(), b.hinge_groups.end(), group);
      const unsigned int g  = b.hinge_groups.empty() ? 0 : at - b.hinge_groups.begin();
      origins.push_back({value_for(b.hinge_stiffnesses, g) <= 0,
                         value_for(b.hinge_yield_moments, g) > 0});
    };
    for (const Hinge &hinge : model.hinges)
      origin(hinge.building, model.members[hinge.member].group);
    for (const Hinge3D &hinge : model.hinges_3d)
      origin(hinge.building, model.members_3d[hinge.member].group);
    return origins;
  }

  void
  settle_hinge_origins(std::vector<ModelParameter> &parameters, std::vector<HingeOrigin> origins,
                       const Model &model)
  {
    AssertDimension(origins.size(), model.hinges.size() + model.hinges_3d.size());
    for (const ModelParameter &p : parameters) // the 2D hinges, then the 3D ones
      for (unsigned int h = 0; h < origins.size(); ++h)
        if (hinge_building(model, h) == p.building)
          {
            if (p.kind == Kind::hinge_stiffness)
              origins[h].stiffness_from_section = false;
            if (p.kind == Kind::hinge_yield_moment)
              origins[h].yield_from_moment = true;
          }
    const auto shared = std::make_shared<const std::vector<HingeOrigin>>(std::move(origins));
    for (ModelParameter &p : parameters)
      p.hinges = shared;
  }

  ModelParameter
  model_parameter(const std::string &path, const Model &model,
                  std::shared_ptr<const std::vector<HingeOrigin>> hinges,
                  std::shared_ptr<const ModelInputs>              inputs)
  {
    static const std::regex with_entry(R"(^\s*(.*?)\s*\[\s*([0-9]+)\s*\]\s*$)");
    static const std::regex building(R"(^Building ([0-9]+)/(.+)$)");
    ModelParameter p;
    p.path            = path;
    p.hinges          = std::move(hinges);
    p.inputs          = std::move(inputs);
    std::string entry = path;
    std::smatch match;
    const bool  indexed = std::regex_match(path, match, with_entry);
    if (indexed)
      {
        entry = match[1];
        // no list holds more than an int's worth of entries (parse_count
        // instead of std::stoi, whose overflow says only "stoi")
        const std::optional<unsigned long> index =
          parse_count(match[2].str(), std::numeric_limits<int>::max());
        if (!index)
          throw std::invalid_argument("'" + path + "': the index " + match[2].str() +
                                      " is out of range (entries count from 1)");
        p.entry = static_cast<int>(*index) - 1;
        if (p.entry < 0)
          throw std::invalid_argument("'" + path + "': entries count from 1");
      }
    if (std::regex_match(entry, match, building))
      {
        p.building = building_index(path, match[1], model);
        return building_parameter(p, match[2], indexed, model);
      }
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
    if (entry.rfind("Contact/Barriers", 0) == 0)
      return barrier_parameter(p, entry, model);
    if (const std::optional<ModelParameter> found =
          contact_or_friction_parameter(p, entry, indexed, model))
      return *found;
    static const std::regex list_field(R"(^((?:Links|Springs)/[^/]+)(/([^/]*))?$)");
    if (entry == "Links/Viscous dampers") // c, as the mitigation study varies it
      return list_entry_parameter(p, entry, "c", model);
    if (std::regex_match(entry, match, list_field))
      return list_entry_parameter(p, match[1], match[3], model);
    if (entry == "Bumpers/Stiffness" || entry == "Bumpers/Thickness")
      {
        refuse_entry(p, entry, indexed);
        return bumper_parameter(p, entry, model);
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
          if (!model.plane_links.empty() && !named_planes(p, model).empty()) // 3D: k/2 a plane
            return 2 * named_planes(p, model).front()->stiffness;
          return model.links[named_storeys(p, model).front()].stiffness;
        case Kind::storey_damping:
          return model.links[named_storeys(p, model).front()].damping;
        case Kind::storey_yield_drift:
          if (!model.plane_links.empty() && !named_planes(p, model).empty())
            return named_planes(p, model).front()->hysteresis.yield_deformation;
          return model.links[named_storeys(p, model).front()].hysteresis.yield_deformation;
        case Kind::floor_mass:
          return floor_mass(model, *named_floors(p, model).front());
        case Kind::polar_moment:
          for (const NodalMass &m : model.masses)
            if (m.node == named_floors(p, model).front()->nodes.front())
              return m.polar_moment;
          break;
        case Kind::hinge_yield_moment:
          for (const auto &h : hinges_of(model, p.building))
            return h.law->yield_deformation * h.law->stiffness;
          break;
        case Kind::damping_ratio:
          return model.buildings[p.building].damping.damping_ratio;
        case Kind::separation:
          return model.gaps[gaps_after(model, p.building).front()].initial_gap;
        case Kind::barrier_gap:
          return model.gaps[named_barriers(p, model).front()].initial_gap;
        case Kind::contact_stiffness:
          return model.contact.stiffness;
        case Kind::contact_damping:
          return model.contact.damping;
        case Kind::static_friction:
          return model.friction_surfaces.front().law.static_coefficient;
        case Kind::kinetic_friction:
          return model.friction_surfaces.front().law.kinetic_coefficient;
        case Kind::link_entry:
          return model.building_links[named_list_members(p, model).front()].law.*p.link_field;
        case Kind::spring_entry:
          return model.springs[named_list_members(p, model).front()].law.*p.spring_field;
        case Kind::bumper_entry:
          return model.bumper.*p.bumper_field;
        case Kind::resisting_plane:
          return p.plane_yield_drift ?
                   named_planes(p, model).front()->hysteresis.yield_deformation :
                   named_planes(p, model).front()->stiffness;
        case Kind::member_section:
          for (const Member &member : model.members)
            if (named_member(p, member))
              return member.section.*p.section;
          break;
        case Kind::hinge_stiffness:
        case Kind::hinge_stiffness_factor:
        case Kind::hinge_yield_rotation:
        case Kind::bouc_wen_shape:
          return hinge_or_storey_value(p, model);
        case Kind::rayleigh_a0:
          return model.buildings[p.building].damping.a0;
        case Kind::rayleigh_a1:
          return model.buildings[p.building].damping.a1;
        case Kind::modal_ratio:
          return model.buildings[p.building].damping.modal_ratios[std::max(p.entry, 0)];
        case Kind::member_section_3d:
          for (const Member3D &member : model.members_3d)
            if (named_member(p, member))
              return member.section.*p.section_3d;
          break;
        case Kind::friction_entry:
          {
            FrictionLawParameters law = model.friction_surfaces.front().law;
            return p.friction(law);
          }
        case Kind::contact_restitution:
          return p.inputs->contact.restitution;
        case Kind::foundation_entry:
          {
            FoundationParameters typed =
              p.inputs->model.buildings[p.building].foundation.as_typed(model.dimension == 3);
            return p.foundation(typed);
          }
      }
    return 0;
  }

  namespace
  {
    /// The bumper no thicker than any gap (nor, a table bumper, than its
    /// table: its force beyond is not given), as the builder and the input
    /// check it (model/building_links.cc, model/link_parameters.cc).
    void
    require_bumper_fits(const Model &model)
    {
      const BumperParameters &bumper = model.bumper;
      for (const Gap &gap : model.gaps)
        if (bumper.thickness > gap.initial_gap)
          throw std::invalid_argument(
            "the sampled bumper (" + number_text(bumper.thickness) +
            " m) is thicker than the gap " + gap.label + " (" + number_text(gap.initial_gap) +
            " m) (Bumpers/Thickness must not exceed the smallest gap: sample them so, e.g. "
            "bounded or correlated)");
      if (bumper.law == BumperLaw::table && bumper.thickness > bumper.table.back()[0])
        throw std::invalid_argument("the sampled bumper (" + number_text(bumper.thickness) +
                                    " m) is thicker than its Bumpers/Table reaches (" +
                                    number_text(bumper.table.back()[0]) + " m)");
    }
  } // namespace

  ModelRealization::ModelRealization(const Analysis &base, std::vector<ModelParameter> parameters,
                                     const Eigensolver eigensolver_)
    : working(base)
    , targets(std::move(parameters))
    , eigensolver(eigensolver_)
  {
    for (const ModelParameter &p : targets)
      {
        linear = linear || p.enters_linear_part();
        if (p.inputs && !has_inputs)
          {
            inputs     = *p.inputs;
            has_inputs = true;
            for (BuildingParameters &b : inputs.model.buildings) // the foundations as typed
              b.foundation = b.foundation.as_typed(base.model.dimension == 3);
          }
      }
  }

  void
  ModelRealization::apply(const std::vector<double> &values)
  {
    AssertDimension(values.size(), targets.size());
    Model &model = working.model;
    bool matrices_changed = false; // M or K: the modes change
    bool contact_changed  = false; // k, m_e or e: the contact damping fitted again
    bool friction_changed = false;
    bool springs_changed  = false; // a friction element's N may take an SD reaction
    bool bumper_or_gap_changed = false;
    std::vector<bool> foundation_changed(model.buildings.size(), false);
    for (unsigned int i = 0; i < targets.size(); ++i)
      {
        const ModelParameter &p = targets[i];
        write(p, values[i], model, inputs);
        matrices_changed = matrices_changed || p.enters_matrices();
        contact_changed  = contact_changed || p.kind == Kind::contact_stiffness ||
                          p.kind == Kind::contact_restitution || p.kind == Kind::floor_mass;
        friction_changed = friction_changed || p.kind == Kind::static_friction ||
                           p.kind == Kind::kinetic_friction;
        springs_changed  = springs_changed || p.kind == Kind::spring_entry;
        bumper_or_gap_changed =
          bumper_or_gap_changed || p.kind == Kind::bumper_entry || p.kind == Kind::separation ||
          p.kind == Kind::barrier_gap;
        if (p.kind == Kind::foundation_entry)
          foundation_changed[p.building] = true;
      }
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      if (foundation_changed[b])
        map_foundation(b);
    const ContactParameters &contact = inputs.contact;
    if (has_inputs && contact_changed && contact_law_is_damped(contact.law) &&
        contact.damping_from != ContactDampingFrom::given)
      model.contact.damping = contact_law_damping(contact, model.contact);
    if (friction_changed)
      for (const FrictionSurface &surface : model.friction_surfaces)
        if (surface.law.kinetic_coefficient > surface.law.static_coefficient)
          throw std::invalid_argument(
            "the sampled friction coefficients give mu_k = " +
            number_text(surface.law.kinetic_coefficient) + " > mu_s = " +
            number_text(surface.law.static_coefficient) + " (Friction/Kinetic coefficient "
            "must not exceed the static one: sample them so, e.g. correlated or bounded)");
    if (springs_changed)
      for (FrictionSurface &surface : model.friction_surfaces)
        if (surface.law.normal.sd_reaction)
          take_sd_reaction(surface.law.normal, sd_spring_at(model, surface.node)->law);
    if (bumper_or_gap_changed && model.bumper.law != BumperLaw::none)
      require_bumper_fits(model);
    if (linear)
      assemble_linear_part(matrices_changed);
    if (!model.friction_surfaces.empty()) // k_s (automatic) and c_s of the new K, M
      fit_stick_laws(working.system, model);
  }

  void
  ModelRealization::map_foundation(const unsigned int b)
  {
    Model               &model = working.model;
    FoundationParameters p     = inputs.model.buildings[b].foundation;
    const FoundationGeometry &g = p.geometry;
    if (p.type != FoundationType::given && g.embedment > std::min(g.length, g.width))
      throw std::invalid_argument("the sampled foundation of building '" +
                                  model.buildings[b].name + "' is embedded " +
                                  number_text(g.embedment) + " m, deeper than its smaller side " +
                                  number_text(std::min(g.length, g.width)) + " m");
    p.recompute_impedance(model.dimension == 3);
    for (Foundation &f : model.foundations)
      if (f.building == b)
        {
          const bool vertical = std::any_of(f.parts.begin(), f.parts.end(), [](const FoundationPart &part) {
            return part.name == "_vertical";
          });
          f = f.rocking_node >= 0 ?
                plan_foundation(p, b, f.node, f.rocking_node,
                                {{f.parts[0].coefficients[0], f.parts[0].coefficients[1]}},
                                vertical) :
                planar_foundation(p, b, f.node, vertical);
        }
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
        working.system.structure_mass      = std::move(fresh.structure_mass);
        working.system.structure_stiffness = std::move(fresh.structure_stiffness);
      }
    LinearSystem &system = working.system;
    std::vector<std::array<double, 2>> coefficients = system.rayleigh;
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const RayleighDamping &d = model.buildings[b].damping;
        if (d.kind == RayleighDamping::Kind::coefficients)
          coefficients[b] = {{d.a0, d.a1}};
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
