// Frame element against closed forms of beam theory (Euler-Bernoulli cubic
// elements are exact for end loads, so the tolerances are round-off level).
#include <poundfe/assembly/linear_system.h>
#include <poundfe/elements/frame_element.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <cmath>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  const Section section{2.1e11, 5.38e-3, 8.356e-5, 42.2}; // a steel HEB 200
  constexpr double tol = 1e-9;                             // relative, round-off

  Vector
  solve_static(const Model &model, const unsigned int node, const Component c, const double load,
               LinearSystem &system)
  {
    system = assemble_mass_and_stiffness(model);
    Vector f = Vector::Zero(system.n_equations());
    f[model.equation(Model::dof(node, c))] = load;
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(system.stiffness);
    BOOST_REQUIRE(ldlt.info() == Eigen::Success);
    return ldlt.solve(f);
  }
} // namespace

BOOST_AUTO_TEST_CASE(cantilever_tip_deflection_is_PL3_over_3EI)
{
  const double L = 4.0, P = 1.0e4, EI = section.youngs_modulus * section.second_moment;
  for (const unsigned int n : {1u, 4u})
    {
      Model model = poundfe_test::straight_member({0, 0}, {0, L}, section, n);
      model.nodes[0].fixed = {{true, true, true}};
      model.number_equations();
      LinearSystem system;
      const Vector u   = solve_static(model, n, Component::ux, P, system);
      const double tip = u[model.equation(Model::dof(n, Component::ux))];
      const double rot = u[model.equation(Model::dof(n, Component::rz))];
      BOOST_TEST(tip == P * L * L * L / (3 * EI), boost::test_tools::tolerance(tol));
      // a positive ux at the top of a vertical cantilever turns it clockwise
      BOOST_TEST(-rot == P * L * L / (2 * EI), boost::test_tools::tolerance(tol));
    }
}

BOOST_AUTO_TEST_CASE(inclined_cantilever_gives_the_same_deflection_normal_to_its_axis)
{
  const double L = 3.0, P = 5.0e3, EI = section.youngs_modulus * section.second_moment;
  const double angle = 0.6;
  const double cx = std::cos(angle), cy = std::sin(angle);
  Model model = poundfe_test::straight_member({1, 2}, {1 + L * cx, 2 + L * cy}, section, 3);
  model.nodes[0].fixed = {{true, true, true}};
  model.number_equations();
  LinearSystem system = assemble_mass_and_stiffness(model);
  Vector       f      = Vector::Zero(system.n_equations());
  // load normal to the member axis
  f[model.equation(Model::dof(3, Component::ux))] = -P * cy;
  f[model.equation(Model::dof(3, Component::uy))] = P * cx;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(system.stiffness);
  const Vector u = ldlt.solve(f);
  const double normal = -u[model.equation(Model::dof(3, Component::ux))] * cy +
                        u[model.equation(Model::dof(3, Component::uy))] * cx;
  BOOST_TEST(normal == P * L * L * L / (3 * EI), boost::test_tools::tolerance(tol));
}

// The displaced shape inside one element (what the VTU draws between nodes):
// an inclined cantilever of ONE element under a tip load normal to it and an
// axial one; the deflection at x is P x^2 (3L - x) / (6EI), its slope
// P x (2L - x) / (2EI), the axial displacement F x / EA (closed forms of
// beam theory; the cubic element is exact for end loads: round-off).
BOOST_AUTO_TEST_CASE(displacement_inside_an_element_is_the_elastic_curve)
{
  const double L = 3.0, P = 5.0e3, F = 2.0e5, angle = 0.6;
  const double EI = section.youngs_modulus * section.second_moment;
  const double EA = section.youngs_modulus * section.area;
  const double cx = std::cos(angle), cy = std::sin(angle);
  Model model = poundfe_test::straight_member({1, 2}, {1 + L * cx, 2 + L * cy}, section, 1);
  model.nodes[0].fixed = {{true, true, true}};
  model.number_equations();
  LinearSystem system = assemble_mass_and_stiffness(model);
  Vector       f      = Vector::Zero(system.n_equations());
  f[model.equation(Model::dof(1, Component::ux))] = -P * cy + F * cx;
  f[model.equation(Model::dof(1, Component::uy))] = P * cx + F * cy;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(system.stiffness);
  const Vector u = ldlt.solve(f);
  Vector6      ue = Vector6::Zero();
  for (unsigned int c = 0; c < 3; ++c)
    ue[3 + c] = u[model.equation(Model::dof(1, static_cast<Component>(c)))];
  const FrameElement element(model.nodes[0].position, model.nodes[1].position, section);
  for (const double xi : {0.0, 0.25, 0.5, 0.8, 1.0})
    {
      const double x        = xi * L;
      const auto   d        = element.displacement_at(ue, xi);
      const double normal   = -d[0] * cy + d[1] * cx;
      const double axial    = d[0] * cx + d[1] * cy;
      const double deflection = P * x * x * (3 * L - x) / (6 * EI);
      BOOST_TEST(normal == deflection, boost::test_tools::tolerance(tol));
      BOOST_TEST(d[2] == P * x * (2 * L - x) / (2 * EI), boost::test_tools::tolerance(tol));
      BOOST_TEST(axial == F * x / EA, boost::test_tools::tolerance(tol));
    }
}

