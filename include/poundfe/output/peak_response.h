// Peaks of a time history, tracked at every accepted step: floor
// displacement, inter-storey drift ratio (and its time), absolute floor
// acceleration (FloorResponse), and per nonlinear element the peak |d| (and
// its time), peak |F|, peak plastic part |d - F/k0| and, for gaps, the
// smallest opening. The impact log adds the deepest points that fall
// between steps to the smallest opening at the end. A 3D model's peaks also
// hold the floor response along y (drifts of the mass centres along y,
// absolute accelerations with a_y), the floors' rotations θz (their angular
// velocities and accelerations; no ground rotation) and the plan response
// (floor rotations, corner drifts, base shears and torque: plan_response.h).
#ifndef poundfe_output_peak_response_h
#define poundfe_output_peak_response_h

#include <poundfe/output/floor_response.h>
#include <poundfe/output/observer.h>
#include <poundfe/output/plan_response.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace poundfe
{
  class UniaxialElement;

  class PeakResponse : public StepObserver
  {
  public:
    PeakResponse(const Model &model, const NonlinearElements &elements);

    /// Forgets the peaks of an earlier run, then observes the initial state.
    void initialize(const ResponseView &state) override;
    void observe_step(const ResponseView &state) override;
    /// Peaks inside a contact fall between the steps.
    void observe_substep(const ResponseView &state) override { observe_step(state); }
    void finish(const ResponseView &state, const RunStatus &status) override;
    /// Observation by rank, before finish(): the floors' (along x and y),
    /// the plan's and the elements' peaks from the ranks that own them, on
    /// rank 0. Collective.
    void merge(const RankMerge &ranks) override;

    /// The floor response at the last observed step and its peaks.
    const FloorResponse &floors() const { return floor_response; }
    /// A 3D model's floor response along y and its plan response (nullptr in 2D).
    const FloorResponse *floors_y() const { return floor_response_y.get(); }
    /// A 3D model's floor rotations θz (nullptr in 2D): its "displacement"
    /// is θz (rad), its "drift ratio" the storey's twist over its height.
    const FloorResponse *floors_rz() const { return floor_response_rz.get(); }
    const PlanResponse  *plan() const { return plan_response.get(); }
    /// The largest peak drift ratio of the mass centres (along x and, in 3D, y).
    double largest_drift_ratio() const;

    /// Elements are hinges and storeys first, then gaps, then springs and
    /// friction elements (make_nonlinear_elements).
    unsigned int n_hysteretic() const { return n_hysteretic_elements; }
    /// The gaps are elements [n_hysteretic(), n_hysteretic() + n_gaps()).
    unsigned int n_gaps() const { return n_gap_elements; }
    const std::vector<double> &peak_deformation() const { return peak_d; }
    const std::vector<double> &time_of_peak_deformation() const { return peak_d_at; }
    const std::vector<double> &peak_force() const { return peak_f; }
    const std::vector<double> &peak_plastic_deformation() const { return peak_plastic; }
    /// Peak |d| / yield deformation of element h (0 without a yield deformation).
    double ductility(unsigned int h) const;
    /// Smallest gap opening over the run (negative: penetration); +inf without gaps.
    double min_clearance() const { return smallest_clearance; }

  private:
    /// One element's peaks at time t; `d` its deformation now.
    template <typename Element>
    void observe_element(unsigned int h, const Element &e, double t, double d);
    /// The floors' (and in 3D the plan's) peaks at this state.
    void observe_floors(const ResponseView &state);
    /// Every observed element's peaks; `from_trial`: a uniaxial element's
    /// deformation read from its last evaluation (ResponseView::elements_hold_state).
    void observe_elements(const ResponseView &state, bool from_trial);

    const NonlinearElements &elements;
    /// Element h as the UniaxialElement it is, else null, of the elements
    /// observed (initialize()): the loop over them with no test of the
    /// class or the observation per element and step.
    std::vector<std::pair<unsigned int, const UniaxialElement *>> observed;
    FloorResponse           floor_response;
    std::unique_ptr<FloorResponse> floor_response_y;  // 3D models
    std::unique_ptr<FloorResponse> floor_response_rz; // 3D models
    std::unique_ptr<PlanResponse>  plan_response;    // 3D models
    unsigned int            n_hysteretic_elements = 0, n_gap_elements = 0;
    std::vector<double>     peak_d, peak_d_at, peak_f, peak_plastic;
    double                  smallest_clearance = 0;
  };

  /// The scalars of a 3D model's run along y and in plan (empty for a 2D
  /// model), named with their units: per storey the peak drift ratio along y
  /// of the mass centres, per floor the peak absolute acceleration along y
  /// (m/s^2), per building the largest corner drift ratio of any storey in x
  /// or y, the peak floor rotation (rad), the peak base shears along x and y
  /// (N) and the peak base torque (N m).
  std::vector<std::string> plan_scalar_names(const Model &model);
  /// Their values after a run observed by `peaks`, appended to `row`.
  void append_plan_scalars(const Model &model, const PeakResponse &peaks, std::vector<double> &row);
} // namespace poundfe

#endif
