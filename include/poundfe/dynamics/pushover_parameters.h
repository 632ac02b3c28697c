// The `Pushover` section: the lateral load pattern of each building, the
// control node (a floor of one building), the target drift or the cyclic
// protocol of drifts, and the static solver's settings (dynamics/pushover.h).
#ifndef poundfe_dynamics_pushover_parameters_h
#define poundfe_dynamics_pushover_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// The lateral loads of a building, on each floor's ux: m_i phi_i with
  /// phi the first mode (mode), the height above the base (triangular:
  /// the inverse triangle of EC8 §4.3.3.2.3) or 1 (uniform).
  enum class LoadPattern
  {
    mode,
    triangular,
    uniform
  };

  const NameTable<LoadPattern> &load_pattern_names();

  struct PushoverParameters
  {
    /// One for all buildings or one per building (names as load_pattern_names).
    std::vector<std::string> pattern_names{"triangular"};
    std::vector<LoadPattern> patterns; // finalize(): one per building
    unsigned int control_building = 1; // 1-based
    unsigned int control_floor    = 0; // 1-based; 0: the roof
    bool         cyclic           = false;
    /// Monotonic: the control node's drift ratio (displacement over its
    /// height above the base) to reach.
    double       target_drift = 0.02;
    /// Cyclic: the drift ratios to reach in turn (signed).
    std::vector<double> protocol;
    unsigned int n_steps        = 50; // per excursion
    double       tolerance      = 1e-8;
    unsigned int max_iterations = 25;
    unsigned int max_step_cuts  = 6;
    /// Past a peak or a snap-back that displacement control cannot pass:
    /// continue by arc length (Crisfield).
    bool         arc_length = true;

    /// Declare the `Pushover` section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// Check the entries against the number of buildings. Throws InputError.
    void finalize(const InputFile &input, unsigned int n_buildings);
    /// The drift ratios of the excursions in turn.
    std::vector<double> targets() const;
  };
} // namespace poundfe

#endif
