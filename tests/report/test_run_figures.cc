// What the figures of a run and of `poundfe switching` draw, decided by code
// rather than by gnuplot (the pixels are not tested):
//  - energy.png (energy_plot): every energy term in kJ (energy.csv's J over
//    1000), each in its own colour, none of them yellow-ish (unreadable on
//    white), the same colour for a term in both panels; the balance error a
//    ratio on the right-hand axis, unscaled;
//  - phase_portrait.png of `poundfe switching` (switching_phase_portrait):
//    a key entry only for the classes of hit that occurred, sliding samples
//    only when something slid, axes with the units of equation 1's DOF;
//  - the titles of a run's figures of the whole model name its buildings,
//    and the other figures' titles (which name their own) are left alone.
#include <poundfe/report/run_plots.h>
#include <poundfe/report/switching_plot.h>

#include <boost/test/unit_test.hpp>

#include <map>
#include <set>
#include <string>

namespace
{
  /// The colour of a series' style ("... lc rgb '<colour>'"), empty if none.
  std::string
  colour_of(const poundfe::PlotSeries &series)
  {
    const std::size_t at = series.style.find("lc rgb '");
    if (at == std::string::npos)
      return "";
    const std::size_t start = at + 8;
    return series.style.substr(start, series.style.find('\'', start) - start);
  }

  /// Whether a "#rrggbb" colour is light and yellow-ish: red and green
  /// both bright, blue low (gnuplot's default cycle has such a yellow).
  bool
  yellowish(const std::string &colour)
  {
    if (colour == "yellow" || colour == "gold")
      return true;
    if (colour.size() != 7 || colour[0] != '#')
      return false;
    const auto channel = [&](const int i) { return std::stoi(colour.substr(1 + 2 * i, 2), nullptr, 16); };
    return channel(0) > 180 && channel(1) > 180 && channel(2) < 120;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(run_figures)

BOOST_AUTO_TEST_CASE(energy_is_in_kilojoules_in_readable_distinct_colours)
{
  poundfe::Model model;
  model.friction_surfaces.resize(1); // friction and belt terms in both panels
  model.building_links.resize(1);
  const poundfe::Plot energy = poundfe::energy_plot(model);
  BOOST_CHECK_EQUAL(energy.y_label, "energy (kJ)");
  BOOST_REQUIRE_EQUAL(energy.below.size(), 1u);
  BOOST_CHECK_EQUAL(energy.below[0].y_label, "energy (kJ)");
  std::map<std::string, std::string> colour_of_term;
  std::set<std::string>              colours;
  for (const poundfe::Plot *panel : {&energy, &energy.below[0]})
    for (const poundfe::PlotSeries &s : panel->series)
      {
        const std::string colour = colour_of(s);
        BOOST_CHECK_MESSAGE(!colour.empty(), s.title << " has no colour of its own");
        BOOST_CHECK_MESSAGE(!yellowish(colour), s.title << " is drawn in " << colour);
        if (s.title == "balance error")
          {
            BOOST_CHECK_EQUAL(s.axes, "x1y2");
            BOOST_CHECK_EQUAL(s.using_spec, "1:8"); // a ratio: not scaled
            continue;
          }
        const std::string column = s.using_spec.substr(4, s.using_spec.find('/') - 4);
        BOOST_CHECK_EQUAL(s.using_spec, "1:($" + column + "/1000)");
        const auto [known, first] = colour_of_term.emplace(s.title, colour);
        if (first)
          BOOST_CHECK_MESSAGE(colours.insert(colour).second, s.title << " shares " << colour);
        else
          BOOST_CHECK_EQUAL(known->second, colour); // the same term, the same colour
      }
  for (const char *term : {"input", "kinetic", "damping", "strain", "hysteretic", "contact",
                           "friction", "belt", "links"})
    BOOST_CHECK_MESSAGE(colour_of_term.count(term), "no curve of " << term);
}

BOOST_AUTO_TEST_CASE(switching_portrait_lists_only_the_classes_that_occur)
{
  poundfe::SwitchingSurface gap{"gap", poundfe::Vector::Zero(2), 0.01};
  gap.normal[0] = 1; // u_1 = 0.01: a vertical dashed line
  const poundfe::Plot plot =
    poundfe::switching_phase_portrait({gap}, 1, {"crossing", "grazing"}, false, false);
  std::vector<std::string> titles;
  for (const poundfe::PlotSeries &s : plot.series)
    titles.push_back(s.title);
  const std::vector<std::string> expected{"trajectory", "crossing", "grazing"};
  BOOST_CHECK_EQUAL_COLLECTIONS(titles.begin(), titles.end(), expected.begin(), expected.end());
  BOOST_CHECK_EQUAL(plot.x_label, "displacement u_1 (m)");
  BOOST_CHECK_EQUAL(plot.y_label, "velocity v_1 (m/s)");
  BOOST_CHECK(plot.settings.find("set arrow from first 0.01, graph 0 to first 0.01, graph 1") !=
              std::string::npos);
  // the class column of switching.csv (2 n + 9) names the class drawn
  BOOST_CHECK_EQUAL(plot.series[1].using_spec, "2:(strcol(11) eq 'crossing' ? $3 : 1/0)");
}

BOOST_AUTO_TEST_CASE(switching_portrait_of_a_stick_slip_rotation)
{
  const poundfe::Plot plot = poundfe::switching_phase_portrait(
    {}, 2, {"attracting-sliding", "sliding-exit"}, true, true);
  std::vector<std::string> titles;
  for (const poundfe::PlotSeries &s : plot.series)
    titles.push_back(s.title);
  const std::vector<std::string> expected{"trajectory", "sliding (Filippov)", "attracting sliding",
                                          "sliding exit"};
  BOOST_CHECK_EQUAL_COLLECTIONS(titles.begin(), titles.end(), expected.begin(), expected.end());
  BOOST_CHECK_EQUAL(plot.x_label, "rotation u_1 (rad)");
  BOOST_CHECK_EQUAL(plot.y_label, "angular velocity v_1 (rad/s)");
}

BOOST_AUTO_TEST_CASE(run_figure_titles_name_the_buildings)
{
  poundfe::Model model;
  const auto     with = [&](const std::vector<std::string> &names) {
    model.buildings.resize(names.size());
    for (std::size_t b = 0; b < names.size(); ++b)
      model.buildings[b].name = names[b];
    return poundfe::buildings_in_title(model);
  };
  BOOST_CHECK_EQUAL(with({"A"}), "Building A: ");
  BOOST_CHECK_EQUAL(with({"A", "B"}), "Buildings A and B: ");
  BOOST_CHECK_EQUAL(with({"A", "B", "C"}), "Buildings A, B and C: ");
  BOOST_CHECK_EQUAL(with({"1", "2", "3", "4", "5"}), "5 buildings: ");
  with({"A", "B"});
  std::vector<poundfe::Plot> plots{{"roof_displacement.png", "Roof displacement", "", "", {}},
                                   {"energy.png", "Energy balance", "", "", {}},
                                   {"hysteresis_A_S1.png", "Storey S1 of A", "", "", {}},
                                   {"ground_motion.png", "El Centro", "", "", {}}};
  poundfe::name_buildings_in_titles(plots, model);
  BOOST_CHECK_EQUAL(plots[0].title, "Buildings A and B: Roof displacement");
  BOOST_CHECK_EQUAL(plots[1].title, "Buildings A and B: Energy balance");
  BOOST_CHECK_EQUAL(plots[2].title, "Storey S1 of A");
  BOOST_CHECK_EQUAL(plots[3].title, "El Centro");
}

BOOST_AUTO_TEST_SUITE_END()
