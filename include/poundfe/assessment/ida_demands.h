// An IDA's demands at a given intensity, for the demand tables a loss model
// reads (output/demand_table.h) and the fractile curves:
// along each record's IDA curve, a demand at intensity x is interpolated
// linearly between the two runs that did not collapse around x (from 0 at
// intensity 0: a record at rest has no demand); a record that collapsed at
// or below x has no finite demand there (+inf) and one whose runs stop
// below x none at all (NaN). The ground's PGA scales exactly with the
// record: PGA(x) = PGA of the record in the suite times x / its intensity.
// An MSA stripe's demands are its runs' own (every record scaled to the
// stripe's intensity): no interpolation, a collapsed run has none.
#ifndef poundfe_assessment_ida_demands_h
#define poundfe_assessment_ida_demands_h

#include <poundfe/assessment/ida.h>
#include <poundfe/output/demand_table.h>

#include <functional>
#include <vector>

namespace poundfe
{
  /// Record's demand in `column` at intensity x (above); `magnitude`:
  /// interpolate |demand| (a signed residual drift).
  double demand_at(const IdaRecordResult &record, unsigned int column, double x,
                   bool magnitude = false);

  /// Every record's demands at intensity x, as a run's (ResponseDemands),
  /// for the records that neither collapsed at or below x nor stopped below it.
  struct IdaDemandSample
  {
    double                       intensity = 0;
    std::vector<unsigned int>    records; // suite index of each row
    std::vector<ResponseDemands> rows;
    unsigned int                 collapsed = 0, not_reached = 0;
  };
  IdaDemandSample ida_demands_at(const IdaRunner &runner, const IdaResult &result, double x);

  /// The demands of a stripe's runs (record r at intensity x: stripe[r]; a
  /// run with no demands was not run) that did not collapse.
  IdaDemandSample stripe_demands(const IdaRunner &runner, const std::vector<IdaPoint> &stripe,
                                 double x);
  /// The demands of a cloud's runs (record r at its own intensity:
  /// cloud[r]) that did not collapse, each row at its run's intensity; the
  /// sample's intensity is NaN (none common to its rows).
  IdaDemandSample cloud_demands(const IdaRunner &runner, const std::vector<IdaPoint> &cloud);

  /// Record r's demands at intensity x as a demand table's row (the PGA
  /// scaled with the record, Sa = x), `value(column, magnitude)` giving each
  /// of the runner's demand columns (magnitude: |a signed residual|).
  ResponseDemands record_demands(const IdaRunner &runner, unsigned int r, double x,
                                 const std::function<double(unsigned int, bool)> &value);
} // namespace poundfe

#endif
