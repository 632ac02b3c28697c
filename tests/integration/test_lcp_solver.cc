// The Siconos Numerics wrapper (integration/lcp_solver.h) against LCPs
// solved by hand: a 2x2 with both constraints active and a 3x3 with the
// middle one inactive, by each solver the program offers; the trivial
// problem (q >= 0: z = 0). Without Siconos in the build it checks that the
// wrapper says so.
#include <poundfe/integration/lcp_solver.h>

#include <boost/test/unit_test.hpp>

using namespace poundfe;

namespace
{
  void
  check_solution(const Eigen::MatrixXd &M, const Eigen::VectorXd &q, const Eigen::VectorXd &z,
                 const LcpSolverKind kind)
  {
    LcpOptions options;
    options.solver         = kind;
    const LcpSolution s    = solve_lcp(M, q, options);
    BOOST_TEST_MESSAGE(lcp_solver_names().name(kind)
                       << ": " << s.solver << ", " << s.iterations << " iterations, error "
                       << s.residual << ", z = " << s.z.transpose());
    BOOST_TEST(s.info == 0);
    BOOST_TEST(!s.solver.empty());
    BOOST_TEST((s.z - z).lpNorm<Eigen::Infinity>() < 1e-9);
    BOOST_TEST((s.w - (M * z + q)).lpNorm<Eigen::Infinity>() < 1e-9);
    BOOST_TEST(s.residual < 1e-9);
  }
} // namespace

BOOST_AUTO_TEST_CASE(siconos_solves_small_lcps_solved_by_hand)
{
  if (!lcp_solver_available())
    {
      BOOST_TEST(lcp_solver_description().find("not found") != std::string::npos);
      return;
    }
  for (const LcpSolverKind kind : {LcpSolverKind::lemke, LcpSolverKind::nsgs,
                                   LcpSolverKind::enumeration, LcpSolverKind::newton_fb})
    {
      // both active: w = 0, M z = -q = (5, 6) -> z = (4/3, 7/3)
      Eigen::MatrixXd M2(2, 2);
      M2 << 2, 1, 1, 2;
      check_solution(M2, Eigen::Vector2d(-5, -6), Eigen::Vector2d(4. / 3, 7. / 3), kind);
      // z2 = 0: [2 0; 0 2] (z1, z3) = (1, 2) -> (0.5, 1); w2 = 0.5 + 1 + 1 = 2.5 > 0
      Eigen::MatrixXd M3(3, 3);
      M3 << 2, 1, 0, 1, 2, 1, 0, 1, 2;
      check_solution(M3, Eigen::Vector3d(-1, 1, -2), Eigen::Vector3d(0.5, 0, 1), kind);
      // q >= 0: z = 0, w = q
      check_solution(M3, Eigen::Vector3d(1, 0.5, 2), Eigen::Vector3d::Zero(), kind);
    }
  // a problem of size 0 (no contact closing): nothing to solve
  const LcpSolution empty = solve_lcp(Eigen::MatrixXd(0, 0), Eigen::VectorXd(0));
  BOOST_TEST(empty.z.size() == 0);
  BOOST_TEST(empty.info == 0);
}
