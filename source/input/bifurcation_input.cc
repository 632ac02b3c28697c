#include <poundfe/input/bifurcation_input.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/progress.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/sweep.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

namespace poundfe
{
  namespace
  {
    /// The value's model prepared once and run once (from `state` when
    /// given, see bifurcation_point); the wall time includes the preparation.
    BifurcationPoint
    run_value(const BifurcationValue &v, BifurcationState *state = nullptr)
    {
      const auto       start    = std::chrono::steady_clock::now();
      const Analysis   analysis = prepare_analysis(v.input);
      BifurcationPoint point =
        bifurcation_point(analysis, time_history_parameters(v.input), v.input.bifurcation, v.value,
                          v.period, v.steps_per_period, state);
      point.wall_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return point;
    }
  } // namespace

  BifurcationValue
  bifurcation_value(const InputParameters &input, const double value)
  {
    const SweepParameters &sweep = input.bifurcation.sweep;
    const InputParameters  at    = sweep_input(sweep, input, value);
    BifurcationValue       v;
    v.value            = value;
    v.period           = forcing_period(at.bifurcation, at.nodal_forces, at);
    v.steps_per_period = std::max(1.0, std::round(v.period / at.time_integration.newmark.time_step));
    const unsigned int n_periods =
      at.bifurcation.transient_periods + at.bifurcation.sampled_periods;
    v.input = sweep_input(sweep, input, value,
                          {{"Time integration/Time step",
                            format_value(v.period / v.steps_per_period)},
                           {"Time integration/End time", format_value(n_periods * v.period)}});
    return v;
  }

  BifurcationPoint
  bifurcation_point(const InputParameters &input, const double value)
  {
    return run_value(bifurcation_value(input, value));
  }

  std::vector<BifurcationPoint>
  bifurcation_points(const InputParameters &input)
  {
    const BifurcationParameters &b = input.bifurcation;
    b.sweep.require(input);
    std::vector<BifurcationValue> values; // every value's input checked before any work
    for (const double value : b.sweep.values())
      values.push_back(bifurcation_value(input, value));
    std::vector<BifurcationPoint> points;
    Progress         progress(std::cerr, "bifurcation: values", values.size());
    BifurcationState state; // empty: from rest
    for (const BifurcationValue &v : values)
      {
        if (interruption_requested()) // the values done so far are the result
          break;
        points.push_back(run_value(v, b.continuation ? &state : nullptr));
        progress.update(points.size());
      }
    return points;
  }
} // namespace poundfe
