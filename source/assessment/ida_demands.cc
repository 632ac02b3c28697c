// An IDA's demands at a given intensity, and an MSA stripe's
// (assessment/ida_demands.h).
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

  ResponseDemands
  record_demands(const IdaRunner &runner, const unsigned int r, const double x,
                 const std::function<double(unsigned int, bool)> &value)
  {
    // the runner's columns (IdaRunner::demand_names): per floor of the model
    // the peak drift ratio, the peak acceleration and the residual drift
    // ratio, the largest drift ratio, then three per gap, then a 3D model's
    // drift and acceleration along y, rotation and residual drift along y
    const unsigned int n_floors = runner.max_drift_column() / 3;
    const unsigned int plan     = runner.plan_column();
    const bool         three_d  = plan < runner.demand_names().size();
    ResponseDemands    d;
    const double       scale = x / runner.base_intensities()[r];
    d.sa  = x;
    d.pga = three_d ? runner.ground_peaks()[r][0] * scale :
                      runner.suite().records[r].components[0].peak() * scale;
    d.pga_y = runner.ground_peaks()[r][1] * scale;
    for (unsigned int f = 0; f < n_floors; ++f)
      {
        d.peak_drift.push_back(value(f, false));
        d.peak_acceleration.push_back(value(n_floors + f, false));
        d.residual_drift.push_back(value(2 * n_floors + f, true));
        if (three_d)
          {
            d.peak_drift_y.push_back(value(plan + f, false));
            d.peak_acceleration_y.push_back(value(plan + n_floors + f, false));
            d.peak_rotation.push_back(value(plan + 2 * n_floors + f, false));
            d.residual_drift_y.push_back(value(plan + 3 * n_floors + f, true));
          }
      }
    for (unsigned int c = runner.max_drift_column() + 1; c + 2 < plan; c += 3)
      {
        d.impacts.push_back(value(c, false));
        d.impact_force.push_back(value(c + 1, false));
        d.impact_velocity.push_back(value(c + 2, false));
      }
    return d;
  }

  IdaDemandSample
  ida_demands_at(const IdaRunner &runner, const IdaResult &result, const double x)
  {
    IdaDemandSample sample;
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
        sample.records.push_back(r);
        sample.rows.push_back(
          record_demands(runner, r, x, [&](const unsigned int column, const bool magnitude) {
            return demand_at(record, column, x, magnitude);
          }));
      }
    return sample;
  }

  namespace
  {
    /// The rows of `runs` (record r: runs[r]) that did not collapse, each
    /// at intensity `x`, or at its run's own when x is NaN.
    IdaDemandSample
    demands_of_runs(const IdaRunner &runner, const std::vector<IdaPoint> &runs, const double x)
    {
      IdaDemandSample sample;
      sample.intensity = x;
      for (unsigned int r = 0; r < runs.size(); ++r)
        {
          const IdaPoint &p = runs[r];
          if (p.demands.empty())
            ++sample.not_reached;
          else if (p.collapsed)
            ++sample.collapsed;
          else
            {
              sample.records.push_back(r);
              sample.rows.push_back(record_demands(
                runner, r, std::isnan(x) ? p.intensity : x,
                [&](const unsigned int column, const bool magnitude) {
                  return magnitude ? std::abs(p.demands[column]) : p.demands[column];
                }));
            }
        }
      return sample;
    }
  } // namespace

  IdaDemandSample
  stripe_demands(const IdaRunner &runner, const std::vector<IdaPoint> &stripe, const double x)
  {
    return demands_of_runs(runner, stripe, x);
  }

  IdaDemandSample
  cloud_demands(const IdaRunner &runner, const std::vector<IdaPoint> &cloud)
  {
    return demands_of_runs(runner, cloud, std::numeric_limits<double>::quiet_NaN());
  }
} // namespace poundfe
