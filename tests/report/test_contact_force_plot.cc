// contact_force.png's curves (report/run_plots.h: contact_force_plot) from
// a contact_force.csv written here by CsvWriter:
//  - up to max_named_curves gaps: a curve per gap, read by gnuplot from the
//    file (column 2g + 2, in kN), titled with the gap's label;
//  - more: a curve per pair of buildings (or building and barrier), each
//    the sum of its gaps' forces, given as a data block whose numbers are
//    compared with the test's own sums of the file's values: exactly (both
//    add the same doubles in the same order; the block's text reads back
//    to the double written);
//  - more pairs than that too: the max_named_curves pairs with the largest
//    peaks, in the order of their names, and the title says so;
//  - only the gaps that touched (a force other than 0 in some row), the
//    title saying how many of the recorded ones; none: a line at 0 titled so.
#include <poundfe/output/csv_writer.h>
#include <poundfe/report/run_plots.h>

#include "../output/output_test_files.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

namespace
{
  /// `n_buildings` buildings B1, B2, ... in a row, `per_pair` gaps between
  /// each two neighbours and one between B1 and a barrier on its left.
  poundfe::Model
  row_of_buildings(const unsigned int n_buildings, const unsigned int per_pair)
  {
    poundfe::Model model;
    model.buildings.resize(n_buildings);
    for (unsigned int b = 0; b < n_buildings; ++b)
      model.buildings[b].name = "B" + std::to_string(b + 1);
    poundfe::Gap barrier;
    barrier.nodes     = {{-1, 0}};
    barrier.buildings = {{0, 0}};
    barrier.label     = "B1-barrier@3";
    model.gaps.push_back(barrier);
    for (unsigned int b = 0; b + 1 < n_buildings; ++b)
      for (unsigned int k = 0; k < per_pair; ++k)
        {
          poundfe::Gap gap;
          gap.nodes     = {{int(10 * b + k), int(10 * b + 10 + k)}};
          gap.buildings = {{b, b + 1}};
          gap.label     = model.buildings[b].name + "-" + model.buildings[b + 1].name + "@" +
                      std::to_string(3 * (k + 1));
          model.gaps.push_back(gap);
        }
    return model;
  }

  /// The pair a gap of row_of_buildings belongs to.
  std::string
  pair_of(const poundfe::Model &model, const unsigned int g)
  {
    const poundfe::Gap &gap = model.gaps[g];
    return (gap.nodes[0] < 0 ? "barrier" : model.buildings[gap.buildings[0]].name) + "-" +
           model.buildings[gap.buildings[1]].name;
  }

  /// contact_force.csv of `model` in `directory`: gap g's force in row r
  /// grows with its pair (so that the pairs' peaks differ), penetration beside.
  poundfe_test::Table
  write_contact_forces(const poundfe::Model &model, const std::string &directory,
                       const std::vector<bool> &touches = {})
  {
    std::filesystem::create_directories(directory);
    std::vector<std::string> header{"time_s"};
    for (const poundfe::Gap &gap : model.gaps)
      header.insert(header.end(), {gap.label + "_force_N", gap.label + "_penetration_m"});
    poundfe::CsvWriter  csv(directory + "/contact_force.csv", header);
    std::vector<double> row(2 * model.gaps.size());
    for (unsigned int r = 0; r < 40; ++r)
      {
        for (unsigned int g = 0; g < model.gaps.size(); ++g)
          {
            const double pair = model.gaps[g].buildings[1] + 1 + (model.gaps[g].nodes[0] < 0 ? 0.5 : 0);
            row[2 * g]     = 1e5 * pair * std::max(0.0, std::sin(0.3 * r + 0.1 * g)) + 0.1 * g;
            if (!touches.empty() && !touches[g])
              row[2 * g] = 0; // this gap never closed
            row[2 * g + 1] = 1e-4 * std::sin(0.3 * r);
          }
        csv.add_row(0.005 * r, row);
      }
    csv.commit();
    return poundfe_test::read_csv(directory + "/contact_force.csv");
  }

