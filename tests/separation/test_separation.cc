// The separation rules and the probability of pounding against independent
// references (theory §7.1):
//   - Der Kiureghian's correlation and the ABS/SRSS/DDC/EC8/ASCE 7 rules on
//     two SDOF buildings, numbers worked by hand here; the correlation also
//     against the closed-form cross-covariance of two oscillators under the
//     same white noise (Crandall & Mark 1963), a different formula;
//   - the fundamental modes and damping ratios of the pair
//     (tests/cli/separation-sdof-pair.prm) against sqrt(k/m) and c/(2 m w);
//   - the time-history minimum and the peaks against the maximum of
//     u_1 - u_2 and of |u_i| taken here from the run's own displacements;
//   - the exceedance curve at a gap equal to one realization's largest
//     approach (P = 1 just below, 0 at and above), and the Wilson interval
//     against published values;
//   - the Monte Carlo band of the stationary point-in-time probability
//     P(|u_1 - u_2| > g) = 2 (1 - Phi(g / sigma)) against its closed form;
//   - the common levels of buildings whose floors differ and the height
//     interpolation weights, worked by hand (input/floor-to-column.prm).
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/separation/separation.h>
#include <poundfe/separation/separation_report.h>
#include <poundfe/reliability/statistics.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  const char *const pair_file = "tests/cli/separation-sdof-pair.prm";

  /// Stationary covariance of x_1, x_2 of x_i'' + 2 z_i w_i x_i' + w_i^2 x_i
  /// = -w(t), <w(t) w(t')> = 2 pi S0 delta(t - t') (Crandall & Mark 1963, Random
  /// Vibration in Mechanical Systems; Lin 1967, Probabilistic Theory of
  /// Structural Dynamics, §5.6): the integral of S0 H_1 conj(H_2) over all w.
  double
  white_noise_covariance(const double w1, const double z1, const double w2, const double z2,
                         const double s0)
  {
    const double a = z1 * w1 + z2 * w2;
    return 4 * M_PI * s0 * a /
           ((w1 * w1 - w2 * w2) * (w1 * w1 - w2 * w2) + 4 * w1 * w2 * a * (z1 * w2 + z2 * w1));
  }

  /// The floor displacements of both buildings at every step (the floors'
  /// single ux each): the run's own output, read here without FloorResponse.
  class FloorHistory : public StepObserver
  {
  public:
    explicit FloorHistory(const Model &model)
      : left(model.equation(Model::dof(model.buildings[0].floors[0].nodes[0], Component::ux)))
      , right(model.equation(Model::dof(model.buildings[1].floors[0].nodes[0], Component::ux)))
    {}
    void observe_step(const ResponseView &state) override
    {
      u_left.push_back(state.displacement()[left]);
      u_right.push_back(state.displacement()[right]);
    }
    std::vector<double> u_left, u_right;

  private:
    int left, right;
  };
} // namespace

BOOST_AUTO_TEST_CASE(rules_on_two_sdof_buildings_by_hand)
{
  // T = 0.5 s, zeta 0.05 and T = 0.8 s, zeta 0.03: r = w2/w1 = 0.5/0.8 = 0.625,
  // r^1.5 = 0.4941059; numerator 8 sqrt(0.0015) (0.05 + 0.625 * 0.03) r^1.5
  // = 8 * 0.03872983 * 0.06875 * 0.4941059 = 0.01052507; denominator
  // (1 - 0.390625)^2 + 4 * 0.0015 * 0.625 * 1.390625 + 4 * 0.0034 * 0.390625
  // = 0.3713379 + 0.0052148 + 0.0053125 = 0.3818652; rho = 0.0275625.
  const double w1 = 2 * M_PI / 0.5, w2 = 2 * M_PI / 0.8;
  const double rho = modal_correlation(w1, 0.05, w2, 0.03);
  BOOST_TEST(rho == 0.0275625, boost::test_tools::tolerance(1e-5));
  // the same number as the white-noise correlation of the two oscillators
  const double s0 = 1;
  BOOST_TEST(rho == white_noise_covariance(w1, 0.05, w2, 0.03, s0) /
                      std::sqrt(M_PI * s0 / (2 * 0.05 * w1 * w1 * w1) * M_PI * s0 /
                                (2 * 0.03 * w2 * w2 * w2)),
             boost::test_tools::tolerance(1e-12));
  // identical oscillators are fully correlated
  BOOST_TEST(modal_correlation(w1, 0.05, w1, 0.05) == 1.0, boost::test_tools::tolerance(1e-12));

  // u1 = 0.04 m, u2 = 0.07 m; EC8 q = 1.5 and 2 (floors coincide: 0.7);
  // ASCE 7 C_d = 4 and 5.5, I_e = 1 and 1.25.
  const SeparationRules s =
    separation_rules(0.04, 0.07, rho, {4.0, 1.0, 1.5}, {5.5, 1.25, 2.0}, true, 0.7);
  BOOST_TEST(s.abs == 0.11, boost::test_tools::tolerance(1e-12));
  // sqrt(0.0016 + 0.0049) = sqrt(0.0065)
  BOOST_TEST(s.srss == 0.08062258, boost::test_tools::tolerance(1e-7));
  // sqrt(0.0065 - 2 * 0.0275625 * 0.0028) = sqrt(0.006345650)
  BOOST_TEST(s.ddc == 0.07965959, boost::test_tools::tolerance(1e-7));
  // 0.7 sqrt(0.06^2 + 0.14^2) = 0.7 sqrt(0.0232) = 0.7 * 0.1523155
  BOOST_TEST(s.ec8 == 0.1066208, boost::test_tools::tolerance(1e-6));
  // sqrt(0.16^2 + (5.5 * 0.07 / 1.25)^2) = sqrt(0.0256 + 0.308^2) = sqrt(0.120464)
  BOOST_TEST(s.asce7 == 0.3470792, boost::test_tools::tolerance(1e-6));
  // floors at different levels: no 0.7
  const SeparationRules d =
    separation_rules(0.04, 0.07, rho, {4.0, 1.0, 1.5}, {5.5, 1.25, 2.0}, false, 0.7);
  BOOST_TEST(d.ec8 == 0.1523155, boost::test_tools::tolerance(1e-6));
}

