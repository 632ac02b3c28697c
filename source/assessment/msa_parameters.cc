// The `MSA` section (msa_parameters.h).
#include <poundfe/assessment/msa.h>
#include <poundfe/assessment/msa_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace poundfe
{
  void
  MsaParameters::declare(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::List;
    prm.enter_subsection("MSA");
    prm.add_parameter("Intensities", intensities,
                      "The stripes: every record of IDA/Suite scaled to each of these values of "
                      "IDA/Intensity measure. Unit: that of the measure (g, or m/s for PGV).",
                      List(Double(0), 0, 1000, ","));
    prm.add_parameter("Hazard curve", hazard_curve,
                      "A CSV with the intensity column (Hazard column) and "
                      "annual_rate_per_year, e.g. the site-hazard command's hazard_curve.csv "
                      "(relative to the input): stripes at Return periods, and each limit "
                      "state's annual rate of exceedance. Unit: -.");
    prm.add_parameter("Hazard column", hazard_column,
                      "The hazard curve's intensity column, in the unit of IDA/Intensity "
                      "measure (pga_g of hazard_curve.csv with PGA). Unit: -.");
    prm.add_parameter("Return periods", return_periods,
                      "Further stripes at the intensities of these return periods on the "
                      "hazard curve. Unit: years.", List(Double(0), 0, 100, ","));
    prm.add_parameter("Limit states", limit_states,
                      "Besides collapse (IDA/Collapse drift ratio or no convergence): terms "
                      "'demand > threshold' separated by ';', the demand a column of msa.csv, "
                      "e.g. max_drift_ratio > 0.01; gap1_impacts > 0; "
                      "gap1_peak_impact_force_N > 1e5. A collapsed run exceeds every one. "
                      "Unit: that of the demand.");
    prm.add_parameter("Cloud", cloud,
                      "Also run every record unscaled and regress ln(Cloud demand) on "
                      "ln(intensity). Unit: -.");
    prm.add_parameter("Cloud demand", cloud_demand,
                      "The demand of the cloud regression (a column of msa.csv). Unit: -.");
    prm.leave_subsection();
  }

  std::vector<NamedInputFile>
  MsaParameters::input_files() const
  {
    if (hazard_curve.empty())
      return {};
    return {{"MSA/Hazard curve", "hazard curve", hazard_curve, ""}};
  }

  void
  MsaParameters::check(const InputFile &input) const
  {
    input.distinct("MSA/Intensities", intensities);
    input.distinct("MSA/Return periods", return_periods);
    for (const double x : intensities)
      input.positive("MSA/Intensities", x);
    for (const double t : return_periods)
      input.positive("MSA/Return periods", t);
    if (!return_periods.empty() && hazard_curve.empty())
      input.fail("MSA/Return periods", "stripes at return periods need a MSA/Hazard curve");
  }

  std::vector<LimitState>
  MsaParameters::parse_limit_states(const InputFile &input,
                                    const std::vector<std::string> &names) const
  {
    std::vector<LimitState> states{{"collapse", -1, 0}};
    std::stringstream       terms(limit_states);
    for (std::string term; std::getline(terms, term, ';');)
      {
        term = trimmed(term);
        if (term.empty())
          continue;
        const std::size_t at = term.find('>');
        if (at == std::string::npos)
          input.fail("MSA/Limit states", "expected 'demand > threshold', got '" + term + "'");
        const std::string demand = trimmed(term.substr(0, at));
        const auto        it     = std::find(names.begin(), names.end(), demand);
        if (it == names.end())
          input.fail("MSA/Limit states", "'" + demand + "' is not a demand of this model (one "
                                         "of the columns of msa.csv after 'collapsed')");
        std::size_t  used = 0;
        double       threshold = 0;
        const std::string number = trimmed(term.substr(at + 1));
        try
          {
            threshold = std::stod(number, &used);
          }
        catch (const std::exception &)
          {}
        if (number.empty() || used != number.size() || !std::isfinite(threshold) || threshold < 0)
          input.fail("MSA/Limit states", "the threshold of '" + demand + "' must be a number "
                                         ">= 0, got '" + number + "'");
        states.push_back({demand + " > " + number, int(it - names.begin()), threshold});
      }
    return states;
  }
} // namespace poundfe