  /// The rows of data block `name` in `blocks` (after its header).
  std::vector<std::pair<double, double>>
  block_rows(const std::string &blocks, const std::string &name)
  {
    const std::size_t start = blocks.find(name + " << EOD\n");
    BOOST_REQUIRE_MESSAGE(start != std::string::npos, "no data block " << name);
    std::istringstream in(blocks.substr(start));
    std::string        line;
    std::getline(in, line); // "$name << EOD"
    std::getline(in, line); // the header
    std::vector<std::pair<double, double>> rows;
    while (std::getline(in, line) && line != "EOD")
      {
        const std::size_t comma = line.find(',');
        rows.emplace_back(std::strtod(line.substr(0, comma).c_str(), nullptr),
                          std::strtod(line.substr(comma + 1).c_str(), nullptr));
      }
    return rows;
  }

  /// The test's own sums of the file's forces by pair.
  std::map<std::string, std::vector<double>>
  pair_totals(const poundfe::Model &model, const poundfe_test::Table &table)
  {
    std::map<std::string, std::vector<double>> totals;
    for (unsigned int g = 0; g < model.gaps.size(); ++g)
      {
        std::vector<double> &total = totals[pair_of(model, g)];
        total.resize(table.rows.size(), 0.0);
        for (unsigned int r = 0; r < table.rows.size(); ++r)
          total[r] += table.rows[r][2 * g + 1];
      }
    return totals;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(contact_force_figure)

BOOST_AUTO_TEST_CASE(a_few_gaps_are_a_curve_each_from_the_file)
{
  const poundfe::Model model     = row_of_buildings(3, 2); // 5 gaps
  const std::string    directory = poundfe_test::fresh_directory("contact-plot-few");
  write_contact_forces(model, directory);
  const poundfe::Plot plot = poundfe::contact_force_plot(model, directory);
  BOOST_CHECK(plot.data_blocks.empty());
  BOOST_REQUIRE_EQUAL(plot.series.size(), model.gaps.size());
  for (unsigned int g = 0; g < model.gaps.size(); ++g)
    {
      BOOST_CHECK_EQUAL(plot.series[g].data_file, "contact_force.csv");
      BOOST_CHECK_EQUAL(plot.series[g].using_spec, "1:($" + std::to_string(2 * g + 2) + "/1000)");
      BOOST_CHECK_EQUAL(plot.series[g].title, model.gaps[g].label);
    }
}

BOOST_AUTO_TEST_CASE(many_gaps_are_a_curve_per_pair_of_buildings_their_total_force)
{
  const poundfe::Model model = row_of_buildings(4, 10); // 31 gaps: barrier-B1, B1-B2, B2-B3, B3-B4
  BOOST_REQUIRE_GT(model.gaps.size(), poundfe::max_named_curves);
  const std::string         directory = poundfe_test::fresh_directory("contact-plot-pairs");
  const poundfe_test::Table table     = write_contact_forces(model, directory);
  const poundfe::Plot       plot      = poundfe::contact_force_plot(model, directory);
  const auto                totals    = pair_totals(model, table);
  BOOST_CHECK_EQUAL(plot.title, "Total contact force between adjacent buildings (31 gap elements)");
  BOOST_REQUIRE_EQUAL(plot.series.size(), 4u);
  auto expected = totals.begin();
  for (const poundfe::PlotSeries &series : plot.series)
    {
      BOOST_CHECK_EQUAL(series.title, expected->first);
      BOOST_CHECK_EQUAL(series.using_spec, "1:($2/1000)");
      const auto rows = block_rows(plot.data_blocks, series.data_file);
      BOOST_REQUIRE_EQUAL(rows.size(), table.rows.size());
      for (unsigned int r = 0; r < rows.size(); ++r)
        {
          BOOST_CHECK_EQUAL(rows[r].first, table.rows[r][0]);
          BOOST_CHECK_EQUAL(rows[r].second, expected->second[r]); // exact: the same sums
        }
      ++expected;
    }
}

BOOST_AUTO_TEST_CASE(more_pairs_than_a_key_names_are_those_with_the_largest_peaks)
{
  const poundfe::Model model = row_of_buildings(15, 1); // 15 pairs, B14-B15's peak the largest
  const std::string         directory = poundfe_test::fresh_directory("contact-plot-many-pairs");
  const poundfe_test::Table table     = write_contact_forces(model, directory);
  const poundfe::Plot       plot      = poundfe::contact_force_plot(model, directory);
  BOOST_CHECK_EQUAL(plot.title, "Total contact force between adjacent buildings (15 gap elements): "
                                "the 12 of 15 pairs with the largest peaks");
  // peaks grow with the right-hand building: barrier-B1 (1.5), B1-B2 (2) and
  // B2-B3 (3) are left out
  std::vector<std::string> kept;
  for (const auto &[name, total] : pair_totals(model, table))
    if (name != "barrier-B1" && name != "B1-B2" && name != "B2-B3")
      kept.push_back(name);
  BOOST_REQUIRE_EQUAL(plot.series.size(), kept.size());
  for (unsigned int p = 0; p < kept.size(); ++p)
    BOOST_CHECK_EQUAL(plot.series[p].title, kept[p]);
}

BOOST_AUTO_TEST_CASE(gaps_that_never_touched_are_left_out)
{
  const poundfe::Model model     = row_of_buildings(3, 2); // 5 gaps
  const std::string    directory = poundfe_test::fresh_directory("contact-plot-touched");
  write_contact_forces(model, directory, {true, false, true, false, false});
  const poundfe::Plot plot = poundfe::contact_force_plot(model, directory);
  BOOST_CHECK_EQUAL(plot.title, "Contact forces of the 2 of 5 recorded gap elements that touched");
  BOOST_REQUIRE_EQUAL(plot.series.size(), 2u);
  BOOST_CHECK_EQUAL(plot.series[0].title, model.gaps[0].label);
  BOOST_CHECK_EQUAL(plot.series[0].using_spec, "1:($2/1000)");
  BOOST_CHECK_EQUAL(plot.series[1].title, model.gaps[2].label);
  BOOST_CHECK_EQUAL(plot.series[1].using_spec, "1:($6/1000)");
}

BOOST_AUTO_TEST_CASE(pairs_are_of_the_gaps_that_touched)
{
  const poundfe::Model model = row_of_buildings(4, 10); // barrier-B1, then 10 gaps per pair
  std::vector<bool>    touches(model.gaps.size(), true);
  for (unsigned int g = 11; g < 21; ++g) // B2-B3 never closed
    touches[g] = false;
  const std::string directory = poundfe_test::fresh_directory("contact-plot-touched-pairs");
  write_contact_forces(model, directory, touches);
  const poundfe::Plot plot = poundfe::contact_force_plot(model, directory);
  BOOST_CHECK_EQUAL(plot.title,
                    "Total contact force between adjacent buildings (21 gap elements that touched)");
  BOOST_REQUIRE_EQUAL(plot.series.size(), 3u);
  for (const poundfe::PlotSeries &series : plot.series)
    BOOST_CHECK_NE(series.title, "B2-B3");
}

BOOST_AUTO_TEST_CASE(no_gap_touched_is_a_line_at_zero_that_says_so)
{
  const poundfe::Model model     = row_of_buildings(3, 2);
  const std::string    directory = poundfe_test::fresh_directory("contact-plot-untouched");
  write_contact_forces(model, directory, std::vector<bool>(model.gaps.size(), false));
  const poundfe::Plot plot = poundfe::contact_force_plot(model, directory);
  BOOST_CHECK_EQUAL(plot.title, "Contact forces: none of the 5 recorded gap elements touched");
  BOOST_REQUIRE_EQUAL(plot.series.size(), 1u);
  BOOST_CHECK_EQUAL(plot.series[0].using_spec, "1:(0)");
  BOOST_CHECK_EQUAL(plot.series[0].title, "no gap touched");
}

BOOST_AUTO_TEST_CASE(without_the_file_the_figure_has_no_curves)
{
  const poundfe::Model model = row_of_buildings(4, 10);
  const poundfe::Plot  plot =
    poundfe::contact_force_plot(model, poundfe_test::fresh_directory("contact-plot-none"));
  BOOST_CHECK(plot.series.empty());
}

BOOST_AUTO_TEST_SUITE_END()
