// Incremental dynamic analysis (assessment/ida.h):
//  - a LINEAR model: every demand of a run at intensity x is x times that
//    at x = 1 (the response is linear in the record): tolerance 1e-9
//    relative (round-off of the integrator's sums over ~600 steps); the
//    collapse intensity of a drift limit is then known exactly, limit / d1
//    (d1: the largest drift ratio at x = 1), and hunt and fill brackets it
//    within its tolerance;
//  - a Bouc-Wen (nonlinear) shear building, collapse by a drift limit: hunt
//    and fill against a dense brute-force stripe grid (every 0.005 g): the
//    collapse intensity of each record the same within the search's
//    tolerance plus the grid's spacing;
//  - hunt and fill on a threshold (collapse iff x >= c, no model): the
//    bracket holds c, and the runs stay within the budget after bracketing;
//  - the lognormal maximum-likelihood fit recovers theta, beta from 400
//    synthetic collapse intensities within three standard errors (the MLE's
//    asymptotic ones: sd(ln theta) = beta / sqrt(n), sd(beta) =
//    beta / sqrt(2 n); with censoring at the 80th percentile, 3.5 of them);
//    the uncensored fit equals the closed form computed here;
//  - the fractiles of the IDA curves: the empirical quantile of type 7
//    (Hyndman & Fan 1996) by hand, h = (n - 1) p, x_floor(h) + (h -
//    floor(h)) (x_ceil - x_floor), exact to round-off (1e-14); a record
//    collapsed (+inf) above a fractile's place makes it infinite, below it
//    leaves it finite.
#include <poundfe/assessment/ida.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/excitation/records.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  /// A folder with `n` generated records (AT2) and suite.csv listing them.
  std::string
  write_suite(const std::string &name, const unsigned int n)
  {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("poundfe_" + name);
    std::filesystem::create_directories(folder);
    std::string suite = "name,file,scale\n";
    for (unsigned int r = 0; r < n; ++r)
      {
        std::vector<double> a;
        for (unsigned int k = 0; k <= 600; ++k)
          {
            const double t = 0.01 * k;
            a.push_back(std::exp(-0.4 * t) * t * (std::sin((6 + 2 * r) * t) +
                                                   0.5 * std::sin((15 - r) * t + r)));
          }
        const std::string file = "r" + std::to_string(r) + ".AT2";
        std::ofstream(folder / file) << at2_text(a, 0.01, "test record");
        suite += "rec" + std::to_string(r) + "," + file + ",1\n";
      }
    std::ofstream(folder / "suite.csv") << suite;
    return (folder / "suite.csv").string();
  }

  /// A two-storey shear building, linear or Bouc-Wen (`storey`: extra lines).
  InputParameters
  shear_input(const std::string &name, const std::string &storey, const std::string &ida)
  {
    return read_parameters(poundfe_test::temporary_file(
      name + ".prm",
      "subsection Building 1\n  set Type = shear\n  set Number of storeys = 2\n"
      "  set Floor masses = 1000\n  set Storey stiffnesses = 2e6\n" + storey +
        "\nend\nsubsection Time integration\n  set Time step = 0.01\nend\n"
        "subsection Output\n  set Plots = false\n  set Number of modes = 2\nend\n"
        "subsection IDA\n" + ida + "\nend\n"));
  }

  /// Hunt and fill of record r (no MPI): the search's collapse intensity.
  std::optional<double>
  hunt_and_fill(IdaRunner &runner, const unsigned int r)
  {
    HuntFill search(runner.search());
    while (const std::optional<double> x = search.next())
      search.record(*x, runner.run(r, *x).collapsed);
    return search.collapse_intensity();
  }
} // namespace

BOOST_AUTO_TEST_CASE(linear_model_demands_proportional)
{
  const std::string     suite = write_suite("ida_linear", 2);
  const InputParameters input =
    shear_input("ida_linear", "", "  set Collapse drift ratio = 0.01\n  set Tolerance = 0.005");
  const Analysis analysis = prepare_analysis(input);
  IdaRunner      runner(analysis, time_history_parameters(input), input.ida,
                        read_record_suite(suite));
  for (unsigned int r = 0; r < 2; ++r)
    {
      const IdaPoint unit = runner.run(r, 1.0);
      for (const double x : {0.05, 0.37, 2.9})
        {
          const IdaPoint point = runner.run(r, x);
          for (std::size_t i = 0; i < unit.demands.size(); ++i)
            BOOST_TEST(point.demands[i] == x * unit.demands[i], boost::test_tools::tolerance(1e-9));
        }
      const double exact = 0.01 / unit.demands[runner.max_drift_column()];
      const std::optional<double> found = hunt_and_fill(runner, r);
      BOOST_REQUIRE(found);
      BOOST_TEST(*found >= exact);
      BOOST_TEST(*found <= exact + 0.005 + 1e-12);
    }
}

