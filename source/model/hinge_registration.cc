// The parameters of a building's hinges and Bouc-Wen laws
// (model/parameter_registry.h), as the model builder sets them
// (model_builder.cc's insert_hinges, frame_building_3d.cc's add_hinge):
//   Building b/Hinges/Yield moment     M_y of every hinge of b: u_y = M_y / k (nonlinear)
//   Building b/Hinges/Stiffness, Building b/Hinges/Stiffness factor
//                                      k of every hinge of b (K), given or
//                                      f 6 E I / L of its member (u_y = M_y / k follows)
//   Building b/Hinges/Yield rotation   u_y of b's hinges without a yield moment
//   Building b/Bouc-Wen/P              P = alpha, A, beta, gamma, n, delta A, delta nu,
//                                      delta eta of every hinge (2D; 3D: both bending
//                                      axes, uniaxial or biaxial) and hysteretic storey
//                                      or resisting plane of b (nonlinear; a
//                                      bidirectional law: n >= 2, no degradation)
#include <poundfe/base/numbers.h>
#include <poundfe/laws/bouc_wen_bounds.h>
#include <poundfe/model/parameter_registry.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace poundfe
{
  void
  set_hinge_stiffness(BoucWenParameters &law, const HingeOrigin &origin, const double stiffness)
  {
    if (origin.yield_from_moment)
      law.yield_deformation = law.stiffness * law.yield_deformation / stiffness;
    law.stiffness = stiffness;
  }

  double
  section_stiffness(const Model &model, const Hinge &hinge)
  {
    const Member &member = model.members[hinge.member];
    return 6 * member.section.youngs_modulus * member.section.second_moment /
           member.member_length;
  }

  double
  section_stiffness_3d(const Model &model, const Hinge3D &hinge)
  {
    const Member3D &member = model.members_3d[hinge.member];
    const double    length = std::hypot(member.ends[1][0] - member.ends[0][0],
                                     member.ends[1][1] - member.ends[0][1],
                                     member.ends[1][2] - member.ends[0][2]);
    return 6 * member.section.youngs_modulus *
           (hinge.slot == 0 ? member.section.second_moment_y : member.section.second_moment_z) /
           length;
  }
} // namespace poundfe

namespace poundfe::hinge_registration
{
  namespace
  {
    const double infinity = std::numeric_limits<double>::infinity();

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

    enum class HingeEntry
    {
      yield_moment,
      stiffness,
      stiffness_factor,
      yield_rotation
    };

    /// "Hinges/ENTRY": the building's hinges must have what the entry sets
    /// (checked when `p.hinges` is known).
    void
    check_hinges(const ModelParameter &p, const Model &model, const HingeEntry entry)
    {
      const std::string &name = model.buildings[p.building].name;
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
        refuse_parameter(p, ": building '" + name + "' has no hinges");
      if (p.hinges && entry == HingeEntry::stiffness_factor && !from_section)
        refuse_parameter(p, ": the hinges of building '" + name +
                              "' have a given Hinges/Stiffness (the factor is unused)");
      if (p.hinges && entry == HingeEntry::yield_rotation && !from_rotation)
        refuse_parameter(p, ": the hinges of building '" + name +
                              "' yield at their Hinges/Yield moment (the rotation is unused)");
    }

    ParameterRegistration
    hinge_entry(const std::string &name, const HingeEntry entry, const unsigned int touches)
    {
      ParameterRegistration r;
      r.name                = "Hinges/" + name;
      r.of_building         = true;
      r.index_refused_first = false; // an unknown or missing hinge says so first
      r.range               = {0, false, infinity};
      r.touches             = touches;
      r.resolve = [entry](ModelParameter &p, const Model &model) { check_hinges(p, model, entry); };
      return r;
    }

    /// Its effect on the origins of the building's hinges once sampled.
    auto
    settle_origins(const bool stiffness)
    {
      return [stiffness](const ModelParameter &p, std::vector<HingeOrigin> &origins,
                         const Model &model) {
        for (unsigned int h = 0; h < origins.size(); ++h)
          if (hinge_building(model, h) == p.building)
            (stiffness ? origins[h].stiffness_from_section : origins[h].yield_from_moment) =
              !stiffness;
      };
    }

    void
    hinges(ParameterRegistry &registry)
    {
      ParameterRegistration my =
        hinge_entry("Yield moment", HingeEntry::yield_moment, ModelParameter::nonlinear_only);
      my.get = [](const ModelParameter &p, const Model &model) {
        for (const auto &h : hinges_of(model, p.building))
          return h.law->yield_deformation * h.law->stiffness;
        return 0.0;
      };
      my.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        for (const auto &hinge : hinges_of(model, p.building))
          hinge.law->yield_deformation = value / hinge.law->stiffness;
      };
      my.settle = settle_origins(false);
      registry.add(my);

      ParameterRegistration k = hinge_entry("Stiffness", HingeEntry::stiffness, ModelParameter::stiffness);
      k.get = [](const ModelParameter &p, const Model &model) {
        for (const auto &h : hinges_of(model, p.building))
          return h.law->stiffness;
        return 0.0;
      };
      k.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        for (const auto &hinge : hinges_of(model, p.building))
          set_hinge_stiffness(*hinge.law, origin_of(p, model, hinge), value);
      };
      k.settle = settle_origins(true);
      registry.add(k);

