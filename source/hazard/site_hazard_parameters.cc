#include <poundfe/base/numbers.h>
#include <poundfe/excitation/ground_motion_bounds.h>
#include <poundfe/hazard/site_hazard_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  namespace
  {
    /// The largest lognormal dispersion of a typed-in fragility, only against
    /// absurd values (1e200 ran with exit 0): `poundfe fragility` fits curves
    /// that are flat over their intensities with dispersions of 1e14 and more,
    /// and such a curve typed in must run.
    constexpr double largest_fragility_beta = largest_model_value;
  } // namespace

  const NameTable<IntensityHazard::Model> &
  hazard_model_names()
  {
    static const NameTable<IntensityHazard::Model> table(
      {{IntensityHazard::Model::gumbel, "gumbel"}, {IntensityHazard::Model::poisson, "poisson"}});
    return table;
  }

  namespace
  {
    /// Site hazard/Fragility: the fragility that the hazard is combined with.
    void
    declare_fragility_entries(dealii::ParameterHandler &prm, SiteHazardParameters &p)
    {
      prm.enter_subsection("Fragility");
      prm.add_parameter("Median PGA", p.fragility_median,
                        "theta of a lognormal fragility P(F | a) = Phi(ln(a/theta)/beta) "
                        "(0: none, or the File's), at most 10 g. Unit: g.",
                        Patterns::Double(0));
      prm.add_parameter("Beta", p.fragility_beta,
                        "beta of the typed-in fragility, at most 1e150. Unit: dimensionless.",
                        Patterns::Double(0));
      prm.add_parameter("File", p.fragility_file,
                        "summary.json written by `poundfe fragility` (relative to this parameter "
                        "file); its curve named Curve is used. Unit: -.");
      prm.add_parameter("Curve", p.fragility_curve,
                        "Name of the curve in File: pounding, or drift_<limit> (e.g. drift_0.01). "
                        "Unit: -.");
      prm.leave_subsection();
    }
  } // namespace

  void
  SiteHazardParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Site hazard");
    prm.add_parameter("Catalogue file", catalogue_file,
                      "CSV of historical earthquakes, relative to this parameter file: a header "
                      "naming the columns date (YYYY, YYYY-MM or YYYY-MM-DD), latitude (degrees "
                      "north), longitude (degrees east) and magnitude, in any order (other "
                      "columns are kept out); lines starting with # are comments. Unit: -.");
    prm.add_parameter("Site latitude", site.latitude, "Degrees north of the site. Unit: degrees.",
                      Patterns::Double(-90, 90));
    prm.add_parameter("Site longitude", site.longitude, "Degrees east of the site. Unit: degrees.",
                      Patterns::Double(-180, 360));
    prm.add_parameter("First year", first_year,
                      "First year of the observation period (0: the year of the first event). "
                      "Unit: year.",
                      Patterns::Integer(0));
    prm.add_parameter("Last year", last_year,
                      "Last year of the observation period (0: the year of the last event). "
                      "Unit: year.",
                      Patterns::Integer(0));
    add_choice(prm, "Fit", fit,
               "gumbel: Gumbel type I of the annual maxima of the site intensity (maximum "
               "likelihood, years without an event above the minimum intensity censored at "
               "it); poisson: Poisson occurrences with an exponential (Gutenberg-Richter) law "
               "of the intensities above the minimum (Aki's maximum-likelihood b). Unit: -.",
               hazard_model_names());
    prm.add_parameter("Return periods", return_periods,
                      "Years (each > 1) whose site intensity and PGA are reported. Unit: years.",
                      Patterns::List(Patterns::Double(0), 1, 100, ","));
    prm.add_parameter("Minimum intensity", minimum_intensity,
                      "Site intensities below this are not counted (and censor the Gumbel "
                      "years without a larger one). Unit: dimensionless (a macroseismic "
                      "intensity).");
    prm.add_parameter("Focal depth", focal_depth,
                      "h: Cornell's r = sqrt(Delta^2 + h^2), Delta the epicentral distance "
                      "(0: r = Delta, as the thesis does). Unit: km.",
                      Patterns::Double(0));
    prm.add_parameter("Maximum distance", maximum_distance,
                      "Events farther than this are left out (0: none). Unit: km.",
                      Patterns::Double(0));
    prm.add_parameter("Exposure", exposure_years,
                      "Years of the reported probability of failure, 1 - exp(-years lambda_F). "
                      "Unit: years.",
                      Patterns::Double(0));
    prm.add_parameter("Intensity decimals", intensity_decimals,
                      "Each event's site intensity is rounded to this many decimals before "
                      "its acceleration and the fit (-1: not rounded; the thesis's Table 2.2 "
                      "rounds to 1 for some rows). Unit: count.",
                      Patterns::Integer(-1, 6));
    declare_fragility_entries(prm, *this);
    study.declare(prm);
    prm.leave_subsection();
  }

  std::vector<NamedInputFile>
  SiteHazardParameters::input_files() const
  {
    std::vector<NamedInputFile> files;
    if (!catalogue_file.empty())
      files.push_back({"Site hazard/Catalogue file", "catalogue", catalogue_file, ""});
    if (!fragility_file.empty())
      files.push_back({"Site hazard/Fragility/File", "fragility file", fragility_file, ""});
    return files;
  }

  void
  SiteHazardParameters::check(const InputFile &input) const
  {
    for (const double T : return_periods)
      if (!(T > 1) || !std::isfinite(T))
        input.fail("Site hazard/Return periods", "every return period must exceed 1 year");
    input.distinct("Site hazard/Return periods", return_periods);
    if (first_year > 0 && last_year > 0 && last_year < first_year)
      input.fail("Site hazard/Last year", "is before the First year");
    if (!std::isfinite(minimum_intensity))
      input.fail("Site hazard/Minimum intensity", "must be finite");
    if (fragility_median > 0 && !fragility_file.empty())
      input.fail("Site hazard/Fragility/File",
                 "give a fragility either by Median PGA and Beta or by File, not both");
    if (fragility_median > 0 && !(fragility_beta > 0))
      input.fail("Site hazard/Fragility/Beta", "a typed-in fragility needs Beta > 0");
    if (!has_fragility() && fragility_beta > 0)
      input.fail("Site hazard/Fragility/Median PGA", "Beta is given without a Median PGA");
    if (fragility_median > largest_ground_acceleration_g)
      input.fail("Site hazard/Fragility/Median PGA",
                 "must be at most " + number_text(largest_ground_acceleration_g) + " g (" +
                   largest_ground_acceleration_why + "), got " + number_text(fragility_median));
    if (fragility_beta > largest_fragility_beta)
      input.fail("Site hazard/Fragility/Beta",
                 "must be at most " + number_text(largest_fragility_beta) +
                   " (the largest value of a model: `poundfe fragility` fits a curve that "
                   "is flat over its intensities with dispersions of 1e14 and more, and "
                   "such a curve typed in must run), got " + number_text(fragility_beta));
    study.check(input);
  }

  void
  SiteHazardParameters::require(const InputFile &input) const
  {
    if (catalogue_file.empty() && !study.given())
      input.fail("Site hazard/Catalogue file",
                 "site-hazard needs a catalogue of earthquakes or a Site study");
    if (catalogue_file.empty() && has_fragility())
      input.fail("Site hazard/Fragility/Median PGA",
                 "a fragility is convolved with a catalogue's hazard: give a Catalogue file");
  }
} // namespace poundfe
