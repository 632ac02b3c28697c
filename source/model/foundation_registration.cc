// The parameters of a building's compliant foundation (model/parameter_registry.h):
//   Building b/Foundation/ENTRY        the soil (Shear-wave velocity, Soil density,
//                                      Poisson ratio), size (Length, Width, Embedment),
//                                      typed springs and dashpots, Mass and inertias
//                                      of b's compliant foundation (K, M; dashpots:
//                                      nonlinear)
// A value is written into the working copy of the input's foundation entries
// (as typed); once every value is set the foundation record is made again as
// the builder makes it (FoundationParameters::recompute_impedance,
// planar_foundation, plan_foundation).
#include <poundfe/base/numbers.h>
#include <poundfe/model/foundation_parameters.h>
#include <poundfe/model/frame_foundation.h>
#include <poundfe/model/parameter_registry.h>
#include <poundfe/model/plan_foundation.h>

#include <algorithm>

namespace poundfe::foundation_registration
{
  namespace
  {
    const double                infinity = std::numeric_limits<double>::infinity();
    const ModelParameter::Range positive{0, false, infinity}, non_negative{0, true, infinity};

    /// A foundation entry: where it is, its values, which foundations have
    /// it (those from the soil: gazetas, cone; typed ones: given; every
    /// one), `three_d` only in 3D, `vertical` only with a vertical part
    /// (frames); `matrices`: it enters K and M (else only the dashpots).
    struct FoundationEntry
    {
      const char *name;
      double &(*at)(FoundationParameters &);
      ModelParameter::Range range;
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
      {"Shear-wave velocity", POUNDFE_FOUNDATION_FIELD(soil.shear_wave_velocity), positive,
       FoundationEntry::soil, false, false, true},
      {"Soil density", POUNDFE_FOUNDATION_FIELD(soil.density), positive, FoundationEntry::soil,
       false, false, true},
      {"Poisson ratio", POUNDFE_FOUNDATION_FIELD(soil.poisson_ratio), {0, false, 0.5},
       FoundationEntry::soil, false, false, true},
      {"Length", POUNDFE_FOUNDATION_FIELD(geometry.length), positive, FoundationEntry::soil,
       false, false, true},
      {"Width", POUNDFE_FOUNDATION_FIELD(geometry.width), positive, FoundationEntry::soil, false,
       false, true},
      {"Embedment", POUNDFE_FOUNDATION_FIELD(geometry.embedment), non_negative,
       FoundationEntry::soil, false, false, true},
      {"Horizontal stiffness", POUNDFE_FOUNDATION_FIELD(given.horizontal_stiffness), positive,
       FoundationEntry::typed, false, false, true},
      {"Rocking stiffness", POUNDFE_FOUNDATION_FIELD(given.rocking_stiffness), positive,
       FoundationEntry::typed, false, false, true},
      {"Vertical stiffness", POUNDFE_FOUNDATION_FIELD(given.vertical_stiffness), positive,
       FoundationEntry::typed, false, true, true},
      {"Horizontal damping", POUNDFE_FOUNDATION_FIELD(given.horizontal_damping), non_negative,
       FoundationEntry::typed, false, false, false},
      {"Rocking damping", POUNDFE_FOUNDATION_FIELD(given.rocking_damping), non_negative,
       FoundationEntry::typed, false, false, false},
      {"Vertical damping", POUNDFE_FOUNDATION_FIELD(given.vertical_damping), non_negative,
       FoundationEntry::typed, false, true, false},
      {"Horizontal stiffness y", POUNDFE_FOUNDATION_FIELD(given_3d.sway_stiffness[1]), positive,
       FoundationEntry::typed, true, false, true},
      {"Rocking stiffness x", POUNDFE_FOUNDATION_FIELD(given_3d.rocking_stiffness[0]), positive,
       FoundationEntry::typed, true, false, true},
      {"Torsional stiffness", POUNDFE_FOUNDATION_FIELD(given_3d.torsional_stiffness), positive,
       FoundationEntry::typed, true, false, true},
      {"Horizontal damping y", POUNDFE_FOUNDATION_FIELD(given_3d.sway_damping[1]),
       non_negative, FoundationEntry::typed, true, false, false},
      {"Rocking damping x", POUNDFE_FOUNDATION_FIELD(given_3d.rocking_damping[0]), non_negative,
       FoundationEntry::typed, true, false, false},
      {"Torsional damping", POUNDFE_FOUNDATION_FIELD(given_3d.torsional_damping), non_negative,
       FoundationEntry::typed, true, false, false},
      {"Mass", POUNDFE_FOUNDATION_FIELD(mass), positive, FoundationEntry::any, false, false,
       true},
      {"Rotary inertia", POUNDFE_FOUNDATION_FIELD(rotary_inertia), positive,
       FoundationEntry::any, false, false, true},
      {"Rotary inertia x", POUNDFE_FOUNDATION_FIELD(rotary_inertia_x), positive,
       FoundationEntry::any, true, false, true},
      {"Polar inertia", POUNDFE_FOUNDATION_FIELD(polar_inertia), positive, FoundationEntry::any,
       true, false, true}};
#undef POUNDFE_FOUNDATION_FIELD

