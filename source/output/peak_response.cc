#include <poundfe/output/peak_response.h>

#include <poundfe/elements/uniaxial_element.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace poundfe
{
  PeakResponse::PeakResponse(const Model &model, const NonlinearElements &elements_)
    : elements(elements_)
    , floor_response(model)
  {
    if (model.dimension == 3)
      {
        floor_response_y  = std::make_unique<FloorResponse>(model, Component::uy);
        floor_response_rz = std::make_unique<FloorResponse>(model, Component::rz);
        plan_response    = std::make_unique<PlanResponse>(model);
      }
    for (const NonlinearElement &e : elements)
      {
        // fibre members are made with the hinges, before the gaps
        n_hysteretic_elements += e.kind == ElementKind::hinge || e.kind == ElementKind::storey ||
                                 e.kind == ElementKind::member;
        n_gap_elements += e.kind == ElementKind::gap;
      }
  }

  void
  PeakResponse::initialize(const ResponseView &state)
  {
    floor_response.reset();
    if (plan_response)
      {
        floor_response_y->reset();
        floor_response_rz->reset();
        plan_response->reset();
      }
    for (auto *v : {&peak_d, &peak_d_at, &peak_f, &peak_plastic})
      v->assign(elements.size(), 0.0);
    smallest_clearance = std::numeric_limits<double>::infinity();
    // listed again at every run: the elements may have been replaced
    observed.clear();
    for (unsigned int h = 0; h < elements.size(); ++h)
      if (state.observes_element(h))
        observed.emplace_back(h, as_uniaxial(elements[h]));
    observe_floors(state);
    observe_elements(state, false); // the initial state: formed from u
  }

  void
  PeakResponse::observe_step(const ResponseView &state)
  {
    observe_floors(state);
    observe_elements(state, state.elements_hold_state());
  }

  void
  PeakResponse::observe_floors(const ResponseView &state)
  {
    const double t = state.time();
    floor_response.evaluate(t, state.displacement(), state.velocity(), state.acceleration(),
                            state.ground_acceleration());
    if (plan_response)
      {
        floor_response_y->evaluate(t, state.displacement(), state.velocity(),
                                   state.acceleration(), state.ground_acceleration_y());
        floor_response_rz->evaluate(t, state.displacement(), state.velocity(),
                                    state.acceleration(), 0.0); // the ground does not turn
        plan_response->observe_step(state);
      }
  }

  void
  PeakResponse::observe_elements(const ResponseView &state, const bool from_trial)
  {
    const double  t = state.time();
    const Vector &u = state.displacement();
    // A uniaxial element through its final class (calls to its law only),
    // its deformation from its last evaluation when that is this state:
    // the same sums as deformation(u), so the same bits.
    for (const auto &[h, typed] : observed)
      if (!typed)
        observe_element(h, elements[h], t, elements[h].deformation(u));
      else
        observe_element(h, *typed, t,
                        from_trial ? typed->trial_deformation_value() : typed->deformation(u));
  }

  template <typename Element>
  void
  PeakResponse::observe_element(const unsigned int h, const Element &e, const double t,
                                const double d)
  {
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
    // (a fibre member's yields in its sections: no one k0 of its end)
    const double k0 = e.initial_stiffness();
    if (k0 > 0 && e.kind != ElementKind::member)
      peak_plastic[h] = std::max(peak_plastic[h], std::abs(d - f / k0));
  }

  void
  PeakResponse::finish(const ResponseView &state, const RunStatus &)
  {
    // the log locates the deepest point within steps
    for (const Impact &impact : state.impact_log().impacts())
      smallest_clearance = std::min(smallest_clearance, -impact.max_penetration);
  }

  double
  PeakResponse::largest_drift_ratio() const
  {
    double largest = 0;
    const FloorResponse *y = floor_response_y.get();
    for (const FloorResponse *floors : {&floor_response, y})
      if (floors)
        for (const double d : floors->peak_drift_ratio())
          largest = std::max(largest, d);
    return largest;
  }

  std::vector<std::string>
  plan_scalar_names(const Model &model)
  {
    std::vector<std::string> names;
    if (model.dimension != 3)
      return names;
    const FloorResponse floors(model, Component::uy);
    names = floors.column_names("storey", "peak_drift_ratio_y");
    for (const std::string &name : floors.column_names("floor", "peak_acc_y_m_s2"))
      names.push_back(name);
    for (const Building &building : model.buildings)
      for (const char *what : {"_max_corner_drift_ratio", "_peak_floor_rotation_rad",
                               "_peak_base_shear_x_N", "_peak_base_shear_y_N",
                               "_peak_base_torque_N_m", "_peak_corner_acc_x_m_s2",
                               "_peak_corner_acc_y_m_s2"})
        names.push_back(building.name + what);
    return names;
  }

  void
  append_plan_scalars(const Model &model, const PeakResponse &peaks, std::vector<double> &row)
  {
    if (!peaks.plan())
      return;
    const FloorResponse &y = *peaks.floors_y();
    row.insert(row.end(), y.peak_drift_ratio().begin(), y.peak_drift_ratio().end());
    row.insert(row.end(), y.peak_acceleration().begin(), y.peak_acceleration().end());
    const auto &buildings = peaks.plan()->buildings();
    for (unsigned int b = 0; b < buildings.size(); ++b)
      {
        double corner = 0, rotation = 0, corner_x = 0, corner_y = 0;
        for (unsigned int i = 0; i < buildings[b].storeys.size(); ++i)
          {
            const PlanResponse::Storey &s = buildings[b].storeys[i];
            const double height = model.buildings[b].floors[i].storey_height;
            for (const std::vector<double> *drifts : {&s.corner_drift_x, &s.corner_drift_y})
              for (const double d : *drifts)
                corner = std::max(corner, d / height);
            rotation = std::max(rotation, s.rotation);
            for (const double a : s.corner_acceleration_x)
              corner_x = std::max(corner_x, a);
            for (const double a : s.corner_acceleration_y)
              corner_y = std::max(corner_y, a);
          }
        for (const double v : {corner, rotation, buildings[b].base_shear_x,
                               buildings[b].base_shear_y, buildings[b].base_torque, corner_x,
                               corner_y})
          row.push_back(v);
      }
  }

  double
  PeakResponse::ductility(const unsigned int h) const
  {
    const double yield = elements[h].yield_deformation();
    return yield > 0 ? peak_d[h] / yield : 0.0;
  }

  void
  PeakResponse::merge(const RankMerge &ranks)
  {
    floor_response.merge(ranks);
    if (plan_response)
      {
        floor_response_y->merge(ranks);
        floor_response_rz->merge(ranks);
        plan_response->merge(ranks);
      }
    for (std::vector<double> *x : {&peak_d, &peak_d_at, &peak_f, &peak_plastic})
      ranks.owned(Owner::element, *x);
    // an element at rest on a rank that does not observe it is no closer
    // than at t = 0, which its observer saw too
    ranks.least(smallest_clearance);
  }
} // namespace poundfe
