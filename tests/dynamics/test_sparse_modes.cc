// The sparse (shift-invert Lanczos) modal solver against the dense one and
// against closed forms:
//   - a 10-storey 2-bay frame, lumped masses (massless rotations, M
//     singular), 2 elements per member (240 equations), and a 40-storey shear
//     building with storey stiffnesses varying with height: frequencies to
//     1e-10 relative, mode shapes up to sign to 1e-7 of their norm (an
//     eigenvector's error is the eigenvalue's over the gap to the next mode,
//     so looser), effective mass ratios to 1e-9 (absolute; they are below 1);
//   - a uniform 2500-storey shear building (2500 equations), whose discrete
//     frequencies are exact: omega_j = 2 sqrt(k/m) sin((2j - 1) pi / (2(2N + 1)))
//     (e.g. Humar, Dynamics of Structures, 3rd ed., §11.4), to 1e-10;
//   - a 50-storey 3-bay frame, 3 elements per member (2700 equations), whose
//     only masses are the floors' (400 DOFs): the exact static condensation
//     onto those DOFs (flexibility F = (K^-1)_mm, massless DOFs condensed
//     exactly, not Guyan's approximation) gives M_m^1/2 F M_m^1/2 v = v/omega^2,
//     a 400 x 400 dense problem; frequencies to 1e-9, because round-off
//     already separates the three computations by that much on mode 1 (its
//     1/omega^2 is K^-1's largest): sparse against condensation 1.3e-10,
//     dense (28 s, run once) against sparse 1.8e-10, against condensation
//     3.1e-10; modes 2-6 agree to 3e-11;
//   - a cantilever column of 100 elements against the Euler-Bernoulli
//     frequencies (beta_j L)^2 sqrt(EI/(m L^4)) (Chopra, Dynamics of
//     Structures, 4th ed., ch. 16), consistent mass (non-diagonal M) to 1e-6
//     (cubic elements: O(h^4) error, measured 2.8e-7 for mode 5) and lumped
//     mass to 1e-3 (O(h^2), measured 4.7e-4). A finely meshed single member
//     is the ill-conditioned case: K's condition number grows as n^4, and
//     both solvers lose ~1e-9 on the first mode at 100 elements (5e-5 at
//     1000), so sparse against dense is checked on building models only;
//   - the automatic choice: dense up to 500 equations, sparse above.
#include <poundfe/dynamics/modal.h>
#include <poundfe/model/model_builder.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <cmath>

#include <boost/test/unit_test.hpp>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  LinearSystem
  system_of(const InputParameters &p)
  {
    return assemble_mass_and_stiffness(build_model(p.model, p.contact, p, p.springs, p.friction));
  }

  void
  check_agreement(const LinearSystem &s, const unsigned int n_modes)
  {
    const Modes dense  = compute_modes_dense(s.mass, s.stiffness, s.influence, n_modes);
    const Modes sparse = compute_modes_sparse(s.mass, s.stiffness, s.influence, n_modes);
    BOOST_REQUIRE(sparse.n_modes() == n_modes);
    BOOST_REQUIRE(dense.n_modes() == n_modes);
    double worst_omega = 0, worst_shape = 0, worst_mass = 0;
    for (unsigned int j = 0; j < n_modes; ++j)
      {
        worst_omega = std::max(worst_omega, std::abs(sparse.omega[j] / dense.omega[j] - 1));
        const Vector a = dense.shapes.col(j), b = sparse.shapes.col(j);
        worst_shape    = std::max(worst_shape, std::min((a - b).norm(), (a + b).norm()) / a.norm());
        worst_mass     = std::max(worst_mass, std::abs(sparse.participating_mass_ratio[j] -
                                                   dense.participating_mass_ratio[j]));
      }
    BOOST_TEST_MESSAGE(s.n_equations() << " equations, " << n_modes
                                       << " modes: sparse against dense, frequencies "
                                       << worst_omega << ", shapes " << worst_shape
                                       << ", mass ratios " << worst_mass);
    BOOST_TEST(worst_omega < 1e-10);
    BOOST_TEST(worst_shape < 1e-7);
    BOOST_TEST(worst_mass < 1e-9);
  }

  /// A uniform cantilever column along y, fixed at the base.
  LinearSystem
  cantilever(const unsigned int n_elements, const MassMatrixType mass, const Section &section,
             const double length)
  {
    Model model = poundfe_test::straight_member({0, 0}, {0, length}, section, n_elements);
    model.nodes[0].fixed = {{true, true, true}};
    model.mass_matrix    = mass;
    model.number_equations();
    return assemble_mass_and_stiffness(model);
  }

  /// The first five roots of 1 + cos(x) cosh(x) = 0 (cantilever, beta L).
  constexpr double beta_l[5] = {1.8751040687119611, 4.6940911329741745, 7.8547574382376126,
                                10.995540734875467, 14.137168391046471};
} // namespace

