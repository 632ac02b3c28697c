// The probability of pounding over an exposure time against the gap width.
// Equations and sources in include/poundfe/hazard/pounding_hazard.h and
// doc/theory.md §7.1.
#include <poundfe/reliability/montecarlo.h>
#include <poundfe/hazard/pounding_hazard.h>
#include <poundfe/hazard/site_hazard_parameters.h>
#include <poundfe/reliability/statistics.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/excitation/stochastic.h>

// property_tree includes boost/bind.hpp, which asks for this (a note at every build)
#define BOOST_BIND_GLOBAL_PLACEHOLDERS
#include <boost/math/tools/roots.hpp>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace poundfe
{
  PgaHazard
  power_law_hazard(const double k0, const double k, const double minimum_pga)
  {
    PgaHazard h;
    h.annual_rate = [k0, k](const double a) { return k0 * std::pow(a, -k); };
    h.minimum_pga = minimum_pga;
    h.source      = "power law " + rounded(k0) + " a^-" + rounded(k);
    return h;
  }

  PgaHazard
  tabulated_hazard(const std::vector<double> &pga, const std::vector<double> &rate)
  {
    if (pga.size() < 2 || pga.size() != rate.size())
      throw std::invalid_argument("a hazard curve needs two or more points (PGA, annual rate)");
    std::vector<double> x, y; // ln a, ln lambda
    for (std::size_t i = 0; i < pga.size(); ++i)
      {
        if (!(pga[i] > 0 && rate[i] > 0 && std::isfinite(pga[i]) && std::isfinite(rate[i])))
          throw std::invalid_argument("the hazard curve has a PGA or rate that is not positive "
                                      "(point " + std::to_string(i + 1) + ")");
        if (i > 0 && !(pga[i] > pga[i - 1] && rate[i] < rate[i - 1]))
          throw std::invalid_argument(
            "the hazard curve is not monotone: the PGAs must increase and the annual rates "
            "decrease (point " + std::to_string(i + 1) + ")");
        x.push_back(std::log(pga[i]));
        y.push_back(std::log(rate[i]));
      }
    PgaHazard h;
    h.minimum_pga = h.lowest_pga = pga.front();
    h.annual_rate = [x, y](const double a) {
      const double u = std::log(a);
      // the segment of u; beyond the ends, the first or last segment
      const std::size_t i =
        std::min<std::size_t>(std::max<std::ptrdiff_t>(std::upper_bound(x.begin(), x.end(), u) -
                                                         x.begin() - 1, 0),
                              x.size() - 2);
      const double t = (u - x[i]) / (x[i + 1] - x[i]);
      return std::exp(y[i] + t * (y[i + 1] - y[i]));
    };
    h.source = "hazard curve of " + std::to_string(pga.size()) + " points";
    return h;
  }

  namespace
  {
    /// The hazard_curve.csv of site-hazard: columns pga_g and annual_rate_per_year.
    PgaHazard
    read_hazard_curve_csv(const std::string &file, const std::string &parameter)
    {
      std::istringstream in(read_input_text(file, "hazard file", parameter));
      std::string        line;
      if (!std::getline(in, line))
        throw InputError(file, 0, parameter, "the hazard curve is empty");
      std::vector<std::string> names;
      {
        std::stringstream header(line);
        for (std::string name; std::getline(header, name, ',');)
          names.push_back(name);
      }
      const auto column = [&](const std::string &name) {
        const auto it = std::find(names.begin(), names.end(), name);
        if (it == names.end())
          throw InputError(file, 1, parameter,
                           "the header has no column '" + name +
                             "' (a hazard_curve.csv of `poundfe site-hazard` has pga_g and "
                             "annual_rate_per_year)");
        return std::size_t(it - names.begin());
      };
      const std::size_t   pga_column = column("pga_g"), rate_column = column("annual_rate_per_year");
      std::vector<double> pga, rate;
      for (int number = 2; std::getline(in, line); ++number)
        {
          std::vector<double> values;
          std::stringstream   row(line);
          for (std::string field; std::getline(row, field, ',');)
            {
              char        *end   = nullptr;
              const double value = std::strtod(field.c_str(), &end);
              values.push_back(end != field.c_str() && *end == '\0' ? value :
                                                                       std::nan(""));
            }
          if (values.size() != names.size() || std::isnan(values[pga_column]) ||
              std::isnan(values[rate_column]))
            throw InputError(file, number, parameter, "a row that is not " +
                                                         std::to_string(names.size()) + " numbers");
          pga.push_back(values[pga_column]);
          rate.push_back(values[rate_column]);
        }
      try
        {
          return tabulated_hazard(pga, rate);
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError(file, 0, parameter, e.what());
        }
    }

    /// The fit of a site-hazard summary.json.
    PgaHazard
    read_hazard_summary(const std::string &file, const std::string &parameter)
    {
      boost::property_tree::ptree tree;
      try
        {
          std::istringstream in(read_json_text(file, "hazard file", parameter));
          boost::property_tree::read_json(in, tree);
        }
      catch (const boost::property_tree::json_parser_error &e)
        {
          throw InputError(file, e.line(), parameter,
                           "cannot read it as a site-hazard summary.json: " + e.message());
        }
      if (tree.get<std::string>("command", "") != "site-hazard")
        throw InputError(file, 0, parameter, "not a summary.json of `poundfe site-hazard`");
      IntensityHazard hazard;
      const double    minimum_intensity = tree.get<double>("attenuation.minimum_intensity", NAN);
      try
        {
          hazard.model = hazard_model_names().value(tree.get<std::string>("fit.model", ""));
        }
      catch (const std::exception &)
        {
          throw InputError(file, 0, parameter, "its fit.model is neither gumbel nor poisson");
        }
      if (hazard.model == IntensityHazard::Model::gumbel)
        {
          hazard.gumbel.location = tree.get<double>("fit.location", NAN);
          hazard.gumbel.scale    = tree.get<double>("fit.scale", NAN);
        }
      else
        {
          hazard.poisson.threshold            = minimum_intensity;
          hazard.poisson.rate_above_threshold = tree.get<double>("fit.rate_above_minimum_per_year", NAN);
          hazard.poisson.b                    = tree.get<double>("fit.b_per_intensity_unit", NAN);
        }
      const bool complete = hazard.model == IntensityHazard::Model::gumbel ?
                              hazard.gumbel.scale > 0 && std::isfinite(hazard.gumbel.location) :
                              hazard.poisson.b > 0 && hazard.poisson.rate_above_threshold > 0;
      if (!complete || !std::isfinite(minimum_intensity))
        throw InputError(file, 0, parameter,
                         "its fit or attenuation.minimum_intensity is missing or not positive");
      PgaHazard h;
      h.annual_rate = [hazard](const double a) { return annual_rate_of_pga(hazard, a); };
      h.minimum_pga = trifunac_brady_pga_g(minimum_intensity);
      h.source      = hazard_model_names().name(hazard.model) + " fit of " + file;
      return h;
    }
  } // namespace

  PgaHazard
  read_pga_hazard(const std::string &file, const std::string &parameter)
  {
    const bool json = file.size() >= 5 && file.compare(file.size() - 5, 5, ".json") == 0;
    check_input_file(file, "hazard file", parameter);
    return json ? read_hazard_summary(file, parameter) : read_hazard_curve_csv(file, parameter);
  }

  PowerLawDemand
  fit_power_law_demand(const std::vector<double> &pga, const std::vector<double> &demand)
  {
    Assert(pga.size() == demand.size(), dealii::ExcMessage("one PGA per demand"));
    const std::size_t n = pga.size();
    double            mean_x = 0, mean_y = 0;
    for (std::size_t i = 0; i < n; ++i)
      {
        if (!(demand[i] > 0))
          throw std::invalid_argument("a realization whose buildings never approach each other "
                                      "(largest approach <= 0): the lognormal demand needs D > 0");
        mean_x += std::log(pga[i]) / n;
        mean_y += std::log(demand[i]) / n;
      }
    double sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < n; ++i)
      {
        const double dx = std::log(pga[i]) - mean_x;
        sxx += dx * dx;
        sxy += dx * (std::log(demand[i]) - mean_y);
      }
    if (n < 3 || !(sxx > 1e-12 * n))
      throw std::invalid_argument("the demand fit needs realizations at two or more distinct PGAs");
    PowerLawDemand d;
    d.n        = n;
    d.exponent = sxy / sxx;
    if (!(d.exponent > 0))
      throw std::invalid_argument("the largest approach does not grow with the PGA (b = " +
                                  rounded(d.exponent) + ")");
    d.median_at_1g = std::exp(mean_y - d.exponent * mean_x);
    double residuals = 0;
    for (std::size_t i = 0; i < n; ++i)
      residuals += std::pow(std::log(demand[i]) - mean_y - d.exponent * (std::log(pga[i]) - mean_x), 2);
    d.dispersion = std::sqrt(residuals / (n - 2));
    return d;
  }

  LognormalCurve
  pounding_fragility(const PowerLawDemand &demand, const double gap)
  {
    return {std::pow(gap / demand.median_at_1g, 1 / demand.exponent),
            demand.dispersion / demand.exponent};
  }

  double
  annual_pounding_rate(const PgaHazard &hazard, const PowerLawDemand &demand, const double gap)
  {
    if (!(gap > 0))
      return hazard.annual_rate(hazard.minimum_pga);
    // beta_D = 0 (D = c a^b exactly): pounding above a = theta, the step
    return annual_failure_rate(hazard.annual_rate, hazard.minimum_pga,
                               pounding_fragility(demand, gap));
  }

  double
  gap_for_probability_in_years(const PgaHazard &hazard, const PowerLawDemand &demand,
                               const double years, const double probability)
  {
    Assert(probability > 0 && probability < 1 && years > 0,
           dealii::ExcMessage("a probability in (0, 1) over a positive time"));
    const double target = -std::log1p(-probability) / years; // lambda*
    if (annual_pounding_rate(hazard, demand, 0) <= target)
      return 0;
    // f(ln g) = ln lambda(g) - ln lambda*, decreasing; bracket from the median at a_min
    const auto f = [&](const double log_gap) {
      return std::log(annual_pounding_rate(hazard, demand, std::exp(log_gap))) - std::log(target);
    };
    double low = std::log(demand.median_at_1g * std::pow(hazard.minimum_pga, demand.exponent));
    double high = low;
    for (unsigned int i = 0; f(low) < 0 && i < 200; ++i)
      low -= 1;
    for (unsigned int i = 0; f(high) > 0 && i < 200; ++i)
      high += 1;
    if (!(f(low) >= 0 && f(high) <= 0))
      throw NumericalError("no gap of probability " + rounded(probability) + " in " +
                           rounded(years) + " years within e^200 of the median demand");
    if (f(low) == 0)
      return std::exp(low);
    if (f(high) == 0)
      return std::exp(high);
    std::uintmax_t iterations = 100;
    const auto     root       = boost::math::tools::toms748_solve(
      f, low, high, boost::math::tools::eps_tolerance<double>(40), iterations);
    return std::exp(0.5 * (root.first + root.second));
  }

  PoundingHazard
  prepare_pounding_hazard(const PoundingHazardParameters &p, const InputFile &input,
                          const double reference_pga)
  {
    const std::string s = "Separation/Site hazard/";
    PoundingHazard    result;
    result.hazard = p.hazard_file.empty() ?
                      power_law_hazard(p.power_law_coefficient, p.power_law_exponent, p.minimum_pga) :
                      read_pga_hazard(input.resolve(p.hazard_file), s + "File");
    if (p.minimum_pga > 0)
      {
        if (p.minimum_pga < result.hazard.lowest_pga)
          input.fail(s + "Minimum PGA", "is below the hazard curve's lowest PGA, " +
                                          rounded(result.hazard.lowest_pga) + " g");
        result.hazard.minimum_pga = p.minimum_pga;
      }
    result.reference_pga = reference_pga;
    result.pga_levels    = p.pga_levels;
    return result;
  }

  namespace
  {
    /// A warning when pair i's demand fit's dispersion holds no
    /// record-to-record scatter: one realization per level (the scatter
    /// about a line through one motion's responses), or realizations that
    /// do not scatter. Its P(pounding) is then a step at the median demand
    /// and its gap unconservative.
    void
    warn_of_a_thin_demand_fit(const std::string &pair, const std::size_t i, PoundingHazard &result)
    {
      std::size_t fewest = std::numeric_limits<std::size_t>::max();
      for (const std::vector<double> &level : result.largest_approach[i])
        fewest = std::min(fewest, level.size());
      const double      beta = result.demand[i].dispersion;
      const std::string unconservative =
        ": P(pounding) and the gap for the target are unconservative (raise Monte "
        "Carlo/Realizations; a stochastic ground motion gives each realization its own motion)";
      if (fewest < 2)
        result.warnings.push_back("pair " + pair + ": the demand's dispersion beta_D = " +
                                  rounded(beta) + " rests on " + std::to_string(fewest) +
                                  " realization at a PGA level, so it holds no record-to-record "
                                  "scatter" + unconservative);
      else if (beta < 1e-6)
        result.warnings.push_back("pair " + pair + ": the demand's dispersion beta_D = " +
                                  rounded(beta) + ": the realizations do not scatter" +
                                  unconservative);
    }

    /// The demand model of each pair and its gap for the target (rank 0).
    void
    fit_demand_and_gaps(const std::vector<std::string> &pair_names,
                        const PoundingHazardParameters &p, PoundingHazard &result)
    {
      for (std::size_t i = 0; i < pair_names.size(); ++i)
        {
          std::vector<double> pga, demand;
          for (std::size_t k = 0; k < result.pga_levels.size(); ++k)
            for (const double d : result.largest_approach[i][k])
              pga.push_back(result.pga_levels[k]), demand.push_back(d);
          try
            {
              result.demand.push_back(fit_power_law_demand(pga, demand));
            }
          catch (const std::invalid_argument &e)
            {
              throw NumericalError("pair " + pair_names[i] + ": " + e.what());
            }
          result.gap_for_target.push_back(gap_for_probability_in_years(
            result.hazard, result.demand.back(), p.exposure_years, p.target_probability));
          warn_of_a_thin_demand_fit(pair_names[i], i, result);
        }
    }
  } // namespace

  void
  run_pounding_hazard(const ApproachJob &approach, const unsigned long n,
                      const PoundingHazardParameters &p, const std::string &directory,
                      const MPI_Comm comm, PoundingHazard &result)
  {
    const std::vector<std::string> &pair_names       = approach.pair_names;
    double                          amplitude_factor = 1;
    RealizationJob                  job;
    for (const std::string &name : pair_names)
      job.names.push_back(name + "_largest_approach_m");
    job.seed = approach.seed;
    job.run  = [&](const std::uint64_t r, std::vector<double> &row) {
      return approach.run(r, amplitude_factor, row);
    };
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    result.largest_approach.assign(pair_names.size(), {});
    Progress progress(std::cerr, "realizations at the PGA levels", result.pga_levels.size() * n);
    for (std::size_t k = 0; k < result.pga_levels.size() && !result.interrupted; ++k)
      {
        const double      a               = result.pga_levels[k];
        const std::string level_directory = directory + "/pga_" + rounded(a, 6) + "g";
        if (rank == 0 && !directory.empty())
          create_directories(level_directory);
        amplitude_factor            = a / result.reference_pga;
        const MonteCarloTable table = run_realizations(job, n,
                                                       directory.empty() ? "" :
                                                         level_directory + "/realizations.csv",
                                                       comm, "PGA " + rounded(a) + " g: ",
                                                       &progress, k * n);
        result.interrupted = table.interrupted; // the same on every rank
        if (rank == 0 && !result.interrupted)
          for (std::size_t i = 0; i < pair_names.size(); ++i)
            result.largest_approach[i].push_back(table.completed_values(i));
      }
    progress.finish();
    if (rank != 0 || result.interrupted)
      return;
    try
      {
        fit_demand_and_gaps(pair_names, p, result);
      }
    catch (const NumericalError &e)
      {
        result.failure = e.what();
        result.demand.clear();
        result.gap_for_target.clear();
        result.warnings.clear();
      }
  }
} // namespace poundfe
