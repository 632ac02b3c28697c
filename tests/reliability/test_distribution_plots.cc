// The figures of a Monte Carlo response's distribution
// (reliability/distribution_plots.h), decided by code, not by gnuplot:
//  - the titles name the quantity and the building, with the number of
//    realizations;
//  - the axis is in the engineer's unit, the CSV's SI values divided by it
//    (and the density, per unit of the axis, multiplied by it);
//  - the histogram's x range is its bins' outer edges (no bar cut at either
//    end);
//  - a count gets one bar per whole number whatever the bins of its CSV,
//    the bar's height the number of realizations with that count;
//  - the y range ends a tenth above the tallest bar (none touches the frame).
#include <poundfe/base/numbers.h>
#include <poundfe/reliability/distribution_plots.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <sstream>

BOOST_AUTO_TEST_SUITE(distribution_plots)

BOOST_AUTO_TEST_CASE(a_displacement_in_millimetres_with_no_bar_cut)
{
  const std::vector<double> values{0.010, 0.012, 0.015, 0.020};
  const poundfe::Histogram  h = poundfe::histogram(values, 5);
  const poundfe::ResponseFigure figure{"peak_roof_displacement_A", "Peak roof displacement of building A",
                                       "peak roof displacement (mm)", "mm", 1e-3};
  const auto [pdf, cdf] = poundfe::distribution_plots(figure, h, values);
  BOOST_CHECK_EQUAL(pdf.file, "pdf_peak_roof_displacement_A.png");
  BOOST_CHECK_EQUAL(pdf.title, "Peak roof displacement of building A: histogram of 4 realizations");
  BOOST_CHECK_EQUAL(cdf.title, "Peak roof displacement of building A: empirical CDF of 4 realizations");
  BOOST_CHECK_EQUAL(pdf.x_label, "peak roof displacement (mm)");
  BOOST_CHECK_EQUAL(pdf.y_label, "probability density (1/mm)");
  BOOST_REQUIRE_EQUAL(pdf.series.size(), 1u);
  BOOST_CHECK_EQUAL(pdf.series[0].using_spec, "($3/0.001):($5*0.001)");
  BOOST_CHECK_EQUAL(cdf.series[0].using_spec, "($1/0.001):2");
  // the bins' outer edges, 10 mm and 20 mm
  BOOST_CHECK_CLOSE(h.edges.front(), 0.010, 1e-9);
  BOOST_CHECK_CLOSE(h.edges.back(), 0.020, 1e-9);
  const std::string range = "set xrange [" + poundfe::number_text(h.edges.front() / 1e-3) + ":" +
                            poundfe::number_text(h.edges.back() / 1e-3) + "]";
  BOOST_CHECK_MESSAGE(pdf.settings.find(range) != std::string::npos, pdf.settings);
  // the tallest bar's density per mm, and a tenth above it
  const double tallest = *std::max_element(h.density.begin(), h.density.end()) * 1e-3;
  const std::string top = "set yrange [0:" + poundfe::number_text(1.1 * tallest) + "]";
  BOOST_CHECK_MESSAGE(pdf.settings.find(top) != std::string::npos, pdf.settings);
}

BOOST_AUTO_TEST_CASE(impacts_get_one_bar_per_whole_number)
{
  // 0 to 40 impacts: a CSV of 5 bins groups 9 counts per bin; the figure
  // draws 41 bars of width 1
  const std::vector<double> values{0, 0, 3, 3, 3, 17, 40};
  const poundfe::Histogram  h = poundfe::count_histogram(values, 5);
  BOOST_REQUIRE_GT(h.edges[1] - h.edges[0], 1.0);
  const poundfe::ResponseFigure figure{"n_impacts", "Number of impacts of all gap elements",
                                       "number of impacts", "", 1, true};
  const poundfe::Plot pdf = poundfe::distribution_plots(figure, h, values)[0];
  BOOST_CHECK_EQUAL(pdf.y_label, "realizations");
  BOOST_REQUIRE_EQUAL(pdf.series.size(), 1u);
  BOOST_CHECK_EQUAL(pdf.series[0].data_file, "$counts");
  std::istringstream block(pdf.data_blocks);
  std::string        line;
  std::getline(block, line); // $counts << EOD
  std::getline(block, line); // the header
  unsigned int bars = 0, realizations = 0;
  while (std::getline(block, line) && line != "EOD")
    {
      const double       x     = std::stod(line.substr(0, line.find(',')));
      const unsigned int count = std::stoul(line.substr(line.find(',') + 1));
      BOOST_CHECK_EQUAL(x, double(bars)); // 0, 1, 2, ...: a bar at every whole number
      BOOST_CHECK_EQUAL(count, x == 0 ? 2u : x == 3 ? 3u : x == 17 || x == 40 ? 1u : 0u);
      ++bars;
      realizations += count;
    }
  BOOST_CHECK_EQUAL(bars, 41u);
  BOOST_CHECK_EQUAL(realizations, values.size());
  BOOST_CHECK(pdf.settings.find("set xrange [-0.5:40.5]") != std::string::npos);
  // the tallest bar (3 realizations) below the frame
  BOOST_CHECK_MESSAGE(pdf.settings.find("set yrange [0:" + poundfe::number_text(1.1 * 3) + "]") !=
                        std::string::npos,
                      pdf.settings);
}

BOOST_AUTO_TEST_CASE(a_ratio_is_drawn_from_its_columns_as_they_are)
{
  // gnuplot takes "3:5", not "$3:$5"
  const std::vector<double> values{0.004, 0.006, 0.011};
  const poundfe::ResponseFigure figure{"max_drift_ratio",
                                       "Largest peak inter-storey drift ratio of all buildings",
                                       "largest peak drift ratio", ""};
  const auto [pdf, cdf] =
    poundfe::distribution_plots(figure, poundfe::histogram(values, 3), values);
  BOOST_CHECK_EQUAL(pdf.series[0].using_spec, "3:5");
  BOOST_CHECK_EQUAL(cdf.series[0].using_spec, "1:2");
  BOOST_CHECK_EQUAL(pdf.y_label, "probability density");
}

BOOST_AUTO_TEST_CASE(an_acceleration_in_g)
{
  const std::vector<double> values{1.0, 2.0, 4.0};
  const poundfe::ResponseFigure figure{"max_floor_acceleration", "Largest peak absolute floor "
                                       "acceleration of all buildings",
                                       "largest peak absolute floor acceleration (g)", "g", 9.80665};
  const poundfe::Plot pdf =
    poundfe::distribution_plots(figure, poundfe::histogram(values, 3), values)[0];
  BOOST_CHECK_EQUAL(pdf.series[0].using_spec, "($3/9.80665):($5*9.80665)");
  BOOST_CHECK_EQUAL(pdf.y_label, "probability density (1/g)");
}

BOOST_AUTO_TEST_SUITE_END()
