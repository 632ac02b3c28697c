// P-Delta (the geometric stiffness of the gravity loads, assembly/linear_system.h)
// against closed forms:
//   - the critical load of a cantilever column from (K_E + lambda K_G) phi = 0
//     with K_G of a unit compression: Euler's pi^2 EI / (4 L^2). The
//     consistent K_G converges as h^4 (cubic elements); measured errors
//     7.5e-3, 5.1e-4, 3.3e-5, 2.1e-6 for 1, 2, 4, 8 elements, so 4 elements
//     are held to 5e-5 and each halving must gain more than 12x;
//   - the lateral tip drift of that cantilever under a tip force F with the
//     tip weight P = mg, P / P_cr = 0.25, 0.5, 0.75: the exact beam-column
//     solution delta = F (tan kL - kL) / (P k), k = sqrt(P / EI) (Timoshenko
//     & Gere, Theory of Elastic Stability, 2nd ed., ch. 1), to 1e-5 with 8
//     elements (measured 1.7e-7, 1.0e-6, 4.6e-6: the discretisation error
//     grows towards buckling); the amplification 1/(1 - P/P_cr) approximates
//     the exact 3 (tan u - u) / u^3, u = kL (1.3289, 1.9863, 3.9578), from
//     above by 0.34 %, 0.69 %, 1.07 %: held to 1.5 %;
//   - the gravity analysis: every element of that column carries N = -P, and
//     the base columns of a frame carry its whole weight (statics, 1e-10);
//   - a three-storey shear building: K - K_E has -P_i/h_i per storey
//     (P_i = g times the floor masses above, by hand, 1e-12), and a one-storey
//     one has omega^2 = (k - m g / h) / m exactly (1e-12);
//   - a model whose weight exceeds its buckling load is refused.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/model/model_builder.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <cmath>

#include <boost/test/unit_test.hpp>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  const Section section{2.1e11, 5.38e-3, 8.356e-5, 0.0}; // a steel HEB 200, massless
  const double  L       = 6.0;
  const double  EI      = section.youngs_modulus * section.second_moment;
  const double  p_euler = M_PI * M_PI * EI / (4 * L * L);

  /// A vertical cantilever of n elements, fixed at the base.
  Model
  cantilever(const unsigned int n)
  {
    Model model = poundfe_test::straight_member({0, 0}, {0, L}, section, n);
    model.nodes[0].fixed = {{true, true, true}};
    model.number_equations();
    return model;
  }

  /// The smallest lambda of K_E phi = lambda (-K_G) phi, K_G under N = -1.
  double
  critical_load(const unsigned int n)
  {
    const Model        model = cantilever(n);
    const SparseMatrix k_e   = assemble_mass_and_stiffness(model).stiffness;
    const SparseMatrix k_g =
      geometric_stiffness(model, std::vector<double>(model.members.size(), -1.0), {});
    // (-K_G) phi = mu K_E phi with K_E positive definite: mu = 1 / lambda.
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      Eigen::MatrixXd(-k_g), Eigen::MatrixXd(k_e), Eigen::EigenvaluesOnly | Eigen::Ax_lBx);
    return 1 / solver.eigenvalues().maxCoeff();
  }
} // namespace

BOOST_AUTO_TEST_CASE(critical_load_of_a_cantilever_column_is_eulers)
{
  double previous = 0;
  for (const unsigned int n : {1u, 2u, 4u, 8u})
    {
      const double error = critical_load(n) / p_euler - 1;
      BOOST_TEST_MESSAGE(n << " elements: P_cr / (pi^2 EI / 4L^2) - 1 = " << error);
      BOOST_TEST(error > 0); // a stiffer discrete column buckles later
      if (previous > 0)
        BOOST_TEST(previous / error > 12); // h^4: 16 per halving
      if (n == 4)
        BOOST_TEST(error < 5e-5);
      previous = error;
    }
}

BOOST_AUTO_TEST_CASE(tip_drift_is_amplified_as_the_exact_beam_column)
{
  const double g = 9.81, force = 1e3;
  for (const double ratio : {0.25, 0.5, 0.75})
    {
      const double P     = ratio * p_euler;
      Model        model = cantilever(8);
      const unsigned int tip = 8;
      model.masses.push_back({tip, P / g});
      model.geometric_nonlinearity = GeometricNonlinearity::p_delta;
      model.gravity                = g;
      const LinearSystem system    = assemble_mass_and_stiffness(model);

      // gravity analysis: every element carries the tip weight
      const LinearSystem elastic = [&] {
        Model m                  = model;
        m.geometric_nonlinearity = GeometricNonlinearity::none;
        return assemble_mass_and_stiffness(m);
      }();
      for (const double n :
           member_axial_forces(model, elastic.stiffness, gravity_loads(model)))
        BOOST_TEST(n == -P, boost::test_tools::tolerance(1e-10));

      Vector f = Vector::Zero(system.n_equations());
      const int ux = model.equation(Model::dof(tip, Component::ux));
      f[ux]        = force;
      const Eigen::SimplicialLDLT<SparseMatrix> ldlt(system.stiffness);
      const double drift = ldlt.solve(f)[ux];

      const double k          = std::sqrt(P / EI), u = k * L;
      const double exact      = force * (std::tan(u) - u) / (P * k);
      const double first      = force * L * L * L / (3 * EI);
      const double simplified = first / (1 - ratio);
      BOOST_TEST_MESSAGE("P/P_cr = " << ratio << ": drift / exact - 1 = " << drift / exact - 1
                                     << "; amplification exact " << exact / first
                                     << ", 1/(1 - P/P_cr) " << 1 / (1 - ratio) << " ("
                                     << simplified / exact - 1 << ")");
      BOOST_TEST(drift == exact, boost::test_tools::tolerance(1e-5));
      BOOST_TEST(simplified / exact - 1 > 0);
      BOOST_TEST(simplified / exact - 1 < 0.015);
    }
}

