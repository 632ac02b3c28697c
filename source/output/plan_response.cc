// The plan response of include/poundfe/output/plan_response.h.
#include <poundfe/output/json_writer.h>
#include <poundfe/output/plan_response.h>
#include <poundfe/output/storey_forces.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    /// (u_x, u_y, θz) of a floor node (0 on fixed DOFs).
    std::array<double, 3>
    floor_motion(const Model &model, const Vector &u, const unsigned int node)
    {
      std::array<double, 3> q{{0, 0, 0}};
      for (const Component c : {Component::ux, Component::uy, Component::rz})
        {
          const int e = model.equation(Model::dof(node, c));
          q[static_cast<unsigned int>(c)] = e >= 0 ? u[e] : 0;
        }
      return q;
    }

    void
    keep_peak(double &peak, const double value)
    {
      peak = std::max(peak, std::abs(value));
    }

    /// At one instant, the corners' drifts δ: whether max_k |δ_k| beats
    /// `peak`; if so it becomes the peak and `ratio` Δmax/Δavg of these
    /// drifts, Δavg = s (max_k s δ_k + min_k s δ_k) / 2 with s the sign of
    /// the largest (a pure twist: Δavg = 0, the ratio left as it was).
    void
    keep_instant(const std::vector<double> &drifts, double &peak, double &ratio)
    {
      const auto [lo, hi] = std::minmax_element(drifts.begin(), drifts.end());
      const double largest = std::max(std::abs(*lo), std::abs(*hi));
      if (!(largest > peak))
        return;
      peak                 = largest;
      const double average = std::abs(*hi) >= std::abs(*lo) ? 0.5 * (*hi + *lo) : -0.5 * (*hi + *lo);
      if (average > 0)
        ratio = largest / average;
    }

    /// Δmax / ((Δmax + Δmin) / 2) of the corners' peak drifts; 1 when still.
    double
    irregularity(const std::vector<double> &drifts)
    {
      const auto [lo, hi] = std::minmax_element(drifts.begin(), drifts.end());
      return *hi > 0 ? 2 * *hi / (*hi + *lo) : 1.0;
    }
  } // namespace

  PlanResponse::PlanResponse(const Model &model)
    : model(model)
  {
    if (model.dimension != 3)
      return;
    for (const Building &building : model.buildings)
      {
        BuildingPeaks b;
        for (const PlanFloor &floor : building.plan)
          {
            Storey s;
            s.corner_drift_x.assign(floor.outline.size(), 0);
            s.corner_drift_y.assign(floor.outline.size(), 0);
            s.corner_acceleration_x.assign(floor.outline.size(), 0);
            s.corner_acceleration_y.assign(floor.outline.size(), 0);
            corner_acceleration.resize(corner_acceleration.size() + 2 * floor.outline.size(), 0);
            corner_drift.resize(corner_drift.size() + 2 * floor.outline.size(), 0);
            b.storeys.push_back(s);
          }
        peaks.push_back(b);
      }
  }

  PlanResponse::~PlanResponse() = default;

  void
  PlanResponse::reset()
  {
    for (BuildingPeaks &b : peaks)
      {
        for (Storey &s : b.storeys)
          {
            s.rotation = 0;
            std::fill(s.corner_drift_x.begin(), s.corner_drift_x.end(), 0.0);
            std::fill(s.corner_drift_y.begin(), s.corner_drift_y.end(), 0.0);
            std::fill(s.corner_acceleration_x.begin(), s.corner_acceleration_x.end(), 0.0);
            std::fill(s.corner_acceleration_y.begin(), s.corner_acceleration_y.end(), 0.0);
            s.irregularity_ratio = s.ratio_at_peak = {{1, 1}};
            s.peak_drift         = {{0, 0}};
            s.resultant_displacement = 0;
          }
        b.base_shear_x = b.base_shear_y = b.base_torque = 0;
      }
    forces.reset();
  }

  unsigned int
  PlanResponse::storey_drifts(const Vector &u, const unsigned int b, unsigned int at)
  {
    const Building        &building = model.buildings[b];
    std::array<double, 3>  below{{0, 0, 0}};
    Point2                 below_centre = building.plan.front().mass_centre;
    for (unsigned int i = 0; i < building.floors.size(); ++i)
      {
        const auto    q      = floor_motion(model, u, building.floors[i].nodes[0]);
        const Point2 &centre = building.plan[i].mass_centre;
        Storey       &s      = peaks[b].storeys[i];
        keep_peak(s.rotation, q[2]);
        keep_peak(s.resultant_displacement, std::hypot(q[0], q[1]));
        const std::vector<Point2> &corners = building.plan[i].outline;
        std::array<std::vector<double>, 2> drift{{std::vector<double>(corners.size()),
                                                 std::vector<double>(corners.size())}};
        for (unsigned int k = 0; k < corners.size(); ++k)
          {
            const Point2 &x = corners[k];
            drift[0][k]     = (q[0] - q[2] * (x.y - centre.y)) -
                          (below[0] - below[2] * (x.y - below_centre.y));
            drift[1][k] = (q[1] + q[2] * (x.x - centre.x)) -
                          (below[1] + below[2] * (x.x - below_centre.x));
            keep_peak(s.corner_drift_x[k], drift[0][k]);
            keep_peak(s.corner_drift_y[k], drift[1][k]);
            corner_drift[at++] = drift[0][k] / building.floors[i].storey_height;
            corner_drift[at++] = drift[1][k] / building.floors[i].storey_height;
          }
        s.irregularity_ratio = {{irregularity(s.corner_drift_x), irregularity(s.corner_drift_y)}};
        for (unsigned int d = 0; d < 2; ++d)
          keep_instant(drift[d], s.peak_drift[d], s.ratio_at_peak[d]);
        below        = q;
        below_centre = centre;
      }
    return at;
  }

  std::optional<double>
  PlanResponse::Storey::irregularity(const unsigned int d, const bool at_peak) const
  {
    const std::vector<double> *drifts[] = {&corner_drift_x, &corner_drift_y};
    double largest[2];
    for (unsigned int i = 0; i < 2; ++i)
      largest[i] = drifts[i]->empty() ? 0.0 : *std::max_element(drifts[i]->begin(), drifts[i]->end());
    if (!(largest[d] > relative_drift_floor * std::max(largest[0], largest[1])))
      return std::nullopt;
    return at_peak ? ratio_at_peak[d] : irregularity_ratio[d];
  }

  unsigned int
  PlanResponse::corner_accelerations(const ResponseView &state, const unsigned int b,
                                     unsigned int at)
  {
    const Building &building = model.buildings[b];
    for (unsigned int i = 0; i < building.floors.size(); ++i)
      {
        const auto    a      = floor_motion(model, state.acceleration(), building.floors[i].nodes[0]);
        const Point2 &centre = building.plan[i].mass_centre;
        Storey       &s      = peaks[b].storeys[i];
        const std::vector<Point2> &corners = building.plan[i].outline;
        for (unsigned int k = 0; k < corners.size(); ++k)
          {
            const double a_x = a[0] + state.ground_acceleration() - a[2] * (corners[k].y - centre.y);
            const double a_y = a[1] + state.ground_acceleration_y() + a[2] * (corners[k].x - centre.x);
            keep_peak(s.corner_acceleration_x[k], a_x);
            keep_peak(s.corner_acceleration_y[k], a_y);
            corner_acceleration[at++] = a_x;
            corner_acceleration[at++] = a_y;
          }
      }
    return at;
  }

  std::vector<std::string>
  PlanResponse::corner_acceleration_names() const
  {
    return corner_names("_floor", "_acc_", "_m_s2");
  }

  std::vector<std::string>
  PlanResponse::corner_drift_names() const
  {
    return corner_names("_storey", "_drift_ratio_", "");
  }

  std::vector<std::string>
  PlanResponse::corner_names(const std::string &level, const std::string &what,
                             const std::string &unit) const
  {
    std::vector<std::string> names;
    for (unsigned int b = 0; b < peaks.size(); ++b)
      for (unsigned int i = 0; i < peaks[b].storeys.size(); ++i)
        for (unsigned int k = 0; k < peaks[b].storeys[i].corner_acceleration_x.size(); ++k)
          {
            const std::string stem = model.buildings[b].name + level + std::to_string(i + 1) +
                                     "_corner" + std::to_string(k + 1) + what;
            names.push_back(stem + "x" + unit);
            names.push_back(stem + "y" + unit);
          }
    return names;
  }

  void
  PlanResponse::observe_step(const ResponseView &state)
  {
    unsigned int at = 0, at_drift = 0;
    for (unsigned int b = 0; b < peaks.size(); ++b)
      {
        at_drift = storey_drifts(state.displacement(), b, at_drift);
        at       = corner_accelerations(state, b, at);
      }
    if (peaks.empty())
      return;
    if (!forces)
      forces = std::make_unique<StoreyForces>(model, state.elements);
    for (unsigned int b = 0; b < peaks.size(); ++b)
      {
        const auto base = forces->plan_forces(forces->index(b, 0), state.displacement());
        keep_peak(peaks[b].base_shear_x, base[0]);
        keep_peak(peaks[b].base_shear_y, base[1]);
        keep_peak(peaks[b].base_torque, base[2]);
      }
  }

  void
  write_plan_response(JsonWriter &json, const PlanResponse &plan, const unsigned int b)
  {
    const PlanResponse::BuildingPeaks &peaks = plan.buildings()[b];
    std::vector<double> rotation, corner_x, corner_y, resultant;
    std::vector<std::optional<double>> ratio_x, ratio_y, instant_x, instant_y;
    for (const PlanResponse::Storey &s : peaks.storeys)
      {
        resultant.push_back(s.resultant_displacement);
        corner_x.push_back(*std::max_element(s.corner_acceleration_x.begin(),
                                             s.corner_acceleration_x.end()));
        corner_y.push_back(*std::max_element(s.corner_acceleration_y.begin(),
                                             s.corner_acceleration_y.end()));
        rotation.push_back(s.rotation);
        ratio_x.push_back(s.irregularity(0, false));
        ratio_y.push_back(s.irregularity(1, false));
        instant_x.push_back(s.irregularity(0, true));
        instant_y.push_back(s.irregularity(1, true));
      }
    json.begin_object("plan")
      .value("peak_floor_rotation_rad", rotation)
      .value("torsional_irregularity_x", ratio_x)
      .value("torsional_irregularity_y", ratio_y)
      .value("torsional_irregularity_at_peak_x", instant_x)
      .value("torsional_irregularity_at_peak_y", instant_y)
      .value("peak_corner_acceleration_x_m_s2", corner_x)
      .value("peak_corner_acceleration_y_m_s2", corner_y)
      .value("peak_floor_displacement_resultant_m", resultant)
      .value("peak_base_shear_x_N", peaks.base_shear_x)
      .value("peak_base_shear_y_N", peaks.base_shear_y)
      .value("peak_base_torque_N_m", peaks.base_torque)
      .end_object();
  }

  template <typename Function>
  void
  PlanResponse::for_each_number(const Function &f)
  {
    unsigned int at = 0; // in corner_acceleration
    for (unsigned int b = 0; b < peaks.size(); ++b)
      {
        BuildingPeaks &p = peaks[b];
        for (Storey &s : p.storeys)
          {
            f(b, s.rotation);
            f(b, s.resultant_displacement);
            for (std::vector<double> *x : {&s.corner_drift_x, &s.corner_drift_y,
                                           &s.corner_acceleration_x, &s.corner_acceleration_y})
              for (double &y : *x)
                f(b, y);
            for (std::array<double, 2> *x : {&s.irregularity_ratio, &s.ratio_at_peak, &s.peak_drift})
              for (double &y : *x)
                f(b, y);
            for (unsigned int k = 0; k < 2 * s.corner_acceleration_x.size(); ++k)
              {
                f(b, corner_drift[at]);
                f(b, corner_acceleration[at++]);
              }
          }
        for (double *x : {&p.base_shear_x, &p.base_shear_y, &p.base_torque})
          f(b, *x);
      }
  }

  void
  PlanResponse::merge(const RankMerge &ranks)
  {
    std::vector<double>       values;
    std::vector<unsigned int> building_of;
    for_each_number([&](const unsigned int b, const double x) {
      values.push_back(x);
      building_of.push_back(b);
    });
    ranks.owned(Owner::building, building_of, values);
    std::size_t i = 0;
    for_each_number([&](unsigned int, double &x) { x = values[i++]; });
  }
} // namespace poundfe
