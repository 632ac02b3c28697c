// The `Pushover` section: the lateral load pattern of each building, the
// control node (a floor of one building), the target drift or the cyclic
// protocol of drifts, the static solver's settings (dynamics/pushover.h)
// and the method of the target displacement (EC8's N2,
// dynamics/capacity_curve.h; ASCE 41's coefficients, dynamics/asce41_target.h).
#ifndef poundfe_dynamics_pushover_parameters_h
#define poundfe_dynamics_pushover_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/dynamics/asce41_target.h>

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

  /// The target displacement of the capacity curve: EN 1998-1 Annex B's N2,
  /// ASCE 41-17's coefficient method, or both.
  enum class TargetMethod
  {
    n2,
    asce41,
    both
  };

  const NameTable<TargetMethod> &target_method_names();

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
    TargetMethod target_method = TargetMethod::n2;
    /// ASCE 41: the site class (C1's factor a) and C_m of Table 7-4.
    SiteClass    site_class            = SiteClass::D;
    double       effective_mass_factor = 1.0;

    /// Declare the `Pushover` section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// Check the entries against the number of buildings and whether a
    /// Spectrum/Target is given. Throws InputError.
    void finalize(const InputFile &input, unsigned int n_buildings, bool spectrum_target);
    /// The drift ratios of the excursions in turn.
    std::vector<double> targets() const;
    /// Whether the method asks for N2's target, ASCE 41's.
    bool n2() const { return target_method != TargetMethod::asce41; }
    bool asce41() const { return target_method != TargetMethod::n2; }
  };
} // namespace poundfe

#endif
