#include <poundfe/integration/stick_slip_log.h>

#include <algorithm>

namespace poundfe
{
  void
  StickSlipLog::reset(const unsigned int n_elements)
  {
    log.clear();
    open.assign(n_elements, -1);
  }

  void
  StickSlipLog::record(const unsigned int h, const double t0, const double t1,
                       const SlipState &a, const SlipState &b)
  {
    if (open[h] < 0) // the element's first step: its state since t0
      {
        open[h] = log.size();
        log.push_back({h, a.slipping, t0, -1});
      }
    if (a.slipping == b.slipping)
      return;
    double switch_time = 0.5 * (t0 + t1);
    if (a.slipping && a.slip_velocity * b.slip_velocity < 0)
      switch_time = t0 + (t1 - t0) * a.slip_velocity / (a.slip_velocity - b.slip_velocity);
    log[open[h]].end = switch_time;
    open[h]          = log.size();
    log.push_back({h, b.slipping, switch_time, -1});
  }

  StickSlipStatistics
  stick_slip_statistics(const StickSlipLog &log, const unsigned int element,
                        const double end_time, const double shortest_stick)
  {
    // The element's episodes, with reversals folded into the slips around them.
    std::vector<FrictionEpisode> episodes;
    StickSlipStatistics          s;
    for (const FrictionEpisode &e : log.episodes())
      {
        if (e.element != element)
          continue;
        const std::size_t n = episodes.size();
        if (e.slipping && n >= 2 && episodes[n - 2].slipping &&
            episodes[n - 1].end - episodes[n - 1].start < shortest_stick)
          {
            episodes.pop_back(); // the reversal
            episodes.back().end = e.end;
            ++s.n_reversals;
            continue;
          }
        episodes.push_back(e);
      }
    for (const FrictionEpisode &e : episodes)
      {
        const double end      = e.end < 0 ? end_time : e.end;
        const double duration = std::max(0.0, end - e.start);
        (e.slipping ? s.n_slips : s.n_sticks) += 1;
        (e.slipping ? s.time_slipping : s.time_stuck) += duration;
        if (e.end >= 0)
          (e.slipping ? s.slip_durations : s.stick_durations).push_back(duration);
      }
    return s;
  }
} // namespace poundfe