    bool
    has_vertical_part(const Foundation &f)
    {
      return std::any_of(f.parts.begin(), f.parts.end(),
                         [](const FoundationPart &part) { return part.name == "_vertical"; });
    }

    /// "Foundation/ENTRY" of building b's compliant foundation: an entry
    /// its Type uses (the soil's for gazetas and cone, the typed springs
    /// and dashpots for given), in 3D the 3D ones, the vertical ones under
    /// a frame.
    void
    check_foundation(const ModelParameter &p, const Model &model, const FoundationEntry &e)
    {
      const std::string &name       = model.buildings[p.building].name;
      const auto         foundation = std::find_if(model.foundations.begin(), model.foundations.end(),
                                           [&](const Foundation &f) { return f.building == p.building; });
      if (foundation == model.foundations.end())
        refuse_parameter(p, ": building '" + name + "' has no compliant foundation "
                              "(Foundation/Type = none)");
      if (!p.inputs)
        refuse_parameter(p, ": a foundation entry needs the input the model was built from");
      const FoundationParameters &input = p.inputs->model.buildings[p.building].foundation;
      const bool                  given = input.type == FoundationType::given;
      if (e.of == FoundationEntry::soil && given)
        refuse_parameter(p, ": building '" + name + "' has its springs and dashpots typed in "
                              "(Foundation/Type = given), not from the soil");
      if (e.of == FoundationEntry::typed && !given)
        refuse_parameter(p, ": building '" + name + "' has its springs and dashpots from the "
                              "soil (Foundation/Type = " +
                              foundation_type_names().name(input.type) +
                              "); vary the soil's entries");
      if (e.three_d && model.dimension != 3)
        refuse_parameter(p, " is an entry of a 3D foundation (Model/Dimension = 3)");
      if (e.vertical && !has_vertical_part(*foundation))
        refuse_parameter(p, ": the foundation of building '" + name +
                              "' has no vertical spring (a shear building's)");
      if (std::string(e.name) == "Embedment" && input.type == FoundationType::cone)
        refuse_parameter(p, ": the cones are for surface foundations (Embedment = 0)");
    }

    /// Building b's foundation record from its entries as set, as the
    /// builder makes it.
    void
    map_foundation(const ModelParameter &parameter, Model &model, const ModelInputs *inputs)
    {
      const unsigned int   b = parameter.building;
      FoundationParameters p = inputs->model.buildings[b].foundation;
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
            const bool vertical = has_vertical_part(f);
            f = f.rocking_node >= 0 ?
                  plan_foundation(p, b, f.node, f.rocking_node,
                                  {{f.parts[0].coefficients[0], f.parts[0].coefficients[1]}},
                                  vertical) :
                  planar_foundation(p, b, f.node, vertical);
          }
    }

    void
    foundations(ParameterRegistry &registry)
    {
      for (const FoundationEntry &e : foundation_entries)
        {
          ParameterRegistration r;
          r.name        = std::string("Foundation/") + e.name;
          r.of_building = true;
          r.family      = "Foundation";
          r.label       = e.name;
          r.range       = e.range;
          r.touches     = e.matrices ? ModelParameter::mass | ModelParameter::stiffness :
                                       ModelParameter::nonlinear_only;
          r.resolve     = [&e](ModelParameter &p, const Model &model) { check_foundation(p, model, e); };
          r.get         = [at = e.at](const ModelParameter &p, const Model &model) {
            FoundationParameters typed =
              p.inputs->model.buildings[p.building].foundation.as_typed(model.dimension == 3);
            return at(typed);
          };
          r.set = [at = e.at](const ModelParameter &p, const double value, Model &,
                              ModelInputs &inputs) {
            at(inputs.model.buildings[p.building].foundation) = value;
          };
          r.follow_up = map_foundation;
          registry.add(r);
        }
      registry.add_explanation([](const ModelParameter &p, const std::string &entry,
                                  const bool of_building, const bool indexed, const Model &) {
        if (of_building && indexed && entry.rfind("Foundation/", 0) == 0)
          refuse_parameter(p, ": '" + entry + "' takes no [entry]");
      });
    }
  } // namespace
} // namespace poundfe::foundation_registration

namespace poundfe
{
  void
  register_foundation_parameters(ParameterRegistry &registry)
  {
    foundation_registration::foundations(registry);
  }
} // namespace poundfe
