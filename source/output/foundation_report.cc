#include <poundfe/output/foundation_report.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/observer.h>
#include <poundfe/output/peak_response.h>

namespace poundfe
{
  void
  write_foundations(JsonWriter &json, const ResponseView &state, const PeakResponse &peaks)
  {
    const Model &model = state.model;
    if (model.foundations.empty())
      return;
    // the foundation elements: sway then rocking of each, in model order
    std::vector<unsigned int> elements;
    for (unsigned int h = 0; h < state.elements.size(); ++h)
      if (state.elements[h].kind == ElementKind::foundation)
        elements.push_back(h);
    json.begin_array("foundations");
    for (unsigned int i = 0; i < model.foundations.size(); ++i)
      {
        const Foundation  &f       = model.foundations[i];
        const unsigned int sway    = elements.at(2 * i);
        const unsigned int rocking = elements.at(2 * i + 1);
        json.begin_object()
          .value("building", model.buildings[f.building].name)
          .value("horizontal_stiffness_N_m", f.horizontal_stiffness)
          .value("rocking_stiffness_N_m_rad", f.rocking_stiffness)
          .value("horizontal_damping_N_s_m", f.horizontal_damping)
          .value("rocking_damping_N_m_s_rad", f.rocking_damping)
          .value("mass_kg", f.mass)
          .value("rotary_inertia_kg_m2", f.rotary_inertia)
          .value("peak_sway_m", peaks.peak_deformation()[sway])
          .value("peak_rocking_rad", peaks.peak_deformation()[rocking])
          .value("peak_horizontal_force_N", peaks.peak_force()[sway])
          .value("peak_moment_N_m", peaks.peak_force()[rocking])
          .value("dissipated_energy_J",
                 state.dissipated_energy(sway) + state.dissipated_energy(rocking))
          .end_object();
      }
    json.end_array();
  }
} // namespace poundfe
