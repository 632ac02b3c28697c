// The plan response of 3D shear buildings (Model/Dimension = 3), tracked at
// every step: per floor the peak twist |θz|; per storey the peak drifts
// along x and y at every corner of the slab (rigid diaphragm, small
// rotations: a point X of floor i moves u_x - θ (X_y - C_y),
// u_y + θ (X_x - C_x)), and from them the torsional irregularity ratio
//   Δmax / Δavg,  Δavg = (Δmax + Δmin) / 2
// over the corners' peak drifts in each direction (ASCE/SEI 7-16 Table
// 12.3-1, types 1a (> 1.2) and 1b (> 1.4); EN 1998-1 §4.3.3.2.2(6)), and
// the same ratio at the instant when the storey's largest corner drift
// peaks (doc/theory.md §1.12: the code's ratio is of one deformed shape); per
// building the peak base shears V_x, V_y and the peak base torque about the
// first floor's mass centre at rest (output/storey_forces.h: the resisting
// planes of the first storey, T = Σ (p_j - C_1) × F_j d_j, or the element
// forces of a 3D frame's ground-storey columns); per floor the absolute
// acceleration of every slab corner, by the same rigid-diaphragm kinematics
//   a_x = u_x'' + a_gx - θz'' (X_y - C_y),  a_y = u_y'' + a_gy + θz'' (X_x - C_x)
// (small rotations, the centripetal term θz'^2 left out as in the drifts;
// Chopra, Dynamics of Structures, 4th ed., §9.5: the floor's motion as a
// rigid body; ASCE/SEI 7-16 §13.3.1: nonstructural components see the
// acceleration of the point they hang from, largest at the corners of a
// twisting floor), its peak over time and its value at each step; per
// floor the peak resultant displacement of the mass centre, sqrt(u_x^2 +
// u_y^2) (the one direction-free displacement: a resultant drift or
// acceleration of a corner mixes two corners' peaks). A ratio along an axis
// whose largest corner drift is below relative_drift_floor times the
// storey's largest in either axis (a symmetric building shaken along the
// other axis: round-off) has no meaning: irregularity() is empty there.
#ifndef poundfe_output_plan_response_h
#define poundfe_output_plan_response_h

#include <poundfe/output/observer.h>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace poundfe
{
  class StoreyForces;

  class PlanResponse final : public StepObserver
  {
  public:
    explicit PlanResponse(const Model &model);
    ~PlanResponse();

    void observe_step(const ResponseView &state) override;
    /// Forget the peaks (a new run).
    void reset();
    /// Observation by rank: each building's peaks and corner accelerations
    /// from the rank that owns it, on rank 0. Collective.
    void merge(const RankMerge &ranks) override;

    struct Storey
    {
      double                rotation = 0;              // peak |θz| of the floor on top, rad
      std::vector<double>   corner_drift_x, corner_drift_y; // peaks, m
      std::array<double, 2> irregularity_ratio{{1, 1}};   // x, y
      /// The same ratio taken at one instant: when the storey's largest
      /// corner drift max_k |δ_k(t)| peaks (x, y), with the signed drifts
      /// of that instant, Δavg = s (max_k s δ_k + min_k s δ_k) / 2, s the
      /// sign of the largest; that largest drift, m.
      std::array<double, 2> ratio_at_peak{{1, 1}};
      std::array<double, 2> peak_drift{{0, 0}};
      /// Peak absolute accelerations of the corners of the floor on top,
      /// along x and y, m/s^2.
      std::vector<double>   corner_acceleration_x, corner_acceleration_y;
      /// Peak resultant displacement of the floor's mass centre, m.
      double resultant_displacement = 0;
      /// The torsional irregularity ratio along axis d (0: x, 1: y) over
      /// the peaks (at_peak = false) or at the instant of the largest
      /// drift; empty along an axis with (almost) no drift.
      std::optional<double> irregularity(unsigned int d, bool at_peak) const;
    };
    /// Below this fraction of the storey's largest corner drift, an axis has
    /// no drift of its own (round-off is ~1e-16 of it).
    static constexpr double relative_drift_floor = 1e-9;
    struct BuildingPeaks
    {
      std::vector<Storey> storeys;
      double base_shear_x = 0, base_shear_y = 0, base_torque = 0; // peaks of |.|
    };
    /// Per building (empty for 2D models).
    const std::vector<BuildingPeaks> &buildings() const { return peaks; }

    /// The corners' absolute accelerations at the last observed step: for
    /// every building, floor (bottom up) and slab corner, a_x then a_y.
    const std::vector<double> &corner_accelerations() const { return corner_acceleration; }
    /// Their columns, "<building>_floor<i>_corner<k>_acc_x_m_s2" and _y.
    std::vector<std::string> corner_acceleration_names() const;
    /// The corners' drift ratios at the last observed step (drift over the
    /// storey height): for every building, storey and slab corner, x then y.
    const std::vector<double> &corner_drift_ratios() const { return corner_drift; }
    /// Their columns, "<building>_storey<i>_corner<k>_drift_ratio_x" and _y.
    std::vector<std::string> corner_drift_names() const;

  private:
    /// Building b's storeys' drifts into the peaks and corner_drift from
    /// `at` on; returns the next index.
    unsigned int storey_drifts(const Vector &u, unsigned int b, unsigned int at);
    /// Fills corner_acceleration from building b's floors, from `at` on;
    /// returns the next index.
    unsigned int corner_accelerations(const ResponseView &state, unsigned int b, unsigned int at);
    /// "<building><level><i>_corner<k><what>x<unit>" and y, of every corner.
    std::vector<std::string> corner_names(const std::string &level, const std::string &what,
                                          const std::string &unit) const;
    /// f(b, x) for every number x of building b's peaks and corner
    /// accelerations, building after building, always in the same order.
    template <typename Function>
    void for_each_number(const Function &f);

    const Model                  &model;
    std::vector<BuildingPeaks>    peaks;
    std::vector<double>           corner_acceleration, corner_drift;
    /// Of the run's elements: made at its first step, forgotten by reset.
    std::unique_ptr<StoreyForces> forces;
  };

  class JsonWriter;

  /// The "plan" object of building b in summary.json: per storey the peak
  /// floor rotation and the irregularity ratios in x and y (null along an
  /// axis without drift), the peak base shears and torque.
  void write_plan_response(JsonWriter &json, const PlanResponse &plan, unsigned int b);
} // namespace poundfe

#endif
