// The LCP w = M z + q, 0 <= z ⊥ w >= 0, handed to Siconos Numerics
// (integration/lcp_solver.h): a dense NumericsMatrix (column-major, as
// Eigen's), the solver's SolverOptions with the tolerance and iteration
// limit, linearComplementarity_driver, and lcp_compute_error for the
// residual every solver reports alike; the 2D friction-contact problem the
// same way through fc2d_driver and fc2d_compute_error. Compiled alone, with Siconos's
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
#  include <FrictionContactProblem.h>
#  include <Friction_cst.h>
// fc2d_compute_error.h writes C99's restrict, which C++ spells __restrict
#  define restrict __restrict
#  include <fc2d_compute_error.h>
#  undef restrict
#endif

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <memory>
#include <utility>

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

  const NameTable<FrictionSolverKind> &
  friction_solver_names()
  {
    static const NameTable<FrictionSolverKind> table(
      {{FrictionSolverKind::nsgs, "nsgs"},
       {FrictionSolverKind::lemke, "lemke"},
       {FrictionSolverKind::enumeration, "enum"}});
    return table;
  }

#ifdef POUNDFE_WITH_SICONOS
  namespace
  {
    /// Siconos's solver of each choice, one row a choice: the LCP's nsgs
    /// is Siconos's projected Gauss-Seidel.
    constexpr std::pair<LcpSolverKind, int> lcp_solver_ids[] = {
      {LcpSolverKind::lemke, SICONOS_LCP_LEMKE},
      {LcpSolverKind::nsgs, SICONOS_LCP_PGS},
      {LcpSolverKind::enumeration, SICONOS_LCP_ENUM},
      {LcpSolverKind::newton_fb, SICONOS_LCP_NEWTON_FB_FBLSA}};

    constexpr std::pair<FrictionSolverKind, int> friction_solver_ids[] = {
      {FrictionSolverKind::nsgs, SICONOS_FRICTION_2D_NSGS},
      {FrictionSolverKind::lemke, SICONOS_FRICTION_2D_LEMKE},
      {FrictionSolverKind::enumeration, SICONOS_FRICTION_2D_ENUM}};

    template <typename Kind, std::size_t n>
    int
    siconos_solver_id(const std::pair<Kind, int> (&ids)[n], const Kind kind)
    {
      for (const auto &[choice, id] : ids)
        if (choice == kind)
          return id;
      // thrown in every build: a Release build must not run another solver
      // than the one chosen (the static_asserts below cannot see a choice
      // added after the last one)
      AssertThrow(false, dealii::ExcMessage("a solver choice without its Siconos solver"));
      return -1;
    }

    /// Whether row i of `ids` is the choice numbered i: with the count of
    /// rows checked against the last choice below, every choice declared so
    /// far has its row.
    template <typename Kind, std::size_t n>
    constexpr bool
    in_choice_order(const std::pair<Kind, int> (&ids)[n])
    {
      for (std::size_t i = 0; i < n; ++i)
        if (ids[i].first != static_cast<Kind>(i))
          return false;
      return true;
    }
    static_assert(in_choice_order(lcp_solver_ids) &&
                    std::size(lcp_solver_ids) == std::size_t(LcpSolverKind::newton_fb) + 1,
                  "lcp_solver_ids: one row for each LcpSolverKind, in order");
    static_assert(in_choice_order(friction_solver_ids) &&
                    std::size(friction_solver_ids) == std::size_t(FrictionSolverKind::enumeration) + 1,
                  "friction_solver_ids: one row for each FrictionSolverKind, in order");

    int
    siconos_solver_id(const LcpSolverKind kind)
    {
      return siconos_solver_id(lcp_solver_ids, kind);
    }

    int
    siconos_solver_id(const FrictionSolverKind kind)
    {
      return siconos_solver_id(friction_solver_ids, kind);
    }

    // Siconos owns what it allocates: the matrix and the options are freed
    // by its own functions on every path out of a solve.
    using SiconosMatrix  = std::unique_ptr<NumericsMatrix, NumericsMatrix *(*)(NumericsMatrix *)>;
    using SiconosOptions = std::unique_ptr<SolverOptions, void (*)(SolverOptions *)>;

    /// A dense NumericsMatrix holding M (column-major, as Eigen's).
    SiconosMatrix
    dense_matrix(const Eigen::MatrixXd &M)
    {
      SiconosMatrix matrix(NM_create(NM_DENSE, M.rows(), M.cols()), NM_free);
      std::copy(M.data(), M.data() + M.size(), matrix->matrix0);
      return matrix;
    }

    /// Solver `id`'s options with the tolerance and iteration limit.
    SiconosOptions
    solver_options(const int id, const double tolerance, const unsigned int max_iterations)
    {
      SiconosOptions options(solver_options_create(id), solver_options_delete);
      options->dparam[SICONOS_DPARAM_TOL]      = tolerance;
      options->iparam[SICONOS_IPARAM_MAX_ITER] = max_iterations;
      return options;
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
    const SiconosMatrix matrix = dense_matrix(M);
    Eigen::VectorXd     q_copy = q; // the problem's q is not const
    LinearComplementarityProblem problem;
    problem.size = n;
    problem.M    = matrix.get();
    problem.q    = q_copy.data();
    const SiconosOptions solver =
      solver_options(siconos_solver_id(options.solver), options.tolerance, options.max_iterations);
    solution.info = linearComplementarity_driver(&problem, solution.z.data(), solution.w.data(),
                                                 solver.get());
    solution.iterations = solver->iparam[SICONOS_IPARAM_ITER_DONE];
    // Lemke does not fill dparam's residual: the same measure for every solver
    lcp_compute_error(&problem, solution.z.data(), solution.w.data(), options.tolerance,
                      &solution.residual);
    return solution;
  }

  LcpSolution
  solve_friction_contact(const Eigen::MatrixXd &W, const Eigen::VectorXd &q,
                         const Eigen::VectorXd &mu, const FrictionContactOptions &options)
  {
    const int n = q.size();
    Assert(W.rows() == n && W.cols() == n && 2 * mu.size() == n,
           dealii::ExcDimensionMismatch(W.rows(), n));
    LcpSolution solution;
    solution.z.setZero(n);
    solution.w = q;
    solution.solver = solver_options_id_to_name(siconos_solver_id(options.solver));
    if (n == 0)
      return solution;
    const SiconosMatrix    matrix = dense_matrix(W);
    Eigen::VectorXd        q_copy = q, mu_copy = mu; // the problem's are not const
    FrictionContactProblem problem;
    problem.dimension        = 2;
    problem.numberOfContacts = mu.size();
    problem.M                = matrix.get();
    problem.q                = q_copy.data();
    problem.mu               = mu_copy.data();
    const SiconosOptions solver =
      solver_options(siconos_solver_id(options.solver), options.tolerance, options.max_iterations);
    solution.info = fc2d_driver(&problem, solution.z.data(), solution.w.data(), solver.get());
    solution.iterations = solver->iparam[SICONOS_IPARAM_ITER_DONE];
    // the same measure for every solver, relative to |q| as the LCP's
    fc2d_compute_error(&problem, solution.z.data(), solution.w.data(), options.tolerance,
                       std::max(q.norm(), 1e-300), &solution.residual);
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

  LcpSolution
  solve_friction_contact(const Eigen::MatrixXd &, const Eigen::VectorXd &,
                         const Eigen::VectorXd &, const FrictionContactOptions &)
  {
    AssertThrow(false, dealii::ExcMessage("solve_friction_contact: this build has no Siconos "
                                          "Numerics; Contact/Model = nonsmooth must have been "
                                          "refused"));
    return {};
  }
#endif
} // namespace poundfe