BOOST_AUTO_TEST_CASE(fundamental_modes_and_common_level_of_the_pair)
{
  InputParameters input = read_parameters(pair_file);
  input.output.n_modes  = 0; // fundamental_mode computes its own then
  const Analysis                  analysis = prepare_analysis(input);
  const FundamentalMode           left     = fundamental_mode(analysis, 0);
  const FundamentalMode           right    = fundamental_mode(analysis, 1);
  BOOST_TEST(left.omega == 4 * M_PI, boost::test_tools::tolerance(1e-10));
  BOOST_TEST(right.omega == 2 * M_PI / 0.8, boost::test_tools::tolerance(1e-10));
  BOOST_TEST(left.damping_ratio == 0.05, boost::test_tools::tolerance(1e-10));
  BOOST_TEST(right.damping_ratio == 0.03, boost::test_tools::tolerance(1e-10));
  const std::vector<AdjacentPair> pairs = adjacent_pairs(analysis.model);
  BOOST_TEST_REQUIRE(pairs.size() == 1u);
  BOOST_TEST_REQUIRE(pairs[0].levels.size() == 1u);
  BOOST_TEST(pairs[0].levels[0].level == 3.0);
  BOOST_TEST(pairs[0].levels[0].floors_coincide);
  BOOST_TEST(pairs[0].existing_gap == 0.02, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(time_history_minimum_is_the_largest_approach_of_the_run)
{
  const InputParameters           input    = read_parameters(pair_file);
  const Analysis                  analysis = prepare_analysis(input);
  const std::vector<AdjacentPair> pairs    = adjacent_pairs(analysis.model);
  TimeHistory                     history(analysis, time_history_parameters(input));
  SeparationObserver              separation(analysis.model, pairs);
  FloorHistory                    floors(analysis.model);
  const Excitation                excitation = make_excitation(analysis, input);
  BOOST_TEST_REQUIRE(history.run(excitation, {&separation, &floors}).completed());
  double max_difference = -1e300, peak_left = 0, peak_right = 0;
  for (std::size_t i = 0; i < floors.u_left.size(); ++i)
    {
      max_difference = std::max(max_difference, floors.u_left[i] - floors.u_right[i]);
      peak_left      = std::max(peak_left, std::abs(floors.u_left[i]));
      peak_right     = std::max(peak_right, std::abs(floors.u_right[i]));
    }
  const SeparationObserver::LevelResponse &r = separation.responses()[0][0];
  BOOST_TEST_MESSAGE("largest approach " << r.max_approach << " m over "
                                         << floors.u_left.size() << " states");
  BOOST_TEST(max_difference > 0);
  BOOST_TEST(r.max_approach == max_difference, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(r.peak_left == peak_left, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(r.peak_right == peak_right, boost::test_tools::tolerance(1e-14));

  // one realization: pounds just below its largest approach, not at or above
  const std::vector<ExceedancePoint> curve =
    exceedance_curve({r.max_approach},
                     {r.max_approach * (1 - 1e-12), r.max_approach, r.max_approach * (1 + 1e-12)},
                     0.95);
  BOOST_TEST(curve[0].probability == 1.0);
  BOOST_TEST(curve[1].probability == 0.0);
  BOOST_TEST(curve[2].probability == 0.0);
}

BOOST_AUTO_TEST_CASE(wilson_interval_against_published_values)
{
  // Brown, Cai & DasGupta (2001) and Newcombe (1998, Stat. Med. 17, table II):
  // 0 of 10 at 95 %: [0, 0.2775]; 5 of 10: [0.2366, 0.7634]; 81 of 263: [0.2553, 0.3662]
  const ProbabilityInterval a = wilson_interval(0, 10, 0.95);
  BOOST_TEST(a.lower == 0.0); // exactly: a printed 2.8e-17 misled
  BOOST_TEST(a.upper == 0.2775, boost::test_tools::tolerance(3e-4));
  const ProbabilityInterval all = wilson_interval(10, 10, 0.95); // the mirror of a
  BOOST_TEST(all.upper == 1.0);
  BOOST_TEST(all.lower == 1 - 0.2775, boost::test_tools::tolerance(3e-4));
  const ProbabilityInterval b = wilson_interval(5, 10, 0.95);
  BOOST_TEST(b.lower == 0.2366, boost::test_tools::tolerance(3e-4));
  BOOST_TEST(b.upper == 0.7634, boost::test_tools::tolerance(3e-4));
  const ProbabilityInterval c = wilson_interval(81, 263, 0.95);
  BOOST_TEST(c.lower == 0.2553, boost::test_tools::tolerance(3e-4));
  BOOST_TEST(c.upper == 0.3662, boost::test_tools::tolerance(3e-4));
}

BOOST_AUTO_TEST_CASE(monte_carlo_band_covers_the_stationary_white_noise_probability)
{
  // The pair's relative displacement at t = 15 s is Gaussian, zero-mean, with
  // sigma^2 = s1^2 + s2^2 - 2 c12 (closed forms above): P(|u1 - u2| > g) =
  // 2 (1 - Phi(g / sigma)). 400 realizations, a 99.9 % Wilson band at three
  // gaps: each misses with probability 1e-3.
  const InputParameters input    = read_parameters(pair_file);
  const Analysis        analysis = prepare_analysis(input);
  const double          s0 = 0.01, w1 = 4 * M_PI, w2 = 2 * M_PI / 0.8, z1 = 0.05, z2 = 0.03;
  const double          variance = M_PI * s0 / (2 * z1 * w1 * w1 * w1) +
                          M_PI * s0 / (2 * z2 * w2 * w2 * w2) -
                          2 * white_noise_covariance(w1, z1, w2, z2, s0);
  const double sigma = std::sqrt(variance);

  RealizationRunner               runner(analysis, time_history_parameters(input));
  const std::vector<AdjacentPair> pairs = adjacent_pairs(analysis.model);
  SeparationObserver              separation(analysis.model, pairs);
  std::vector<double>             at_end;
  for (unsigned int r = 0; r < 400; ++r)
    {
      BOOST_TEST_REQUIRE(runner.run(r, Observers{&separation}));
      at_end.push_back(std::abs(separation.responses()[0][0].approach));
    }
  const std::vector<double> gaps{0.5 * sigma, sigma, 2 * sigma};
  const auto                curve = exceedance_curve(at_end, gaps, 0.999);
  for (const ExceedancePoint &p : curve)
    {
      const double exact = std::erfc(p.gap / sigma / std::sqrt(2.0)); // 2 (1 - Phi)
      BOOST_TEST_MESSAGE("g = " << p.gap << " m: exact " << exact << ", Monte Carlo "
                                << p.probability << " [" << p.lower << ", " << p.upper << "]");
      BOOST_TEST(p.lower <= exact);
      BOOST_TEST(exact <= p.upper);
    }
}

BOOST_AUTO_TEST_CASE(levels_where_floors_differ_are_interpolated_in_height)
{
  // input/floor-to-column.prm: A3's floors at 3.5, 6.5, 9.5 m, B2's at 4.5
  // and 8 m. Common levels up to the lower roof: 3.5, 4.5, 6.5, 8; at 3.5 m
  // B2 lies 3.5/4.5 of the way from its base to its first floor, at 4.5 m A3
  // (4.5 - 3.5)/3 = 1/3 from its first floor to its second, at 8 m
  // (8 - 6.5)/3 = 1/2 from its second to its roof.
  InputParameters input = read_parameters("input/floor-to-column.prm");
  input.contact.law     = "none";
  const Analysis                  analysis = prepare_analysis(input);
  const FloorResponse             floors(analysis.model);
  const std::vector<AdjacentPair> pairs = adjacent_pairs(analysis.model);
  BOOST_TEST_REQUIRE(pairs.size() == 1u);
  const std::vector<CommonLevel> &levels = pairs[0].levels;
  BOOST_TEST_REQUIRE(levels.size() == 4u);
  const double expected_level[] = {3.5, 4.5, 6.5, 8.0};
  for (unsigned int l = 0; l < 4; ++l)
    BOOST_TEST(levels[l].level == expected_level[l], boost::test_tools::tolerance(1e-12));
  for (const CommonLevel &level : levels)
    BOOST_TEST(!level.floors_coincide);
  // 3.5 m: A3's floor 1; B2 between its base and floor 1
  BOOST_TEST(levels[0].sides[0].below == int(floors.index(0, 0)));
  BOOST_TEST(levels[0].sides[0].above == int(floors.index(0, 0)));
  BOOST_TEST(levels[0].sides[1].below == -1);
  BOOST_TEST(levels[0].sides[1].above == int(floors.index(1, 0)));
  BOOST_TEST(levels[0].sides[1].weight == 3.5 / 4.5, boost::test_tools::tolerance(1e-12));
  // 4.5 m: A3 between floors 1 and 2
  BOOST_TEST(levels[1].sides[0].below == int(floors.index(0, 0)));
  BOOST_TEST(levels[1].sides[0].above == int(floors.index(0, 1)));
  BOOST_TEST(levels[1].sides[0].weight == 1.0 / 3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(levels[1].sides[1].below == int(floors.index(1, 0)));
  // 8 m: A3 between floors 2 and 3
  BOOST_TEST(levels[3].sides[0].below == int(floors.index(0, 1)));
  BOOST_TEST(levels[3].sides[0].above == int(floors.index(0, 2)));
  BOOST_TEST(levels[3].sides[0].weight == 0.5, boost::test_tools::tolerance(1e-12));
}

// separation.png of a pair with one common level: the existing gap a line
// from the ground to that level (a single point drew nothing), every rule in
// a colour of its own, none of them gnuplot's default yellow.
BOOST_AUTO_TEST_CASE(separation_figure_draws_the_gap_and_readable_rules)
{
  AdjacentPair pair;
  pair.existing_gap = 0.025;
  pair.name         = "A1-B1";
  pair.levels.resize(1);
  pair.levels[0].level = 3.5;
  const Plot plot = separation_plot({pair}, nullptr, false);
  BOOST_CHECK_EQUAL(plot.x_label, "separation (mm)");
  BOOST_CHECK(plot.title.find("A1-B1") != std::string::npos);
  BOOST_CHECK(plot.title.find("(time history)") != std::string::npos);
  // a random run's peaks are the Monte Carlo means: the title and the curve say so
  const Plot random = separation_plot({pair}, nullptr, true);
  BOOST_CHECK(random.title.find("(Monte Carlo mean)") != std::string::npos);
  BOOST_CHECK(std::any_of(random.series.begin(), random.series.end(), [](const PlotSeries &s) {
    return s.title == "Monte Carlo mean (no contact)";
  }));
  BOOST_CHECK(plot.data_blocks.find("$gap1 << EOD\ngap_mm,level_m\n25,0\n25,3.5\nEOD\n") !=
              std::string::npos);
  std::set<std::string> colours;
  bool                  gap_drawn = false;
  for (const PlotSeries &s : plot.series)
    {
      const std::size_t at = s.style.find("lc rgb '");
      BOOST_REQUIRE_MESSAGE(at != std::string::npos, s.title << ": gnuplot's default colour");
      const std::string colour = s.style.substr(at + 8, s.style.find('\'', at + 8) - at - 8);
      BOOST_CHECK_MESSAGE(colours.insert(colour).second, s.title << " shares " << colour);
      if (colour.size() == 7 && colour[0] == '#') // not light yellow: red and green bright, blue low
        BOOST_CHECK_MESSAGE(!(std::stoi(colour.substr(1, 2), nullptr, 16) > 180 &&
                              std::stoi(colour.substr(3, 2), nullptr, 16) > 180 &&
                              std::stoi(colour.substr(5, 2), nullptr, 16) < 120),
                            s.title << " in " << colour);
      gap_drawn |= s.title == "existing gap" && s.data_file == "$gap1" && s.using_spec == "1:2";
    }
  BOOST_CHECK(gap_drawn);
}
