// What a loss model and a FEMA P-695 evaluation read from an IDA:
//  - FEMA P-695 (2009) by hand: SSF of Tables 7-1a/7-1b at their entries
//    and between them, beta_TOT of eq. 7-5 with Table 7-2's rounding to
//    0.025, the acceptable ACMR of Table 7-3, CMR and ACMR of an example;
//    every entry of both SSF tables against their closed form (P-695
//    Appendix B: SSF = exp(beta_1 (eps_0 - 0.6 (1.5 - T))), beta_1 =
//    0.14 (mu_T - 1)^0.42, eps_0 = 1.5 for SDC D_max and 1.0 for B, C,
//    D_min) within 0.005, the tables' rounding to two decimals;
//  - pelicun demand tables (output/demand_table.h) of a pounding pair under
//    an IDA: the file against pelicun 3's DEMAND sample schema (written out
//    below), its numbers against the runs' demands exactly at an intensity
//    run and, for a linear pair (no gap closes), x times those at x = 1
//    (interpolation along a linear curve is exact; 1e-9 relative);
//  - an IDA's demands at an intensity from made-up runs: interpolated by
//    hand (1e-14), a record collapsed at or below it and one not run that
//    high left out and counted;
//  - an MSA stripe's demands from made-up runs: the runs' own (exactly), a
//    residual's magnitude, the PGA scaled with the record, Sa the stripe's
//    intensity; a collapsed run and one not run left out and counted.
#include <poundfe/assessment/collapse_margin.h>
#include <poundfe/assessment/ida_demands.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/excitation/records.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "test_utilities.h"

using namespace poundfe;

BOOST_AUTO_TEST_CASE(spectral_shape_factor_against_tables_7_1)
{
  // entries of Table 7-1b (SDC D_max) and 7-1a (B, C, D_min)
  const auto exact = boost::test_tools::tolerance(1e-12);
  BOOST_TEST(spectral_shape_factor(1.0, 4, DesignCategory::d_max) == 1.31, exact);
  BOOST_TEST(spectral_shape_factor(0.3, 12, DesignCategory::d_max) == 1.33, exact);
  BOOST_TEST(spectral_shape_factor(2.0, 8, DesignCategory::b_c_d_min) == 1.37, exact);
  BOOST_TEST(spectral_shape_factor(0.8, 1.0, DesignCategory::b_c_d_min) == 1.00, exact);
  // between entries: T = 0.75 s, mu_T = 5 (D_max): the mean of the four
  // corners 1.25, 1.32, 1.27, 1.35
  BOOST_TEST(spectral_shape_factor(0.75, 5, DesignCategory::d_max) == 1.2975,
             boost::test_tools::tolerance(1e-12));
  const double periods[] = {0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5};
  const double ductilities[] = {1.0, 1.1, 1.5, 2, 3, 4, 6, 8};
  for (const auto &[category, eps_0] :
       {std::pair{DesignCategory::d_max, 1.5}, std::pair{DesignCategory::b_c_d_min, 1.0}})
    for (const double t : periods)
      for (const double mu : ductilities)
        {
          const double closed = std::exp(0.14 * std::pow(mu - 1, 0.42) * (eps_0 - 0.6 * (1.5 - t)));
          BOOST_CHECK_MESSAGE(std::abs(spectral_shape_factor(t, mu, category) - closed) <=
                                0.005 + 1e-12,
                              "T " << t << " mu " << mu << ": "
                                   << spectral_shape_factor(t, mu, category) << " against "
                                   << closed);
        }
}

