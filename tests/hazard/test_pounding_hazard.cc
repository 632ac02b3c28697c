// The probability of pounding over an exposure time from a site hazard
// (hazard/pounding_hazard.h, theory §7.1) against independent references:
//   - the hazard integral of the lognormal demand model and a power-law
//     hazard against Cornell's closed form k0 theta^-k exp(k^2 beta^2 / 2)
//     (Cornell et al. 2002), also through a hazard_curve.csv of the same
//     power law (log-log interpolation is exact for it);
//   - the root-finding giving back the gap of a computed probability, and
//     the closed-form inverse of the power-law case;
//   - the demand fit recovering c, b and beta_D of synthetic data built with
//     them (residuals of zero mean, uncorrelated with ln a: least squares is
//     exact);
//   - a linear pair's Monte Carlo at three PGA levels against the scaling
//     identity P(D > g | a) = P(D_ref > g a_ref / a) of one run at the
//     input's Target PGA a_ref (D is linear in the amplitude);
//   - the messages of a missing hazard file, a non-monotone curve, a target
//     outside (0, 1) and a power law without a Minimum PGA.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/hazard/pounding_hazard.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/separation/separation.h>
#include <poundfe/base/exceptions.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "test_utilities.h"

using namespace poundfe;
using poundfe_test::temporary_file;
// run_pounding_hazard runs over MPI_COMM_WORLD (one fixture per executable:
// this module's other files have none)
using poundfe_test::MpiFixture;
BOOST_GLOBAL_FIXTURE(MpiFixture);

namespace
{
  /// Cornell's closed form of the power-law hazard (no lower limit).
  double
  cornell_rate(const double k0, const double k, const LognormalCurve &f)
  {
    return k0 * std::pow(f.theta, -k) * std::exp(k * k * f.beta * f.beta / 2);
  }

  const PowerLawDemand demand{0.03, 1.2, 0.45, 0}; // c = 3 cm at 1 g, b, beta_D
  const double         k0 = 2e-4, k = 2.5;

} // namespace

BOOST_AUTO_TEST_CASE(hazard_integral_against_cornells_closed_form)
{
  // The lower limit a_min sits 12 beta below the median: the events it
  // leaves out weigh ~Phi(-12 + k beta) ~ 1e-28 of the total. Simpson's rule
  // at steps of beta/40 on a Gaussian integrand in ln a is exact to round-off
  // (measured <= 1e-15): tolerance 1e-10, room for other compilers.
  for (const double gap : {0.005, 0.02, 0.08})
    {
      const LognormalCurve f      = pounding_fragility(demand, gap);
      const PgaHazard      hazard = power_law_hazard(k0, k, f.theta * std::exp(-12 * f.beta));
      BOOST_TEST(f.theta == std::pow(gap / 0.03, 1 / 1.2), boost::test_tools::tolerance(1e-14));
      const double rate = annual_pounding_rate(hazard, demand, gap);
      BOOST_TEST_MESSAGE("g = " << gap << " m: lambda " << rate << "/year, closed form "
                                << cornell_rate(k0, k, f) << ", relative difference "
                                << rate / cornell_rate(k0, k, f) - 1);
      BOOST_TEST(rate == cornell_rate(k0, k, f), boost::test_tools::tolerance(1e-10));
    }
  // The same power law as a hazard_curve.csv from 1e-3 g to 2 g (beyond:
  // its last segment, the same power law).
  std::ostringstream csv;
  csv.precision(17);
  csv << "intensity,pga_cm_s2,pga_g,annual_rate_per_year\n";
  for (int i = 0; i <= 60; ++i)
    {
      const double a = 1e-3 * std::pow(2000.0, i / 60.0);
      csv << "0,0," << a << "," << k0 * std::pow(a, -k) << "\n";
    }
  const std::string file   = temporary_file("pounding_hazard_curve.csv", csv.str());
  const PgaHazard   table  = read_pga_hazard(file, "Separation/Site hazard/File");
  std::remove(file.c_str());
  BOOST_TEST(table.minimum_pga == 1e-3);
  const PgaHazard power = power_law_hazard(k0, k, 1e-3);
  // 17 digits: the table is the power law to round-off
  for (const double gap : {0.01, 0.05})
    BOOST_TEST(annual_pounding_rate(table, demand, gap) == annual_pounding_rate(power, demand, gap),
               boost::test_tools::tolerance(1e-10));
}

