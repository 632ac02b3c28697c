// The aggregator section: each resultant its own uniaxial law (here Steel01
// as a moment-curvature law), the others elastic; clone, revert, failure.
#include <poundfe/laws/material_registry.h>
#include <poundfe/sections/aggregator_section.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

using namespace poundfe;

BOOST_AUTO_TEST_CASE(aggregator_section_follows_its_laws_and_is_elastic_elsewhere)
{
  const double  ea = 2e9, ei = 3e7, gj = 1e7, my = 1e5, b = 0.05;
  SectionVector rigidities(4);
  rigidities << ea, ei, 0.5 * ei, gj;
  AggregatorSection section(rigidities);
  section.set_law(1, [=] {
    return make_material({"Steel01", {{"fy", my}, {"E0", ei}, {"b", b}}});
  });
  BOOST_TEST(section.n_resultants() == 4u);
  BOOST_TEST(section.law(0) == nullptr);
  BOOST_TEST(section.initial_tangent()(1, 1) == ei);
  // past yield in Mz: My + b EI (kappa - kappa_y); the others elastic
  const double  kappa_y = my / ei;
  SectionVector e(4);
  e << 1e-4, 3 * kappa_y, -2e-3, 0.01;
  BOOST_REQUIRE(section.set_trial(e));
  BOOST_TEST(section.resultant()[1] == my + b * ei * 2 * kappa_y,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(section.tangent()(1, 1) == b * ei, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(section.resultant()[0] == ea * 1e-4);
  BOOST_TEST(section.resultant()[2] == 0.5 * ei * -2e-3);
  BOOST_TEST(section.resultant()[3] == gj * 0.01);
  BOOST_TEST(section.tangent()(0, 1) == 0.0);
  section.commit();
  // unloading from the committed plastic state is elastic; revert is exact
  const SectionVector committed = section.resultant();
  SectionVector       back      = e;
  back[1]                       = 2 * kappa_y;
  BOOST_REQUIRE(section.set_trial(back));
  BOOST_TEST(section.tangent()(1, 1) == ei);
  section.revert();
  BOOST_TEST((section.resultant().array() == committed.array()).all());
  BOOST_TEST((section.deformation().array() == e.array()).all());
  // a clone is virgin and independent
  const auto copy = section.clone();
  BOOST_TEST(copy->resultant().norm() == 0.0);
  BOOST_TEST(copy->tangent()(1, 1) == ei);
  section.reset();
  BOOST_TEST(section.resultant().norm() == 0.0);
  // a strain the law refuses names the resultant
  e[1] = std::numeric_limits<double>::infinity();
  BOOST_TEST(!section.set_trial(e));
  BOOST_TEST(section.failure().find("Mz") != std::string::npos);
}
