// The fixed-size step (integration/fixed_size_step.h) against the general
// storage of the same formulas, written here on Eigen's sparse matrices and
// vectors of run-time size as NewmarkIntegrator holds them, on random
// banded systems of 1 to 12 equations: the products, the kinematics, the
// residual and eigen-ldlt's solves give the same bits; the norms and dot
// products, whose order of summation is Eigen's fixed-size one, agree to
// the bound of a reordered sum of n terms, n eps sum |terms| (Higham,
// Accuracy and Stability of Numerical Algorithms, §4.2), and to the bit up
// to 5 equations.
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/integration/fixed_size_step.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace poundfe;

namespace
{
  /// A symmetric banded matrix (half-bandwidth 2, some entries left out),
  /// diagonally dominant by `diagonal`, entries spread over six decades.
  SparseMatrix
  random_banded(const unsigned int n, const double diagonal, std::mt19937 &random)
  {
    std::uniform_real_distribution<double> unit(-1, 1);
    Eigen::MatrixXd                        A = Eigen::MatrixXd::Zero(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < std::min(n, i + 3); ++j)
        if (unit(random) > -0.5)
          A(i, j) = A(j, i) = unit(random) * std::pow(10.0, 3 * unit(random));
    for (unsigned int i = 0; i < n; ++i)
      A(i, i) = diagonal * (1 + std::abs(unit(random))) + A.row(i).cwiseAbs().sum();
    SparseMatrix S = A.sparseView();
    S.makeCompressed();
    return S;
  }

  /// A vector with entries over six decades, some exactly 0 (the solves
  /// skip those).
  Vector
  random_vector(const unsigned int n, std::mt19937 &random)
  {
    std::uniform_real_distribution<double> unit(-1, 1);
    Vector                                 x(n);
    for (unsigned int i = 0; i < n; ++i)
      x[i] = unit(random) > 0.6 ? 0.0 : unit(random) * std::pow(10.0, 3 * unit(random));
    return x;
  }

  /// The general storage (NewmarkIntegrator's, on one process, no modal
  /// damping), the second method the fixed size is checked against.
  struct SparseStorage
  {
    const LinearSystem &system;
    const SparseMatrix &effective;

    void mass_product(const Vector &x, Vector &y) const { y.noalias() = system.mass * x; }
    void damping_product(const Vector &x, Vector &y) const { y.noalias() = system.damping * x; }
    void subtract_effective_product(const Vector &x, Vector &y) const
    {
      y.noalias() -= effective * x;
    }
    double norm(const Vector &x) const { return x.norm(); }
  };

  NewmarkCoefficients
  coefficients(const double dt)
  {
    NewmarkCoefficients c;
    c.dt       = dt;
    c.c_mass_u = 4 / (dt * dt);
    c.c_mass_v = 4 / dt;
    c.c_mass_a = 1;
    c.c_damp_u = 2 / dt;
    c.c_damp_v = 1;
    c.c_damp_a = 0;
    return c;
  }

  /// |a - b| <= n eps scale, scale the sum of the terms' magnitudes (the
  /// same bits up to 5 equations).
  void
  check_reduction(const double a, const double b, const double scale, const unsigned int n)
  {
    if (n <= 5)
      BOOST_CHECK_EQUAL(a, b);
    else
      BOOST_CHECK_LE(std::abs(a - b), n * std::numeric_limits<double>::epsilon() * scale);
  }
} // namespace

BOOST_AUTO_TEST_CASE(fixed_size_solve_is_eigen_ldlt_to_the_bit)
{
  std::mt19937 random(7);
  for (unsigned int n = 1; n <= FixedSizeStep::max_size; ++n)
    for (unsigned int trial = 0; trial < 20; ++trial)
      {
        const SparseMatrix            A      = random_banded(n, 1e3, random);
        std::unique_ptr<LinearSolver> sparse = create_eigen_ldlt_solver();
        std::unique_ptr<LinearSolver> fixed =
          with_fixed_size_solve(create_eigen_ldlt_solver(), n);
        BOOST_REQUIRE(fixed.get() != nullptr);
        sparse->analyze_and_factorize(A);
        fixed->analyze_and_factorize(A);
        BOOST_CHECK_EQUAL(fixed->name(), "eigen-ldlt");
        for (unsigned int k = 0; k < 10; ++k)
          {
            const Vector b = random_vector(n, random);
            Vector       x, y;
            sparse->solve(b, x);
            fixed->solve(b, y);
            BOOST_CHECK_MESSAGE(x == y, "n = " << n << ": the solves differ by "
                                               << (x - y).cwiseAbs().maxCoeff());
          }
      }
}

