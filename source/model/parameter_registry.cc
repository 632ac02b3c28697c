// The registry of the model parameters (model/parameter_registry.h): the
// ONE list of the parts' registration functions, the reading of a path
// ("Building b/ENTRY[i]") into a registration and its indices, and what is
// common to every parameter (range check, the known-paths list, the
// hinges' origins).
#include <poundfe/base/numbers.h>
#include <poundfe/model/parameter_registry.h>
#include <poundfe/model/plan_builder.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <regex>
#include <stdexcept>

namespace poundfe
{
  const ParameterRegistry &
  parameter_registry()
  {
    static const ParameterRegistry registry = [] {
      ParameterRegistry r;
      for (void (*part)(ParameterRegistry &) :
           {register_storey_parameters, register_floor_parameters, register_damping_parameters,
            register_hinge_parameters, register_section_parameters,
            register_contact_parameters, register_device_parameters,
            register_foundation_parameters})
        part(r);
      return r;
    }();
    return registry;
  }

  std::string
  ParameterRegistration::pattern() const
  {
    return (of_building ? "Building b/" : "") + name + (takes_index ? "[i]" : "");
  }

  void
  ParameterRegistry::add(ParameterRegistration registration)
  {
    Assert(registration.get && registration.set, dealii::ExcMessage("a parameter needs get and set"));
    Assert(!find(registration.name, registration.of_building),
           dealii::ExcMessage("'" + registration.name + "' is registered twice"));
    entries.push_back(std::move(registration));
  }

  void
  ParameterRegistry::add_explanation(Explanation explain)
  {
    explanations.push_back(std::move(explain));
  }

  void
  ParameterRegistry::add_alias(const std::string &name, const std::string &same_as)
  {
    aliases.emplace_back(name, same_as);
  }

  std::string
  ParameterRegistry::resolve_alias(const std::string &name) const
  {
    for (const auto &[alias, same_as] : aliases)
      if (alias == name)
        return same_as;
    return name;
  }

  const ParameterRegistration *
  ParameterRegistry::find(const std::string &name, const bool of_building) const
  {
    for (const ParameterRegistration &r : entries)
      if (r.name == name && r.of_building == of_building)
        return &r;
    return nullptr;
  }

  void
  ParameterRegistry::refuse(const ModelParameter &p, const std::string &entry,
                            const bool of_building, const bool indexed, const Model &model) const
  {
    for (const Explanation &explain : explanations)
      explain(p, entry, of_building, indexed, model);
    refuse_unknown_parameter(p);
  }

  std::string
  ParameterRegistry::known_paths() const
  {
    std::string text, family, labels;
    const auto  close = [&] {
      if (!labels.empty())
        text += " (" + labels + ")";
      labels.clear();
    };
    for (const ParameterRegistration &r : entries)
      {
        if (!r.listed)
          continue;
        if (!r.family.empty() && r.family == family)
          {
            labels += (labels.empty() ? "" : ", ") + r.label;
            continue;
          }
        close();
        family = r.family;
        text += (text.empty() ? "" : ", ") + r.pattern();
      }
    close();
    return text;
  }

  void
  refuse_unknown_parameter(const ModelParameter &p)
  {
    throw std::invalid_argument("'" + p.path + "' is not a parameter poundfe can vary (" +
                                parameter_registry().known_paths() + ")");
  }

  void
  refuse_parameter(const ModelParameter &p, const std::string &what)
  {
    throw std::invalid_argument("'" + p.path + "'" + what);
  }

  bool
  ModelParameter::can_be_zero() const
  {
    const Range r = range();
    return r.lower < 0 || (r.lower == 0 && r.lower_included);
  }

  double
  ModelParameter::value(const Model &model) const
  {
    Assert(registration, dealii::ExcMessage("an unresolved parameter"));
    return registration->get(*this, model);
  }

  void
  ModelParameter::set(const double value, Model &model, ModelInputs &working_inputs) const
  {
    Assert(registration, dealii::ExcMessage("an unresolved parameter"));
    const Range r = range();
    // beyond 1e150 in size the builder refuses the entry, or the K or M
    // it enters (dynamics/analysis.cc), whatever the parameter's range
    if (!(r.lower_included ? value >= r.lower : value > r.lower) ||
        !(r.upper_included ? value <= r.upper : value < r.upper) ||
        !(std::abs(value) <= largest_model_value))
      {
        std::string text;
        if (std::isfinite(r.lower))
          text += (r.lower_included ? ">= " : "> ") + number_text(r.lower) + " and ";
        if (std::isfinite(r.upper))
          text += (r.upper_included ? "<= " : "< ") + number_text(r.upper) + " and ";
        text += "at most 1e150 in size";
        throw std::invalid_argument("'" + path + "' cannot take the value " +
                                    number_text(value) + " (it must be " + text +
                                    "; a sampled one: choose a distribution that stays in "
                                    "range, e.g. lognormal or truncated normal)");
      }
    registration->set(*this, value, model, working_inputs);
  }