BOOST_AUTO_TEST_CASE(root_finding_gives_the_gap_back)
{
  const PgaHazard hazard = power_law_hazard(k0, k, 1e-4);
  for (const double gap : {0.004, 0.03, 0.2})
    {
      const double p = probability_in_years(annual_pounding_rate(hazard, demand, gap), 50);
      BOOST_TEST(gap_for_probability_in_years(hazard, demand, 50, p) == gap,
                 boost::test_tools::tolerance(1e-9));
    }
  // Closed-form inverse: lambda* = k0 theta^-k e^(k^2 beta^2/2), g = c theta^b.
  const double target = -std::log(0.9) / 50, beta = demand.dispersion / demand.exponent;
  const double theta  = std::pow(k0 * std::exp(k * k * beta * beta / 2) / target, 1 / k);
  const double gap_10 = gap_for_probability_in_years(hazard, demand, 50, 0.1);
  BOOST_TEST_MESSAGE("10 % in 50 years: gap " << gap_10 << " m, closed form "
                                              << demand.median_at_1g * std::pow(theta, demand.exponent));
  BOOST_TEST(gap_10 == demand.median_at_1g * std::pow(theta, demand.exponent),
             boost::test_tools::tolerance(1e-7));
  // A target every counted event meets: no gap needed.
  BOOST_TEST(gap_for_probability_in_years(power_law_hazard(1e-6, k, 0.5), demand, 50, 0.1) == 0);
}

