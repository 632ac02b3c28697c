// The plan response of include/poundfe/output/plan_response.h.
#include <poundfe/output/json_writer.h>
#include <poundfe/output/plan_response.h>

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
            b.storeys.push_back(s);
          }
        peaks.push_back(b);
      }
    // the hysteretic planes' elements follow the hinges and the storey links
    int next = model.hinges.size() +
               std::count_if(model.links.begin(), model.links.end(),
                             [](const StoreyLink &l) { return l.hysteretic; });
    for (const PlaneLink &link : model.plane_links)
      element_of_link.push_back(link.hysteretic ? next++ : -1);
  }

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
            s.irregularity_ratio = {{1, 1}};
          }
        b.base_shear_x = b.base_shear_y = b.base_torque = 0;
      }
  }

  double
  PlanResponse::plane_force(const ResponseView &state, const unsigned int l) const
  {
    if (element_of_link[l] >= 0)
      return state.elements[element_of_link[l]].force();
    const PlaneLink &link = model.plane_links[l];
    double           d    = 0;
    for (unsigned int k = 0; k < 2; ++k)
      {
        const auto q = floor_motion(model, state.displacement(), link.nodes[k]);
        for (unsigned int c = 0; c < 3; ++c)
          d += link.coefficients[3 * k + c] * q[c];
      }
    return link.stiffness * d;
  }

  void
  PlanResponse::storey_drifts(const Vector &u, const unsigned int b)
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
        const std::vector<Point2> &corners = building.plan[i].outline;
        for (unsigned int k = 0; k < corners.size(); ++k)
          {
            const Point2 &x = corners[k];
            keep_peak(s.corner_drift_x[k], (q[0] - q[2] * (x.y - centre.y)) -
                                             (below[0] - below[2] * (x.y - below_centre.y)));
            keep_peak(s.corner_drift_y[k], (q[1] + q[2] * (x.x - centre.x)) -
                                             (below[1] + below[2] * (x.x - below_centre.x)));
          }
        s.irregularity_ratio = {{irregularity(s.corner_drift_x), irregularity(s.corner_drift_y)}};
        below        = q;
        below_centre = centre;
      }
  }

  void
  PlanResponse::observe_step(const ResponseView &state)
  {
    for (unsigned int b = 0; b < peaks.size(); ++b)
      storey_drifts(state.displacement(), b);
    std::vector<std::array<double, 3>> base(peaks.size(), {{0, 0, 0}});
    for (unsigned int l = 0; l < model.plane_links.size(); ++l)
      {
        const PlaneLink &link = model.plane_links[l];
        if (link.storey != 1)
          continue;
        // the top floor's coefficients are (d_x, d_y, d·(p - C_1) turned)
        const double  f = plane_force(state, l);
        auto         &v = base[link.building];
        v[0] += f * link.coefficients[3];
        v[1] += f * link.coefficients[4];
        v[2] += f * link.coefficients[5];
      }
    for (unsigned int b = 0; b < peaks.size(); ++b)
      {
        keep_peak(peaks[b].base_shear_x, base[b][0]);
        keep_peak(peaks[b].base_shear_y, base[b][1]);
        keep_peak(peaks[b].base_torque, base[b][2]);
      }
  }

  void
  write_plan_response(JsonWriter &json, const PlanResponse &plan, const unsigned int b)
  {
    const PlanResponse::BuildingPeaks &peaks = plan.buildings()[b];
    std::vector<double> rotation, ratio_x, ratio_y;
    for (const PlanResponse::Storey &s : peaks.storeys)
      {
        rotation.push_back(s.rotation);
        ratio_x.push_back(s.irregularity_ratio[0]);
        ratio_y.push_back(s.irregularity_ratio[1]);
      }
    json.begin_object("plan")
      .value("peak_floor_rotation_rad", rotation)
      .value("torsional_irregularity_x", ratio_x)
      .value("torsional_irregularity_y", ratio_y)
      .value("peak_base_shear_x_N", peaks.base_shear_x)
      .value("peak_base_shear_y_N", peaks.base_shear_y)
      .value("peak_base_torque_N_m", peaks.base_torque)
      .end_object();
  }
} // namespace poundfe