  bool
  ModelParameter::set_as_built(const Model &model) const
  {
    Assert(registration, dealii::ExcMessage("an unresolved parameter"));
    return registration->built_alike ? registration->built_alike(*this, model) :
                                       touches == nonlinear_only;
  }

  bool
  ModelParameter::overwrites(const ModelParameter &earlier) const
  {
    return registration == earlier.registration && building == earlier.building &&
           (entry == earlier.entry || entry < 0) && group == earlier.group &&
           variant == earlier.variant;
  }

  double
  model_parameter_value(const ModelParameter &parameter, const Model &model)
  {
    return parameter.value(model);
  }

  namespace
  {
    /// Building b of "Building b/..." (0-based), checked against the model.
    unsigned int
    registered_building_index(const std::string &path, const std::string &number,
                              const Model &model)
    {
      const unsigned long b = std::stoul(number);
      if (b < 1 || b > model.buildings.size())
        throw std::invalid_argument("'" + path + "': the model has buildings 1.." +
                                    std::to_string(model.buildings.size()));
      return b - 1;
    }

    /// The 0-based entry of "ENTRY[i]" (-1 without [i]), `entry` left ENTRY.
    int
    registered_list_entry(const std::string &path, std::string &entry)
    {
      static const std::regex with_entry(R"(^\s*(.*?)\s*\[\s*([0-9]+)\s*\]\s*$)");
      std::smatch             match;
      if (!std::regex_match(path, match, with_entry))
        return -1;
      entry = match[1];
      // no list holds more than an int's worth of entries (parse_count
      // instead of std::stoi, whose overflow says only "stoi")
      const std::optional<unsigned long> index =
        parse_count(match[2].str(), std::numeric_limits<int>::max());
      if (!index)
        throw std::invalid_argument("'" + path + "': the index " + match[2].str() +
                                    " is out of range (entries count from 1)");
      if (*index == 0)
        throw std::invalid_argument("'" + path + "': entries count from 1");
      return static_cast<int>(*index) - 1;
    }
  } // namespace

  ModelParameter
  model_parameter(const std::string &path, const Model &model,
                  std::shared_ptr<const std::vector<HingeOrigin>> hinges,
                  std::shared_ptr<const ModelInputs>              inputs)
  {
    static const std::regex building(R"(^Building ([0-9]+)/(.+)$)");
    static const std::regex section(R"(^Sections/Section ([0-9]+)/(.+)$)");
    ModelParameter p;
    p.path            = path;
    p.hinges          = std::move(hinges);
    p.inputs          = std::move(inputs);
    std::string entry = path;
    p.entry           = registered_list_entry(path, entry);
    const bool  indexed = p.entry >= 0;
    std::smatch match;
    const bool  of_building = std::regex_match(entry, match, building);
    if (of_building)
      {
        p.building = registered_building_index(path, match[1], model);
        entry      = match[2];
      }
    else if (std::regex_match(entry, match, section)) // "Sections/Section k/ENTRY"
      {
        const std::optional<unsigned long> k = parse_count(match[1].str(), 1000);
        p.group = k ? int(*k) - 1 : -1;
        entry   = "Sections/Section k/" + match[2].str();
      }
    const ParameterRegistry     &registry = parameter_registry();
    const ParameterRegistration *r = registry.find(registry.resolve_alias(entry), of_building);
    if (!r)
      registry.refuse(p, entry, of_building, indexed, model);
    p.registration = r;
    p.value_range  = r->range;
    p.touches      = r->touches;
    if (indexed && !r->takes_index && r->index_refused_first)
      refuse_parameter(p, ": '" + entry + "' takes no [entry]");
    if (r->resolve)
      r->resolve(p, model);
    if (indexed && !r->takes_index)
      refuse_parameter(p, ": '" + entry + "' takes no [entry]");
    return p;
  }

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
      if (p.registration && p.registration->settle)
        p.registration->settle(p, origins, model);
    const auto shared = std::make_shared<const std::vector<HingeOrigin>>(std::move(origins));
    for (ModelParameter &p : parameters)
      p.hinges = shared;
  }

  unsigned int
  hinge_building(const Model &model, const unsigned int h)
  {
    return h < model.hinges.size() ? model.hinges[h].building :
                                     model.hinges_3d[h - model.hinges.size()].building;
  }
} // namespace poundfe
