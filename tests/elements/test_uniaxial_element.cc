// The uniaxial element's deformation d = sum_i b_i x_i over its equations,
// ground DOFs (equation < 0) left out (elements/uniaxial_element.h): from a
// local vector in set_trial (every Newton iteration) and from the model's
// displacement in deformation() (observers), the same double, whatever the
// local vector holds at the ground DOFs.
#include <poundfe/elements/uniaxial_element.h>
#include <poundfe/laws/bouc_wen.h>

#include <boost/test/unit_test.hpp>

#include <limits>
#include <memory>

using namespace poundfe;

BOOST_AUTO_TEST_SUITE(uniaxial_element)

BOOST_AUTO_TEST_CASE(ground_dofs_are_left_out_of_the_deformation)
{
  BoucWenParameters law;
  law.stiffness         = 2e7;
  law.yield_deformation = 1.0; // elastic over these deformations
  const double    k     = law.stiffness;
  UniaxialElement element(ElementKind::storey, 0, "s", std::vector<int>{-1, 2, -1, 4},
                          std::vector<double>{1.0, -1.0, 0.5, 0.25},
                          std::make_unique<BoucWen>(law), k);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(5);
  u[2] = 1.25e-3;
  u[4] = -3.5e-3;
  // the local vector of the element's equations, NaN at its ground DOFs
  Eigen::VectorXd local(4), rate = Eigen::VectorXd::Zero(4);
  local << nan, u[2], nan, u[4];
  BOOST_REQUIRE(element.set_trial(local, rate));
  const double d = element.deformation(u);
  BOOST_TEST(d == -1.25e-3 + 0.25 * -3.5e-3, boost::test_tools::tolerance(1e-15));
  // the trial deformation, read back through the reference energy k d^2 / 2
  BOOST_TEST(element.reference_energy() == 0.5 * k * d * d);
}

BOOST_AUTO_TEST_SUITE_END()
