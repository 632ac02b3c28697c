// Rayleigh damping and the direct solver backends.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/base/exceptions.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <cmath>

#include "test_utilities.h"

using namespace poundfe;

using poundfe_test::MpiFixture;
BOOST_GLOBAL_FIXTURE(MpiFixture);

BOOST_AUTO_TEST_CASE(rayleigh_coefficients_give_the_ratio_at_both_frequencies)
{
  const double zeta = 0.05, wi = 6.0, wj = 40.0;
  const auto   c    = rayleigh_coefficients(zeta, wi, wj);
  // zeta(w) = a0 / (2 w) + a1 w / 2 (Chopra eq. 11.4.8)
  for (const double w : {wi, wj})
    BOOST_TEST(c[0] / (2 * w) + c[1] * w / 2 == zeta, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(assembled_damping_is_modal_at_the_target_modes)
{
  // Second method: phi_n^T C phi_n = 2 zeta_n omega_n for mass-normalised modes.
  InputParameters p = poundfe_test::shear_building_input(3, 1000, 5e6, 0.04);
  p.model.buildings[0].damping_modes = {1, 3};
  const Analysis a = prepare_analysis(p);
  for (const unsigned int n : {0u, 2u})
    {
      const Vector phi = a.modes.shapes.col(n);
      const double c   = phi.dot(a.system.damping * phi);
      BOOST_TEST(c / (2 * a.modes.omega[n]) == 0.04, boost::test_tools::tolerance(1e-10));
    }
  // the middle mode gets less (Rayleigh's curve dips between the targets)
  const Vector phi = a.modes.shapes.col(1);
  BOOST_TEST(phi.dot(a.system.damping * phi) / (2 * a.modes.omega[1]) < 0.04);
}

BOOST_AUTO_TEST_CASE(all_solver_backends_agree)
{
  const InputParameters input = read_parameters("input/two-buildings.prm");
  const Analysis        a     = prepare_analysis(input);
  const double          dt    = 1e-3;
  SparseMatrix          k_eff = a.system.stiffness + (2 / dt) * a.system.damping +
                       (4 / (dt * dt)) * a.system.mass;
  k_eff.makeCompressed();
  Vector b(k_eff.rows());
  for (int i = 0; i < b.size(); ++i)
    b[i] = std::sin(1.0 + i); // a dense, sign-changing right-hand side
  Vector reference;
  for (const std::string &name : linear_solver_names())
    {
      auto solver = create_linear_solver(name);
      solver->analyze_and_factorize(k_eff);
      Vector x;
      solver->solve(b, x);
      BOOST_TEST_MESSAGE(name << ": residual " << (k_eff * x - b).norm() / b.norm());
      BOOST_TEST((k_eff * x - b).norm() <= 1e-12 * b.norm());
      if (reference.size() == 0)
        reference = x;
      // the condition number of K_eff is ~1e6 here: agreement to 1e-9
      BOOST_TEST((x - reference).norm() <= 1e-9 * reference.norm());
      // refactorising a matrix of the same pattern reuses the analysis
      solver->factorize(2.0 * k_eff);
      Vector half;
      solver->solve(b, half);
      BOOST_TEST((2.0 * half - x).norm() <= 1e-9 * x.norm());
    }
}

// The eigen-ldlt backend solves x = P^-1 L^-T D^-1 L^-1 P b through its own
// buffer, permuting by index: the numbers of Eigen's own solve to the bit,
// on a model whose fill-reducing ordering is not the identity.
BOOST_AUTO_TEST_CASE(eigen_ldlt_solve_is_eigens_own_to_the_bit)
{
  const InputParameters input = read_parameters("input/two-buildings.prm");
  const Analysis        a     = prepare_analysis(input);
  const double          dt    = 1e-3;
  SparseMatrix          k_eff = a.system.stiffness + (2 / dt) * a.system.damping +
                       (4 / (dt * dt)) * a.system.mass;
  k_eff.makeCompressed();
  Vector b(k_eff.rows());
  for (int i = 0; i < b.size(); ++i)
    b[i] = std::sin(1.0 + i);
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> eigen(k_eff);
  const Eigen::VectorXi &p = eigen.permutationP().indices();
  BOOST_TEST(!(p.array() == Eigen::VectorXi::LinSpaced(p.size(), 0, p.size() - 1).array()).all());
  const Vector reference = eigen.solve(b);
  auto         solver    = create_linear_solver("eigen-ldlt");
  solver->analyze_and_factorize(k_eff);
  Vector x;
  for (int round = 0; round < 2; ++round) // the second with the buffer kept
    {
      solver->solve(b, x);
      BOOST_TEST((x.array() == reference.array()).all());
    }
}

// MUMPS's global status: a singular effective matrix (a mechanism) is a
// NumericalError, as with the other backends (theory §3.5a).
BOOST_AUTO_TEST_CASE(petsc_mumps_reports_a_singular_matrix)
{
  SparseMatrix singular(3, 3);
  singular.insert(0, 0) = 1;
  singular.insert(0, 1) = 1;
  singular.insert(1, 0) = 1;
  singular.insert(1, 1) = 1; // rows 0 and 1 equal
  singular.insert(2, 2) = 1;
  singular.makeCompressed();
  auto solver = create_linear_solver("petsc-mumps");
  BOOST_CHECK_THROW(solver->analyze_and_factorize(singular), NumericalError);
}

// petsc-mumps factorises a symmetric matrix as L D L^T (MUMPS SYM = 2) and a
// matrix of the same pattern that is not symmetric (a friction tangent) as
// L U, analysed again; an indefinite symmetric matrix (a softening tangent)
// still as L D L^T, with MUMPS's 2x2 pivots. Reference: Eigen's dense LU of
// the same matrix (a second method); the condition numbers are below 1e3, so
// agreement to 1e-12.
BOOST_AUTO_TEST_CASE(petsc_mumps_factorises_symmetric_matrices_as_ldlt)
{
  const int    n = 40;
  SparseMatrix a(n, n);
  for (int i = 0; i < n; ++i)
    {
      a.insert(i, i) = 4.0 + 0.01 * i;
      if (i + 1 < n)
        a.insert(i, i + 1) = a.insert(i + 1, i) = -1.0 + 0.001 * i;
      if (i + 7 < n)
        a.insert(i, i + 7) = a.insert(i + 7, i) = 0.3;
    }
  a.makeCompressed();
  Vector b(n);
  for (int i = 0; i < n; ++i)
    b[i] = std::sin(1.0 + i);
  const auto check = [&](LinearSolver &solver, const SparseMatrix &m, const bool ldlt) {
    const unsigned long before = distributed_solver_profile().symmetric_factorizations;
    solver.factorize(m);
    BOOST_TEST(distributed_solver_profile().symmetric_factorizations - before == (ldlt ? 1u : 0u));
    Vector x;
    solver.solve(b, x);
    const Vector reference = Eigen::MatrixXd(m).partialPivLu().solve(b);
    BOOST_TEST((x - reference).norm() <= 1e-12 * reference.norm());
  };
  auto solver = create_linear_solver("petsc-mumps");
  solver->analyze(a);
  check(*solver, a, true);
  SparseMatrix unsymmetric = a; // same pattern, k_34 != k_43
  unsymmetric.coeffRef(3, 4) += 0.5;
  check(*solver, unsymmetric, false);
  check(*solver, a, false); // the L U analysis serves a symmetric matrix too

  SparseMatrix indefinite = a; // the first diagonal entries negative
  for (int i = 0; i < 5; ++i)
    indefinite.coeffRef(i, i) = -4.0;
  auto other = create_linear_solver("petsc-mumps");
  other->analyze(indefinite);
  check(*other, indefinite, true);
}
