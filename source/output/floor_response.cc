#include <poundfe/output/floor_response.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  FloorResponse::FloorResponse(const Model &model, const Component direction)
    : model(model)
  {
    equation_start.push_back(0);
    for (const Building &building : model.buildings)
      {
        first.push_back(weight.size());
        for (unsigned int f = 0; f < building.floors.size(); ++f)
          {
            const Floor &floor = building.floors[f];
            for (const unsigned int node : floor.nodes)
              if (const int e = model.equation(Model::dof(node, direction)); e >= 0)
                equations.push_back(e);
            equation_start.push_back(equations.size());
            weight.push_back(1.0 / floor.nodes.size());
            inverse_height.push_back(1 / floor.storey_height);
            is_bottom_floor.push_back(f == 0);
          }
      }
    const unsigned int n = weight.size();
    for (auto *v : {&floor_displacement, &floor_velocity, &drift, &acceleration, &peak_u, &peak_drift,
                    &peak_drift_at, &peak_a})
      v->assign(n, 0.0);
  }

  void
  FloorResponse::reset()
  {
    for (auto *v : {&floor_displacement, &floor_velocity, &drift, &acceleration, &peak_u,
                    &peak_drift, &peak_drift_at, &peak_a})
      std::fill(v->begin(), v->end(), 0.0);
  }

  void
  FloorResponse::evaluate(const double time, const Vector &u, const Vector &v, const Vector &a,
                          const double ground_acceleration)
  {
    for (unsigned int i = 0; i < weight.size(); ++i)
      {
        double             sum_u = 0, sum_v = 0, sum_a = 0;
        const unsigned int begin = equation_start[i], end = equation_start[i + 1];
        if (end == begin + 1) // a shear building's floor: one equation, no loop
          {
            const int e = equations[begin];
            sum_u += u[e];
            sum_v += v[e];
            sum_a += a[e];
          }
        else
          for (unsigned int k = begin; k < end; ++k)
            {
              const int e = equations[k];
              sum_u += u[e];
              sum_v += v[e];
              sum_a += a[e];
            }
        floor_displacement[i] = sum_u * weight[i];
        floor_velocity[i]     = sum_v * weight[i];
        acceleration[i]       = sum_a * weight[i] + ground_acceleration;
        const double below    = is_bottom_floor[i] ? 0.0 : floor_displacement[i - 1];
        drift[i]              = (floor_displacement[i] - below) * inverse_height[i];

        peak_u[i] = std::max(peak_u[i], std::abs(floor_displacement[i]));
        peak_a[i] = std::max(peak_a[i], std::abs(acceleration[i]));
        if (std::abs(drift[i]) > peak_drift[i])
          {
            peak_drift[i]    = std::abs(drift[i]);
            peak_drift_at[i] = time;
          }
      }
  }

  std::vector<std::string>
  FloorResponse::column_names(const std::string &what, const std::string &suffix) const
  {
    std::vector<std::string> names;
    for (const Building &building : model.buildings)
      for (unsigned int f = 1; f <= building.floors.size(); ++f)
        names.push_back(building.name + "_" + what + std::to_string(f) + "_" + suffix);
    return names;
  }

  void
  FloorResponse::merge(const RankMerge &ranks)
  {
    for (std::vector<double> *x : {&floor_displacement, &floor_velocity, &drift, &acceleration,
                                   &peak_u, &peak_drift, &peak_drift_at, &peak_a})
      ranks.owned(Owner::floor, *x);
  }
} // namespace poundfe
