// Floor response of each building from the equations' values (along x, or
// along y for a 3D model's y direction: uy and a_y in place of ux and a_g):
//   floor displacement x_i = mean ux of the floor's joints (relative to ground),
//   floor velocity = mean relative ux',
//   inter-storey drift ratio IDR_i = (x_i - x_{i-1}) / h_i (x_0 = 0, the base),
//   absolute floor acceleration = mean relative ux'' + a_g.
// Peaks (max over time of |.|) are tracked at every step, not just at the
// output interval.
#ifndef poundfe_output_floor_response_h
#define poundfe_output_floor_response_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/base/rank_merge.h>
#include <poundfe/model/model.h>

#include <string>
#include <vector>

namespace poundfe
{
  class FloorResponse
  {
  public:
    explicit FloorResponse(const Model &model, Component direction = Component::ux);

    void evaluate(double time, const Vector &u, const Vector &v, const Vector &a,
                  double ground_acceleration);

    /// Forget the peaks (a new run).
    void reset();
    /// Observation by rank: each floor's values from the rank that owns
    /// its building, on rank 0 (base/rank_merge.h). Collective.
    void merge(const RankMerge &ranks);

    unsigned int n_floors() const { return weight.size(); }
    /// Index of floor f (0-based, bottom up) of building b in the flat arrays.
    unsigned int index(unsigned int b, unsigned int f) const { return first[b] + f; }

    const std::vector<double> &displacement() const { return floor_displacement; }
    const std::vector<double> &velocity() const { return floor_velocity; }
    const std::vector<double> &drift_ratio() const { return drift; }
    const std::vector<double> &absolute_acceleration() const { return acceleration; }

    const std::vector<double> &peak_displacement() const { return peak_u; }
    const std::vector<double> &peak_drift_ratio() const { return peak_drift; }
    const std::vector<double> &peak_drift_time() const { return peak_drift_at; }
    const std::vector<double> &peak_acceleration() const { return peak_a; }

    /// "<building>_<what><n>_<suffix>" for every floor (what = "floor") or
    /// storey (what = "storey"), e.g. A3_storey1_drift_ratio.
    std::vector<std::string> column_names(const std::string &what,
                                          const std::string &suffix) const;

  private:
    // Flat arrays, read at every step: floor i's free equations are
    // equations[equation_start[i]] up to equation_start[i + 1] (its fixed
    // nodes are left out but counted in weight[i] = 1 / number of nodes).
    const Model                    &model;
    std::vector<unsigned int>       first;
    std::vector<int>                equations;
    std::vector<unsigned int>       equation_start;
    std::vector<double>             weight;
    std::vector<double>             inverse_height;
    std::vector<char>               is_bottom_floor;
    std::vector<double>             floor_displacement, floor_velocity, drift, acceleration;
    std::vector<double>             peak_u, peak_drift, peak_drift_at, peak_a;
  };
} // namespace poundfe

#endif
