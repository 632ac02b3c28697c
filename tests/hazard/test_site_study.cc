// The site study's earthquake coefficient (hazard/site_study.h) against
// independent references:
//   - Kawasumi's JMA relation a = 0.45 10^(S/2) at the even grades, where it
//     is a power of ten worked out by hand (0.45, 4.5, 45, 450 gal);
//   - the Poisson return period of a probability in a life against the
//     published design values: 10 % in 50 years is the 475-year earthquake
//     (474.56), 2 % in 50 years the 2475-year one (2474.9), 50 % in 100
//     years 100/ln 2 = 144.27 (the thesis's 144, §2.3.1);
//   - an intensity-frequency line through two chosen points gives them back;
//   - the thesis's Table 2.3 (§2.3.1) at the digits it prints: ISC 2.5 and
//     4.0 -> 5.8 and 16.4 gal, JMA 1.5 ("I - II") and 3 (III) -> 2.5 and 14
//     gal, M.R. 5 -> 32.7 gal; k = 0.01 (100 years) and 0.03 (250); OBE 0.03 g,
//     MCE 0.06 g;
//   - rounding as a table prints (half away from zero, typed decimals);
//   - the typed-in entries' messages: an intensity outside its scale, an
//     unknown scale, a short entry, a return period of 1 year.
#include <poundfe/hazard/site_study.h>
#include <poundfe/hazard/site_study_parameters.h>
#include <poundfe/base/exceptions.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

using namespace poundfe;

namespace
{
  /// The message of the InputError the typed entries `text` raise ("" if none).
  std::string
  entry_error(const std::string &text)
  {
    SiteStudyParameters p;
    p.intensities = {text};
    InputFile input;
    input.file = "study.prm";
    try
      {
        p.typed_entries(input);
      }
    catch (const InputError &e)
      {
        BOOST_TEST(e.file() == "study.prm");
        BOOST_TEST_MESSAGE("site study error: " << e.what());
        return e.what();
      }
    return "";
  }
} // namespace

BOOST_AUTO_TEST_CASE(kawasumi_at_even_grades)
{
  // hand: 0.45 x 10^(S/2) at S = 0, 2, 4, 6 is 0.45 x 1, 10, 100, 1000
  const double expected[] = {0.45, 4.5, 45, 450};
  for (int i = 0; i < 4; ++i)
    BOOST_TEST(jma_acceleration_gal(2 * i) == expected[i], boost::test_tools::tolerance(1e-14));
  // the ISC scale goes through Trifunac-Brady: 10^(0.014 + 0.30 x 10) at X
  BOOST_TEST(intensity_acceleration_gal(IntensityScale::isc, 10.0) ==
               std::pow(10.0, 3.014), boost::test_tools::tolerance(1e-14));
  BOOST_TEST(intensity_scale_minimum(IntensityScale::isc) == 1.0);
  BOOST_TEST(intensity_scale_maximum(IntensityScale::isc) == 12.0);
  BOOST_TEST(intensity_scale_maximum(IntensityScale::jma) == 7.0);
}

BOOST_AUTO_TEST_CASE(return_periods_of_design_earthquakes)
{
  // the published values (e.g. Eurocode 8 §2.1: 10 % in 50 years is 475
  // years; 2 % in 50 years 2475), to the digits they are quoted with
  BOOST_TEST(std::abs(return_period_of_exceedance(50, 0.10) - 475) < 0.5);
  BOOST_TEST(std::abs(return_period_of_exceedance(50, 0.02) - 2475) < 0.5);
  // 50 % in 100 years: 100 / ln 2 = 144.2695 (hand), the thesis's 144
  BOOST_TEST(return_period_of_exceedance(100, 0.5) == 144.26950408889634,
             boost::test_tools::tolerance(1e-14));
  BOOST_TEST(std::floor(return_period_of_exceedance(100, 0.5)) == 144);
}

