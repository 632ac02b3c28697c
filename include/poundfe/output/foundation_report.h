// What a run reports of its compliant foundations (doc/theory.md §1.16):
// summary.json's `foundations` array, one object per foundation with its
// springs, dashpots, mass and rotary inertia, the peak sway and rocking, the
// peak horizontal force and moment on the soil (spring plus dashpot) and the
// energy its dashpots dissipated.
#ifndef poundfe_output_foundation_report_h
#define poundfe_output_foundation_report_h

namespace poundfe
{
  class JsonWriter;
  class PeakResponse;
  class ResponseView;

  /// The `foundations` array (nothing if the model has none).
  void write_foundations(JsonWriter &json, const ResponseView &state, const PeakResponse &peaks);
} // namespace poundfe

#endif
