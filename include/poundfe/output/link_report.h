// What a run reports of its links between buildings and its gaps' bumpers:
// summary.json's `links` array (each link's kind, the two buildings, peak
// deformation and force, dissipated energy: laws/link_laws.h) and the
// `bumper` object (the layer and how many impacts stayed on it or reached
// the structure: laws/bumper.h, integration/impact_log.h).
#ifndef poundfe_output_link_report_h
#define poundfe_output_link_report_h

namespace poundfe
{
  class JsonWriter;
  class PeakResponse;
  class ResponseView;

  /// The `links` array (nothing if the model has none).
  void write_links(JsonWriter &json, const ResponseView &state, const PeakResponse &peaks);

  /// The `bumper` object (nothing if the gaps have none).
  void write_bumper(JsonWriter &json, const ResponseView &state);
} // namespace poundfe

#endif
