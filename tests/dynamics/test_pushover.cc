// The pushover engine (dynamics/pushover.h): an elastic building's initial
// slope against its static stiffness under the pattern, a shear building of
// elastic-perfectly plastic storeys and a portal frame of plastic hinges
// against the collapse loads of plastic analysis, the equivalent system's
// factors, and two buildings pushed together through their gap.
#include <poundfe/dynamics/pushover.h>
#include <poundfe/input/engine_parameters.h>

#include "time_history_helpers.h"

#include <boost/test/unit_test.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <string>

using namespace poundfe;

namespace
{
  /// A shear building of three storeys of 3 m, masses 4e4, 3e4, 2e4 kg,
  /// stiffnesses 6e7, 5e7, 4e7 N/m; `extra` adds entries to Building 1 and
  /// `pushover` to the Pushover section.
  std::string
  shear_building(const std::string &extra, const std::string &pushover)
  {
    return "subsection Building 1\n set Type = shear\n set Number of storeys = 3\n"
           " set Storey heights = 3\n set Floor masses = 4e4, 3e4, 2e4\n"
           " set Storey stiffnesses = 6e7, 5e7, 4e7\n" + extra +
           " subsection Damping\n  set Type = none\n end\nend\n"
           "subsection Ground motion\n set Type = none\nend\n"
           "subsection Pushover\n" + pushover + "end\n";
  }

  PushoverResult
  pushover_of(const std::string &name, const std::string &text)
  {
    const InputParameters p = poundfe_test::input_of(name, text);
    return run_pushover(prepare_analysis(p), p.pushover, p);
  }
} // namespace

BOOST_AUTO_TEST_SUITE(pushover)

