// Whether a run's response stayed where the model means anything. A run
// can end "completed" with drift ratios of 2 or a roof 100 m away: the
// equations were solved, but the models behind them were not made for it.
//   - Storey drift ratio IDR = (x_i - x_{i-1}) / h_i (output/floor_response.h)
//     beyond D (Output/Warnings/Drift ratio, 0.10): 2.5 times the
//     collapse-prevention drift of concrete frames, 0.04 (FEMA 356 (2000),
//     Prestandard and commentary for the seismic rehabilitation of
//     buildings, Table C1-3), a drift the model cannot represent: its
//     members stay elastic and its Bouc-Wen hinges never lose strength.
//   - Roof displacement over the building's height beyond the same D.
//   - A node rotation |theta| beyond R (Output/Warnings/Rotation, 0.1 rad):
//     the frame elements use linear kinematics (small displacements, Euler-
//     Bernoulli, elements/frame_element.h); at 0.1 rad, sin(theta) differs
//     from theta by 0.17 % and the chord shortens by 1 - cos(theta) = 0.5 %,
//     which the small-displacement stiffness ignores.
// Each warning names the quantity, where, its peak and the bound; the run
// prints them and summary.json lists them under "warnings".
#ifndef poundfe_output_response_range_h
#define poundfe_output_response_range_h

#include <poundfe/output/observer.h>

#include <string>
#include <vector>

namespace poundfe
{
  class PeakResponse;

  class ResponseRange : public StepObserver
  {
  public:
    /// `drift_limit` and `rotation_limit` (rad): 0 switches the check off.
    ResponseRange(const Model &model, const PeakResponse &peaks, double drift_limit,
                  double rotation_limit);

    void initialize(const ResponseView &state) override;
    void observe_step(const ResponseView &state) override;
    void observe_substep(const ResponseView &state) override { observe_step(state); }
    /// Observation by rank, before warnings(): each building's peak
    /// rotation from the rank that owns it, on rank 0. Collective.
    void merge(const RankMerge &ranks) override;

    /// The warnings over the steps observed so far (the peaks' too).
    std::vector<std::string> warnings() const;

  private:
    const Model        &model;
    const PeakResponse &peaks;
    const double        drift_limit, rotation_limit;
    /// The rz equations of the nodes, in node order (none in a shear
    /// building: nothing to do per step), with their node and building.
    std::vector<int>          rotation_equations;
    std::vector<unsigned int> rotation_nodes, rotation_buildings;
    /// Peak |rz| of each building, the node and time where it was reached.
    std::vector<double>       peak_rotation, peak_rotation_time;
    std::vector<unsigned int> peak_rotation_node;
  };
} // namespace poundfe

#endif
