#include <poundfe/integration/impact_log.h>
#include <poundfe/laws/bumper.h>

#include <algorithm>

namespace poundfe
{
  void
  ImpactLog::reset(const unsigned int n_elements)
  {
    log.clear();
    open.assign(n_elements, -1);
  }

  void
  ImpactLog::record(const unsigned int h, const double t0, const double t1, const GapState &a,
                    const GapState &b)
  {
    const double dt = t1 - t0;
    // fraction of the step at which the penetration crosses zero
    auto crossing = [&](const double d0, const double d1) {
      return (d0 != d1) ? std::clamp(-d0 / (d1 - d0), 0.0, 1.0) : 0.0;
    };
    if (open[h] < 0 && b.force > 0)
      {
        Impact impact;
        impact.element           = h;
        const double s           = a.penetration <= 0 ? crossing(a.penetration, b.penetration) : 0;
        impact.start_time        = t0 + s * dt;
        impact.approach_velocity = a.rate + s * (b.rate - a.rate);
        impact.step_start        = t0;
        // no penetration (a rigid contact's episode) peaks at its start
        impact.max_penetration_time = impact.start_time;
        open[h]                  = log.size();
        log.push_back(impact);
      }
    if (open[h] < 0)
      return;
    Impact &impact = log[open[h]];
    impact.impulse += 0.5 * (a.force + b.force) * dt;
    impact.tangential_impulse += 0.5 * (a.tangential_force + b.tangential_force) * dt;
    impact.bumper    = impact.bumper || b.phase == bumper_contact;
    impact.structure = impact.structure || b.phase == structure_contact;
    if (b.force > impact.peak_force)
      {
        impact.peak_force = b.force;
        impact.point      = b.point;
      }
    if (b.penetration > impact.max_penetration)
      {
        impact.max_penetration      = b.penetration;
        impact.max_penetration_time = t1;
      }
    if (a.rate > 0 && b.rate <= 0)
      {
        // The peak inside the step: where the linearly interpolated rate
        // vanishes, on the cubic Hermite interpolant of the penetration
        // through both ends' values and rates.
        const double s = a.rate / (a.rate - b.rate), s2 = s * s, s3 = s2 * s;
        const double peak = (2 * s3 - 3 * s2 + 1) * a.penetration + (s3 - 2 * s2 + s) * dt * a.rate +
                            (3 * s2 - 2 * s3) * b.penetration + (s3 - s2) * dt * b.rate;
        if (peak > impact.max_penetration)
          {
            impact.max_penetration      = peak;
            impact.max_penetration_time = t0 + s * dt;
          }
      }
    if (!(b.force > 0))
      {
        // released: at the zero of the penetration, or (a damped law whose
        // force was clipped while still penetrating) at the step's end
        const double s = b.penetration <= 0 ? crossing(a.penetration, b.penetration) : 1;
        impact.end_time            = t0 + s * dt;
        impact.separation_velocity = -(a.rate + s * (b.rate - a.rate));
        open[h]                    = -1;
      }
  }

  void
  ImpactLog::merge(const RankMerge &ranks)
  {
    constexpr unsigned int n_numbers = 15; // per impact, in the order below
    std::vector<double>    numbers;
    numbers.reserve(n_numbers * log.size());
    for (const Impact &i : log)
      numbers.insert(numbers.end(),
                     {double(i.element), i.start_time, i.max_penetration_time, i.end_time,
                      i.approach_velocity, i.separation_velocity, i.max_penetration, i.peak_force,
                      i.impulse, i.point[0], i.point[1], double(i.bumper), double(i.structure),
                      i.step_start, i.tangential_impulse});
    ranks.concatenated(numbers);
    log.clear();
    std::fill(open.begin(), open.end(), -1);
    for (std::size_t k = 0; k + n_numbers <= numbers.size(); k += n_numbers)
      {
        const double *x = &numbers[k];
        Impact        i;
        i.element              = static_cast<unsigned int>(x[0]);
        i.start_time           = x[1];
        i.max_penetration_time = x[2];
        i.end_time             = x[3];
        i.approach_velocity    = x[4];
        i.separation_velocity  = x[5];
        i.max_penetration      = x[6];
        i.peak_force           = x[7];
        i.impulse              = x[8];
        i.point                = {{x[9], x[10]}};
        i.bumper               = x[11] != 0;
        i.structure            = x[12] != 0;
        i.step_start           = x[13];
        i.tangential_impulse   = x[14];
        log.push_back(i);
      }
    // one process opens the impacts of a step in the order of the elements
    std::stable_sort(log.begin(), log.end(), [](const Impact &a, const Impact &b) {
      return a.step_start < b.step_start || (a.step_start == b.step_start && a.element < b.element);
    });
  }
} // namespace poundfe
