// The `Monte Carlo`, `Subset simulation` and `Fragility` sections.
#ifndef poundfe_reliability_reliability_parameters_h
#define poundfe_reliability_reliability_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/model/parameters.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  struct MonteCarloParameters
  {
    unsigned int        realizations = 100;
    std::vector<double> drift_limits{0.005, 0.01, 0.02}; // drift ratios
    unsigned int        histogram_bins = 20;

    /// Declare the section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    void check(const InputFile &input) const;
  };

  /// The response whose exceedance Subset Simulation estimates.
  enum class SubsetResponse
  {
    peak_drift_ratio,
    peak_roof_displacement,
    limit_state, // the system of Random parameters/Limit states: Y = -g, failure Y > 0
    peak_contact_force
  };

  /// Also the names in summary.json and in plots.
  const NameTable<SubsetResponse> &subset_response_names();

  struct SubsetParameters
  {
    SubsetResponse response  = SubsetResponse::peak_drift_ratio;
    std::string    building_field = "1"; // as read: a number or a Name
    unsigned int   building  = 1;        // 1-based, resolved by check()
    unsigned int   storey    = 0; // 0: the largest over the building's storeys
    double         threshold = 0.01;
    unsigned int   samples_per_level       = 500;
    double         conditional_probability = 0.1;
    unsigned int   max_levels              = 10;
    double         proposal_spread         = 1.0;

    void declare(dealii::ParameterHandler &prm);
    /// `model`: the building and storey must exist; resolves `building`.
    /// Throws InputError.
    void check(const InputFile &input, const ModelParameters &model);
  };

  struct FragilityParameters
  {
    std::vector<double> pga_levels{0.1, 0.2, 0.3, 0.4, 0.5}; // g
    unsigned int        realizations_per_level = 50;

    void declare(dealii::ParameterHandler &prm);
    void check(const InputFile &input) const;
  };
} // namespace poundfe

#endif