BOOST_AUTO_TEST_CASE(collapse_margin_by_hand)
{
  // beta_RTR = 0.1 + 0.1 mu_T at most 0.4 (eq. 7-2)
  CollapseMarginParameters p;
  p.mce_spectral_acceleration = 0.9;
  p.ductility                 = 4;
  p.category                  = DesignCategory::d_max;
  // good, good, good: sqrt(0.4^2 + 3 0.2^2) = 0.5292 -> 0.525 (Table 7-2);
  // Table 7-3 at 0.525: 1.96 (10 %) and 1.56 (20 %)
  const CollapseMargin m = collapse_margin(p, 1.2, false, 1.0);
  BOOST_TEST(m.beta_rtr == 0.4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.beta_total_exact == std::sqrt(0.28), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.beta_total == 0.525, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(m.acceptable_10 - 1.96) < 0.005);
  BOOST_TEST(std::abs(m.acceptable_20 - 1.56) < 0.005);
  // CMR = 1.2 / 0.9, SSF(1.0 s, 4) = 1.31, ACMR = 1.7467: passes 20 %, not 10 %
  BOOST_TEST(m.cmr == 1.2 / 0.9, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.ssf == 1.31, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.acmr == 1.31 * 1.2 / 0.9, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.passes_20);
  BOOST_TEST(!m.passes_10);
  // superior x 3, mu_T = 1.5: beta_RTR 0.25, sqrt(0.0625 + 0.03) = 0.304 ->
  // 0.300; Table 7-3 at 0.300: 1.47 (10 %), 1.29 (20 %)
  p.ductility           = 1.5;
  p.design_requirements = p.test_data = p.modeling = QualityRating::superior;
  const CollapseMargin s = collapse_margin(p, 1.2, false, 1.0);
  BOOST_TEST(s.beta_rtr == 0.25, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s.beta_total == 0.3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(s.acceptable_10 - 1.47) < 0.005);
  BOOST_TEST(std::abs(s.acceptable_20 - 1.29) < 0.005);
  // poor x 3, beta_RTR given 0.4: sqrt(0.16 + 0.75) = 0.954 -> 0.950;
  // Table 7-3 at 0.950: 3.38 (10 %), 2.22 (20 %)
  p.design_requirements = p.test_data = p.modeling = QualityRating::poor;
  p.record_to_record    = 0.4;
  const CollapseMargin q = collapse_margin(p, 1.2, false, 1.0);
  BOOST_TEST(q.beta_total == 0.95, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(q.acceptable_10 - 3.38) < 0.005);
  BOOST_TEST(std::abs(q.acceptable_20 - 2.22) < 0.005);
  // S_CT: the median with the records that did not collapse counted above
  BOOST_TEST(median_collapse_intensity({0.9, 0.5, 0.7}, 1) == 0.8,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(median_collapse_intensity({0.9, 0.5, 0.7}, 0) == 0.7);
  BOOST_TEST(std::isinf(median_collapse_intensity({0.9, 0.5}, 2)));
}

namespace
{
  /// pelicun 3's DEMAND sample (file_io.load_data, DemandModel.load_sample):
  /// an index column; a header "<event>-<type>-<location>-<direction>"
  /// split at '-' into four parts, the type without '-'; a second row
  /// "Units" naming each column's unit among pelicun's default units; then
  /// one row per realization, numbers only. Returns the columns.
  std::vector<std::string>
  check_pelicun_schema(const std::string &csv, const std::size_t n_rows)
  {
    static const std::set<std::string> units = {"rad", "unitless", "g", "mps2", "inps2", "m",
                                                "in", "mps", "inps", "N", "kN", "ea"};
    std::istringstream       in(csv);
    std::string              line;
    std::vector<std::vector<std::string>> rows;
    while (std::getline(in, line))
      {
        std::vector<std::string> fields;
        std::stringstream        s(line);
        for (std::string f; std::getline(s, f, ',');)
          fields.push_back(f);
        if (!line.empty() && line.back() == ',')
          fields.push_back("");
        rows.push_back(fields);
      }
    BOOST_REQUIRE(rows.size() == 2 + n_rows);
    BOOST_TEST(rows[0][0] == "");
    BOOST_TEST(rows[1][0] == "Units");
    const std::regex header(R"(1-[A-Z][A-Z0-9_.]*-[0-9]+-[0-9]+)");
    for (std::size_t c = 1; c < rows[0].size(); ++c)
      {
        BOOST_CHECK_MESSAGE(std::regex_match(rows[0][c], header), rows[0][c]);
        BOOST_CHECK_MESSAGE(units.count(rows[1][c]) == 1, rows[1][c]);
      }
    for (std::size_t r = 2; r < rows.size(); ++r)
      {
        BOOST_TEST(rows[r].size() == rows[0].size());
        BOOST_TEST(rows[r][0] == std::to_string(r - 2));
        for (std::size_t c = 1; c < rows[r].size(); ++c)
          BOOST_TEST(std::isfinite(std::stod(rows[r][c])));
      }
    return std::vector<std::string>(rows[0].begin() + 1, rows[0].end());
  }

  /// A 3- and a 2-storey shear building 10 mm apart, and a suite of two records.
  InputParameters
  pair_input(const std::string &name, const std::string &storey)
  {
    const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("poundfe_" + name);
    std::filesystem::create_directories(folder);
    std::string suite = "name,file\n";
    for (unsigned int r = 0; r < 2; ++r)
      {
        std::vector<double> a;
        for (unsigned int k = 0; k <= 500; ++k)
          a.push_back(std::exp(-0.5 * 0.01 * k) * std::sin((7 + 3 * r) * 0.01 * k));
        std::ofstream(folder / ("r" + std::to_string(r) + ".AT2")) << at2_text(a, 0.01, "test");
        suite += "rec" + std::to_string(r) + ",r" + std::to_string(r) + ".AT2\n";
      }
    std::ofstream(folder / "suite.csv") << suite;
    std::string buildings;
    for (const auto &[b, n] : {std::pair{1, 3}, std::pair{2, 2}})
      buildings += "subsection Building " + std::to_string(b) + "\n  set Name = b" +
                   std::to_string(n) + "\n  set Type = shear\n  set Number of storeys = " +
                   std::to_string(n) + "\n  set Floor masses = 1000\n  set Storey stiffnesses = "
                   "5e5\n" + storey + "\nend\n";
    return read_parameters(poundfe_test::temporary_file(
      name + ".prm", "subsection Model\n  set Number of buildings = 2\n  set Separations = 0.01\n"
                     "end\n" + buildings + "subsection Contact\n  set Law = linear\n"
                     "  set Stiffness = 5e8\nend\nsubsection Time integration\n  set Time step = "
                     "0.005\nend\nsubsection Output\n  set Plots = false\n  set Number of modes = "
                     "2\nend\nsubsection IDA\n  set Suite = " + (folder / "suite.csv").string() +
                     "\n  set Collapse drift ratio = 0.5\nend\n"));
  }

  /// The IDA result of records run at the given intensities each.
  IdaResult
  runs_at(IdaRunner &runner, const std::vector<double> &intensities)
  {
    IdaResult result;
    result.records.resize(runner.suite().records.size());
    for (unsigned int r = 0; r < result.records.size(); ++r)
      {
        for (const double x : intensities)
          result.records[r].points.push_back(runner.run(r, x));
        result.records[r].highest_survived = intensities.back();
        result.records[r].done             = true;
      }
    return result;
  }
} // namespace

BOOST_AUTO_TEST_CASE(pelicun_demand_table_of_a_pounding_pair)
{
  const InputParameters input = pair_input("loss_pounding", "  set Storey yield drifts = 0.003");
  const Analysis        analysis = prepare_analysis(input);
  IdaRunner runner(analysis, time_history_parameters(input), input.ida,
                   read_record_suite(input.ida.suite));
  const IdaResult result = runs_at(runner, {0.5, 2.0});
  const IdaDemandSample sample = ida_demands_at(runner, result, 2.0);
  BOOST_REQUIRE(sample.rows.size() == 2);
  const Model &model = analysis.model;
  const auto   tol   = boost::test_tools::tolerance(1e-12);
  BOOST_REQUIRE(model.gaps.size() == 2); // the lower building's two floors
  for (unsigned int b = 0; b < 2; ++b)
    {
      DemandTable table(model, b, false);
      for (const ResponseDemands &row : sample.rows)
        table.add(row);
      const std::vector<std::string> columns = check_pelicun_schema(table.csv(), 2);
      const unsigned int n = model.buildings[b].floors.size();
      // PFA 0..n, PID 1..n, RID 1..n, three per gap at floors 1 and 2
      BOOST_TEST(columns.size() == (n + 1) + 2 * n + 3 * 2);
      BOOST_TEST(columns.front() == "1-PFA-0-1");
      BOOST_TEST(columns[n + 1] == "1-PID-1-1");
      BOOST_TEST(columns[2 * n + 1] == "1-RID-1-1");
      BOOST_TEST(columns[3 * n + 1] == "1-NIMP-1-1");
      BOOST_TEST(columns[3 * n + 5] == "1-PIMF-2-2");
      const unsigned int first = b == 0 ? 0 : 3;
      for (unsigned int r = 0; r < 2; ++r)
        {
          const std::vector<double> &row = table.rows()[r];
          const IdaPoint            &run = result.records[r].points[1]; // at 2.0
          BOOST_TEST(row[0] == runner.suite().records[r].components[0].peak() * 2.0 /
                                 runner.base_intensities()[r] / standard_gravity,
                     tol);
          for (unsigned int f = 0; f < n; ++f)
            {
              // d0 + (d - d0) at an intensity run: d to round-off
              BOOST_TEST(row[1 + f] == run.demands[5 + first + f] / standard_gravity, tol);
              BOOST_TEST(row[n + 1 + f] == run.demands[first + f], tol);
              BOOST_TEST(row[2 * n + 1 + f] == std::abs(run.demands[10 + first + f]), tol);
            }
          for (unsigned int g = 0; g < 2; ++g)
            for (unsigned int k = 0; k < 3; ++k)
              BOOST_TEST(row[3 * n + 1 + 3 * g + k] == run.demands[16 + 3 * g + k], tol);
        }
    }
  // the records pound at 2.0: the tables carry it
  BOOST_TEST(sample.rows[0].impacts[0] + sample.rows[1].impacts[0] > 0);
}

BOOST_AUTO_TEST_CASE(demand_table_of_a_linear_pair_scales_with_the_intensity)
{
  const InputParameters input    = pair_input("loss_linear", "");
  const Analysis        analysis = prepare_analysis(input);
  IdaRunner runner(analysis, time_history_parameters(input), input.ida,
                   read_record_suite(input.ida.suite));
  const IdaResult unit = runs_at(runner, {0.01});
  BOOST_REQUIRE(unit.records[0].points[0].demands[16] == 0); // no impact
  const IdaResult result = runs_at(runner, {0.004, 0.01});
  for (const double x : {0.002, 0.007})
    {
      const IdaDemandSample sample = ida_demands_at(runner, result, x);
      const IdaDemandSample at_1   = ida_demands_at(runner, unit, 0.01);
      for (unsigned int r = 0; r < 2; ++r)
        for (unsigned int b = 0; b < 2; ++b)
          {
            DemandTable table(analysis.model, b, false), reference(analysis.model, b, false);
            table.add(sample.rows[r]);
            reference.add(at_1.rows[r]);
            for (std::size_t c = 0; c < table.rows()[0].size(); ++c)
              BOOST_TEST(table.rows()[0][c] == x / 0.01 * reference.rows()[0][c],
                         boost::test_tools::tolerance(1e-9));
          }
    }
}

BOOST_AUTO_TEST_CASE(ida_demands_leave_out_collapsed_and_short_records)
{
  // two records of made-up runs: record 0 survives 0.4 and collapses at 0.8,
  // every demand 1; record 1 runs only at 0.3, every demand -2
  const InputParameters input    = pair_input("loss_censored", "");
  const Analysis        analysis = prepare_analysis(input);
  IdaRunner runner(analysis, time_history_parameters(input), input.ida,
                   read_record_suite(input.ida.suite));
  const std::size_t n = runner.demand_names().size();
  IdaResult         result;
  result.records.resize(2);
  IdaPoint survived;
  survived.intensity = 0.4;
  survived.demands.assign(n, 1.0);
  IdaPoint collapsed = survived;
  collapsed.intensity = 0.8;
  collapsed.collapsed = true;
  result.records[0].points             = {survived, collapsed};
  result.records[0].collapse_intensity = 0.8;
  result.records[0].highest_survived   = 0.4;
  IdaPoint low;
  low.intensity = 0.3;
  low.demands.assign(n, -2.0);
  result.records[1].points = {low};
  const auto tol = boost::test_tools::tolerance(1e-14);
  // 0.2: both, along (0, 0)..(0.4, 1) and (0, 0)..(0.3, -2); a residual
  // drift's magnitude
  const IdaDemandSample both = ida_demands_at(runner, result, 0.2);
  BOOST_REQUIRE(both.rows.size() == 2);
  BOOST_TEST(both.rows[0].peak_drift[0] == 0.5, tol);
  BOOST_TEST(both.rows[1].peak_drift[0] == -2 * 0.2 / 0.3, tol);
  BOOST_TEST(both.rows[1].residual_drift[0] == 2 * 0.2 / 0.3, tol);
  BOOST_TEST(both.rows[1].impact_force[1] == -2 * 0.2 / 0.3, tol);
  // 0.35: record 1 was not run that high
  const IdaDemandSample one = ida_demands_at(runner, result, 0.35);
  BOOST_TEST(one.rows.size() == 1);
  BOOST_TEST(one.records == std::vector<unsigned int>{0}, boost::test_tools::per_element());
  BOOST_TEST(one.not_reached == 1);
  // 0.5: record 0 collapsed (above the highest intensity it survived)
  const IdaDemandSample none = ida_demands_at(runner, result, 0.5);
  BOOST_TEST(none.rows.empty());
  BOOST_TEST(none.collapsed == 1);
  BOOST_TEST(none.not_reached == 1);
}

BOOST_AUTO_TEST_CASE(stripe_demands_are_the_runs_own)
{
  // a stripe at 0.4 of made-up runs: record 0 every demand -2, record 1
  // collapsed; then record 1 not run (no demands: an interrupted stripe)
  const InputParameters input    = pair_input("loss_stripe", "");
  const Analysis        analysis = prepare_analysis(input);
  IdaRunner runner(analysis, time_history_parameters(input), input.ida,
                   read_record_suite(input.ida.suite));
  const std::size_t n = runner.demand_names().size();
  IdaPoint          run;
  run.intensity    = 0.4;
  run.scale_factor = 0.4 / runner.base_intensities()[0];
  run.demands.assign(n, -2.0);
  IdaPoint collapsed = run;
  collapsed.collapsed = true;
  const IdaDemandSample sample = stripe_demands(runner, {run, collapsed}, 0.4);
  BOOST_REQUIRE(sample.rows.size() == 1);
  BOOST_TEST(sample.records == std::vector<unsigned int>{0}, boost::test_tools::per_element());
  BOOST_TEST(sample.collapsed == 1);
  BOOST_TEST(sample.not_reached == 0);
  const ResponseDemands &d = sample.rows[0];
  BOOST_TEST(d.peak_drift[0] == -2.0);
  BOOST_TEST(d.residual_drift[1] == 2.0);
  BOOST_TEST(d.impact_force[1] == -2.0);
  BOOST_TEST(d.sa == 0.4);
  BOOST_TEST(d.pga == runner.suite().records[0].components[0].peak() * run.scale_factor,
             boost::test_tools::tolerance(1e-14));
  const IdaDemandSample short_stripe = stripe_demands(runner, {run, IdaPoint()}, 0.4);
  BOOST_TEST(short_stripe.rows.size() == 1);
  BOOST_TEST(short_stripe.not_reached == 1);
  BOOST_TEST(short_stripe.collapsed == 0);
}
