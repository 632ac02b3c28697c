// An IDA's demands at a given intensity (assessment/ida_demands.h).
#include <poundfe/assessment/ida_demands.h>

#include <cmath>
#include <limits>

namespace poundfe
{
  double
  demand_at(const IdaRecordResult &record, const unsigned int column, const double x,
            const bool magnitude)
  {
    if (record.collapse_intensity && x > record.highest_survived)
      return std::numeric_limits<double>::infinity();
    double x0 = 0, d0 = 0;
    for (const IdaPoint &p : record.points)
      if (!p.collapsed)
        {
          const double d = magnitude ? std::abs(p.demands[column]) : p.demands[column];
          if (p.intensity >= x)
            return d0 + (x - x0) / (p.intensity - x0) * (d - d0);
          x0 = p.intensity, d0 = d;
        }
    return std::nan("");
  }

  IdaDemandSample
  ida_demands_at(const IdaRunner &runner, const IdaResult &result, const double x)
  {
    // the runner's columns (IdaRunner::demand_names): per floor of the model
    // the peak drift ratio, the peak acceleration and the residual drift
    // ratio, the largest drift ratio, then three per gap
    const unsigned int n_floors = runner.max_drift_column() / 3;
    IdaDemandSample    sample;
    sample.intensity = x;
    for (unsigned int r = 0; r < result.records.size(); ++r)
      {
        const IdaRecordResult &record = result.records[r];
        const double largest = demand_at(record, runner.max_drift_column(), x);
        if (std::isinf(largest))
          {
            ++sample.collapsed;
            continue;
          }
        if (std::isnan(largest))
          {
            ++sample.not_reached;
            continue;
          }
        ResponseDemands d;
        d.pga = runner.suite().records[r].components[0].peak() * x / runner.base_intensities()[r];
        for (unsigned int f = 0; f < n_floors; ++f)
          {
            d.peak_drift.push_back(demand_at(record, f, x));
            d.peak_acceleration.push_back(demand_at(record, n_floors + f, x));
            d.residual_drift.push_back(demand_at(record, 2 * n_floors + f, x, true));
          }
        for (unsigned int c = runner.max_drift_column() + 1; c + 2 < runner.demand_names().size();
             c += 3)
          {
            d.impacts.push_back(demand_at(record, c, x));
            d.impact_force.push_back(demand_at(record, c + 1, x));
            d.impact_velocity.push_back(demand_at(record, c + 2, x));
          }
        sample.records.push_back(r);
        sample.rows.push_back(std::move(d));
      }
    return sample;
  }
} // namespace poundfe
