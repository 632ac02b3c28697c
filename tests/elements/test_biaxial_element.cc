// The two-deformation element around the bidirectional Bouc-Wen law
// (elements/biaxial_element.h) as a 3D hinge (B = I on the rotations about
// the two bending axes) and as a storey's pair of perpendicular planes:
// a moment path about one axis against the independent uniaxial hinge, a
// diagonal path against the closed forms of the circular (interacting) and
// square (independent) yield surfaces, the element's tangent against
// central differences of its force, and the work of a closed path.
#include <poundfe/elements/biaxial_element.h>
#include <poundfe/elements/uniaxial_element.h>
#include <poundfe/laws/bouc_wen.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <memory>

using namespace poundfe;

namespace
{
  /// A hinge about one axis: k = 6 EI/L x 10 of a 0.4 x 0.6 m column and a
  /// yield moment of 300 kN m (the yield rotation M_y / k).
  BoucWenParameters
  hinge_about(const double stiffness)
  {
    BoucWenParameters p;
    p.stiffness         = stiffness;
    p.yield_deformation = 3e5 / stiffness;
    p.alpha             = 0.05;
    return p;
  }

  const double k_y = 2.6e9, k_z = 1.15e9; // about the strong and the weak axis

  BiaxialElement
  biaxial_hinge()
  {
    return BiaxialElement(ElementKind::hinge, 0, "h", {0, 1}, {{{1.0, 0.0}, {0.0, 1.0}}},
                          BidirectionalBoucWen(hinge_about(k_y), hinge_about(k_z)));
  }

