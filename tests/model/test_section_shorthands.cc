// Section shorthands of generated frames (model/section_shorthands.h;
// doc/verification.md, "Section shorthands"): the Saint-Venant torsion
// constant of a rectangle against the tabulated values of its series
// (Timoshenko & Goodier 1970 §109; Roark's Formulas Table 10.7: beta =
// 0.1406 at a/b = 1, 0.2287 at 2, 0.3123 at 10, to the table's 4 digits);
// the circle's closed forms; the entries filled from 'rectangle b h' and
// 'circle D', a shorthand beside a written A refused; G from a Poisson ratio.
#include <poundfe/base/exceptions.h>
#include <poundfe/model/parameters.h>
#include <poundfe/model/section_shorthands.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_CASE(rectangle_torsion_constant_against_the_table)
{
  // the table's 4 digits: half a unit of the last one
  BOOST_TEST(rectangle_torsion_constant(1, 1) == 0.1406, tt::tolerance(5e-5 / 0.1406));
  BOOST_TEST(rectangle_torsion_constant(0.4, 0.4) / std::pow(0.4, 4) == 0.1406,
             tt::tolerance(5e-5 / 0.1406));
  BOOST_TEST(rectangle_torsion_constant(2, 1) / 2 == 0.2287, tt::tolerance(5e-5 / 0.2287));
  BOOST_TEST(rectangle_torsion_constant(1, 2) == rectangle_torsion_constant(2, 1));
  BOOST_TEST(rectangle_torsion_constant(10, 1) / 10 == 0.3123, tt::tolerance(5e-5 / 0.3123));
  // a thin strip: a b^3 / 3 (1 - 0.630 b / a) (Roark)
  BOOST_TEST(rectangle_torsion_constant(100, 1) == 100.0 / 3 * (1 - 0.630 / 100),
             tt::tolerance(1e-4));
}

BOOST_AUTO_TEST_CASE(rectangles_and_circles)
{
  const SolidSection beam = rectangle_section(0.3, 0.5);
  BOOST_TEST(beam.area == 0.15, tt::tolerance(1e-15));
  BOOST_TEST(beam.second_moment == 0.3 * 0.125 / 12, tt::tolerance(1e-15));
  BOOST_TEST(beam.second_moment_z == 0.5 * 0.027 / 12, tt::tolerance(1e-15));
  BOOST_TEST(beam.torsion_constant == rectangle_torsion_constant(0.5, 0.3));
  const SolidSection round = circle_section(0.5);
  BOOST_TEST(round.area == M_PI * 0.0625, tt::tolerance(1e-15));
  BOOST_TEST(round.second_moment == M_PI * 0.0625 * 0.0625 / 4, tt::tolerance(1e-15));
  BOOST_TEST(round.torsion_constant == 2 * round.second_moment_z, tt::tolerance(1e-15));
  BOOST_TEST(parse_solid_section("rectangle 0.4 0.4").has_value());
  BOOST_TEST(parse_solid_section("circle 0.5").has_value());
  for (const char *bad : {"rectangle 0.4", "square 0.4", "circle -1", "circle 1 2", "circle nan",
                          "rectangle 0.4 1e5", ""})
    BOOST_TEST(!parse_solid_section(bad).has_value(), bad);
}

BOOST_AUTO_TEST_CASE(shorthands_fill_the_entries)
{
  InputFile input;
  input.file = "frame.prm";
  BuildingParameters b;
  b.n_storeys = 2;
  expand_section_shorthands(input, "Building 1/", "rectangle 0.5 0.5;  rectangle 0.4 0.4 ",
                            "circle 0.3", b);
  BOOST_TEST(b.column_area.size() == 2u);
  BOOST_TEST(b.column_area[0] == 0.25, tt::tolerance(1e-15));
  BOOST_TEST(b.column_area[1] == 0.16, tt::tolerance(1e-15));
  BOOST_TEST(b.column_second_moment[1] == std::pow(0.4, 4) / 12, tt::tolerance(1e-15));
  BOOST_TEST(b.column_torsion_constant[1] == rectangle_torsion_constant(0.4, 0.4));
  BOOST_TEST(b.beam_torsion_constant[0] == M_PI * std::pow(0.3, 4) / 32, tt::tolerance(1e-15));

  input.lines["Building 1/Column A"] = 9;
  BOOST_CHECK_EXCEPTION(expand_section_shorthands(input, "Building 1/", "circle 0.4", "", b),
                        InputError,
                        [](const InputError &e) {
                          return e.line() == 9 && e.parameter() == "Building 1/Column A" &&
                                 e.problem().find("Column section") != std::string::npos;
                        });
  input.lines.clear();
  BOOST_CHECK_THROW(expand_section_shorthands(input, "Building 1/",
                                              "rectangle 0.5 0.5; rectangle 0.4 0.4; circle 0.3",
                                              "", b),
                    InputError); // three sections for two storeys
  BOOST_CHECK_THROW(expand_section_shorthands(input, "Building 1/", "", "square 0.3", b),
                    InputError);
}

BOOST_AUTO_TEST_CASE(shear_moduli_from_a_poisson_ratio)
{
  InputFile input;
  input.file = "frame.prm";
  BuildingParameters b;
  b.column_youngs_modulus = {3e10, 2.4e10};
  b.beam_youngs_modulus   = {2e11};
  shear_moduli_from_poisson_ratio(input, "Building 1/", "0.2", b);
  BOOST_TEST(b.column_shear_modulus.size() == 2u);
  BOOST_TEST(b.column_shear_modulus[0] == 1.25e10, tt::tolerance(1e-15));
  BOOST_TEST(b.column_shear_modulus[1] == 1e10, tt::tolerance(1e-15));
  BOOST_TEST(b.beam_shear_modulus[0] == 2e11 / 2.4, tt::tolerance(1e-15));
  BOOST_CHECK_THROW(shear_moduli_from_poisson_ratio(input, "Building 1/", "0.6", b), InputError);
  BOOST_CHECK_THROW(shear_moduli_from_poisson_ratio(input, "Building 1/", "0.2 0.3", b),
                    InputError);
  input.lines["Building 1/Beam G"] = 4;
  BOOST_CHECK_THROW(shear_moduli_from_poisson_ratio(input, "Building 1/", "0.3", b), InputError);
}