BOOST_AUTO_TEST_CASE(hunt_and_fill_against_a_stripe_grid)
{
  const std::string     suite = write_suite("ida_bouc_wen", 3);
  const double          spacing = 0.005, tolerance = 0.01;
  const InputParameters input =
    shear_input("ida_bouc_wen", "  set Storey yield drifts = 0.003",
                "  set Collapse drift ratio = 0.02\n  set Tolerance = 0.01\n"
                "  set Upper intensity = 4");
  const Analysis analysis = prepare_analysis(input);
  IdaRunner      runner(analysis, time_history_parameters(input), input.ida,
                        read_record_suite(suite));
  for (unsigned int r = 0; r < 3; ++r)
    {
      std::optional<double> grid;
      for (unsigned int k = 1; k * spacing <= 4 && !grid; ++k)
        if (runner.run(r, k * spacing).collapsed)
          grid = k * spacing;
      const std::optional<double> found = hunt_and_fill(runner, r);
      BOOST_REQUIRE(grid);
      BOOST_REQUIRE(found);
      BOOST_TEST_MESSAGE("record " << r << ": grid " << *grid << ", hunt and fill " << *found);
      BOOST_TEST(std::abs(*found - *grid) <= tolerance + spacing + 1e-12);
    }
}

namespace
{
  /// Runs of hunting (steps 0.1 + 0.05 k) and bisecting to 0.02 for threshold c.
  unsigned int
  n_to_bracket(const double c)
  {
    unsigned int n = 0;
    double       x = 0, lo = 0;
    while (x < c)
      lo = x, x += 0.1 + 0.05 * n++;
    for (double hi = x; hi - lo > 0.02; ++n)
      ((lo + hi) / 2 >= c ? hi : lo) = (lo + hi) / 2;
    return n;
  }
} // namespace

BOOST_AUTO_TEST_CASE(hunt_and_fill_brackets_a_threshold)
{
  for (const double c : {0.04, 0.83, 2.71, 9.0})
    {
      HuntFill search({0.1, 0.05, 5, 0.02, 12});
      unsigned int n = 0;
      while (const std::optional<double> x = search.next())
        search.record(*x, *x >= c), ++n;
      if (c > 5)
        {
          BOOST_TEST(!search.collapse_intensity()); // reported, not an error
          BOOST_TEST(search.highest_survived() == 5);
          continue;
        }
      BOOST_REQUIRE(search.collapse_intensity());
      BOOST_TEST(*search.collapse_intensity() >= c);
      BOOST_TEST(*search.collapse_intensity() - search.highest_survived() <= 0.02);
      BOOST_TEST(search.highest_survived() < c);
      // hunting and bracketing may exceed the budget of 12, filling does not
      BOOST_TEST(n <= std::max(12u, n_to_bracket(c)));
    }
}

BOOST_AUTO_TEST_CASE(lognormal_collapse_fragility_recovers_its_parameters)
{
  const double          theta = 0.8, beta = 0.4;
  const unsigned int    n     = 400;
  std::mt19937_64       generator(2026);
  std::normal_distribution<double> normal;
  std::vector<double>   sample;
  for (unsigned int i = 0; i < n; ++i)
    sample.push_back(theta * std::exp(beta * normal(generator)));
  // uncensored: the closed form
  double mean = 0, variance = 0;
  for (const double x : sample)
    mean += std::log(x) / n;
  for (const double x : sample)
    variance += std::pow(std::log(x) - mean, 2) / n;
  const CollapseFragility fit = fit_collapse_fragility(sample);
  BOOST_TEST(fit.fitted);
  BOOST_TEST(fit.theta == std::exp(mean), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(fit.beta == std::sqrt(variance), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(std::log(fit.theta / theta)) < 3 * beta / std::sqrt(n));
  BOOST_TEST(std::abs(fit.beta - beta) < 3 * beta / std::sqrt(2.0 * n));
  // censored at the 80th percentile: the records above it did not collapse
  const double        upper = theta * std::exp(beta * 0.8416212335729143);
  std::vector<double> collapsed;
  for (const double x : sample)
    if (x <= upper)
      collapsed.push_back(x);
  const CollapseFragility censored =
    fit_collapse_fragility(collapsed, n - collapsed.size(), upper);
  BOOST_TEST(censored.fitted);
  BOOST_TEST(std::abs(std::log(censored.theta / theta)) < 3.5 * beta / std::sqrt(n));
  BOOST_TEST(std::abs(censored.beta - beta) < 3.5 * beta / std::sqrt(2.0 * n));
  // ignoring the censoring would bias theta low: the censored fit is closer
  BOOST_TEST(std::abs(std::log(censored.theta / theta)) <
             std::abs(std::log(fit_collapse_fragility(collapsed).theta / theta)));
}

BOOST_AUTO_TEST_CASE(fractiles_are_type_7_quantiles)
{
  const auto tol = boost::test_tools::tolerance(1e-14);
  // 4 values: h = 3 p; 16 %: 1 + 0.48, 50 %: 2.5, 84 %: 3 + 0.52
  const std::vector<double> x = {4, 1, 3, 2};
  BOOST_TEST(empirical_quantile(x, 0.16) == 1.48, tol);
  BOOST_TEST(empirical_quantile(x, 0.5) == 2.5, tol);
  BOOST_TEST(empirical_quantile(x, 0.84) == 3.52, tol);
  BOOST_TEST(empirical_quantile(x, 0.0) == 1.0);
  BOOST_TEST(empirical_quantile(x, 1.0) == 4.0);
  // one of 5 records collapsed: h = 4 p; 84 % (h = 3.36) reaches it, 50 % not
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> y = {0.1, inf, 0.3, 0.2, 0.4};
  BOOST_TEST(empirical_quantile(y, 0.5) == 0.3, tol);
  BOOST_TEST(std::isinf(empirical_quantile(y, 0.84)));
  BOOST_TEST(empirical_quantile(y, 0.75) == 0.4); // h = 3 exactly: the value, not inf - inf
}