BOOST_AUTO_TEST_CASE(intensity_frequency_line_through_two_points)
{
  // log10 N = a - b I through (I = 2.5, N = 1/100) and (4.0, 1/250):
  // b = log10(2.5)/1.5, a = -2 + 2.5 b (by hand)
  const double                     b = std::log10(2.5) / 1.5;
  const IntensityFrequencyRelation relation{-2 + 2.5 * b, b};
  BOOST_TEST(relation.intensity_for_return_period(100) == 2.5,
             boost::test_tools::tolerance(1e-13));
  BOOST_TEST(relation.intensity_for_return_period(250) == 4.0,
             boost::test_tools::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(thesis_table_2_3)
{
  // thesis §2.3.1, Table 2.3, as printed; the method column's values
  const std::vector<SiteStudyEntry> entries{{"ISC", IntensityScale::isc, 100, 2.5},
                                            {"JMA", IntensityScale::jma, 100, 1.5},
                                            {"ISC", IntensityScale::isc, 250, 4.0},
                                            {"JMA", IntensityScale::jma, 250, 3.0},
                                            {"M.R.", IntensityScale::isc, 250, 5.0}};
  SiteStudySettings settings;
  settings.gravity           = 9.80; // the thesis's k = gal/980
  settings.obe_return_period = 250;
  const SiteStudyResult study = site_study(entries, settings);
  // printed to one decimal (JMA 250: to the unit, "14 gal"): half a unit
  const double printed[] = {5.8, 2.5, 16.4, 14, 32.7};
  const double half[]    = {0.05, 0.05, 0.05, 0.5, 0.05};
  BOOST_REQUIRE(study.rows.size() == 5);
  for (unsigned int i = 0; i < 5; ++i)
    {
      BOOST_TEST_MESSAGE(study.rows[i].entry.method << " " << study.rows[i].acceleration_gal);
      BOOST_TEST(std::abs(study.rows[i].acceleration_gal - printed[i]) <= half[i]);
    }
  BOOST_REQUIRE(study.coefficients.size() == 2);
  BOOST_TEST(study.coefficients[0].rounded == 0.01); // 100 years
  BOOST_TEST(study.coefficients[1].rounded == 0.03); // 250 years
  BOOST_TEST(study.design.obe_g == 0.03);
  BOOST_TEST(study.design.mce_g == 0.06);
  BOOST_TEST(std::floor(study.design.service_life_return_period) == 144);
}

BOOST_AUTO_TEST_CASE(rounding_like_a_printed_table)
{
  BOOST_TEST(rounded_to_decimals(0.125, 2) == 0.13);  // half away from zero
  BOOST_TEST(rounded_to_decimals(-0.125, 2) == -0.13);
  BOOST_TEST(rounded_to_decimals(1.005, 2) == 1.01);  // stored 1.00499999...
  BOOST_TEST(rounded_to_decimals(3.6624, 1) == 3.7);
  BOOST_TEST(rounded_to_decimals(0.0334, 2) == 0.03);
  BOOST_TEST(rounded_to_decimals(3.6624, -1) == 3.6624); // unchanged
}

BOOST_AUTO_TEST_CASE(typed_entries_refused_with_a_message)
{
  BOOST_TEST(entry_error("ISC isc 100 2.5; JMA jma 250 3").find("fields") != std::string::npos);
  BOOST_TEST(entry_error("ISC isc 100 2.5").empty());
  BOOST_TEST(entry_error("ISC isc 100 13").find("outside the ISC scale [1, 12]") !=
             std::string::npos);
  BOOST_TEST(entry_error("ISC isc 100 0.5").find("outside the ISC scale") != std::string::npos);
  BOOST_TEST(entry_error("JMA jma 250 7.5").find("outside the JMA scale [0, 7]") !=
             std::string::npos);
  BOOST_TEST(entry_error("MM mm 100 3").find("neither isc nor jma") != std::string::npos);
  BOOST_TEST(entry_error("ISC isc 1 3").find("years > 1") != std::string::npos);
  BOOST_TEST(entry_error("ISC isc 100 III").find("not a number") != std::string::npos);
}
