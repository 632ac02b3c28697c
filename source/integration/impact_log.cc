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
        open[h]                  = log.size();
        log.push_back(impact);
      }
    if (open[h] < 0)
      return;
    Impact &impact = log[open[h]];
    impact.impulse += 0.5 * (a.force + b.force) * dt;
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
} // namespace poundfe
