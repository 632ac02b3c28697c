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
    // Raw pointers, read once: the stores into the floor arrays below then
    // do not make the compiler load the vectors' data pointers again for
    // every floor. The sums, from 0, in the equations' order as ever.
    const double *const U = u.data(), *const V = v.data(), *const A = a.data();
    const int *const          equation = equations.data();
    const unsigned int *const start    = equation_start.data();
    const double *const       w = weight.data(), *const inverse_h = inverse_height.data();
    const char *const         bottom = is_bottom_floor.data();
    double *const x = floor_displacement.data(), *const x_dot = floor_velocity.data(),
                  *const idr = drift.data(), *const x_ddot = acceleration.data();
    double *const peak_x = peak_u.data(), *const peak_idr = peak_drift.data(),
                  *const peak_idr_at = peak_drift_at.data(), *const peak_x_ddot = peak_a.data();
    const unsigned int n = weight.size();
    for (unsigned int i = 0; i < n; ++i)
      {
        double             sum_u = 0, sum_v = 0, sum_a = 0;
        const unsigned int begin = start[i], end = start[i + 1];
        if (end == begin + 1) // a shear building's floor: one equation, no loop to set up
          {
            const int e = equation[begin];
            sum_u += U[e];
            sum_v += V[e];
            sum_a += A[e];
          }
        else
          for (unsigned int k = begin; k < end; ++k)
            {
              const int e = equation[k];
              sum_u += U[e];
              sum_v += V[e];
              sum_a += A[e];
            }
        const double x_i = sum_u * w[i], x_ddot_i = sum_a * w[i] + ground_acceleration;
        const double idr_i = (x_i - (bottom[i] ? 0.0 : x[i - 1])) * inverse_h[i];
        x[i]      = x_i;
        x_dot[i]  = sum_v * w[i];
        x_ddot[i] = x_ddot_i;
        idr[i]    = idr_i;

        peak_x[i]      = std::max(peak_x[i], std::abs(x_i));
        peak_x_ddot[i] = std::max(peak_x_ddot[i], std::abs(x_ddot_i));
        if (std::abs(idr_i) > peak_idr[i])
          {
            peak_idr[i]    = std::abs(idr_i);
            peak_idr_at[i] = time;
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
