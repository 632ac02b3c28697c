// The uniaxial element's deformation d = sum_i b_i x_i over its equations,
// ground DOFs (equation < 0) left out (elements/uniaxial_element.h): from a
// local vector in set_trial (every Newton iteration) and from the model's
// displacement in deformation() (observers), the same double, whatever the
// local vector holds at the ground DOFs.
#include <poundfe/elements/uniaxial_element.h>
#include <poundfe/laws/bouc_wen.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
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

BOOST_AUTO_TEST_CASE(typed_evaluation_is_the_interface_to_the_bit)
{
  // The integrator's typed loop (UniaxialElement::evaluate, reading the
  // global vectors) against the interface's set_trial, force_correction and
  // tangent_change on the gathered local vectors, on a twin element: the
  // same force correction, D and work to the bit, over a Bouc-Wen loop
  // through yield and back, each state committed.
  BoucWenParameters law;
  law.stiffness         = 2e7;
  law.yield_deformation = 1e-3;
  law.alpha             = 0.1;
  law.n                 = 2;
  const std::vector<int>    equations{-1, 2, 0, 4};
  const std::vector<double> coefficients{1.0, -1.0, 0.5, 0.25};
  const double              k_ref = 0.5 * law.stiffness;
  UniaxialElement typed(ElementKind::storey, 0, "typed", equations, coefficients,
                        std::make_unique<BoucWen>(law), k_ref);
  UniaxialElement twin(ElementKind::storey, 0, "twin", equations, coefficients,
                       std::make_unique<BoucWen>(law), k_ref);
  const double c = 2 / 1e-3; // gamma / (beta dt)
  Eigen::VectorXd u = Eigen::VectorXd::Zero(5), v = Eigen::VectorXd::Zero(5);
  double smallest_d = 0;
  for (unsigned int step = 1; step <= 40; ++step)
    {
      const double t = 0.05 * step;
      u[0] = 2e-3 * std::sin(6 * t);
      u[2] = -3e-3 * std::sin(5 * t + 0.3);
      u[4] = 1e-3 * std::cos(7 * t);
      v[0] = 12e-3 * std::cos(6 * t);
      v[2] = -15e-3 * std::cos(5 * t + 0.3);
      v[4] = -7e-3 * std::sin(7 * t);
      Eigen::VectorXd local_u(4), local_v(4), f_twin(4), d_twin(1);
      for (unsigned int q = 0; q < 4; ++q)
        {
          local_u[q] = equations[q] >= 0 ? u[equations[q]] : 0.0;
          local_v[q] = equations[q] >= 0 ? v[equations[q]] : 0.0;
        }
      BOOST_REQUIRE(twin.set_trial(local_u, local_v));
      twin.force_correction(f_twin);
      Eigen::MatrixXd d_matrix(1, 1);
      twin.tangent_change(c, d_matrix);
      d_twin[0] = d_matrix(0, 0);
      std::vector<double> f(4, std::nan(""));
      double              d = std::nan("");
      BOOST_REQUIRE(typed.evaluate(equations.data(), u, v, c, f.data(), d));
      BOOST_TEST_INFO("step " << step);
      for (unsigned int q = 0; q < 4; ++q)
        BOOST_TEST(f[q] == f_twin[q]); // exact: the same operations
      BOOST_TEST(d == d_twin[0]);
      smallest_d = std::min(smallest_d, d);
      BOOST_TEST(typed.work_increment() == twin.work_increment());
      typed.commit();
      twin.commit();
    }
  // through yield: the tangent fell below k_ref (elastic: k - k_ref > 0)
  BOOST_TEST(smallest_d < 0);
  BOOST_TEST(typed.stored_energy() == twin.stored_energy());
}

BOOST_AUTO_TEST_SUITE_END()
