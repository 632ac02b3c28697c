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
    // ratio, the largest drift ratio, then three per gap, then a 3D model's
    // drift and acceleration along y and rotation per floor
    const unsigned int n_floors = runner.max_drift_column() / 3;
    const unsigned int plan     = runner.plan_column();
    const bool         three_d  = plan < runner.demand_names().size();
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
        const double scale = x / runner.base_intensities()[r];
        d.pga = three_d ? runner.ground_peaks()[r][0] * scale :
                          runner.suite().records[r].components[0].peak() * scale;
        d.pga_y = runner.ground_peaks()[r][1] * scale;
        for (unsigned int f = 0; f < n_floors; ++f)
          {
            d.peak_drift.push_back(demand_at(record, f, x));
            d.peak_acceleration.push_back(demand_at(record, n_floors + f, x));
            d.residual_drift.push_back(demand_at(record, 2 * n_floors + f, x, true));
            if (three_d)
              {
                d.peak_drift_y.push_back(demand_at(record, plan + f, x));
                d.peak_acceleration_y.push_back(demand_at(record, plan + n_floors + f, x));
                d.peak_rotation.push_back(demand_at(record, plan + 2 * n_floors + f, x));
              }
          }
        for (unsigned int c = runner.max_drift_column() + 1; c + 2 < plan; c += 3)
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