BOOST_AUTO_TEST_CASE(base_columns_of_a_frame_carry_its_weight)
{
  InputParameters     p = poundfe_test::shear_building_input(4, 1000, 5e6, 0);
  BuildingParameters &b = p.model.buildings[0];
  b                     = BuildingParameters();
  b.type                = BuildingType::frame;
  b.n_storeys           = 4;
  b.n_bays              = 3;
  b.bay_widths          = {5.0, 7.0, 6.0};
  b.floor_masses        = {40000, 40000, 30000, 20000};
  b.storey_heights         = {3.0};
  b.column_mass_per_length = {400};
  b.beam_mass_per_length   = {300};
  b.elements_per_member    = 2;
  b.damping_type           = RayleighDamping::Kind::none;
  p.model.mass_matrix      = MassMatrixType::consistent;
  b.finalize(p, 1);
  const Model        model  = build_model(p.model, p.contact, p, p.springs, p.friction);
  const LinearSystem system = assemble_mass_and_stiffness(model);
  const std::vector<double> n =
    member_axial_forces(model, system.stiffness, gravity_loads(model));
  // The base columns carry the whole weight but the half of their own lowest
  // elements that the consistent mass puts on the supports.
  double base = 0, on_supports = 0;
  for (unsigned int m = 0; m < model.members.size(); ++m)
    if (model.nodes[model.members[m].nodes[0]].fixed[1])
      {
        base += n[m];
        on_supports += 0.5 * 400 * 3.0 / 2; // rho L_e / 2, L_e = h / 2
      }
  const double weight = 9.81 * (model.total_mass(0) - on_supports);
  BOOST_TEST(-base == weight, boost::test_tools::tolerance(1e-10));
}

BOOST_AUTO_TEST_CASE(shear_building_storeys_lose_p_over_h)
{
  InputParameters p = poundfe_test::shear_building_input(3, 1000, 5e6, 0);
  BuildingParameters &b = p.model.buildings[0];
  b.floor_masses        = {3e5, 2e5, 1e5};
  b.storey_heights      = {4.0, 3.0, 3.5};
  b.storey_stiffnesses  = {8e7, 6e7, 4e7};
  Model elastic_model = build_model(p.model, p.contact, p, p.springs, p.friction);
  p.model.geometric_nonlinearity = GeometricNonlinearity::p_delta;
  p.model.gravity                = 9.81;
  const Model  model   = build_model(p.model, p.contact, p, p.springs, p.friction);
  const Eigen::MatrixXd k_g =
    Eigen::MatrixXd(assemble_mass_and_stiffness(model).stiffness) -
    Eigen::MatrixXd(assemble_mass_and_stiffness(elastic_model).stiffness);
  // storey i between floors i-1 and i: -P_i/h_i [1 -1; -1 1]
  const double    g = 9.81;
  const double    k1 = -g * 6e5 / 4.0, k2 = -g * 3e5 / 3.0, k3 = -g * 1e5 / 3.5;
  Eigen::Matrix3d hand;
  hand << k1 + k2, -k2, 0, -k2, k2 + k3, -k3, 0, -k3, k3;
  BOOST_TEST((k_g - hand).norm() / hand.norm() < 1e-12);
}

BOOST_AUTO_TEST_CASE(one_storey_frequency_with_p_delta)
{
  const double    m = 2e5, k = 4e7, h = 3.0, g = 9.81;
  InputParameters p = poundfe_test::shear_building_input(1, m, k, 0);
  p.model.geometric_nonlinearity = GeometricNonlinearity::p_delta;
  const Analysis a               = prepare_analysis(p);
  BOOST_TEST(a.modes.omega[0] == std::sqrt((k - m * g / h) / m),
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(weight_above_the_buckling_load_is_refused)
{
  // one storey: buckles where m g / h exceeds k
  InputParameters p = poundfe_test::shear_building_input(1, 2e5, 4e7, 0);
  p.model.geometric_nonlinearity = GeometricNonlinearity::p_delta;
  p.model.gravity                = 1.01 * 4e7 * 3.0 / 2e5;
  BOOST_CHECK_THROW(prepare_analysis(p), InputError);
  p.model.gravity = 0.99 * 4e7 * 3.0 / 2e5;
  BOOST_CHECK_NO_THROW(prepare_analysis(p));
}
