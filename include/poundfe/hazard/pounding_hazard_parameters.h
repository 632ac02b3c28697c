// The `Separation/Site hazard` subsection: the site hazard with which the
// `separation` command turns its Monte Carlo at several PGA levels into the
// annual rate and the probability over an exposure time of pounding against
// the gap width (hazard/pounding_hazard.h).
#ifndef poundfe_hazard_pounding_hazard_parameters_h
#define poundfe_hazard_pounding_hazard_parameters_h

#include <poundfe/base/input_file.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  struct PoundingHazardParameters
  {
    /// hazard_curve.csv or summary.json of `poundfe site-hazard` (relative to
    /// the parameter file), or a typed-in power law k0 a^-k.
    std::string         hazard_file{};
    double              power_law_coefficient = 0; // k0, 1/year (lambda at 1 g)
    double              power_law_exponent    = 0; // k
    double              minimum_pga           = 0; // g; 0: the file's
    std::vector<double> pga_levels{0.1, 0.2, 0.3, 0.4, 0.5}; // g
    double              exposure_years     = 50;
    double              target_probability = 0.1; // over the exposure

    /// Declare the subsection (entered and left here, inside Separation).
    void declare(dealii::ParameterHandler &prm);
    /// The hazard file, when given.
    std::vector<NamedInputFile> input_files() const;
    /// Throws InputError.
    void check(const InputFile &input) const;
    /// Whether a hazard is given: without one the command is unchanged.
    bool given() const { return !hazard_file.empty() || power_law_coefficient > 0; }
  };
} // namespace poundfe

#endif
