// What a run reports of its springs and friction elements: summary.json's
// `springs` and `friction` arrays (peaks, dissipated energy, stick-slip
// statistics: number of stick and slip episodes, distributions of their
// durations, fraction of time stuck) and friction_episodes.csv (every
// episode, located inside the step: integration/stick_slip_log.h).
#ifndef poundfe_output_stick_slip_report_h
#define poundfe_output_stick_slip_report_h

#include <string>
#include <vector>

namespace poundfe
{
  class JsonWriter;
  class MemoryResults;
  class PeakResponse;
  class ResponseView;

  /// Count, mean, standard deviation and quantiles (linear interpolation
  /// between order statistics, Hyndman & Fan 1996 type 7) of durations.
  void write_distribution(JsonWriter &json, const std::string &key, std::vector<double> values);

  /// The shortest stick of friction element h that counts as one: a period
  /// 2 pi sqrt(m/k_s) of its node's mass on the stick spring (twice the
  /// time a velocity reversal spends passing through the spring).
  double reversal_duration(const ResponseView &state, unsigned int h);

  /// The `springs` and `friction` arrays (nothing if the model has neither).
  void write_springs_and_friction(JsonWriter &json, const ResponseView &state,
                                  const PeakResponse &peaks, double end_time);

  /// friction_episodes.csv in `directory`, atomically (into `memory`
  /// when given: output/table_writer.h).
  void write_friction_episodes(const std::string &directory, const ResponseView &state,
                               double end_time, MemoryResults *memory = nullptr);
} // namespace poundfe

#endif
