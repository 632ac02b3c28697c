// The parameters of a building's damping (model/parameter_registry.h), all
// entering C only:
//   Building b/Damping/Damping ratio   zeta of b's Rayleigh damping fitted at two
//                                      modes (the coefficients follow the modes:
//                                      dynamics/model_parameter.h's realization)
//   Building b/Damping/a0, a1          given Rayleigh coefficients
//   Building b/Damping/Modal ratios[i] zeta of mode i, modal damping
#include <poundfe/model/parameter_registry.h>

namespace poundfe::damping_registration
{
  namespace
  {
    /// A damping entry of building b whose Damping/Type must be `kind`.
    ParameterRegistration
    damping_entry(const std::string &name, const RayleighDamping::Kind kind,
                  const std::string &missing, const bool zero)
    {
      ParameterRegistration r;
      r.name        = "Damping/" + name;
      r.of_building = true;
      r.range       = {0, zero, std::numeric_limits<double>::infinity()};
      r.touches     = ModelParameter::damping;
      r.resolve     = [kind, missing](ModelParameter &p, const Model &model) {
        const Building &building = model.buildings[p.building];
        if (building.damping.kind != kind)
          refuse_parameter(p, ": building '" + building.name + "' has no " + missing);
      };
      return r;
    }

    void
    damping(ParameterRegistry &registry)
    {
      ParameterRegistration ratio =
        damping_entry("Damping ratio", RayleighDamping::Kind::modes,
                      "Rayleigh damping fitted at modes (Damping/Type = modes)", false);
      ratio.get = [](const ModelParameter &p, const Model &model) {
        return model.buildings[p.building].damping.damping_ratio;
      };
      ratio.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        model.buildings[p.building].damping.damping_ratio = value;
      };
      registry.add(ratio);

      for (const bool a1 : {false, true})
        {
          ParameterRegistration a = damping_entry(
            a1 ? "a1" : "a0", RayleighDamping::Kind::coefficients,
            "given Rayleigh coefficients (Damping/Type = coefficients)", true);
          a.get = [a1](const ModelParameter &p, const Model &model) {
            const RayleighDamping &d = model.buildings[p.building].damping;
            return a1 ? d.a1 : d.a0;
          };
          a.set = [a1](const ModelParameter &p, const double value, Model &model,
                       ModelInputs &) {
            RayleighDamping &d = model.buildings[p.building].damping;
            (a1 ? d.a1 : d.a0) = value;
          };
          registry.add(a);
        }

      ParameterRegistration modal = damping_entry(
        "Modal ratios", RayleighDamping::Kind::modal, "modal damping (Damping/Type = modal)", true);
      modal.takes_index = true;
      const auto check_type = modal.resolve;
      modal.resolve = [check_type](ModelParameter &p, const Model &model) {
        check_type(p, model);
        const Building &building = model.buildings[p.building];
        if (p.entry >= int(building.damping.modal_ratios.size()))
          refuse_parameter(p, ": building '" + building.name + "' has modal ratios 1.." +
                                std::to_string(building.damping.modal_ratios.size()));
      };
      modal.get = [](const ModelParameter &p, const Model &model) {
        return model.buildings[p.building].damping.modal_ratios[std::max(p.entry, 0)];
      };
      modal.set = [](const ModelParameter &p, const double value, Model &model, ModelInputs &) {
        std::vector<double> &ratios = model.buildings[p.building].damping.modal_ratios;
        for (unsigned int i = 0; i < ratios.size(); ++i)
          if (p.entry < 0 || int(i) == p.entry)
            ratios[i] = value;
      };
      registry.add(modal);
    }
  } // namespace
} // namespace poundfe::damping_registration

namespace poundfe
{
  void
  register_damping_parameters(ParameterRegistry &registry)
  {
    damping_registration::damping(registry);
  }
} // namespace poundfe
