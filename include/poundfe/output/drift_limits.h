// Storey drift ratios checked against limits: the user's, and a code's.
//   ASCE 7-16 Table 12.12-1 (allowable story drift Delta_a, "all other
//     structures"): 0.020 h_sx for risk categories I and II, 0.015 h_sx for
//     III, 0.010 h_sx for IV (ASCE/SEI 7-16, Minimum Design Loads and
//     Associated Criteria for Buildings and Other Structures, ASCE 2017).
//   Eurocode 8 §4.4.3.2 damage limitation: d_r nu <= 0.005 h (brittle
//     non-structural elements attached to the structure), 0.0075 h (ductile
//     ones), 0.010 h (none, or fixed so as not to interfere); nu = 0.5
//     (importance classes I, II) or 0.4 (III, IV) recommended (EN 1998-1:2004,
//     Design of structures for earthquake resistance, Part 1, CEN). A run at
//     the damage-limitation action itself has nu = 1.
// The code values are limits on the design storey drift (ASCE 7: the
// elastic drift times C_d / I_e; Eurocode 8: at the design seismic action);
// a nonlinear time history's peak drift ratio is compared with them as it
// is: the user chooses the ground motion that makes the comparison meaningful.
// A storey passes a limit when its peak |IDR| <= the limit (the fragility
// command counts a failure when the peak exceeds it).
#ifndef poundfe_output_drift_limits_h
#define poundfe_output_drift_limits_h

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
  enum class DriftCode
  {
    none,
    asce7,
    eurocode8
  };

  const NameTable<DriftCode> &drift_code_names();

  struct DriftLimit
  {
    std::string name;        // for summary.json and the plot's legend
    double      drift_ratio; // the limit of the peak |IDR|
  };

  struct DriftLimitParameters
  {
    std::string limits_text{}; // "0.5 %, 1 %, 2 %" or "0.005, 0.01"
    DriftCode   code = DriftCode::none;
    std::string risk_category = "II";          // ASCE 7: I, II, III, IV
    std::string non_structural = "brittle";    // Eurocode 8: brittle, ductile, none
    double      nu = 0.5;                      // Eurocode 8 reduction factor

    /// Declare the `Drift limits` section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// Parse and check the limits. Throws InputError.
    void finalize(const InputFile &input);

    /// The user's limits in the order given, then the code's (empty: no check).
    const std::vector<DriftLimit> &limits() const { return all_limits; }

  private:
    std::vector<DriftLimit> all_limits;
  };

  /// The code's limit (ASCE 7 by risk category; Eurocode 8 by the kind of
  /// non-structural elements and nu); `code` is not none.
  DriftLimit code_drift_limit(DriftCode code, const std::string &risk_category,
                              const std::string &non_structural, double nu);

  /// One building against one limit.
  struct DriftCheck
  {
    DriftLimit                limit;
    double                    peak_drift_ratio = 0; // largest over the storeys
    unsigned int              storey_of_peak   = 0; // 1-based
    std::vector<unsigned int> storeys_exceeding;    // 1-based
    bool                      passes = true;
  };

  /// Each limit against the peak drift ratios of a building's storeys (bottom up).
  std::vector<DriftCheck> check_drift_limits(const std::vector<DriftLimit> &limits,
                                             const std::vector<double>     &peak_drift_ratios);
} // namespace poundfe

#endif
