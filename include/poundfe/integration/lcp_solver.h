// The linear complementarity problem of one step of rigid contact
//   w = M z + q,   0 <= z  ⊥  w >= 0
// (Cottle, Pang & Stone, The Linear Complementarity Problem, 1992, §1.1)
// handed to Siconos Numerics' solvers (Acary & Brogliato, Numerical Methods
// for Nonsmooth Dynamical Systems, Springer 2008, ch. 12; Siconos Numerics'
// LCP_Solvers.h): Lemke's pivoting method, projected Gauss-Seidel (NSGS),
// enumeration, and the semismooth Newton method on Fischer-Burmeister's
// function. The program writes no LCP solver of its own: without Siconos
// (a build that did not find it) lcp_solver_available() is false and
// solve_lcp() is a programming error.
// With Coulomb friction the step's problem is a friction-contact problem
// in a contact space of two dimensions (normal and tangent in plan),
//   u = W r + q,  K* ∋ u + (μ |u_T|, 0)  ⊥  r ∈ K,  K = {r : |r_T| <= μ r_N}
// (De Saxcé's bipotential form; Acary & Brogliato 2008, §13.2), handed to
// Siconos Numerics' fc2d solvers (fc2d_Solvers.h): projected Gauss-Seidel
// over the contacts (NSGS), Lemke's method on its LCP reformulation, and
// enumeration. (Siconos's local Newton solvers are fc3d's, for a contact
// space of three dimensions, which a contact in plan has not.)
// Only source/integration/lcp_solver.cc includes Siconos's headers.
#ifndef poundfe_integration_lcp_solver_h
#define poundfe_integration_lcp_solver_h

#include <poundfe/base/choices.h>

#include <Eigen/Core>

#include <string>

namespace poundfe
{
  enum class LcpSolverKind
  {
    lemke,     // Lemke's lexicographic pivoting (SICONOS_LCP_LEMKE): exact, small problems
    nsgs,      // projected Gauss-Seidel (SICONOS_LCP_PGS): iterative
    enumeration, // every complementary basis (SICONOS_LCP_ENUM): tiny problems
    newton_fb    // semismooth Newton on Fischer-Burmeister (SICONOS_LCP_NEWTON_FB_FBLSA)
  };

  const NameTable<LcpSolverKind> &lcp_solver_names();

  struct LcpOptions
  {
    LcpSolverKind solver         = LcpSolverKind::lemke;
    double        tolerance      = 1e-12; // on Siconos's relative complementarity error
    unsigned int  max_iterations = 10000;
  };

  struct LcpSolution
  {
    Eigen::VectorXd z, w;
    /// Siconos's name of the solver that ran, its iterations (pivots for
    /// Lemke) and its error (lcp_compute_error: ||z - proj(z - w)|| / ||q||).
    std::string solver;
    int         iterations = 0;
    double      residual   = 0;
    /// Siconos's status: 0 solved, else the solver's failure code.
    int         info = 0;
  };

  enum class FrictionSolverKind
  {
    nsgs,       // SICONOS_FRICTION_2D_NSGS: Gauss-Seidel over the contacts, each solved exactly
    lemke,      // SICONOS_FRICTION_2D_LEMKE: Lemke on the problem's LCP (fc2d_tolcp)
    enumeration // SICONOS_FRICTION_2D_ENUM: every complementary basis, a few contacts
  };

  const NameTable<FrictionSolverKind> &friction_solver_names();

  struct FrictionContactOptions
  {
    FrictionSolverKind solver         = FrictionSolverKind::nsgs;
    double             tolerance      = 1e-12; // on Siconos's fc2d_compute_error
    unsigned int       max_iterations = 10000;
  };

  /// Whether this build has Siconos Numerics (Contact/Model = nonsmooth).
  bool lcp_solver_available();
  /// "Siconos Numerics" with its version, or why it is missing.
  std::string lcp_solver_description();

  /// Solve the LCP (M, q), M square and dense. A problem of size 0 returns
  /// empty vectors. Siconos's failure is reported in `info` (the caller
  /// decides: a step's NumericalError).
  LcpSolution solve_lcp(const Eigen::MatrixXd &M, const Eigen::VectorXd &q,
                        const LcpOptions &options = LcpOptions());

  /// Solve the 2D friction-contact problem (W, q, mu): contact k's
  /// reaction (r_N, r_T) is z[2k], z[2k + 1], its velocity (u_N, u_T)
  /// w[2k], w[2k + 1] (W and q ordered alike); `info`, `residual`
  /// (fc2d_compute_error) and `iterations` as solve_lcp's.
  LcpSolution solve_friction_contact(const Eigen::MatrixXd &W, const Eigen::VectorXd &q,
                                     const Eigen::VectorXd       &mu,
                                     const FrictionContactOptions &options);
} // namespace poundfe

#endif
