// CG with algebraic multigrid (assembly/iterative_solver.h): the tolerance
// it is given, the preconditioner kept across new values and rebuilt when
// asked, a solve that cannot converge reported. Reference: the same system
// solved by UMFPACK (a second, direct method).
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/assembly/iterative_solver.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/base/exceptions.h>

#include <cmath>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  /// K_eff of the shipped two-building frame model at dt = 1 ms, and a
  /// dense, sign-changing right-hand side.
  struct EffectiveSystem
  {
    SparseMatrix k_eff;
    Vector       b;
    EffectiveSystem()
    {
      const Analysis a  = prepare_analysis(read_parameters("input/two-buildings.prm"));
      const double   dt = 1e-3;
      k_eff = a.system.stiffness + (2 / dt) * a.system.damping + (4 / (dt * dt)) * a.system.mass;
      k_eff.makeCompressed();
      b.resize(k_eff.rows());
      for (int i = 0; i < b.size(); ++i)
        b[i] = std::sin(1.0 + i);
    }
  };

  Vector
  direct_solution(const SparseMatrix &matrix, const Vector &b)
  {
    auto   solver = create_linear_solver("umfpack");
    Vector x;
    solver->analyze_and_factorize(matrix);
    solver->solve(b, x);
    return x;
  }

  const char *const iterative_names[] = {"petsc-cg-boomeramg", "trilinos-cg-ml"};
} // namespace

// MPI, PETSc and Trilinos: test_assembly.cc's global fixture
BOOST_AUTO_TEST_SUITE(iterative_solver)

// ||b - A x|| <= eta ||b|| for the eta given, and x within cond-ish of the
// direct solution: eta = 1e-6 leaves a residual the Newton iteration would
// correct; both backends meet it, and the looser solve is not exact.
BOOST_AUTO_TEST_CASE(solve_meets_the_relative_tolerance)
{
  const EffectiveSystem s;
  const Vector          reference = direct_solution(s.k_eff, s.b);
  for (const char *name : iterative_names)
    for (const double eta : {1e-6, 1e-12})
      {
        IterativeSolveCounts counts;
        IterativeSolverSetup setup;
        setup.relative_tolerance = eta;
        setup.counts             = &counts;
        auto solver              = create_linear_solver(name, setup);
        solver->analyze_and_factorize(s.k_eff);
        Vector x;
        solver->solve(s.b, x);
        const double residual = (s.b - s.k_eff * x).norm() / s.b.norm();
        BOOST_TEST_INFO(name << " eta " << eta << ": residual " << residual << ", "
                             << counts.iterations << " iterations");
        BOOST_TEST(residual <= eta);
        // K_eff is mass-dominated (condition ~1e6 at most): the error of x
        // is within 1e6 eta of the direct solution
        BOOST_TEST((x - reference).norm() <= 1e6 * eta * reference.norm());
        BOOST_TEST(counts.preconditioner_builds == 1u);
        BOOST_TEST(counts.solves == 1u);
      }
}

// New values of the same pattern: the preconditioner of the first matrix is
// kept (one build) and CG still solves the new matrix to its tolerance; with
// Preconditioner reuse = false every new matrix gets its own build.
BOOST_AUTO_TEST_CASE(preconditioner_is_kept_across_new_values)
{
  const EffectiveSystem s;
  // a diagonal shift of 0 to 10 % per equation: symmetric positive
  // definite, the pattern kept, the values changed everywhere on the diagonal
  SparseMatrix changed = s.k_eff;
  for (int i = 0; i < changed.rows(); ++i)
    changed.coeffRef(i, i) *= 1.0 + 0.05 * (1.0 + std::sin(0.7 * i));
  BOOST_REQUIRE(changed.nonZeros() == s.k_eff.nonZeros());
  const Vector reference = direct_solution(changed, s.b);
  for (const char *name : iterative_names)
    for (const bool reuse : {true, false})
      {
        IterativeSolveCounts counts;
        IterativeSolverSetup setup;
        setup.relative_tolerance = 1e-12;
        setup.parameters.reuse   = reuse;
        setup.counts             = &counts;
        auto solver              = create_linear_solver(name, setup);
        solver->analyze_and_factorize(s.k_eff);
        Vector x;
        solver->solve(s.b, x);
        solver->factorize(changed);
        solver->solve(s.b, x);
        solver->solve(s.b, x); // the same matrix again: never a build
        BOOST_TEST_INFO(name << (reuse ? " reuse" : " rebuild") << ": " << counts.iterations
                             << " iterations, " << counts.preconditioner_builds << " builds");
        BOOST_TEST((s.b - changed * x).norm() <= 1e-12 * s.b.norm());
        BOOST_TEST((x - reference).norm() <= 1e-6 * reference.norm());
        BOOST_TEST(counts.solves == 3u + counts.rebuilds_slow + counts.rebuilds_failed);
        if (reuse)
          BOOST_TEST(counts.preconditioner_builds == 1u + counts.rebuilds_slow +
                                                       counts.rebuilds_failed);
        else
          BOOST_TEST(counts.preconditioner_builds == 2u);
      }
}

// A CG that cannot reach its tolerance in Linear maximum iterations, even
// with a preconditioner built from its own matrix: NumericalError naming
// the parameter.
BOOST_AUTO_TEST_CASE(non_converging_solve_is_a_numerical_error)
{
  const EffectiveSystem s;
  for (const char *name : iterative_names)
    {
      IterativeSolverSetup setup;
      setup.relative_tolerance        = 1e-30; // below round-off: never met
      setup.parameters.max_iterations = 1;
      auto solver                     = create_linear_solver(name, setup);
      solver->analyze_and_factorize(s.k_eff);
      Vector x;
      try
        {
          solver->solve(s.b, x);
          BOOST_ERROR(name << ": no error");
        }
      catch (const NumericalError &e)
        {
          BOOST_TEST(std::string(e.what()).find("Linear maximum iterations = 1") !=
                     std::string::npos);
        }
    }
}

BOOST_AUTO_TEST_CASE(every_solver_is_built_here)
{
  for (const std::string &name : linear_solver_names())
    BOOST_TEST(linear_solver_unavailable(name) == "", name);
}

BOOST_AUTO_TEST_SUITE_END()