BOOST_AUTO_TEST_CASE(fixed_fixed_column_lateral_stiffness_is_12EI_over_L3)
{
  const double L = 3.5, P = 1.0e4, EI = section.youngs_modulus * section.second_moment;
  Model model = poundfe_test::straight_member({0, 0}, {0, L}, section, 2);
  model.nodes[0].fixed = {{true, true, true}};
  model.nodes[2].fixed = {{false, true, true}}; // sway without top rotation
  model.number_equations();
  LinearSystem system;
  const Vector u = solve_static(model, 2, Component::ux, P, system);
  BOOST_TEST(P / u[model.equation(Model::dof(2, Component::ux))] == 12 * EI / (L * L * L),
             boost::test_tools::tolerance(tol));
}

BOOST_AUTO_TEST_CASE(end_forces_of_a_cantilever_are_statics)
{
  const double L = 4.0, P = 1.0e4;
  const FrameElement element({0, 0}, {0, L}, section);
  Model model = poundfe_test::straight_member({0, 0}, {0, L}, section, 1);
  model.nodes[0].fixed = {{true, true, true}};
  model.number_equations();
  LinearSystem system;
  const Vector u = solve_static(model, 1, Component::ux, P, system);
  Vector6      ue = Vector6::Zero();
  for (unsigned int c = 0; c < 3; ++c)
    ue[3 + c] = u[model.equation(Model::dof(1, Component(c)))];
  const Vector6 f = element.local_end_forces(ue);
  // local y of a vertical member points to -x: shear -P at the free end,
  // and the base moment balances P L.
  BOOST_TEST(f[4] == -P, boost::test_tools::tolerance(tol));
  BOOST_TEST(std::abs(f[2]) == P * L, boost::test_tools::tolerance(tol));
  BOOST_TEST(std::abs(f[0]) < 1e-6 * P);
}

BOOST_AUTO_TEST_CASE(mass_matrices_carry_the_member_mass_in_rigid_translation)
{
  const double L = 5.0;
  const FrameElement element({0, 0}, {L * 0.8, L * 0.6}, section);
  for (const MassMatrixType type : {MassMatrixType::lumped, MassMatrixType::consistent})
    {
      const Matrix6 m = element.mass(type);
      Vector6       rx, ry;
      rx << 1, 0, 0, 1, 0, 0;
      ry << 0, 1, 0, 0, 1, 0;
      BOOST_TEST(rx.dot(m * rx) == section.mass_per_length * L, boost::test_tools::tolerance(tol));
      BOOST_TEST(ry.dot(m * ry) == section.mass_per_length * L, boost::test_tools::tolerance(tol));
      BOOST_TEST((m - m.transpose()).norm() < 1e-12 * m.norm());
    }
}

BOOST_AUTO_TEST_CASE(stiffness_has_three_rigid_body_modes)
{
  const FrameElement element({0.5, 1}, {3, 2}, section);
  const Matrix6      k = element.stiffness();
  Eigen::SelfAdjointEigenSolver<Matrix6> eig(k);
  const auto values = eig.eigenvalues();
  for (int i = 0; i < 3; ++i)
    BOOST_TEST(std::abs(values[i]) < 1e-9 * values[5]);
  BOOST_TEST(values[3] > 1e-6 * values[5]);
}
