// Recorders: the time-history files a user chooses, by engineering name,
// each at its own interval (after OpenSees's `recorder Node/Element/Drift`).
//
//   subsection Output
//     subsection Recorders
//       set Default files = true
//       set Record        = base shear; storey shear every 0.01; residual drift;
//                           member end forces of A3_C1.1, A3_B1.1 every 0.005
//     end
//   end
//
// Each item of `Record` is `<quantity> [of <labels>] [every <seconds>]`;
// without `every`, the rows come every Output interval (every 0: every
// step). The default files (floor displacement, floor acceleration, storey
// drift ratio, hinge states, gap states, energy, ground motion) are written
// unless `Default files = false`. Every column carries its unit. The time
// series are CSV or, with Output/Format = npy, NumPy tables
// (output/table_writer.h).
#ifndef poundfe_output_recorder_parameters_h
#define poundfe_output_recorder_parameters_h

#include <poundfe/output/table_writer.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  enum class RecordedQuantity
  {
    floor_displacement, // floor_displacement.csv, m (relative to the ground)
    floor_velocity,     // floor_velocity.csv, m/s (relative)
    floor_acceleration, // floor_acceleration.csv, m/s^2 (absolute)
    drift_ratio,        // drift.csv
    storey_shear,       // storey_shear.csv, N
    base_shear,         // base_shear.csv, N
    residual_drift,     // residual_drift.csv: the drift ratios at the end
    member_forces,      // member_forces.csv: N, V (N) and M (N m) at both ends
    hinge_states,       // hinges.csv: moment or force, rotation or drift, z
    gap_states,         // contact_force.csv: force (N) and penetration (m)
    energy,             // energy.csv, J
    ground_motion,      // ground_motion.csv, m/s^2
    phase_portrait,     // phase_portrait.csv: u (m), u' (m/s) of every equation
                        // and each friction element's phase (0 stick, +-1 slip)
    corner_acceleration, // corner_acceleration.csv, m/s^2 (absolute, 3D: every
                         // slab corner along x and y; output/plan_response.h)
    section_states       // sections.csv: each integration point of the fibre
                         // members: N, M, eps0, kappa, extreme fibre strains
  };

  struct RecorderRequest
  {
    RecordedQuantity         quantity = RecordedQuantity::floor_displacement;
    std::vector<std::string> labels; // member_forces: the members; hinge/gap states: labels or building names (empty: all)
    double                   interval = -1.0; // s; < 0: the Output interval
  };

  /// Names of the quantities as written in `Record`, in RecordedQuantity order.
  std::vector<std::string> recorded_quantity_names();

  /// The `Output/Recorders` section (deal.II step-33 style: it declares and
  /// parses its own entries).
  struct RecorderParameters
  {
    bool                         default_files = true;
    std::string                  record;       // the text of `Record`
    std::vector<RecorderRequest> requests;     // parsed from it
    double                       output_interval = 0; // Output/Output interval, s
    OutputFormat                 format = OutputFormat::csv; // Output/Format
    int                          line            = 0; // of `Record`, for messages

    /// Declare `Default files` and `Record` in the current subsection.
    void declare(dealii::ParameterHandler &prm);
    /// After parsing: turn `record` into requests. Throws InputError
    /// (file, line) on a malformed item.
    void finalize(const std::string &file, int line_of_record, double output_interval);

    /// Parse the text of `Record`; throws std::invalid_argument with the
    /// reason.
    static std::vector<RecorderRequest> parse(const std::string &text);
  };

} // namespace poundfe

#endif