      ParameterRegistration f =
        hinge_entry("Stiffness factor", HingeEntry::stiffness_factor, ModelParameter::stiffness);
      f.get = [](const ModelParameter &p, const Model &model) {
        for (const auto &h : hinges_of(model, p.building))
          if (origin_of(p, model, h).stiffness_from_section)
            return h.law->stiffness / h.section_stiffness;
        return 0.0;
      };
      f.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        for (const auto &hinge : hinges_of(model, p.building))
          if (origin_of(p, model, hinge).stiffness_from_section)
            set_hinge_stiffness(*hinge.law, origin_of(p, model, hinge),
                                value * hinge.section_stiffness);
      };
      registry.add(f);

      ParameterRegistration uy =
        hinge_entry("Yield rotation", HingeEntry::yield_rotation, ModelParameter::nonlinear_only);
      uy.get = [](const ModelParameter &p, const Model &model) {
        for (const auto &h : hinges_of(model, p.building))
          if (!origin_of(p, model, h).yield_from_moment)
            return h.law->yield_deformation;
        return 0.0;
      };
      uy.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        for (const auto &hinge : hinges_of(model, p.building))
          if (!origin_of(p, model, hinge).yield_from_moment)
            hinge.law->yield_deformation = value;
      };
      registry.add(uy);
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

    /// The shape within the ranges of laws/bouc_wen_bounds.h, as the input
    /// checks it (model/parameters.cc).
    void
    require_bouc_wen_shape(const ModelParameter &p, const BoucWenParameters &h)
    {
      if (const BoucWenShapeProblem shape = bouc_wen_shape_problem(h); !shape.entry.empty())
        throw std::invalid_argument("'" + p.path + "': the value gives the shape A = " +
                                    number_text(h.A) + ", beta = " + number_text(h.beta) +
                                    ", gamma = " + number_text(h.gamma) + ", n = " +
                                    number_text(h.n) + "; its " + shape.entry + ": " +
                                    shape.problem);
    }

    /// The values Bouc-Wen entry `shape` can take (variant 1: bidirectional).
    ModelParameter::Range
    bouc_wen_range(double BoucWenParameters::*shape, const bool bidirectional)
    {
      if (shape == &BoucWenParameters::alpha)
        return {0, true, 1};
      if (shape == &BoucWenParameters::n) // Park-Wen-Ang's interaction needs n >= 2
        return {bidirectional ? 2.0 : 1.0, true, infinity};
      if (shape == &BoucWenParameters::beta || shape == &BoucWenParameters::gamma)
        return {-infinity, true, infinity}; // their sum and order are checked
      return {0, shape != &BoucWenParameters::A, infinity};
    }

    void
    check_bouc_wen(ModelParameter &p, const Model &model, double BoucWenParameters::*shape)
    {
      const std::string &name = model.buildings[p.building].name;
      if (bouc_wen_laws_of(model, p.building).empty())
        refuse_parameter(p, ": building '" + name + "' has no Bouc-Wen hinges, hysteretic "
                              "storeys or hysteretic resisting planes");
      p.variant     = has_bidirectional_bouc_wen(model, p.building) ? 1 : 0;
      p.value_range = bouc_wen_range(shape, p.variant == 1);
      if (p.variant == 1 &&
          (shape == &BoucWenParameters::delta_A || shape == &BoucWenParameters::delta_nu ||
           shape == &BoucWenParameters::delta_eta))
        refuse_parameter(p, ": the Bouc-Wen law of building '" + name +
                              "' is bidirectional (Hinges/Biaxial interaction = true or "
                              "Plan/Storey law = bidirectional Bouc-Wen), which has no "
                              "degradation");
    }

    void
    bouc_wen(ParameterRegistry &registry)
    {
      const std::vector<std::pair<std::string, double BoucWenParameters::*>> entries = {
        {"alpha", &BoucWenParameters::alpha},       {"A", &BoucWenParameters::A},
        {"beta", &BoucWenParameters::beta},         {"gamma", &BoucWenParameters::gamma},
        {"n", &BoucWenParameters::n},               {"delta A", &BoucWenParameters::delta_A},
        {"delta nu", &BoucWenParameters::delta_nu}, {"delta eta", &BoucWenParameters::delta_eta}};
      for (const auto &[label, shape] : entries)
        {
          ParameterRegistration r;
          r.name                = "Bouc-Wen/" + label;
          r.of_building         = true;
          r.index_refused_first = false;
          r.family              = "Bouc-Wen";
          r.label               = label;
          r.range               = bouc_wen_range(shape, false);
          r.resolve = [shape = shape](ModelParameter &p, const Model &model) {
            check_bouc_wen(p, model, shape);
          };
          r.get = [shape = shape](const ModelParameter &p, const Model &model) {
            const auto laws = bouc_wen_laws_of(model, p.building);
            return laws.empty() ? 0 : laws.front()->*shape;
          };
          r.set = [shape = shape](const ModelParameter &p, const double value, Model &model,
                                  ModelInputs &) {
            for (BoucWenParameters *law : bouc_wen_laws_of(model, p.building))
              {
                law->*shape = value;
                require_bouc_wen_shape(p, *law);
              }
          };
          registry.add(r);
        }
    }
  } // namespace
} // namespace poundfe::hinge_registration

namespace poundfe
{
  void
  register_hinge_parameters(ParameterRegistry &registry)
  {
    hinge_registration::hinges(registry);
    hinge_registration::bouc_wen(registry);
  }
} // namespace poundfe
