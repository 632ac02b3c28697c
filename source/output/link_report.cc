#include <poundfe/laws/bumper.h>
#include <poundfe/model/link_parameters.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/link_report.h>
#include <poundfe/output/observer.h>
#include <poundfe/output/peak_response.h>

namespace poundfe
{
  void
  write_links(JsonWriter &json, const ResponseView &state, const PeakResponse &peaks)
  {
    const Model &model = state.model;
    if (model.building_links.empty())
      return;
    json.begin_array("links");
    unsigned int next = 0;
    for (unsigned int h = 0; h < state.elements.size(); ++h)
      {
        const NonlinearElement &e = state.elements[h];
        if (e.kind != ElementKind::link)
          continue;
        const BuildingLink &link = model.building_links[next++];
        json.begin_object()
          .value("label", e.label)
          .value("kind", link_kind_name(link.law.kind))
          .value("buildings", std::vector<std::string>{model.buildings[link.buildings[0]].name,
                                                       model.buildings[link.buildings[1]].name})
          .value("peak_deformation_m", peaks.peak_deformation()[h])
          .value("peak_force_N", peaks.peak_force()[h])
          .value("dissipated_energy_J", state.dissipated_energy(h))
          .end_object();
      }
    json.end_array();
  }

  void
  write_bumper(JsonWriter &json, const ResponseView &state)
  {
    const BumperParameters &bumper = state.model.bumper;
    if (bumper.law == BumperLaw::none)
      return;
    unsigned int on_bumper = 0, on_structure = 0;
    for (const Impact &impact : state.impact_log().impacts())
      ++(impact.structure ? on_structure : on_bumper);
    json.begin_object("bumper")
      .value("law", bumper_law_names().name(bumper.law))
      .value("thickness_m", bumper.thickness)
      .value("stiffness", bumper.stiffness)
      .value("impacts_on_bumper_only", on_bumper)
      .value("impacts_reaching_structure", on_structure)
      .end_object();
  }
} // namespace poundfe
