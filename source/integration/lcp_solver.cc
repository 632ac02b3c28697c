// The LCP w = M z + q, 0 <= z ⊥ w >= 0, handed to Siconos Numerics
// (integration/lcp_solver.h): a dense NumericsMatrix (column-major, as
// Eigen's), the solver's SolverOptions with the tolerance and iteration
// limit, linearComplementarity_driver, and lcp_compute_error for the
// residual every solver reports alike. Compiled alone, with Siconos's
// include directories and POUNDFE_WITH_SICONOS when the build found it.
#include <poundfe/integration/lcp_solver.h>

#include <deal.II/base/exceptions.h>

#ifdef POUNDFE_WITH_SICONOS
#  include <LCP_Solvers.h>
#  include <LinearComplementarityProblem.h>
#  include <NonSmoothDrivers.h>
#  include <NumericsMatrix.h>
#  include <SolverOptions.h>
#  include <lcp_cst.h>
#endif

#include <algorithm>
#include <memory>

namespace poundfe
{
  const NameTable<LcpSolverKind> &
  lcp_solver_names()
  {
    static const NameTable<LcpSolverKind> table({{LcpSolverKind::lemke, "lemke"},
                                                 {LcpSolverKind::nsgs, "nsgs"},
                                                 {LcpSolverKind::enumeration, "enum"},
                                                 {LcpSolverKind::newton_fb, "newton-fb"}});
    return table;
  }

#ifdef POUNDFE_WITH_SICONOS
  namespace
  {
    int
    siconos_solver_id(const LcpSolverKind kind)
    {
      switch (kind)
        {
          case LcpSolverKind::lemke:
            return SICONOS_LCP_LEMKE;
          case LcpSolverKind::nsgs:
            return SICONOS_LCP_PGS;
          case LcpSolverKind::enumeration:
            return SICONOS_LCP_ENUM;
          case LcpSolverKind::newton_fb:
            return SICONOS_LCP_NEWTON_FB_FBLSA;
        }
      return SICONOS_LCP_LEMKE;
    }
  } // namespace

  bool
  lcp_solver_available()
  {
    return true;
  }

  std::string
  lcp_solver_description()
  {
    return "Siconos Numerics";
  }

  LcpSolution
  solve_lcp(const Eigen::MatrixXd &M, const Eigen::VectorXd &q, const LcpOptions &options)
  {
    const int n = q.size();
    Assert(M.rows() == n && M.cols() == n, dealii::ExcDimensionMismatch(M.rows(), n));
    LcpSolution solution;
    solution.z.setZero(n);
    solution.w = q;
    solution.solver = solver_options_id_to_name(siconos_solver_id(options.solver));
    if (n == 0)
      return solution;
    // Siconos owns what it allocates: the matrix and the options are freed
    // by its own functions on every path out of here.
    const std::unique_ptr<NumericsMatrix, NumericsMatrix *(*)(NumericsMatrix *)> matrix(
      NM_create(NM_DENSE, n, n), NM_free);
    std::copy(M.data(), M.data() + n * n, matrix->matrix0);
    Eigen::VectorXd q_copy = q; // the problem's q is not const
    LinearComplementarityProblem problem;
    problem.size = n;
    problem.M    = matrix.get();
    problem.q    = q_copy.data();
    const std::unique_ptr<SolverOptions, void (*)(SolverOptions *)> solver(
      solver_options_create(siconos_solver_id(options.solver)), solver_options_delete);
    solver->dparam[SICONOS_DPARAM_TOL]     = options.tolerance;
    solver->iparam[SICONOS_IPARAM_MAX_ITER] = options.max_iterations;
    solution.info = linearComplementarity_driver(&problem, solution.z.data(), solution.w.data(),
                                                 solver.get());
    solution.iterations = solver->iparam[SICONOS_IPARAM_ITER_DONE];
    // Lemke does not fill dparam's residual: the same measure for every solver
    lcp_compute_error(&problem, solution.z.data(), solution.w.data(), options.tolerance,
                      &solution.residual);
    return solution;
  }
#else
  bool
  lcp_solver_available()
  {
    return false;
  }

  std::string
  lcp_solver_description()
  {
    return "Siconos Numerics was not found when this poundfe was built (scripts/setup.sh "
           "installs libsiconos-numerics-dev)";
  }

  LcpSolution
  solve_lcp(const Eigen::MatrixXd &, const Eigen::VectorXd &, const LcpOptions &)
  {
    AssertThrow(false, dealii::ExcMessage("solve_lcp: this build has no Siconos Numerics; "
                                          "Contact/Model = nonsmooth must have been refused"));
    return {};
  }
#endif
} // namespace poundfe
