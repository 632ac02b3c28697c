// The parameters of the friction surfaces, links and springs
// (model/parameter_registry.h):
//   Friction/Static coefficient, Friction/Kinetic coefficient, Friction/Stribeck
//   velocity, Belt velocity, Normal force, Normal force per displacement|velocity|
//   velocity cubed, Stick stiffness, Regularization velocity
//                                      of every friction element (nonlinear; a stick
//                                      dashpot 2 sqrt(k_s M_ii) follows k_s and M:
//                                      dynamics' fit_stick_laws)
//   Links/LIST/FIELD[i]                FIELD of entry i of the Links entry LIST
//                                      (nonlinear): Viscous dampers/c, alpha;
//                                      Kelvin-Voigt links/k, c, alpha; Maxwell links/k,
//                                      c; Elastic-plastic links/k, Fy, r; Soil
//                                      coupling/k, c; Rocking soil coupling/k, c.
//                                      Links/Viscous dampers[i] is .../c[i] (0: a
//                                      damper without force, as the mitigation study's
//                                      bare case of a damper size)
//   Springs/SD springs/K[i], L[i], H[i], Springs/Cubic springs/k1[i], k3[i]
//                                      of spring i of that entry (K, k1: the linear K;
//                                      the rest: the element; a friction element's N
//                                      from the SD spring follows)
// as model/building_links.cc and model/springs_and_friction.cc set them.
#include <poundfe/base/numbers.h>
#include <poundfe/model/friction_parameters.h>
#include <poundfe/model/model_builder.h>
#include <poundfe/model/parameter_registry.h>

#include <regex>

namespace poundfe::device_registration
{
  namespace
  {
    const double                infinity = std::numeric_limits<double>::infinity();
    const ModelParameter::Range positive{0, false, infinity}, non_negative{0, true, infinity};

    /// mu_k <= mu_s of every surface, once both are set.
    void
    require_friction_order(const ModelParameter &, Model &model, const ModelInputs *)
    {
      for (const FrictionSurface &surface : model.friction_surfaces)
        if (surface.law.kinetic_coefficient > surface.law.static_coefficient)
          throw std::invalid_argument(
            "the sampled friction coefficients give mu_k = " +
            number_text(surface.law.kinetic_coefficient) + " > mu_s = " +
            number_text(surface.law.static_coefficient) + " (Friction/Kinetic coefficient "
            "must not exceed the static one: sample them so, e.g. correlated or bounded)");
    }

    /// A friction element's N that takes an SD spring's reaction follows it.
    void
    follow_sd_reactions(const ModelParameter &, Model &model, const ModelInputs *)
    {
      for (FrictionSurface &surface : model.friction_surfaces)
        if (surface.law.normal.sd_reaction)
          take_sd_reaction(surface.law.normal, sd_spring_at(model, surface.node)->law);
    }

    /// An entry of the Friction section: where it is in the law, its values.
    struct FrictionField
    {
      const char *name;
      double &(*at)(FrictionLawParameters &);
      ModelParameter::Range range;
    };

#define POUNDFE_FRICTION_FIELD(expression) \
  [](FrictionLawParameters &l) -> double & { return l.expression; }
    const std::vector<FrictionField> friction_fields = {
      {"Static coefficient", POUNDFE_FRICTION_FIELD(static_coefficient), non_negative},
      {"Kinetic coefficient", POUNDFE_FRICTION_FIELD(kinetic_coefficient), non_negative},
      {"Stribeck velocity", POUNDFE_FRICTION_FIELD(stribeck_velocity), non_negative},
      {"Belt velocity", POUNDFE_FRICTION_FIELD(belt_velocity),
       {-maximum_belt_velocity, true, maximum_belt_velocity}},
      {"Normal force", POUNDFE_FRICTION_FIELD(normal.constant), non_negative},
      {"Normal force per displacement", POUNDFE_FRICTION_FIELD(normal.per_displacement),
       {-infinity, true, infinity}},
      {"Normal force per velocity", POUNDFE_FRICTION_FIELD(normal.per_velocity),
       {-infinity, true, infinity}},
      {"Normal force per velocity cubed", POUNDFE_FRICTION_FIELD(normal.per_velocity_cubed),
       {-infinity, true, infinity}},
      {"Stick stiffness", POUNDFE_FRICTION_FIELD(stick_stiffness), positive},
      {"Regularization velocity", POUNDFE_FRICTION_FIELD(regularization_velocity), positive}};
#undef POUNDFE_FRICTION_FIELD