BOOST_AUTO_TEST_CASE(demand_fit_recovers_the_synthetic_model)
{
  const std::vector<double> z{-1.3, -0.4, 0.1, 0.5, 1.1}; // mean 0
  std::vector<double>       pga, d;
  double                    sum_z2 = 0;
  for (const double a : {0.1, 0.25, 0.6})
    for (const double zi : z)
      {
        pga.push_back(a);
        d.push_back(0.03 * std::pow(a, 1.2) * std::exp(0.45 * zi));
        sum_z2 += 0.45 * 0.45 * zi * zi;
      }
  const PowerLawDemand fit = fit_power_law_demand(pga, d);
  BOOST_TEST(fit.median_at_1g == 0.03, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(fit.exponent == 1.2, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(fit.dispersion == std::sqrt(sum_z2 / (pga.size() - 2)),
             boost::test_tools::tolerance(1e-12));
  BOOST_CHECK_THROW(fit_power_law_demand({0.1, 0.1, 0.1}, {1, 2, 3}), std::invalid_argument);
  BOOST_CHECK_THROW(fit_power_law_demand({0.1, 0.2, 0.3}, {1, 0, 3}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(linear_pair_at_three_levels_obeys_the_scaling_identity)
{
  InputParameters input = read_parameters("tests/cli/separation-sdof-pair.prm");
  input.ground_motion.type       = GroundMotionType::kanai_tajimi;
  input.ground_motion.target_pga = 0.15; // a_ref (S0 from it)
  input.ground_motion.spectral_intensity = 0;
  input.ground_motion.duration   = 4;
  input.monte_carlo.realizations = 20;
  input.separation.hazard.power_law_coefficient = k0;
  input.separation.hazard.power_law_exponent    = k;
  input.separation.hazard.minimum_pga           = 0.01;
  input.separation.hazard.pga_levels            = {0.05, 0.1, 0.3};
  input.contact.law                             = "none";
  const Analysis                  analysis = prepare_analysis(input);
  const std::vector<AdjacentPair> pairs    = adjacent_pairs(analysis.model);
  PoundingHazard                  result   = prepare_pounding_hazard(
    input.separation.hazard, input,
    RealizationRunner(analysis, time_history_parameters(input)).reference_pga("the PGA levels of a site hazard"));
  // the peak factor times sigma of S0 from the Target PGA: the Target PGA
  BOOST_TEST(result.reference_pga == 0.15, boost::test_tools::tolerance(1e-12));
  const std::string directory =
    (std::filesystem::temp_directory_path() / "poundfe_pounding_hazard_levels").string();
  std::filesystem::remove_all(directory);
  {
    RealizationRunner  runner(analysis, time_history_parameters(input));
    SeparationObserver observer(analysis.model, pairs);
    run_pounding_hazard(largest_approach_job(runner, observer, pairs),
                        input.monte_carlo.realizations, input.separation.hazard, directory,
                        MPI_COMM_WORLD, result);
  }
  std::filesystem::remove_all(directory);

  // One run of each realization at the input's own PGA, here.
  RealizationRunner   runner(analysis, time_history_parameters(input));
  SeparationObserver  observer(analysis.model, pairs);
  std::vector<double> reference;
  for (unsigned int r = 0; r < 20; ++r)
    {
      BOOST_TEST_REQUIRE(runner.run(r, Observers{&observer}));
      reference.push_back(observer.responses()[0][0].max_approach);
    }
  const std::vector<double> gaps{0.002, 0.005, 0.01, 0.02};
  for (std::size_t level = 0; level < 3; ++level)
    {
      const double a = result.pga_levels[level];
      BOOST_TEST_REQUIRE(result.largest_approach[0][level].size() == 20u);
      std::vector<double> scaled_gaps;
      for (const double g : gaps)
        scaled_gaps.push_back(g * 0.15 / a);
      const auto at_level = exceedance_curve(result.largest_approach[0][level], gaps, 0.95);
      const auto scaled   = exceedance_curve(reference, scaled_gaps, 0.95);
      for (std::size_t j = 0; j < gaps.size(); ++j)
        BOOST_TEST(at_level[j].n_exceeding == scaled[j].n_exceeding);
      // realization by realization, to round-off (the same noise at every level)
      for (unsigned int r = 0; r < 20; ++r)
        BOOST_TEST(result.largest_approach[0][level][r] == reference[r] * a / 0.15,
                   boost::test_tools::tolerance(1e-9));
    }
  // linear: the median grows as a^1
  BOOST_TEST(result.demand[0].exponent == 1.0, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(bad_hazard_input_is_reported)
{
  const std::string parameter = "Separation/Site hazard/File";
  BOOST_TEST(poundfe_test::input_error_of([&] { read_pga_hazard("/nonexistent/hazard_curve.csv", parameter); })
               .find("cannot open the hazard file") != std::string::npos);
  const std::string rising = temporary_file(
    "pounding_rising.csv", "pga_g,annual_rate_per_year\n0.1,0.01\n0.2,0.02\n0.3,0.001\n");
  const std::string message = poundfe_test::input_error_of([&] { read_pga_hazard(rising, parameter); });
  std::remove(rising.c_str());
  BOOST_TEST(message.find("not monotone") != std::string::npos);
  const std::string no_column =
    temporary_file("pounding_no_column.csv", "pga,rate\n0.1,0.01\n0.2,0.001\n");
  BOOST_TEST(poundfe_test::input_error_of([&] { read_pga_hazard(no_column, parameter); }).find("pga_g") !=
             std::string::npos);
  std::remove(no_column.c_str());
  const std::string not_site_hazard =
    temporary_file("pounding_summary.json", "{\"command\": \"fragility\"}\n");
  BOOST_TEST(poundfe_test::input_error_of([&] { read_pga_hazard(not_site_hazard, parameter); })
               .find("not a summary.json of `poundfe site-hazard`") != std::string::npos);
  std::remove(not_site_hazard.c_str());

  InputFile                file{"hazard.prm", ".", {}};
  PoundingHazardParameters p;
  p.power_law_coefficient = k0;
  p.power_law_exponent    = k;
  p.minimum_pga           = 0.01;
  for (const double target : {0.0, 1.0, -0.1})
    {
      p.target_probability = target;
      BOOST_TEST(poundfe_test::input_error_of([&] { p.check(file); }).find("Target probability") !=
                 std::string::npos);
    }
  p.target_probability = 0.1;
  p.minimum_pga        = 0;
  BOOST_TEST(poundfe_test::input_error_of([&] { p.check(file); }).find("Minimum PGA") != std::string::npos);
  p.minimum_pga = 0.01;
  p.pga_levels  = {0.2};
  BOOST_TEST(poundfe_test::input_error_of([&] { p.check(file); }).find("two or more distinct") !=
             std::string::npos);
  p.pga_levels = {0.2, 0.3, 0.2}; // issue 28: a level twice is an error of its own
  BOOST_TEST(poundfe_test::input_error_of([&] { p.check(file); }).find("lists 0.2 twice (values 1 and 3)") !=
             std::string::npos);
}
