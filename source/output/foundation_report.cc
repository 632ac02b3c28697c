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
    // the foundation elements: one per part of each, in model order
    std::vector<unsigned int> elements;
    for (unsigned int h = 0; h < state.elements.size(); ++h)
      if (state.elements[h].kind == ElementKind::foundation)
        elements.push_back(h);
    json.begin_array("foundations");
    unsigned int first = 0;
    for (unsigned int i = 0; i < model.foundations.size(); ++i)
      {
        const Foundation  &f       = model.foundations[i];
        const unsigned int sway    = elements.at(first);
        // 2D: sway, (frames: vertical,) rocking; 3D: sway x, y, torsion, (frames:
        // vertical,) rocking x, y (about y last)
        const unsigned int rocking = elements.at(first + f.parts.size() - 1);
        double             dissipated = 0;
        for (unsigned int j = 0; j < f.parts.size(); ++j)
          dissipated += state.dissipated_energy(elements.at(first + j));
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
          .value("dissipated_energy_J", dissipated);
        if (f.rocking_node >= 0 || f.parts.size() > 2) // 3D, or a frame's (vertical)
          {
            json.begin_array("parts");
            for (unsigned int j = 0; j < f.parts.size(); ++j)
              {
                const FoundationPart &part = f.parts[j];
                const unsigned int    e    = elements.at(first + j);
                json.begin_object()
                  .value("name", part.name.substr(1))
                  .value("stiffness", part.stiffness)
                  .value("damping", part.damping)
                  .value("inertia", part.inertia)
                  .value("peak_deformation", peaks.peak_deformation()[e])
                  .value("peak_force", peaks.peak_force()[e])
                  .value("dissipated_energy_J", state.dissipated_energy(e))
                  .end_object();
              }
            json.end_array();
          }
        json.end_object();
        first += f.parts.size();
      }
    json.end_array();
  }
} // namespace poundfe
