// The IDA runner (a record at an intensity through the model) and its
// journal rows (ida.h); the runs over the ranks are in ida_scheduler.cc.
#include <poundfe/assessment/ida.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/output/demand_table.h>
#include <poundfe/output/floor_response.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/peak_response.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace poundfe
{
  void
  refuse_periods_the_records_do_not_resolve(const IdaParameters &ida, const double first_period,
                                            const RecordSuite &suite, const InputFile &input)
  {
    const std::vector<double> periods = ida.measure_periods(first_period);
    if (periods.empty() || suite.records.empty())
      return;
    const ResolvedPeriods resolved = resolved_periods(suite);
    const auto [low, high]         = std::minmax_element(periods.begin(), periods.end());
    if (resolved.holds(*low) && resolved.holds(*high))
      return;
    const auto        six         = [](const double x) { return rounded(x, 6); };
    const double      centre      = ida.period > 0 ? ida.period : first_period;
    const bool        average     = ida.measure == IntensityMeasure::sa_avg;
    const bool        blame_range = average && resolved.holds(centre);
    const std::string parameter   = blame_range ? "IDA/Sa_avg range" : "IDA/Period";
    for (const SuiteRecord &record : suite.records)
      for (const GroundMotion &component : record.components)
        if (component.duration() < 2 * component.time_step())
          input.fail(parameter, "record '" + record.name + "' lasts " + six(component.duration()) +
                                  " s, less than twice its time step of " +
                                  six(component.time_step()) +
                                  " s: it resolves no period, and Sa cannot be taken from it");
    const std::string first =
      ida.period > 0 ? "" : " (IDA/Period = 0: the model's first period, " + six(first_period) + " s)";
    const std::string taken = average ? "Sa_avg's periods, " + six(*low) + " to " + six(*high) +
                                          " s" + first + ", lie" :
                                        "Sa's period, " + six(*low) + " s" + first + ", lies";
    input.fail(parameter, taken + " outside the periods every record of the suite resolves, " +
                            resolved.text());
  }

  IdaRunner::IdaRunner(const Analysis &analysis_, const TimeHistoryParameters &parameters,
                       const IdaParameters &ida_, RecordSuite suite)
    : analysis(analysis_)
    , ida(ida_)
    , records(std::move(suite))
    , history(std::make_unique<TimeHistory>(analysis_, parameters))
    , peaks(std::make_unique<PeakResponse>(analysis_.model, history->nonlinear_elements()))
    , angle(parameters.ground_motion.incidence_angle * M_PI / 180)
  {
    const InputFile &input = parameters.input;
    if (records.pairs() && analysis.model.dimension != 3)
      throw InputError(input.file, input.line_of("IDA/Suite"), "IDA/Suite",
                       "the suite's records are horizontal pairs: they need a 3D model "
                       "(Model/Dimension = 3)");
    refuse_incidence_angle_in_plane(analysis.model, parameters.ground_motion, input);
    if ((ida.measure == IntensityMeasure::sa || ida.measure == IntensityMeasure::sa_avg) &&
        ida.period == 0 && analysis.modes.omega.empty())
      throw InputError(input.file, input.line_of("IDA/Period"), "IDA/Period",
                       "is 0 (the first period) but no mode was computed: set "
                       "Output/Number of modes >= 1 or a Period");
    const double first = analysis.modes.omega.empty() ? 1.0 : 2 * M_PI / analysis.modes.omega[0];
    periods            = ida.measure_periods(first);
    refuse_periods_the_records_do_not_resolve(ida, first, records, input);
    for (const SuiteRecord &record : records.records)
      {
        base.push_back(intensity_of(record.components, ida.measure, ida.pair, periods,
                                    ida.damping_ratio));
        if (!(base.back() > 0))
          throw InputError(records.file, record.line, "file",
                           "record '" + record.name + "' has no intensity (" +
                             intensity_measure_names().name(ida.measure) + " = 0): it cannot "
                             "be scaled");
      }
    const FloorResponse floors(analysis.model);
    names = floors.column_names("storey", "peak_drift_ratio");
    for (const std::string &n : floors.column_names("floor", "peak_acc_m_s2"))
      names.push_back(n);
    for (const std::string &n : floors.column_names("storey", "residual_drift_ratio"))
      names.push_back(n);
    max_drift = names.size();
    names.push_back("max_drift_ratio");
    for (unsigned int g = 1; g <= analysis.model.gaps.size(); ++g)
      for (const char *what : {"_impacts", "_peak_impact_force_N", "_peak_impact_velocity_m_s"})
        names.push_back("gap" + std::to_string(g) + what);
    plan = names.size();
    if (analysis.model.dimension == 3)
      {
        const FloorResponse y(analysis.model, Component::uy);
        for (const std::string &n : y.column_names("storey", "peak_drift_ratio_y"))
          names.push_back(n);
        for (const std::string &n : y.column_names("floor", "peak_acc_y_m_s2"))
          names.push_back(n);
        for (const std::string &n : y.column_names("floor", "peak_rotation_rad"))
          names.push_back(n);
        for (const std::string &n : y.column_names("storey", "residual_drift_ratio_y"))
          names.push_back(n);
      }
    for (unsigned int r = 0; r < records.records.size(); ++r)
      peaks_xy.push_back(excitation(r, 1, false).applied_horizontal_peaks());
  }

  Excitation
  IdaRunner::excitation(const unsigned int r, const double factor, const bool free_vibration) const
  {
    std::vector<GroundMotion> motions;
    for (const GroundMotion &component : records.records.at(r).components)
      {
        std::vector<double> a = component.samples();
        if (free_vibration)
          a.resize(a.size() + static_cast<std::size_t>(std::ceil(ida.free_vibration /
                                                                 component.time_step())), 0.0);
        motions.emplace_back(component.time_step(), std::move(a), component.description());
        motions.back().scale(factor);
      }
    Excitation result(analysis.system, motions[0], {});
    if (analysis.model.dimension == 3) // a single record along the angle, a pair turned by it
      result.set_horizontal_pair(analysis.system, motions.size() == 2 ? motions[1] : GroundMotion(),
                                 angle);
    return result;
  }

  IdaRunner::~IdaRunner() = default;

  HuntFill::Settings
  IdaRunner::search() const
  {
    return {ida.initial_step, ida.step_increment, ida.upper_intensity, ida.tolerance,
            ida.runs_per_record};
  }

  IdaPoint
  IdaRunner::run(const unsigned int r, const double intensity)
  {
    IdaPoint point;
    point.intensity    = intensity;
    point.scale_factor = intensity / base[r];
    const Excitation     shaking = excitation(r, point.scale_factor, true);
    const RunStatus      status  = history->run(shaking, {peaks.get()});
    const FloorResponse &floors = peaks->floors();
    point.demands = floors.peak_drift_ratio();
    for (const std::vector<double> *part : {&floors.peak_acceleration(), &floors.drift_ratio()})
      point.demands.insert(point.demands.end(), part->begin(), part->end());
    point.demands.push_back(peaks->largest_drift_ratio());
    point.collapsed = !status.completed() || point.demands.back() > ida.collapse_drift_ratio;
    std::vector<double> count, force, velocity;
    gap_demands(analysis.model, history->state().impact_log().impacts(), peaks->n_hysteretic(),
                count, force, velocity);
    for (unsigned int g = 0; g < analysis.model.gaps.size(); ++g)
      point.demands.insert(point.demands.end(), {count[g], force[g], velocity[g]});
    if (const FloorResponse *y = peaks->floors_y())
      for (const std::vector<double> *part :
           {&y->peak_drift_ratio(), &y->peak_acceleration(), &peaks->floors_rz()->peak_displacement(),
            &y->drift_ratio()})
        point.demands.insert(point.demands.end(), part->begin(), part->end());
    return point;
  }

  std::vector<std::string>
  ida_row_names(const IdaRunner &runner)
  {
    std::vector<std::string> names{"record", "intensity", "collapsed"};
    names.insert(names.end(), runner.demand_names().begin(), runner.demand_names().end());
    return names;
  }

  std::vector<double>
  ida_row(IdaRunner &runner, const IdaTask &task)
  {
    const IdaPoint      point = runner.run(task.record, task.intensity);
    std::vector<double> row{double(task.record), task.intensity, point.collapsed ? 1.0 : 0.0};
    row.insert(row.end(), point.demands.begin(), point.demands.end());
    return row;
  }
} // namespace poundfe
