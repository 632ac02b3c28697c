// Intensity measures (excitation/intensity_measures.h, response_spectrum.h):
//  - RotD50 / RotD100 of a pair against a brute-force search written here:
//    for each angle 0..179 degrees the record a1 cos + a2 sin is made and its
//    own response spectrum taken (response_spectrum()), the 180 PSA sorted;
//    the runner superposes the components' histories instead. Tolerance
//    1e-10 relative: the two differ by round-off only (the same points);
//  - the geometric mean against sqrt(PSA1 PSA2);
//  - Arias intensity and CAV of n whole periods of a sine against the closed
//    forms pi/(2g) A^2 n T / 2 and 2 n A T / pi; the sampled sine is linear
//    between 2000 samples a period, an error of O((2 pi / 2000)^2) = 1e-5:
//    tolerance 2e-5 relative;
//  - an AT2 file written by at2_text read back by read_record (9 digits).
#include <poundfe/excitation/intensity_measures.h>
#include <poundfe/excitation/record_suite.h>
#include <poundfe/excitation/records.h>
#include <poundfe/excitation/response_spectrum.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace poundfe;

namespace
{
  /// A decaying sum of three sines, dt = 0.01 s, 6 s.
  GroundMotion
  test_record(const double phase)
  {
    std::vector<double> a;
    for (unsigned int k = 0; k <= 600; ++k)
      {
        const double t = 0.01 * k;
        a.push_back(3 * std::exp(-0.3 * t) *
                    (std::sin(5 * t + phase) + 0.6 * std::sin(13 * t + 2 * phase) +
                     0.3 * std::sin(31 * t - phase)));
      }
    return GroundMotion(0.01, a, "test");
  }

  /// RotD of the pair by rotating the records themselves (brute force).
  double
  brute_force_rotd(const GroundMotion &a1, const GroundMotion &a2, const double period,
                   const double zeta, const bool largest)
  {
    std::vector<double> psa;
    for (unsigned int degrees = 0; degrees < 180; ++degrees)
      {
        const double        c = std::cos(degrees * M_PI / 180), s = std::sin(degrees * M_PI / 180);
        std::vector<double> rotated;
        for (std::size_t k = 0; k < a1.samples().size(); ++k)
          rotated.push_back(c * a1.samples()[k] + s * a2.samples()[k]);
        psa.push_back(
          response_spectrum(GroundMotion(a1.time_step(), rotated, "rotated"), {period}, {zeta})
            .psa(0, 0));
      }
    std::sort(psa.begin(), psa.end());
    return largest ? psa.back() : 0.5 * (psa[89] + psa[90]);
  }
} // namespace

BOOST_AUTO_TEST_CASE(rotd_against_rotating_the_records)
{
  const GroundMotion a1 = test_record(0.3), a2 = test_record(1.7);
  for (const double period : {0.3, 1.0, 2.5})
    {
      const std::vector<GroundMotion> pair{a1, a2};
      const double rotd50 =
        intensity_of(pair, IntensityMeasure::sa, PairMeasure::rotd50, {period}, 0.05);
      const double rotd100 =
        intensity_of(pair, IntensityMeasure::sa, PairMeasure::rotd100, {period}, 0.05);
      BOOST_TEST(rotd50 * standard_gravity == brute_force_rotd(a1, a2, period, 0.05, false),
                 boost::test_tools::tolerance(1e-10));
      BOOST_TEST(rotd100 * standard_gravity == brute_force_rotd(a1, a2, period, 0.05, true),
                 boost::test_tools::tolerance(1e-10));
      const double geometric =
        intensity_of(pair, IntensityMeasure::sa, PairMeasure::geometric_mean, {period}, 0.05);
      const double psa1 = response_spectrum(a1, {period}, {0.05}).psa(0, 0);
      const double psa2 = response_spectrum(a2, {period}, {0.05}).psa(0, 0);
      BOOST_TEST(geometric * standard_gravity == std::sqrt(psa1 * psa2),
                 boost::test_tools::tolerance(1e-12));
      BOOST_TEST(rotd100 >= rotd50);
    }
}

BOOST_AUTO_TEST_CASE(arias_and_cav_of_a_sine)
{
  const double        A = 2.0, T = 0.5, n = 6; // six whole periods
  const unsigned int  per_period = 2000;
  std::vector<double> a;
  for (unsigned int k = 0; k <= n * per_period; ++k)
    a.push_back(A * std::sin(2 * M_PI * k / per_period));
  const GroundMotionIntensity m = ground_motion_intensity(GroundMotion(T / per_period, a, "sine"));
  BOOST_TEST(m.arias_intensity == M_PI / (2 * standard_gravity) * A * A * n * T / 2,
             boost::test_tools::tolerance(2e-5));
  BOOST_TEST(m.cumulative_absolute_velocity == 2 * n * A * T / M_PI,
             boost::test_tools::tolerance(2e-5));
  // the Husid curve of whole periods grows evenly at the period scale: t75 - t5
  // is 70 % of the duration to within a quarter period
  BOOST_TEST(std::abs(m.significant_duration_5_75 - 0.7 * n * T) < T / 4);
}

BOOST_AUTO_TEST_CASE(at2_round_trip)
{
  const GroundMotion  a    = test_record(0.9);
  const std::string   file = (std::filesystem::temp_directory_path() / "poundfe_round.AT2").string();
  std::ofstream(file) << at2_text(a.samples(), a.time_step(), "a test record");
  const GroundMotion b = read_record(file, RecordFormat{});
  BOOST_TEST(b.time_step() == a.time_step());
  BOOST_REQUIRE(b.samples().size() == a.samples().size());
  for (std::size_t k = 0; k < a.samples().size(); ++k)
    BOOST_TEST(std::abs(b.samples()[k] - a.samples()[k]) <= 5e-9 * std::abs(a.samples()[k]) + 1e-300);
}

// A record of 241 samples at 0.015 s lasts 0.015 * 240 = 3.5999999999999996 s
// in doubles: the period 3.6 s written as a decimal is its duration, held;
// a period visibly beyond it is not.
BOOST_AUTO_TEST_CASE(resolved_periods_hold_their_limits_but_for_round_off)
{
  ResolvedPeriods resolved;
  resolved.shortest = 2 * 0.015;
  resolved.longest  = 0.015 * 240;
  BOOST_TEST(resolved.longest < 3.6);
  BOOST_TEST(resolved.holds(3.6));
  BOOST_TEST(resolved.holds(0.03));
  BOOST_TEST(!resolved.holds(3.6 * (1 + 1e-9)));
  BOOST_TEST(!resolved.holds(0.03 * (1 - 1e-9)));
}