BOOST_AUTO_TEST_CASE(sparse_and_dense_modes_agree_on_a_frame)
{
  InputParameters     p = poundfe_test::shear_building_input(10, 1000, 5e6, 0);
  BuildingParameters &b = p.model.buildings[0];
  b                     = BuildingParameters();
  b.type                = BuildingType::frame;
  b.n_storeys           = 10;
  b.n_bays              = 2;
  b.storey_heights      = {4.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0, 3.0};
  b.floor_masses        = {30000};
  b.column_second_moment = {4e-3, 3e-3, 3e-3, 2e-3, 2e-3, 2e-3, 1e-3, 1e-3, 1e-3, 1e-3};
  b.elements_per_member = 2;
  b.finalize(p, 1);
  const LinearSystem s = system_of(p);
  check_agreement(s, 8);
}

BOOST_AUTO_TEST_CASE(sparse_and_dense_modes_agree_on_a_shear_building)
{
  InputParameters p = poundfe_test::shear_building_input(40, 2e5, 1e9, 0);
  std::vector<double> &k = p.model.buildings[0].storey_stiffnesses;
  k.clear();
  for (unsigned int i = 0; i < 40; ++i)
    k.push_back(1e9 * (1 - 0.015 * i)); // softer towards the roof
  const LinearSystem s = system_of(p);
  check_agreement(s, 10);
}

BOOST_AUTO_TEST_CASE(sparse_modes_of_a_uniform_shear_building_are_exact)
{
  const unsigned int N = 2500;
  const double       m = 1000, k = 1e8;
  const LinearSystem s = system_of(poundfe_test::shear_building_input(N, m, k, 0));
  const Modes        modes = compute_modes(s.mass, s.stiffness, s.influence, 6);
  BOOST_REQUIRE(modes.n_modes() == 6u);
  double worst = 0;
  for (unsigned int j = 1; j <= 6; ++j)
    {
      const double exact = 2 * std::sqrt(k / m) * std::sin((2 * j - 1) * M_PI / (2 * (2 * N + 1)));
      worst              = std::max(worst, std::abs(modes.omega[j - 1] / exact - 1));
    }
  BOOST_TEST_MESSAGE(N << "-storey shear building: largest frequency error " << worst);
  BOOST_TEST(worst < 1e-10);
}

BOOST_AUTO_TEST_CASE(sparse_modes_of_a_tall_frame_match_exact_condensation)
{
  InputParameters     p = poundfe_test::shear_building_input(50, 1000, 5e6, 0);
  BuildingParameters &b = p.model.buildings[0];
  b                     = BuildingParameters();
  b.type                = BuildingType::frame;
  b.n_storeys           = 50;
  b.n_bays              = 3;
  b.floor_masses        = {80000};
  b.column_area         = {0.64};
  b.column_second_moment = {3.4e-2};
  b.elements_per_member = 3;
  b.finalize(p, 1);
  const LinearSystem s = system_of(p);
  BOOST_REQUIRE(s.n_equations() == 2700u);
  const Modes modes = compute_modes(s.mass, s.stiffness, s.influence, 6);
  BOOST_REQUIRE(modes.n_modes() == 6u);

  std::vector<Eigen::Index> massive;
  for (Eigen::Index i = 0; i < s.mass.rows(); ++i)
    if (s.mass.coeff(i, i) != 0)
      massive.push_back(i);
  const Eigen::Index                       n_m = massive.size();
  Eigen::MatrixXd                          unit = Eigen::MatrixXd::Zero(s.n_equations(), n_m);
  for (Eigen::Index j = 0; j < n_m; ++j)
    unit(massive[j], j) = 1;
  const Eigen::SimplicialLLT<SparseMatrix> cholesky(s.stiffness);
  const Eigen::MatrixXd                    x = cholesky.solve(unit);
  Eigen::MatrixXd                          scaled(n_m, n_m);
  for (Eigen::Index i = 0; i < n_m; ++i)
    for (Eigen::Index j = 0; j < n_m; ++j)
      scaled(i, j) = std::sqrt(s.mass.coeff(massive[i], massive[i]) *
                               s.mass.coeff(massive[j], massive[j])) *
                     0.5 * (x(massive[i], j) + x(massive[j], i));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> condensed(scaled, Eigen::EigenvaluesOnly);
  double worst = 0;
  for (unsigned int j = 0; j < 6; ++j)
    worst = std::max(worst, std::abs(modes.omega[j] *
                                       std::sqrt(condensed.eigenvalues()[n_m - 1 - j]) - 1));
  BOOST_TEST_MESSAGE("50-storey frame, " << s.n_equations() << " equations, " << n_m
                                         << " with mass: largest frequency error " << worst);
  BOOST_TEST(worst < 1e-9);
}