  /// Total force B F of an element at u: the correction plus B K_ref B^T u.
  Eigen::VectorXd
  total_force(const BiaxialElement &element, const Eigen::VectorXd &u)
  {
    Eigen::VectorXd f(element.n_dofs());
    element.force_correction(f);
    const Eigen::MatrixXd b = element.tangent_basis();
    const Eigen::Matrix2d k_ref =
      Eigen::Vector2d(element.bidirectional_law().initial_stiffness(0),
                      element.bidirectional_law().initial_stiffness(1))
        .asDiagonal();
    return f + b * k_ref * b.transpose() * u;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(biaxial_element)

// A cyclic rotation about one axis: the moment equals the independent
// uniaxial hinge's to 1e-12 of the yield moment (same n, A, beta, gamma).
BOOST_AUTO_TEST_CASE(one_axis_equals_the_independent_hinge)
{
  for (unsigned int axis = 0; axis < 2; ++axis)
    {
      BiaxialElement  biaxial = biaxial_hinge();
      UniaxialElement uniaxial(ElementKind::hinge, 0, "h", std::array<int, 2>{{0, -1}},
                               std::make_unique<BoucWen>(hinge_about(axis == 0 ? k_y : k_z)),
                               axis == 0 ? k_y : k_z);
      const double    theta_y = 3e5 / (axis == 0 ? k_y : k_z);
      double          worst   = 0;
      for (unsigned int i = 1; i <= 400; ++i)
        {
          const double    s = i / 400.0, theta = 5 * theta_y * s * std::sin(6 * M_PI * s);
          Eigen::VectorXd u = Eigen::VectorXd::Zero(2), v = Eigen::VectorXd::Zero(2);
          u[axis]           = theta;
          BOOST_REQUIRE(biaxial.set_trial(u, v));
          BOOST_REQUIRE(uniaxial.set_trial(Eigen::VectorXd::Constant(2, theta), v));
          worst = std::max(worst, std::abs(biaxial.force_component(axis) - uniaxial.force()) / 3e5);
          BOOST_CHECK_EQUAL(biaxial.force_component(1 - axis), 0.0);
          biaxial.commit();
          uniaxial.commit();
        }
      BOOST_TEST_MESSAGE("axis " << axis << ": worst |M - M_uniaxial| / M_y " << worst);
      BOOST_CHECK_LE(worst, 1e-12);
    }
}

// A diagonal path theta = s (theta_y1, theta_y2): the interacting hinge's
// hysteretic moments follow z_i = tanh(sqrt(2) s) / sqrt(2) (the uniaxial
// backbone along the direction, A = beta + gamma = 1, n = 2), the
// independent hinges' z_i = tanh(s): at every s the interacting hinge has
// yielded more (smaller hysteretic moment), its resultant stays inside the
// circle (M_h1 / M_hy1)^2 + (M_h2 / M_hy2)^2 <= 1 while the independent
// ones tend to the square's corner (|z| -> sqrt 2). Tolerance 1e-5: the
// trapezoidal rule's O(h^2), h = theta_y / 100.
BOOST_AUTO_TEST_CASE(diagonal_path_yields_on_the_circle)
{
  BiaxialElement biaxial = biaxial_hinge();
  const double   ty = 3e5 / k_y, tz = 3e5 / k_z, alpha = 0.05;
  double         worst = 0, largest = 0;
  for (unsigned int i = 1; i <= 400; ++i)
    {
      const double    s = i / 100.0;
      Eigen::VectorXd u(2), v = Eigen::VectorXd::Zero(2);
      u << s * ty, s * tz;
      BOOST_REQUIRE(biaxial.set_trial(u, v));
      biaxial.commit();
      // z_i from the moments: M_i = alpha k_i theta_i + (1 - alpha) M_y z_i
      const double z1 = (biaxial.force_component(0) - alpha * k_y * u[0]) / ((1 - alpha) * 3e5);
      const double z2 = (biaxial.force_component(1) - alpha * k_z * u[1]) / ((1 - alpha) * 3e5);
      const double closed = std::tanh(std::sqrt(2.0) * s) / std::sqrt(2.0);
      worst   = std::max({worst, std::abs(z1 - closed), std::abs(z2 - closed)});
      largest = std::max(largest, std::hypot(z1, z2));
      BOOST_CHECK_LT(z1, std::tanh(s)); // below the independent hinge's
    }
  BOOST_TEST_MESSAGE("diagonal path: worst |z_i - closed form| " << worst << ", max |z| "
                                                                  << largest);
  BOOST_CHECK_LE(worst, 1e-5);
  BOOST_CHECK_LE(largest, 1 + 1e-12);
  BOOST_CHECK_GT(largest, 0.999); // it does reach the surface
}

// The element's tangent B (D_e + K_ref) B^T against central differences of
// its force B F(B^T u), for a storey's pair of planes (B the two planes'
// rows a(C) over (q_bottom, q_top), the bottom the ground), after a
// biaxial history; 1e-6 relative (differences with h = 1e-7 of the drift).
BOOST_AUTO_TEST_CASE(tangent_matches_finite_differences)
{
  BoucWenParameters plane_x = hinge_about(1), plane_y = hinge_about(1);
  plane_x.stiffness = 1.5e7, plane_x.yield_deformation = 0.015;
  plane_y.stiffness = 1.2e7, plane_y.yield_deformation = 0.02;
  // planes along x through (0, -4) and along y through (-5, 0), mass centre (1, 0.5)
  const std::vector<double> a_x{-1, 0, -4.5, 1, 0, 4.5}, a_y{0, -1, -6, 0, 1, 6};
  BiaxialElement element(ElementKind::storey, 0, "p", {-1, -1, -1, 0, 1, 2}, {{a_x, a_y}},
                         BidirectionalBoucWen(plane_x, plane_y));
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
  for (unsigned int i = 1; i <= 60; ++i)
    {
      const double s = i / 60.0;
      u.tail<3>() << 0.04 * s * std::sin(9 * s), 0.03 * s * std::cos(7 * s), 0.004 * s;
      BOOST_REQUIRE(element.set_trial(u, v));
      element.commit();
    }
  u.tail<3>() += Eigen::Vector3d(0.003, -0.004, 0.0005);
  BOOST_REQUIRE(element.set_trial(u, v));
  Eigen::MatrixXd d(2, 2);
  element.tangent_change(0, d);
  const Eigen::MatrixXd b = element.tangent_basis();
  const Eigen::Matrix2d k_ref = Eigen::Vector2d(1.5e7, 1.2e7).asDiagonal();
  const Eigen::MatrixXd k     = b * (d + k_ref) * b.transpose();
  Eigen::MatrixXd       fd(6, 6);
  fd.setZero();
  for (unsigned int j = 3; j < 6; ++j)
    {
      const double    h = 1e-7;
      Eigen::VectorXd plus = u, minus = u;
      plus[j] += h;
      minus[j] -= h;
      BOOST_REQUIRE(element.set_trial(plus, v));
      const Eigen::VectorXd f_plus = total_force(element, plus);
      BOOST_REQUIRE(element.set_trial(minus, v));
      fd.col(j) = (f_plus - total_force(element, minus)) / (2 * h);
    }
  const double error = (k.rightCols<3>() - fd.rightCols<3>()).norm() / k.norm();
  BOOST_TEST_MESSAGE("plane pair: tangent relative error " << error);
  BOOST_CHECK_LE(error, 1e-6);
  BOOST_CHECK_EQUAL(k.leftCols<3>().norm(), 0.0); // the ground has no column
}

BOOST_AUTO_TEST_SUITE_END()
