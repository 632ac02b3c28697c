// The `Site hazard` section of `poundfe site-hazard`: the catalogue of
// historical earthquakes, the site, the observation period, the fit, the
// return periods and, optionally, a lognormal fragility to convolve with the
// hazard (typed in, or a curve of the summary.json `poundfe fragility` wrote).
#ifndef poundfe_hazard_site_hazard_parameters_h
#define poundfe_hazard_site_hazard_parameters_h

#include <poundfe/hazard/site_hazard.h>
#include <poundfe/hazard/site_study_parameters.h>
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
  /// Also the names in summary.json.
  const NameTable<IntensityHazard::Model> &hazard_model_names();

  struct SiteHazardParameters
  {
    std::string             catalogue_file{}; // relative to the parameter file
    GeographicPoint         site{};
    int                     first_year = 0, last_year = 0; // 0: from the catalogue
    IntensityHazard::Model  fit        = IntensityHazard::Model::gumbel;
    std::vector<double>     return_periods{100, 144, 250, 475}; // years
    double                  minimum_intensity = 1.0;
    double                  focal_depth       = 0.0; // km
    double                  maximum_distance  = 0.0; // km; 0: every event
    double                  exposure_years    = 50.0;
    int                     intensity_decimals = -1; // < 0: the site intensity not rounded
    // Fragility: a median (g) and beta typed in, or a curve of a file
    double                  fragility_median = 0.0, fragility_beta = 0.0;
    std::string             fragility_file{}, fragility_curve = "pounding";
    SiteStudyParameters     study{}; // Site study: the earthquake coefficient

    /// Declare the section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// The catalogue and the fragility file, those given.
    std::vector<NamedInputFile> input_files() const;
    /// The values that need no file. Throws InputError.
    void check(const InputFile &input) const;
    /// For `site-hazard`: a catalogue is named or a Site study given. Throws InputError.
    void require(const InputFile &input) const;
    /// Whether a fragility is given (typed in or from a file).
    bool has_fragility() const { return fragility_median > 0 || !fragility_file.empty(); }
  };
} // namespace poundfe

#endif
