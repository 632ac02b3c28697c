// The torsionally coupled shear building (model/torsional_shear_building.h)
// against the closed-form frequencies of a one-storey unsymmetric-plan system
// (Chopra, Dynamics of Structures, ch. 9), an exactly decoupled symmetric
// plan, and the planar shear building of the model builder. Frequencies come
// from small dense eigenproblems: round-off level, tolerances 1e-12.
#include <poundfe/assembly/linear_system.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/model/model_builder.h>
#include <poundfe/model/torsional_shear_building.h>

#include <algorithm>
#include <cmath>

#include "test_utilities.h"

using namespace poundfe;
using poundfe_test::generalized_eigenvalues;

namespace
{
  // A rectangular slab b x d with its mass spread evenly.
  constexpr double plan_b = 30.0, plan_d = 20.0;

  double
  slab_polar_moment(const double mass)
  {
    return mass * (plan_b * plan_b + plan_d * plan_d) / 12;
  }

  ResistingPlane
  plane_along_x(const double y, const double k)
  {
    return {{1, 0}, {0, y}, k};
  }

  ResistingPlane
  plane_along_y(const double x, const double k)
  {
    return {{0, 1}, {x, 0}, k};
  }

  /// One storey, mass centre C = (10, 5): frames along y at x = C_x ∓ b/2 of
  /// stiffness k and 2k (stiffness centre b/6 to the right of C), frames
  /// along x at y = C_y ± d/2 of stiffness k each.
  TorsionalShearBuilding
  one_storey_unsymmetric(const double m, const double k)
  {
    TorsionalShearBuilding building;
    TorsionalFloor         floor;
    floor.mass         = m;
    floor.polar_moment = slab_polar_moment(m);
    floor.mass_centre  = {10, 5};
    floor.planes       = {plane_along_y(10 - plan_b / 2, k), plane_along_y(10 + plan_b / 2, 2 * k),
                          plane_along_x(5 - plan_d / 2, k), plane_along_x(5 + plan_d / 2, k)};
    building.floors    = {floor};
    return building;
  }

  Eigen::VectorXd
  squared_frequencies(const TorsionalShearBuilding &building)
  {
    return generalized_eigenvalues(stiffness_matrix(building), mass_matrix(building));
  }

  /// ω² of the coupled (uy, θ) pair of a one-storey system with stiffness
  /// centre at e along x from the mass centre (Chopra ch. 9):
  /// ω² = (ω_y² + ω_θ²)/2 ∓ sqrt(((ω_y² - ω_θ²)/2)² + ω_y⁴ e²/r²),
  /// ω_y² = K_y/m, ω_θ² = K_θ/I (K_θ about the mass centre), r² = I/m.
  std::array<double, 2>
  coupled_squared_frequencies(const double k_y, const double k_theta, const double e,
                              const double m, const double polar_moment)
  {
    const double wy = k_y / m, wt = k_theta / polar_moment, r2 = polar_moment / m;
    const double root = std::sqrt(0.25 * (wy - wt) * (wy - wt) + wy * wy * e * e / r2);
    return {{0.5 * (wy + wt) - root, 0.5 * (wy + wt) + root}};
  }
} // namespace

