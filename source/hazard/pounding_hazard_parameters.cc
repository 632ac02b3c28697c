#include <poundfe/hazard/pounding_hazard_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  namespace
  {
    /// The largest annual rate of PGAs beyond 1 g taken (1/year).
    constexpr double largest_rate_at_1g = 10;
    /// The steepest power law taken: hazard curves fall as a^-1 to a^-4;
    /// a^-1e200 overflowed the hazard integral (a numerical failure).
    constexpr double largest_exponent = 20;
    /// The largest PGA taken (g): the strongest records reach about 4 g.
    constexpr double largest_pga = 10;
    /// The longest exposure taken (years): beyond any structure's life
    /// (1e200 years ran without end).
    constexpr double longest_exposure = 1e4;
  } // namespace

  void
  PoundingHazardParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Site hazard");
    prm.add_parameter("File", hazard_file,
                      "The site's hazard curve, relative to this parameter file: the "
                      "hazard_curve.csv (columns pga_g and annual_rate_per_year, interpolated "
                      "linearly in log-log) or the summary.json (its Gumbel or Poisson fit) "
                      "that `poundfe site-hazard` writes. Empty: none, or the power law of "
                      "Annual rate at 1 g and Exponent. "
                      "With a hazard, separation runs its Monte Carlo at each PGA level and "
                      "reports the annual rate and the probability over the Exposure of "
                      "pounding against the gap width. Unit: -.",
                      Patterns::Anything());
    prm.add_parameter("Annual rate at 1 g", power_law_coefficient,
                      "k0 of a typed-in power-law hazard lambda(a) = k0 a^-k (a the PGA in g), "
                      "0: none (the File's hazard). Unit: 1/year.",
                      Patterns::Double(0));
    prm.add_parameter("Exponent", power_law_exponent,
                      "k > 0 of the typed-in power-law hazard (typically 1 to 4). "
                      "Unit: dimensionless.",
                      Patterns::Double(0));
    prm.add_parameter("Minimum PGA", minimum_pga,
                      "g: events of a smaller PGA are not counted (the lower limit of the hazard "
                      "integral). 0: the PGA of the summary.json's minimum intensity or the "
                      "first row of the hazard_curve.csv; the power law needs one > 0. "
                      "Unit: g.",
                      Patterns::Double(0));
    prm.add_parameter("PGA levels", pga_levels,
                      "g, two or more distinct: the Monte Carlo without contact runs at each "
                      "(the stochastic motion's S0 scaled to the PGA, the same realizations at "
                      "every level); they should bracket the PGAs of return periods of about "
                      "100 to 2500 years, which govern the result. Unit: g.",
                      Patterns::List(Patterns::Double(0), 1, 1000, ","));
    prm.add_parameter("Exposure", exposure_years,
                      "T: the probability of pounding in T years is 1 - exp(-T lambda). "
                      "Unit: years.",
                      Patterns::Double(0));
    prm.add_parameter("Target probability", target_probability,
                      "Probability of pounding in the Exposure for which the gap is reported, "
                      "in (0, 1) (0.1: 10 % in 50 years). Unit: dimensionless.",
                      Patterns::Double(0, 1));
    prm.leave_subsection();
  }

  std::vector<NamedInputFile>
  PoundingHazardParameters::input_files() const
  {
    if (hazard_file.empty())
      return {};
    return {{"Separation/Site hazard/File", "hazard file", hazard_file, ""}};
  }

  void
  PoundingHazardParameters::check(const InputFile &input) const
  {
    const std::string s = "Separation/Site hazard/";
    if (!hazard_file.empty() && power_law_coefficient > 0)
      input.fail(s + "File", "give the hazard either by File or by the power law, not both");
    // k0 is the annual rate of PGAs beyond 1 g: the most active sites have
    // about 1e-2, ten a year is beyond any (1e200 once ran without end)
    input.at_most(s + "Annual rate at 1 g", power_law_coefficient, largest_rate_at_1g,
                  "1/year", "ten events of 1 g a year, beyond any site's hazard");
    input.at_most(s + "Exponent", power_law_exponent, largest_exponent, "",
                  "hazard curves fall as a^-1 to a^-4");
    input.at_most(s + "Minimum PGA", minimum_pga, largest_pga, "g",
                  "the strongest records reach about 4 g");
    if (power_law_coefficient > 0 && !(power_law_exponent > 0))
      input.fail(s + "Exponent", "the power-law hazard needs an Exponent > 0");
    if (power_law_coefficient > 0 && !(minimum_pga > 0))
      input.fail(s + "Minimum PGA",
                 "the power-law hazard needs a Minimum PGA > 0 (its rate grows without bound "
                 "as the PGA falls)");
    if (!given())
      return;
    for (const double a : pga_levels)
      if (!(a > 0) || !std::isfinite(a))
        input.fail(s + "PGA levels", "every level must be positive");
      else
        input.at_most(s + "PGA levels", a, largest_pga, "g", "the strongest records reach about 4 g");
    input.distinct(s + "PGA levels", pga_levels);
    std::vector<double> sorted = pga_levels;
    std::sort(sorted.begin(), sorted.end());
    if (std::unique(sorted.begin(), sorted.end()) - sorted.begin() < 2)
      input.fail(s + "PGA levels", "needs two or more distinct levels");
    if (!(exposure_years > 0) || !std::isfinite(exposure_years))
      input.fail(s + "Exposure", "must be positive");
    input.at_most(s + "Exposure", exposure_years, longest_exposure, "years",
                  "beyond any structure's life");
    if (!(target_probability > 0 && target_probability < 1))
      input.fail(s + "Target probability", "must lie in (0, 1)");
  }
} // namespace poundfe