BOOST_AUTO_TEST_CASE(sparse_modes_of_a_cantilever_match_beam_theory)
{
  const Section section{3e10, 0.5, 0.04, 2500}; // a 1 m x 0.5 m concrete wall
  const double  L  = 50.0;
  const double  EI = section.youngs_modulus * section.second_moment;
  const std::pair<MassMatrixType, double> cases[] = {{MassMatrixType::consistent, 1e-6},
                                                     {MassMatrixType::lumped, 1e-3}};
  for (const auto &[mass, tolerance] : cases)
    {
      const LinearSystem s     = cantilever(100, mass, section, L);
      const Modes        modes = compute_modes_sparse(s.mass, s.stiffness, s.influence, 5);
      BOOST_REQUIRE(modes.n_modes() == 5u);
      double worst = 0;
      for (unsigned int j = 0; j < 5; ++j)
        {
          const double exact =
            beta_l[j] * beta_l[j] * std::sqrt(EI / (section.mass_per_length * std::pow(L, 4)));
          worst = std::max(worst, std::abs(modes.omega[j] / exact - 1));
        }
      BOOST_TEST_MESSAGE((mass == MassMatrixType::lumped ? "lumped" : "consistent")
                         << " cantilever, 100 elements: largest frequency error " << worst);
      BOOST_TEST(worst < tolerance);
    }
}

BOOST_AUTO_TEST_CASE(automatic_choice_is_dense_up_to_the_limit)
{
  const Section section{3e10, 0.5, 0.04, 2500};
  const LinearSystem small = cantilever(dense_eigensolver_limit / 3, MassMatrixType::lumped,
                                        section, 50.0);
  const LinearSystem large = cantilever(dense_eigensolver_limit / 3 + 1,
                                        MassMatrixType::lumped, section, 50.0);
  BOOST_TEST(small.n_equations() <= dense_eigensolver_limit);
  BOOST_TEST(large.n_equations() > dense_eigensolver_limit);
  BOOST_TEST((choose_eigensolver(Eigensolver::automatic, small.mass, 6) == Eigensolver::dense));
  BOOST_TEST((choose_eigensolver(Eigensolver::automatic, large.mass, 6) == Eigensolver::sparse));
  // more modes than the sparse solver can give: dense even when large
  BOOST_TEST((choose_eigensolver(Eigensolver::automatic, large.mass, 1000) == Eigensolver::dense));
  BOOST_TEST((choose_eigensolver(Eigensolver::dense, large.mass, 6) == Eigensolver::dense));
  BOOST_TEST((choose_eigensolver(Eigensolver::sparse, small.mass, 6) == Eigensolver::sparse));
}

// Models too small for ARPACK's Lanczos basis (issue 27: the sparse solver
// on a one-DOF model refused): the sparse solver projects on every massive
// DOF, exact. One storey: omega = sqrt(k/m) to round-off; two to five
// storeys: every mode equals the dense solver's (1e-12; shapes up to sign, 1e-10), including asking
// for more modes than there are (both return all of them).
BOOST_AUTO_TEST_CASE(sparse_modes_of_models_too_small_for_lanczos)
{
  const double       m = 2e5, k = 3e8;
  const LinearSystem one = system_of(poundfe_test::shear_building_input(1, m, k, 0));
  BOOST_REQUIRE(lanczos_mode_limit(one.mass) == 0u);
  BOOST_REQUIRE(max_sparse_modes(one.mass) == 1u);
  const Modes single = compute_modes_sparse(one.mass, one.stiffness, one.influence, 1);
  BOOST_REQUIRE(single.n_modes() == 1u);
  BOOST_TEST(std::abs(single.omega[0] / std::sqrt(k / m) - 1) < 1e-14);
  BOOST_TEST(std::abs(single.participating_mass_ratio[0] - 1) < 1e-14);
  for (unsigned int n_storeys = 2; n_storeys <= 5; ++n_storeys)
    {
      const LinearSystem s = system_of(poundfe_test::shear_building_input(n_storeys, m, k, 0));
      const Modes        dense  = compute_modes_dense(s.mass, s.stiffness, s.influence, 10);
      const Modes        sparse = compute_modes_sparse(s.mass, s.stiffness, s.influence, 10);
      BOOST_REQUIRE(sparse.n_modes() == n_storeys);
      BOOST_REQUIRE(dense.n_modes() == n_storeys);
      for (unsigned int j = 0; j < n_storeys; ++j)
        {
          BOOST_TEST(std::abs(sparse.omega[j] / dense.omega[j] - 1) < 1e-12);
          // up to sign: where two entries tie in size, round-off picks the
          // one the sign convention makes positive
          const Vector a = sparse.shapes.col(j), b = dense.shapes.col(j);
          BOOST_TEST(std::min((a - b).norm(), (a + b).norm()) < 1e-10 * b.norm());
        }
    }
}
