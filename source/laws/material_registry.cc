// The material registry: every uniaxial stress-strain material the input may
// name, with its parameters and factory (MaterialType), and the parameter
// checks the materials share. Adding a material: its file
// source/laws/<material>.cc, which defines the class and
// materials::<material>() (its MaterialType), and MATERIAL(<material>) in
// the one list below (listed rather than registered by static objects
// because the core is a static library: see contact_law_registry.cc).
#include <poundfe/base/exceptions.h>
#include <poundfe/laws/material_registry.h>
#include <poundfe/laws/opensees_dead_bands.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace poundfe
{
#define POUNDFE_MATERIALS(MATERIAL)                                                           \
  MATERIAL(steel01) MATERIAL(steel02) MATERIAL(concrete01) MATERIAL(concrete02)               \
    MATERIAL(elastic_pp) MATERIAL(hysteretic)  \
    MATERIAL(elastic) MATERIAL(elastic_pp_gap) MATERIAL(impact_material)                      \
      MATERIAL(hertzdamp) MATERIAL(jankowski_impact) MATERIAL(viscoelastic_gap) MATERIAL(viscous) \
        MATERIAL(bouc_wen_material)

  namespace materials
  {
#define POUNDFE_DECLARE_MATERIAL(material) MaterialType material();
    POUNDFE_MATERIALS(POUNDFE_DECLARE_MATERIAL)
#undef POUNDFE_DECLARE_MATERIAL
    // the laws with an OpenSees dead band, in their files
    std::unique_ptr<UniaxialLaw> concrete01_with_dead_band(const std::map<std::string, double> &);
    std::unique_ptr<UniaxialLaw> concrete02_with_dead_band(const std::map<std::string, double> &);
    std::unique_ptr<UniaxialLaw> steel02_with_dead_band(const std::map<std::string, double> &);
    std::unique_ptr<UniaxialLaw> hysteretic_with_dead_band(const std::map<std::string, double> &);
  } // namespace materials

  namespace
  {
    const std::vector<MaterialType> &
    material_registry()
    {
#define POUNDFE_MATERIAL_TYPE(material) materials::material(),
      static const std::vector<MaterialType> types{POUNDFE_MATERIALS(POUNDFE_MATERIAL_TYPE)};
#undef POUNDFE_MATERIAL_TYPE
      return types;
    }

    std::string
    material_number_text(const double value)
    {
      std::ostringstream text;
      text.precision(10);
      text << value;
      return text.str();
    }
  } // namespace

  const MaterialType &
  material_type(const std::string &name)
  {
    const auto &types = material_registry();
    const auto  it    = std::find_if(types.begin(), types.end(),
                                 [&](const MaterialType &t) { return t.name == name; });
    if (it != types.end())
      return *it;
    std::string known;
    for (const MaterialType &t : types)
      known += (known.empty() ? "" : ", ") + t.name;
    throw InputError("", 0, "Material", "unknown material '" + name + "' (known: " + known + ")");
  }

  std::vector<std::string>
  material_names()
  {
    std::vector<std::string> names;
    for (const MaterialType &type : material_registry())
      names.push_back(type.name);
    return names;
  }

  std::unique_ptr<UniaxialLaw>
  make_material(const MaterialParameters &parameters)
  {
    const MaterialType &type   = material_type(parameters.material);
    const char         *name   = type.name.c_str();
    auto                values = parameters.values;
    const bool dead_band = values.erase(std::string(opensees_dead_band_entry)) > 0;
    for (const auto &[key, value] : values)
      {
        const bool known = std::any_of(type.parameters.begin(), type.parameters.end(),
                                       [&](const MaterialParameter &q) { return q.name == key; });
        if (!known)
          refuse_parameter(name, key.c_str(), "not a parameter of this material");
        if (!std::isfinite(value))
          refuse_parameter(name, key.c_str(), "must be a finite number");
      }
    for (const MaterialParameter &q : type.parameters)
      if (values.count(q.name) == 0)
        {
          if (std::isnan(q.default_value))
            refuse_parameter(name, q.name.c_str(), "is required (" + q.meaning + ")");
          values[q.name] = q.default_value;
        }
    if (dead_band)
      if (std::unique_ptr<UniaxialLaw> law = make_with_opensees_dead_band(type.name, values))
        return law;
    return type.make(values);
  }

  std::unique_ptr<UniaxialLaw>
  make_with_opensees_dead_band(const std::string &name, const std::map<std::string, double> &values)
  {
    if (name == "Concrete01")
      return materials::concrete01_with_dead_band(values);
    if (name == "Concrete02")
      return materials::concrete02_with_dead_band(values);
    if (name == "Steel02")
      return materials::steel02_with_dead_band(values);
    if (name == "Hysteretic")
      return materials::hysteretic_with_dead_band(values);
    return nullptr;
  }

  void
  refuse_parameter(const char *material, const char *parameter, const std::string &problem)
  {
    throw InputError("", 0, parameter, std::string(material) + ": " + problem);
  }

  void
  require_positive(const char *material, const char *parameter, const double value)
  {
    if (!(std::isfinite(value) && value > 0))
      refuse_parameter(material, parameter,
                       "must be a positive number (got " + material_number_text(value) + ")");
  }

  void
  require_non_negative(const char *material, const char *parameter, const double value)
  {
    if (!(std::isfinite(value) && value >= 0))
      refuse_parameter(material, parameter,
                       "must be a number >= 0 (got " + material_number_text(value) + ")");
  }

  void
  require_in(const char *material, const char *parameter, const double value, const double low,
             const double high)
  {
    if (!(std::isfinite(value) && value >= low && value < high))
      refuse_parameter(material, parameter,
                       "must lie in [" + material_number_text(low) + ", " +
                         material_number_text(high) + ") (got " + material_number_text(value) +
                         ")");
  }
} // namespace poundfe