BOOST_AUTO_TEST_CASE(one_storey_unsymmetric_plan_frequencies_are_the_closed_form)
{
  const double                 m = 2.0e5, k = 4.0e7;
  const TorsionalShearBuilding building = one_storey_unsymmetric(m, k);
  check_building(building);
  const double b2 = plan_b / 2, d2 = plan_d / 2;
  const double k_x = 2 * k, k_y = 3 * k, e = plan_b / 6;
  const double k_theta = k * b2 * b2 + 2 * k * b2 * b2 + 2 * k * d2 * d2; // about C
  const double polar   = slab_polar_moment(m);
  const auto   coupled = coupled_squared_frequencies(k_y, k_theta, e, m, polar);
  std::array<double, 3> expected{{k_x / m, coupled[0], coupled[1]}};
  std::sort(expected.begin(), expected.end());
  const Eigen::VectorXd w2 = squared_frequencies(building);
  for (unsigned int i = 0; i < 3; ++i)
    BOOST_TEST(w2[i] == expected[i], boost::test_tools::tolerance(1e-12));
  BOOST_TEST_MESSAGE("one storey: f = " << w2.cwiseSqrt().transpose() / (2 * M_PI) << " Hz");

  // stiffness centre, torsional radii, EC8: e_0x = b/6 = 5 m exceeds
  // 0.30 r_x = 0.30 sqrt(800k/3k) = 4.90 m, so the storey is not regular
  const StoreyTorsion t = storey_torsion(building, 0);
  BOOST_TEST(t.stiffness_centre.x == 10 + e, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(std::abs(t.stiffness_centre.y - 5) < 1e-14);
  BOOST_TEST(t.eccentricity.x == e, boost::test_tools::tolerance(1e-14));
  const double k_theta_r = k_theta - e * e * k_y;
  BOOST_TEST(t.torsional_stiffness == k_theta_r, boost::test_tools::tolerance(1e-14));
  const auto tight = boost::test_tools::tolerance(1e-14);
  BOOST_TEST(t.torsional_radius_x == std::sqrt(k_theta_r / k_y), tight);
  BOOST_TEST(t.torsional_radius_y == std::sqrt(k_theta_r / k_x), tight);
  BOOST_TEST(t.radius_of_gyration == std::sqrt(polar / m), boost::test_tools::tolerance(1e-14));
  BOOST_TEST(!t.regular_in_plan());
}

// A plan symmetric about its mass centre: the stiffness has exactly no
// translation-rotation coupling, the modes are pure ux, uy, θ with
// ω² = K_x/m, K_y/m, K_θ/I; EC8's check passes with frames at the edges and
// fails with a core (r < l_s: torsionally flexible).
BOOST_AUTO_TEST_CASE(symmetric_plan_decouples_exactly)
{
  const double m = 2.0e5, k = 4.0e7, b2 = plan_b / 2, d2 = plan_d / 2;
  for (const double scale : {1.0, 0.2})
    {
      TorsionalShearBuilding building = one_storey_unsymmetric(m, k);
      TorsionalFloor        &floor    = building.floors[0];
      floor.planes = {plane_along_y(10 - scale * b2, k), plane_along_y(10 + scale * b2, k),
                      plane_along_x(5 - scale * d2, k), plane_along_x(5 + scale * d2, k)};
      const Eigen::MatrixXd stiffness = stiffness_matrix(building);
      BOOST_TEST(stiffness(0, 1) == 0.0);
      BOOST_TEST(stiffness(0, 2) == 0.0);
      BOOST_TEST(stiffness(1, 2) == 0.0);
      const double k_theta = 2 * k * scale * scale * (b2 * b2 + d2 * d2);
      std::array<double, 3> expected{{2 * k / m, 2 * k / m, k_theta / floor.polar_moment}};
      std::sort(expected.begin(), expected.end());
      const Eigen::VectorXd w2 = generalized_eigenvalues(stiffness, mass_matrix(building));
      for (unsigned int i = 0; i < 3; ++i)
        BOOST_TEST(w2[i] == expected[i], boost::test_tools::tolerance(1e-12));
      const StoreyTorsion t = storey_torsion(building, 0);
      BOOST_TEST(t.eccentricity.x == 0.0);
      BOOST_TEST(t.eccentricity.y == 0.0);
      BOOST_TEST(t.regular_in_plan() == (scale == 1.0));
    }
}

// Accidental eccentricity: 5 % of the plan dimension normal to the action;
// moving the mass centre of the symmetric storey by 0.05 b along x gives
// the unsymmetric closed form with e = -0.05 b (stiffness centre left of
// the moved mass centre).
BOOST_AUTO_TEST_CASE(accidental_eccentricity_moves_the_mass_centre)
{
  const Point2 plan{plan_b, plan_d};
  const Point2 along_x = accidental_eccentricity(plan, PlanDirection::x, -1);
  const Point2 along_y = accidental_eccentricity(plan, PlanDirection::y, +1);
  BOOST_TEST(along_x.x == 0.0);
  BOOST_TEST(along_x.y == -0.05 * plan_d, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(along_y.x == 0.05 * plan_b, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(along_y.y == 0.0);

  const double m = 2.0e5, k = 4.0e7, b2 = plan_b / 2, d2 = plan_d / 2;
  TorsionalShearBuilding symmetric = one_storey_unsymmetric(m, k);
  symmetric.floors[0].planes = {plane_along_y(10 - b2, k), plane_along_y(10 + b2, k),
                                plane_along_x(5 - d2, k), plane_along_x(5 + d2, k)};
  const TorsionalShearBuilding shifted =
    with_accidental_eccentricity(symmetric, {plan}, PlanDirection::y, +1);
  const double e = 0.05 * plan_b;
  BOOST_TEST(shifted.floors[0].mass_centre.x == 10 + e, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(storey_torsion(shifted, 0).eccentricity.x == -e, boost::test_tools::tolerance(1e-12));
  // K_θ about the moved mass centre: frames at b/2 ∓ e and d/2 from it
  const double k_theta = k * ((b2 + e) * (b2 + e) + (b2 - e) * (b2 - e)) + 2 * k * d2 * d2;
  const auto coupled =
    coupled_squared_frequencies(2 * k, k_theta, -e, m, symmetric.floors[0].polar_moment);
  std::array<double, 3> expected{{2 * k / m, coupled[0], coupled[1]}};
  std::sort(expected.begin(), expected.end());
  const Eigen::VectorXd w2 = squared_frequencies(shifted);
  for (unsigned int i = 0; i < 3; ++i)
    BOOST_TEST(w2[i] == expected[i], boost::test_tools::tolerance(1e-12));
}

namespace
{
  /// ω² of the planar shear building that the model builder makes from
  /// floor masses and storey stiffnesses (theory §1.4), through the
  /// program's assembly.
  Eigen::VectorXd
  planar_squared_frequencies(const std::vector<double> &masses,
                             const std::vector<double> &stiffnesses)
  {
    InputParameters p = poundfe_test::shear_building_input(masses.size(), 1, 1, 0);
    p.model.buildings[0].floor_masses       = masses;
    p.model.buildings[0].storey_stiffnesses = stiffnesses;
    p.model.buildings[0].storey_heights     = std::vector<double>(masses.size(), 3.0);
    const Model        model  = build_model(p.model, p.contact, p);
    const LinearSystem system = assemble_mass_and_stiffness(model);
    return generalized_eigenvalues(Eigen::MatrixXd(system.stiffness), Eigen::MatrixXd(system.mass));
  }
} // namespace

// Four storeys of unequal masses and stiffnesses, every storey's frames in
// symmetric pairs about the mass centres (which lie on one vertical at
// (3, -2)): the 12 frequencies are those of three planar shear buildings
// from the model builder: (m_i, k_x,i), (m_i, k_y,i) and (I_i, K_θ,i),
// K_θ,i = k_x,i d²/4 + k_y,i b²/4.
BOOST_AUTO_TEST_CASE(building_with_planes_about_the_mass_centres_is_three_planar_ones)
{
  const std::vector<double> masses{3.0e5, 2.8e5, 2.6e5, 2.0e5};
  const std::vector<double> k_x{4.0e8, 3.5e8, 3.0e8, 2.0e8}, k_y{5.0e8, 4.5e8, 3.2e8, 2.6e8};
  const Point2              c{3, -2};
  TorsionalShearBuilding    building;
  std::vector<double>       polar, k_theta;
  for (unsigned int i = 0; i < masses.size(); ++i)
    {
      TorsionalFloor floor;
      floor.mass         = masses[i];
      floor.polar_moment = slab_polar_moment(masses[i]);
      floor.mass_centre  = c;
      floor.planes       = {plane_along_x(c.y - plan_d / 2, k_x[i] / 2),
                            plane_along_x(c.y + plan_d / 2, k_x[i] / 2),
                            plane_along_y(c.x - plan_b / 2, k_y[i] / 2),
                            plane_along_y(c.x + plan_b / 2, k_y[i] / 2)};
      building.floors.push_back(floor);
      polar.push_back(floor.polar_moment);
      k_theta.push_back(k_x[i] * plan_d * plan_d / 4 + k_y[i] * plan_b * plan_b / 4);
    }
  check_building(building);
  std::vector<double> expected;
  for (const Eigen::VectorXd &w2 : {planar_squared_frequencies(masses, k_x),
                                    planar_squared_frequencies(masses, k_y),
                                    planar_squared_frequencies(polar, k_theta)})
    expected.insert(expected.end(), w2.data(), w2.data() + w2.size());
  std::sort(expected.begin(), expected.end());
  const Eigen::VectorXd w2 = squared_frequencies(building);
  BOOST_REQUIRE(w2.size() == 12);
  for (unsigned int i = 0; i < 12; ++i)
    BOOST_TEST(w2[i] == expected[i], boost::test_tools::tolerance(1e-12));
}

// Storeys that cannot hold a floor, and floors without mass, are refused.
BOOST_AUTO_TEST_CASE(singular_storeys_are_bad_input)
{
  const auto refused = [](const TorsionalShearBuilding &building, const std::string &words) {
    const std::string message =
      poundfe_test::input_error_of([&] { check_building(building); });
    BOOST_TEST_MESSAGE(message);
    BOOST_TEST(message.find(words) != std::string::npos, "refused with '" << words << "'");
  };
  const TorsionalShearBuilding good = one_storey_unsymmetric(2e5, 4e7);
  TorsionalShearBuilding       b    = good;
  b.floors[0].planes = {plane_along_y(0, 1e7), plane_along_y(5, 1e7)};
  refused(b, "parallel");
  b.floors[0].planes = {plane_along_y(10, 1e7), plane_along_x(5, 1e7),
                        {{1, 1}, {10, 5}, 1e7}}; // all through (10, 5)
  refused(b, "no torsional stiffness");
  b                 = good;
  b.floors[0].mass  = 0;
  refused(b, "positive");
  b                                   = good;
  b.floors[0].planes[1].direction     = {0, 0};
  refused(b, "zero vector");
  BOOST_CHECK_THROW(with_accidental_eccentricity(good, {{1, 1}, {2, 2}}, PlanDirection::x, 1),
                    InputError);
}
