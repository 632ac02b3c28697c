// Filippov systems: hits of switching surfaces classified from the normal
// components of the fields on both sides, sliding by Filippov's convex
// combination; equations and sources in integration/filippov.h.
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/integration/filippov.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace poundfe
{
  const char *
  switching_class_name(const SwitchingClass kind)
  {
    switch (kind)
      {
        case SwitchingClass::crossing:
          return "crossing";
        case SwitchingClass::attracting_sliding:
          return "attracting-sliding";
        case SwitchingClass::repulsive_sliding:
          return "repulsive-sliding";
        case SwitchingClass::grazing:
          return "grazing";
        case SwitchingClass::sliding_exit:
          return "sliding-exit";
      }
    return "unknown"; // unreachable: every class is listed above
  }

  SwitchingClass
  classify_switching(const double a, const double b, const double tolerance)
  {
    const double scale = tolerance * std::max(std::abs(a), std::abs(b));
    if (std::abs(a) <= scale || std::abs(b) <= scale)
      return SwitchingClass::grazing;
    if ((a > 0) == (b > 0))
      return SwitchingClass::crossing;
    return a > 0 ? SwitchingClass::attracting_sliding : SwitchingClass::repulsive_sliding;
  }

  FilippovSystem::FilippovSystem(std::vector<SwitchingSurface> surfaces_, Field field_,
                                 const FilippovParameters &parameters_)
    : surfaces(std::move(surfaces_))
    , field(std::move(field_))
    , parameters(parameters_)
  {}

  double
  FilippovSystem::value(const unsigned int j, const Vector &state) const
  {
    return surfaces[j].normal.dot(state) - surfaces[j].offset;
  }

  std::pair<double, double>
  FilippovSystem::normal_components(const unsigned int j, const double t, const Vector &state)
  {
    std::vector<int> s = sides;
    s[j]               = -1;
    evaluated          = j;
    field(t, state, s, f_minus);
    s[j] = +1;
    field(t, state, s, f_plus);
    evaluated = -1;
    return {surfaces[j].normal.dot(f_minus), surfaces[j].normal.dot(f_plus)};
  }

  void
  FilippovSystem::rhs(const double t, const Vector &state, Vector &dx)
  {
    if (sliding < 0)
      {
        field(t, state, sides, dx);
        return;
      }
    const auto [a, b]   = normal_components(sliding, t, state);
    const double lambda = a / (a - b);
    dx                  = (1 - lambda) * f_minus + lambda * f_plus;
  }

  void
  FilippovSystem::indicators(const double t, const Vector &state, std::vector<int> &out)
  {
    out.assign(surfaces.size() + 2, 0);
    for (unsigned int j = 0; j < surfaces.size(); ++j)
      if (static_cast<int>(j) != sliding)
        {
          const double h = value(j, state);
          // within the local error of the last event's surface: its side
          const double near = 100 * (parameters.absolute_tolerance +
                                     parameters.relative_tolerance * state.cwiseAbs().maxCoeff());
          out[j] = just_switched[j] && std::abs(h) <= near ? sides[j] : (h > 0 ? 1 : -1);
        }
    if (sliding >= 0)
      {
        const auto [a, b]          = normal_components(sliding, t, state);
        out[surfaces.size()]     = a > 0;
        out[surfaces.size() + 1] = b < 0;
      }
  }

  void
  FilippovSystem::switch_at(const unsigned int j, const double t)
  {
    const auto [a, b] = normal_components(j, t, x);
    SwitchingEvent e;
    e.time          = t;
    e.state         = x;
    e.surface       = j;
    e.region_before = sliding == static_cast<int>(j) ? 0 : sides[j];
    e.value         = value(j, x);
    e.normal_minus  = a;
    e.normal_plus   = b;
    if (sliding == static_cast<int>(j)) // it leaves into the side whose field turned
      {
        e.kind   = SwitchingClass::sliding_exit;
        sides[j] = a <= 0 ? -1 : +1;
        sliding  = -1;
      }
    else
      {
        e.kind = classify_switching(a, b, parameters.grazing_tolerance);
        if (e.kind == SwitchingClass::attracting_sliding)
          {
            if (sliding >= 0)
              throw NumericalError("t = " + number_text(t) + " s: sliding on " +
                                   surfaces[j].name + " while sliding on " +
                                   surfaces[sliding].name + " (one surface at a time)");
            sliding = j;
          }
        else if (e.kind == SwitchingClass::crossing)
          sides[j] = a > 0 ? +1 : -1;
        else // repulsive, grazing: on the side the motion reached
          sides[j] = e.value > 0 ? +1 : (e.value < 0 ? -1 : (a + b > 0 ? +1 : -1));
      }
    e.region_after = sliding == static_cast<int>(j) ? 0 : sides[j];
    just_switched[j] = true;
    events.push_back(e);
  }

  void
  FilippovSystem::sample_step(const double t0, const double h)
  {
    const double dt = parameters.sample_interval;
    if (!(dt > 0))
      return;
    for (double ts = sampled.size() * dt; ts <= t0 + h * (1 + 1e-12); ts = sampled.size() * dt)
      {
        SwitchingSample s;
        s.time    = ts;
        s.sliding = sliding;
        step.dense_output(std::clamp((ts - t0) / h, 0.0, 1.0), s.state);
        sampled.push_back(std::move(s));
      }
  }

  void
  FilippovSystem::run(const Vector &x0, const double t_end)
  {
    x       = x0;
    sliding = -1;
    events.clear();
    sampled.clear();
    sides.assign(surfaces.size(), 1);
    just_switched.assign(surfaces.size(), false);
    const double on_surface = 1e-14;
    for (unsigned int j = 0; j < surfaces.size(); ++j)
      sides[j] = value(j, x) < 0 ? -1 : 1;
    for (unsigned int j = 0; j < surfaces.size(); ++j)
      if (std::abs(value(j, x)) <= on_surface * (1 + std::abs(surfaces[j].offset)))
        switch_at(j, 0);
    if (parameters.sample_interval > 0)
      sampled.push_back({0.0, x0, sliding});
    const DormandPrinceStep::Rhs F = [this](double t, const Vector &s, Vector &dx) {
      rhs(t, s, dx);
    };
    const double rtol = parameters.relative_tolerance, atol = parameters.absolute_tolerance;
    double       t = 0, h = 1e-3 * t_end;
    rhs(t, x, k1);
    for (unsigned long n = 0; t_end - t > 1e-14 * std::max(1.0, t_end); ++n)
      {
        if (n > parameters.max_steps)
          throw NumericalError("t = " + number_text(t) + " s: more than " +
                               std::to_string(parameters.max_steps) + " steps");
        const bool clipped = t + 1.01 * h >= t_end;
        if (clipped)
          h = t_end - t;
        step.take(F, t, x, k1, h);
        const double err = step.error_norm(x, rtol, atol, x.size());
        if (!(err <= 1))
          {
            h = std::min(h, DormandPrinceStep::next_size(h, err));
            if (h < 1e-14 * std::max(1.0, t))
              throw NumericalError("t = " + number_text(t) + " s: the step fell to " +
                                   number_text(h) + " s");
            continue;
          }
        const double h_next = DormandPrinceStep::next_size(h, err);
        for (unsigned int j = 0; j < surfaces.size(); ++j) // left the last event's surface
          if (just_switched[j] && (value(j, x) > 0 ? 1 : -1) == sides[j])
            just_switched[j] = false;
        indicators(t, x, watched);
        indicators(t + h, step.y1, trial_watched);
        int event = -1;
        if (trial_watched != watched)
          {
            // the first change of the indicators, on the dense output
            const double resolution = parameters.event_resolution * std::max(1.0, t);
            const double hi = DormandPrinceStep::locate_change(h, resolution, [&](double theta) {
              step.dense_output(theta, trial);
              indicators(t + theta * h, trial, trial_watched);
              return trial_watched == watched;
            });
            step.dense_output(hi, trial);
            indicators(t + hi * h, trial, trial_watched);
            const auto changed = std::mismatch(watched.begin(), watched.end(), trial_watched.begin());
            event = changed.first - watched.begin();
            if (hi < 1)
              {
                h *= hi;
                step.take(F, t, x, k1, h);
              }
          }
        sample_step(t, h);
        t = (clipped && event < 0) ? t_end : t + h;
        x  = step.y1;
        k1 = step.k7;
        if (event >= 0)
          {
            switch_at(event < static_cast<int>(surfaces.size()) ? event : sliding, t);
            rhs(t, x, k1); // the field of the new region
          }
        if (!clipped || event >= 0)
          h = h_next;
      }
  }

  std::map<std::string, std::map<std::string, unsigned int>>
  FilippovSystem::counts() const
  {
    std::map<std::string, std::map<std::string, unsigned int>> c;
    for (const SwitchingEvent &e : events)
      ++c[surfaces[e.surface].name][switching_class_name(e.kind)];
    return c;
  }

  std::string
  FilippovSystem::log_csv() const
  {
    std::ostringstream csv;
    csv.precision(17);
    csv << "time_s";
    for (Eigen::Index i = 0; i < x.size(); ++i)
      csv << ",x" << i + 1;
    csv << ",surface,region_before,region_after,h,normal_minus,normal_plus,class\n";
    for (const SwitchingEvent &e : events)
      {
        csv << e.time;
        for (Eigen::Index i = 0; i < e.state.size(); ++i)
          csv << "," << e.state[i];
        csv << "," << surfaces[e.surface].name << "," << e.region_before << "," << e.region_after
            << "," << e.value << "," << e.normal_minus << "," << e.normal_plus << ","
            << switching_class_name(e.kind) << "\n";
      }
    return csv.str();
  }
} // namespace poundfe