// Elastic: lambda / u_roof = 1 / (K^-1 p)_roof with p_i = m_i z_i / sum
// m_j z_j (the inverse triangle), K the storeys' tridiagonal stiffness,
// solved here; every point on that line, to 1e-9.
BOOST_AUTO_TEST_CASE(an_elastic_building_pushes_along_its_static_stiffness)
{
  const PushoverResult r = pushover_of(
    "pushover_elastic", shear_building("", " set Load pattern = triangular\n"
                                           " set Target drift = 0.002\n set Number of steps = 4\n"));
  BOOST_REQUIRE(r.completed);
  BOOST_REQUIRE_EQUAL(r.points.size(), 5u);
  const double    m[3] = {4e4, 3e4, 2e4}, k[3] = {6e7, 5e7, 4e7}, z[3] = {3, 6, 9};
  Eigen::Matrix3d K    = Eigen::Matrix3d::Zero();
  for (unsigned int i = 0; i < 3; ++i)
    {
      K(i, i) += k[i];
      if (i > 0)
        {
          K(i - 1, i - 1) += k[i];
          K(i - 1, i) = K(i, i - 1) = -k[i];
        }
    }
  Eigen::Vector3d p;
  for (unsigned int i = 0; i < 3; ++i)
    p[i] = m[i] * z[i];
  p /= p.sum();
  const double slope = 1 / K.lu().solve(p)[2];
  for (unsigned int i = 1; i < r.points.size(); ++i)
    {
      BOOST_TEST(r.points[i].lambda / r.points[i].control_displacement == slope,
                 boost::test_tools::tolerance(1e-9));
      BOOST_TEST(r.points[i].base_shears[0] == r.points[i].lambda,
                 boost::test_tools::tolerance(1e-9));
    }
  BOOST_TEST(r.points.back().control_displacement == 0.002 * 9, boost::test_tools::tolerance(1e-12));
  // Annex B's factors of the shape Phi_i = z_i / z_3
  double m_star = 0, m_phi2 = 0;
  for (unsigned int i = 0; i < 3; ++i)
    {
      m_star += m[i] * z[i] / 9;
      m_phi2 += m[i] * z[i] * z[i] / 81;
    }
  BOOST_TEST(r.equivalent_mass == m_star, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(r.gamma == m_star / m_phi2, boost::test_tools::tolerance(1e-12));
}

// Elastic-perfectly plastic storeys (Bouc-Wen, alpha = 0, n = 30) of
// strengths F_i = k_i u_y,i under a uniform pattern (p_i = m_i / sum m):
// storey i carries lambda sum_{j >= i} p_j, and the upper-bound theorem's
// collapse factor is min_i F_i / sum_{j >= i} p_j (here storey 2's). The
// last point's base shear to 1e-3 (Bouc-Wen reaches F_y asymptotically),
// and no point above it by more than 0.5 % (the law's integration over a
// step overshoots the knee slightly, then relaxes).
BOOST_AUTO_TEST_CASE(a_shear_building_reaches_its_storey_mechanism)
{
  const std::string plastic = " set Storey yield drifts = 0.004, 0.002, 0.005\n"
                              " subsection Bouc-Wen\n  set alpha = 0\n  set n = 30\n end\n";
  const PushoverResult r = pushover_of(
    "pushover_storeys", shear_building(plastic, " set Load pattern = uniform\n"
                                                " set Target drift = 0.006\n"
                                                " set Number of steps = 60\n"));
  BOOST_REQUIRE(r.completed);
  const double F[3] = {6e7 * 0.004, 5e7 * 0.002, 4e7 * 0.005};
  const double above[3] = {1.0, 5.0 / 9, 2.0 / 9};
  double       collapse = 1e300;
  for (unsigned int i = 0; i < 3; ++i)
    collapse = std::min(collapse, F[i] / above[i]);
  BOOST_TEST(collapse == F[1] / above[1]);
  BOOST_TEST(r.points.back().base_shears[0] == collapse, boost::test_tools::tolerance(1e-3));
  for (const PushoverPoint &point : r.points)
    BOOST_TEST(point.base_shears[0] <= collapse * (1 + 5e-3));
}

// A portal frame (h = 4 m) with plastic hinges (M_p = 2e5 N m, alpha = 0,
// n = 10) at the column bases and beam ends under a lateral load at its
// floor: the sway mechanism F h theta = 4 M_p theta gives F = 4 M_p / h;
// the last point's base shear to 1e-3.
BOOST_AUTO_TEST_CASE(a_portal_frame_reaches_its_sway_mechanism)
{
  const double      Mp = 2e5, h = 4;
  const std::string text =
    "subsection Building 1\n set Type = frame\n set Number of storeys = 1\n"
    " set Number of bays = 1\n set Storey heights = 4\n set Bay widths = 6\n"
    " set Column E = 3e10\n set Column A = 0.16\n set Column I = 2.1e-3\n"
    " set Beam E = 3e10\n set Beam A = 0.15\n set Beam I = 3.1e-3\n set Floor masses = 2e4\n"
    " subsection Hinges\n  set Locations = column bases, beam ends\n  set Yield moment = 2e5\n"
    " end\n subsection Bouc-Wen\n  set alpha = 0\n  set n = 10\n end\n"
    " subsection Damping\n  set Type = none\n end\nend\n"
    "subsection Ground motion\n set Type = none\nend\n"
    "subsection Pushover\n set Load pattern = uniform\n set Target drift = 0.03\n"
    " set Number of steps = 150\n set Max iterations = 50\nend\n";
  const PushoverResult r = pushover_of("pushover_portal", text);
  BOOST_REQUIRE(r.completed);
  BOOST_TEST(r.points.back().base_shears[0] == 4 * Mp / h, boost::test_tools::tolerance(1e-3));
  BOOST_REQUIRE_EQUAL(r.elements.size(), 4u);
  for (unsigned int e = 0; e < 4; ++e) // every hinge at its plastic moment
    BOOST_TEST(std::abs(r.points.back().element_forces[e]) == Mp,
               boost::test_tools::tolerance(1e-3));
}

// Two one-storey buildings 0.01 m apart, the left one softer, pushed the
// same way: once the gap closes the left one leans on the right one, whose
// base shear then exceeds the load factor by the contact force, the two
// together carrying 2 lambda; before, each carries lambda alone.
BOOST_AUTO_TEST_CASE(two_buildings_push_through_their_gap)
{
  const std::string text =
    "subsection Model\n set Number of buildings = 2\n set Separations = 0.01\nend\n"
    "subsection Building 1\n set Type = shear\n set Number of storeys = 1\n"
    " set Storey heights = 3\n set Floor masses = 2e4\n set Storey stiffnesses = 1e7\n"
    " subsection Damping\n  set Type = none\n end\nend\n"
    "subsection Building 2\n set Type = shear\n set Number of storeys = 1\n"
    " set Storey heights = 3\n set Floor masses = 2e4\n set Storey stiffnesses = 4e7\n"
    " subsection Damping\n  set Type = none\n end\nend\n"
    "subsection Ground motion\n set Type = none\nend\n"
    "subsection Contact\n set Law = linear\n set Stiffness = 5e8\nend\n"
    "subsection Pushover\n set Load pattern = uniform\n set Target drift = 0.01\n"
    " set Number of steps = 40\nend\n";
  const PushoverResult r = pushover_of("pushover_pair", text);
  BOOST_REQUIRE(r.completed);
  bool closed = false;
  for (const PushoverPoint &p : r.points)
    {
      BOOST_TEST(p.base_shears[0] + p.base_shears[1] == 2 * p.lambda,
                 boost::test_tools::tolerance(1e-8));
      if (p.control_displacement < 0.009)
        BOOST_TEST(p.base_shears[1] == p.lambda, boost::test_tools::tolerance(1e-8));
      closed = closed || p.base_shears[1] > 1.01 * p.lambda;
    }
  BOOST_TEST(closed);
}

// ASCE 41-17's C0 by its first way (7.4.3.3.2): the first mode's
// participation factor phi^T M 1 / phi^T M phi times its roof ordinate, its
// period T_i and the building's mass, against the shear building's
// eigenproblem K phi = omega^2 M phi solved here (Eigen's generalized
// self-adjoint solver), to 1e-9; a push without ASCE 41 computes no mode.
BOOST_AUTO_TEST_CASE(asce41_c0_is_the_first_mode_participation_at_the_roof)
{
  const std::string pushover = " set Target drift = 0.002\n set Number of steps = 2\n";
  const std::string spectrum = "subsection Spectrum\n set Target = ec8-type-1\nend\n";
  const PushoverResult r = pushover_of(
    "pushover_asce41", shear_building("", pushover + " set Target method = ASCE41\n") + spectrum);
  BOOST_REQUIRE(r.completed);
  const double    m[3] = {4e4, 3e4, 2e4}, k[3] = {6e7, 5e7, 4e7};
  Eigen::Matrix3d K    = Eigen::Matrix3d::Zero(), M = Eigen::Matrix3d::Zero();
  for (unsigned int i = 0; i < 3; ++i)
    {
      M(i, i) = m[i];
      K(i, i) += k[i];
      if (i > 0)
        {
          K(i - 1, i - 1) += k[i];
          K(i - 1, i) = K(i, i - 1) = -k[i];
        }
    }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> eigen(K, M);
  const Eigen::Vector3d phi = eigen.eigenvectors().col(0);
  const double          c0  = phi[2] * phi.dot(M * Eigen::Vector3d::Ones()) / phi.dot(M * phi);
  BOOST_TEST(c0 > 1.0);
  BOOST_TEST(r.first_mode_c0 == c0, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(r.first_period == 2 * M_PI / std::sqrt(eigen.eigenvalues()[0]),
             boost::test_tools::tolerance(1e-9));
  BOOST_TEST(r.building_mass == 9e4, boost::test_tools::tolerance(1e-12));
  const PushoverResult n2 = pushover_of("pushover_n2", shear_building("", pushover) + spectrum);
  BOOST_TEST(n2.first_period == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