    void
    friction(ParameterRegistry &registry)
    {
      for (const FrictionField &f : friction_fields)
        {
          const std::string name        = f.name;
          const bool        coefficient = name.find("coefficient") != std::string::npos;
          ParameterRegistration r;
          r.name  = "Friction/" + name;
          r.range = f.range;
          if (!coefficient) // the others listed as one family
            r.family = "Friction/entries", r.label = name;
          r.resolve = [](ModelParameter &p, const Model &model) {
            if (model.friction_surfaces.empty())
              refuse_parameter(p, ": the model has no friction surfaces");
          };
          r.get = [at = f.at](const ModelParameter &, const Model &model) {
            FrictionLawParameters law = model.friction_surfaces.front().law;
            return at(law);
          };
          const bool stick = name == "Stick stiffness";
          r.set = [at = f.at, stick](const ModelParameter &, const double value, Model &model,
                                     ModelInputs &) {
            for (FrictionSurface &surface : model.friction_surfaces)
              {
                at(surface.law) = value;
                if (stick)
                  surface.automatic_stick_stiffness = false;
              }
          };
          if (coefficient)
            r.follow_up = require_friction_order;
          registry.add(r);
        }
    }

    /// A field of the entries of a `Links` or `Springs` list: the list, the
    /// field's name in the entries' form, where the builder puts it in the
    /// law and the values it accepts there.
    struct ListField
    {
      const char                   *list;
      const char                   *name;
      double LinkLawParameters::*   link;
      double SpringLawParameters::* spring;
      ModelParameter::Range         range;
    };

    const ModelParameter::Range  exponent_range{0, false, 1}, hardening_range{0, true, 1, false};
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
    named_list_members(const ModelParameter &p, const Model &model, const std::string &list)
    {
      const std::vector<unsigned int> all = list_members(model, list);
      return p.entry < 0 ? all : std::vector<unsigned int>{all.at(p.entry)};
    }

    /// "LIST/FIELD" of a list it knows, but not a field of it (or none).
    void
    explain_list_field(const ModelParameter &p, const std::string &entry, const bool of_building,
                       bool, const Model &)
    {
      static const std::regex list_field(R"(^((?:Links|Springs)/[^/]+)(/([^/]*))?$)");
      std::smatch             match;
      if (of_building || !std::regex_match(entry, match, list_field))
        return;
      std::string fields;
      for (const ListField &f : list_fields)
        if (f.list == match[1].str())
          fields += (fields.empty() ? "" : ", ") + std::string(f.name);
      if (!fields.empty())
        refuse_parameter(p, ": name a field of the entries of '" + match[1].str() + "', '" +
                              match[1].str() + "/FIELD[i]' with FIELD one of " + fields);
    }

    void
    lists(ParameterRegistry &registry)
    {
      for (const ListField &f : list_fields)
        {
          const std::string list = f.list;
          ParameterRegistration r;
          r.name        = list + "/" + f.name;
          r.takes_index = true;
          r.family      = list;
          r.label       = f.name;
          r.range       = f.range;
          r.touches     = f.spring == &SpringLawParameters::stiffness ? ModelParameter::stiffness :
                                                                        ModelParameter::nonlinear_only;
          r.resolve     = [list](ModelParameter &p, const Model &model) {
            const std::size_t n = list_members(model, list).size();
            if (n == 0)
              refuse_parameter(p, ": the model has no entries of '" + list + "'");
            if (p.entry >= int(n))
              refuse_parameter(p, ": the model has " + list.substr(list.find('/') + 1) +
                                    " 1.." + std::to_string(n));
          };
          if (f.link)
            {
              r.get = [list, field = f.link](const ModelParameter &p, const Model &model) {
                return model.building_links[named_list_members(p, model, list).front()].law.*field;
              };
              r.set = [list, field = f.link](const ModelParameter &p, const double value,
                                             Model &model, ModelInputs &) {
                for (const unsigned int l : named_list_members(p, model, list))
                  model.building_links[l].law.*field = value;
              };
            }
          else
            {
              r.get = [list, field = f.spring](const ModelParameter &p, const Model &model) {
                return model.springs[named_list_members(p, model, list).front()].law.*field;
              };
              r.set = [list, field = f.spring](const ModelParameter &p, const double value,
                                               Model &model, ModelInputs &) {
                for (const unsigned int s : named_list_members(p, model, list))
                  model.springs[s].law.*field = value;
              };
              r.follow_up = follow_sd_reactions;
            }
          registry.add(r);
        }
      // c, as the mitigation study varies it
      registry.add_alias("Links/Viscous dampers", "Links/Viscous dampers/c");
      registry.add_explanation(explain_list_field);
    }
  } // namespace
} // namespace poundfe::device_registration

namespace poundfe
{
  void
  register_device_parameters(ParameterRegistry &registry)
  {
    device_registration::friction(registry);
    device_registration::lists(registry);
  }
} // namespace poundfe