BOOST_AUTO_TEST_CASE(fixed_size_solve_only_for_eigen_ldlt_of_at_most_12_equations)
{
  std::unique_ptr<LinearSolver> solver = create_eigen_ldlt_solver();
  LinearSolver *const           base   = solver.get();
  solver = with_fixed_size_solve(std::move(solver), FixedSizeStep::max_size + 1);
  BOOST_CHECK(solver.get() == base); // left as it is
  LinearSystem large;
  large.stiffness.resize(FixedSizeStep::max_size + 1, FixedSizeStep::max_size + 1);
  BOOST_CHECK(!make_fixed_size_step(large, large.stiffness));
}

BOOST_AUTO_TEST_CASE(fixed_size_step_is_the_general_storage)
{
  std::mt19937 random(11);
  for (unsigned int n = 1; n <= FixedSizeStep::max_size; ++n)
    for (unsigned int trial = 0; trial < 20; ++trial)
      {
        LinearSystem system;
        system.mass      = random_banded(n, 1e3, random);
        system.damping   = random_banded(n, 1e2, random);
        system.stiffness = random_banded(n, 1e6, random);
        const NewmarkCoefficients c = coefficients(5e-4);
        SparseMatrix effective = system.stiffness + c.c_damp_u * system.damping +
                                 c.c_mass_u * system.mass;
        effective.makeCompressed();
        const std::unique_ptr<FixedSizeStep> fixed = make_fixed_size_step(system, effective);
        BOOST_REQUIRE(fixed.get() != nullptr);
        const SparseStorage general{system, effective};

        const Vector p = random_vector(n, random), u = random_vector(n, random),
                     v = random_vector(n, random), a = random_vector(n, random),
                     du = random_vector(n, random);
        Vector stiffness_u(n), ku(n);
        fixed->stiffness_product(u, stiffness_u);
        ku.noalias() = system.stiffness * u;
        BOOST_CHECK(stiffness_u == ku);

        Vector       r0(n), r0_general(n), work(n), product(n);
        const double floor = fixed->start_residual(c, p, ku, v, a, r0);
        const double floor_general = newmark_formulas::start_residual(
          general, c, p, ku, v, a, work, product, r0_general);
        BOOST_CHECK(r0 == r0_general);
        check_reduction(floor, floor_general, floor_general, n);

        Vector r(n), r_general(n);
        fixed->effective_residual(r0, du, r);
        newmark_formulas::effective_residual(general, r0, du, r_general);
        BOOST_CHECK(r == r_general);
        fixed->effective_residual(r0, Vector::Zero(n), r); // du = 0: r_0 itself
        BOOST_CHECK(r == r0);

        Vector v1(n), a1(n), v1_general(n), a1_general(n), u1(n);
        fixed->kinematics(c, du, v, a, v1, a1);
        newmark_formulas::kinematics(c, du, v, a, v1_general, a1_general);
        BOOST_CHECK(v1 == v1_general);
        BOOST_CHECK(a1 == a1_general);
        fixed->iterate(u, du, u1);
        BOOST_CHECK(u1 == Vector(u + du));

        double input = 1, damping = 2, input_general = 1, damping_general = 2;
        fixed->add_step_work(du, p, r0, v, v1, input, damping);
        newmark_formulas::add_step_work(general, du, p, r0, v, v1, work, product,
                                        input_general, damping_general);
        const double work_scale = du.cwiseAbs().dot((p.cwiseAbs() + r0.cwiseAbs()));
        check_reduction(input, input_general, work_scale, n);
        const Vector velocity_sum = (v.cwiseAbs() + v1.cwiseAbs());
        check_reduction(damping, damping_general,
                        du.cwiseAbs().dot(Eigen::MatrixXd(system.damping).cwiseAbs() *
                                          velocity_sum),
                        n);
        check_reduction(fixed->kinetic_energy(v),
                        newmark_formulas::kinetic_energy(general, v, product),
                        v.cwiseAbs().dot(Eigen::MatrixXd(system.mass).cwiseAbs() *
                                         v.cwiseAbs()),
                        n);
        check_reduction(fixed->norm(r0), r0.norm(), r0.norm(), n);
        check_reduction(fixed->dot(u, du), u.dot(du), u.cwiseAbs().dot(du.cwiseAbs()), n);
      }
}
