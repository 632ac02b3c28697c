// The elastic section against s = diag(EA, EIz[, EIy, GJ]) e written here,
// and its state contract (clone virgin, reset to zero).
#include <poundfe/sections/elastic_section.h>

#include <boost/test/unit_test.hpp>

using namespace poundfe;

BOOST_AUTO_TEST_CASE(elastic_section_resultants_are_the_rigidities_times_the_deformations)
{
  ElasticSection plane(2.0e6, 3.0e4);
  SectionVector  e(2);
  e << 1e-3, -2e-2;
  BOOST_TEST(plane.set_trial(e));
  BOOST_TEST(plane.n_resultants() == 2u);
  BOOST_TEST(plane.resultant()(0) == 2.0e6 * 1e-3);
  BOOST_TEST(plane.resultant()(1) == 3.0e4 * -2e-2);
  BOOST_TEST(plane.tangent()(0, 1) == 0.0);

  ElasticSection space(2.0e6, 3.0e4, 5.0e4, 7.0e3);
  SectionVector  e3(4);
  e3 << 1e-3, -2e-2, 4e-3, 0.5;
  BOOST_TEST(space.set_trial(e3));
  BOOST_TEST(space.resultant()(2) == 5.0e4 * 4e-3);
  BOOST_TEST(space.resultant()(3) == 7.0e3 * 0.5);
  const auto copy = space.clone();
  BOOST_TEST(copy->deformation().norm() == 0.0);
  BOOST_TEST(copy->tangent()(3, 3) == 7.0e3);
  space.reset();
  BOOST_TEST(space.resultant().norm() == 0.0);
}
