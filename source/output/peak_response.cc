#include <poundfe/output/peak_response.h>

#include <cmath>
#include <limits>

namespace poundfe
{
  PeakResponse::PeakResponse(const Model &model, const NonlinearElements &elements_)
    : elements(elements_)
    , floor_response(model)
  {
    for (const NonlinearElement &e : elements)
      {
        n_hysteretic_elements += e.kind == ElementKind::hinge || e.kind == ElementKind::storey;
        n_gap_elements += e.kind == ElementKind::gap;
      }
  }

  void
  PeakResponse::initialize(const ResponseView &state)
  {
    floor_response.reset();
    for (auto *v : {&peak_d, &peak_d_at, &peak_f, &peak_plastic})
      v->assign(elements.size(), 0.0);
    smallest_clearance = std::numeric_limits<double>::infinity();
    observe_step(state);
  }

  void
  PeakResponse::observe_step(const ResponseView &state)
  {
    const double t = state.time();
    floor_response.evaluate(t, state.displacement(), state.velocity(), state.acceleration(),
                            state.ground_acceleration());
    for (unsigned int h = 0; h < elements.size(); ++h)
      {
        const NonlinearElement &e = elements[h];
        const double           d = e.deformation(state.displacement());
        if (std::abs(d) > peak_d[h])
          {
            peak_d[h]    = std::abs(d);
            peak_d_at[h] = t;
          }
        const double f = e.force();
        peak_f[h]      = std::max(peak_f[h], std::abs(f));
        if (e.kind == ElementKind::gap) // its opening is minus its penetration
          smallest_clearance = std::min(smallest_clearance, -e.history_variable());
        // plastic part: the deformation left after elastic unloading
        const double k0 = e.initial_stiffness();
        if (k0 > 0)
          peak_plastic[h] = std::max(peak_plastic[h], std::abs(d - f / k0));
      }
  }

  void
  PeakResponse::finish(const ResponseView &state, const RunStatus &)
  {
    // the log locates the deepest point within steps
    for (const Impact &impact : state.impact_log().impacts())
      smallest_clearance = std::min(smallest_clearance, -impact.max_penetration);
  }

  double
  PeakResponse::ductility(const unsigned int h) const
  {
    const double yield = elements[h].yield_deformation();
    return yield > 0 ? peak_d[h] / yield : 0.0;
  }
} // namespace poundfe
