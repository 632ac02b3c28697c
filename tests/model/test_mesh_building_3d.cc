// 3D frames drawn in Gmsh (Model/Dimension = 3, Type = mesh; model/
// mesh_building_3d.h): the mesh of a generated 3D frame's geometry (set
// back, turned, eccentric mass, hinges) against the generator (modes and
// time history), a one-storey portal against the closed form, the convex
// hull and polygon properties against hand values (doc/verification.md,
// "3D frames drawn in Gmsh").
#include <poundfe/dynamics/analysis.h>
#include <poundfe/mesh/line_mesh.h>
#include <poundfe/model/mesh_building_3d.h>

#include "../dynamics/time_history_helpers.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace poundfe;

namespace
{
  /// A Gmsh 2.2 text of `lines` (pairs of (x, y, z)) with physical ids.
  struct DrawnLine
  {
    std::array<double, 3> a, b;
    unsigned int          id;
  };

  std::string
  gmsh_22(const std::vector<DrawnLine> &lines)
  {
    std::vector<std::array<double, 3>> nodes;
    const auto node = [&](const std::array<double, 3> &x) {
      for (unsigned int n = 0; n < nodes.size(); ++n)
        if (nodes[n] == x)
          return n + 1;
      nodes.push_back(x);
      return unsigned(nodes.size());
    };
    std::ostringstream elements;
    for (unsigned int e = 0; e < lines.size(); ++e)
      {
        const unsigned int a = node(lines[e].a), b = node(lines[e].b);
        elements << e + 1 << " 1 2 " << lines[e].id << " " << e + 1 << " " << a << " " << b
                 << "\n";
      }
    std::ostringstream text;
    text.precision(17);
    text << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << nodes.size() << "\n";
    for (unsigned int n = 0; n < nodes.size(); ++n)
      text << n + 1 << " " << nodes[n][0] << " " << nodes[n][1] << " " << nodes[n][2] << "\n";
    text << "$EndNodes\n$Elements\n" << lines.size() << "\n"
         << elements.str() << "$EndElements\n";
    return text.str();
  }

  /// The common tail: damping, ground motion, time integration, output.
  const std::string tail =
    " subsection Damping\n  set Type = coefficients\n  set a0 = 0.3\n  set a1 = 0.003\n"
    " end\nend\n"
    "subsection Ground motion\n set Type = kanai-tajimi\n set Components = 2\n"
    " set Incidence angle = 25\n subsection Stochastic\n"
    "  set Target PGA = 0.6\n  set Duration = 2\n  set Seed = 3\n"
    "  set Method = spectral-representation\n  set Cutoff frequency = 100\n end\nend\n"
    "subsection Time integration\n set Time step = 0.005\n"
    " set Newton residual tolerance = 1e-12\nend\n"
    "subsection Output\n set Number of modes = 8\nend\n";

  const std::string hinges = " subsection Hinges\n  set Locations = column bases, beam ends\n"
                             "  set Yield moment = 8e4\n end\n";

  /// Two storeys (3.5, 3 m) on 2 x 1 bays (6 m, 5 m), storey 2 set back by
  /// the +x bay, turned 10 degrees, mass centre off by (0.4, -0.3): as the
  /// generator makes it ...
  std::string
  generated_text()
  {
    return "subsection Model\n set Dimension = 3\nend\n"
           "subsection Building 1\n set Type = frame\n set Number of storeys = 2\n"
           " set Storey heights = 3.5, 3\n set Number of bays = 2\n set Bay widths = 6\n"
           " set Number of bays y = 1\n set Bay widths y = 5\n set Set-backs = 2: 0 1 0 0\n"
           " set Floor masses = 6e4, 3e4\n"
           " set Column E = 3e10\n set Column G = 1.25e10\n set Column A = 0.16\n"
           " set Column I = 2.1e-3\n set Column Iz = 1.5e-3\n set Column J = 3e-3\n"
           " set Column mass per length = 400\n"
           " set Beam E = 3e10\n set Beam G = 1.25e10\n set Beam A = 0.12\n"
           " set Beam I = 1.6e-3\n set Beam Iz = 9e-4\n set Beam J = 1.9e-3\n"
           " set Beam mass per length = 300\n"
           " subsection Plan\n  set Rotation = 10\n  set Mass eccentricity = 0.4, -0.3\n end\n" +
           hinges + tail;
  }

  /// ... and drawn in a mesh (origin at a corner; some lines drawn top
  /// down or right to left), written to a temporary file.
  std::string
  mesh_text()
  {
    std::vector<DrawnLine> lines;
    const double           z[3] = {0, 3.5, 6.5};
    for (unsigned int s = 1; s <= 2; ++s)
      for (const double x : {0.0, 6.0, 12.0})
        for (const double y : {0.0, 5.0})
          if (s == 1 || x < 12)
            {
              if ((x == 6) != (y == 5)) // some columns drawn top down
                lines.push_back({{{x, y, z[s]}}, {{x, y, z[s - 1]}}, 1});
              else
                lines.push_back({{{x, y, z[s - 1]}}, {{x, y, z[s]}}, 1});
            }
    for (unsigned int s = 1; s <= 2; ++s)
      {
        const double right = s == 1 ? 12 : 6;
        for (const double y : {0.0, 5.0})
          for (double x = 0; x < right; x += 6)
            lines.push_back({{{x + 6, y, z[s]}}, {{x, y, z[s]}}, 2}); // right to left
        for (double x = 0; x <= right; x += 6)
          lines.push_back({{{x, 0, z[s]}}, {{x, 5, z[s]}}, 2});
      }
    const std::string mesh = poundfe_test::temporary_file("mesh3d_setback.msh", gmsh_22(lines));
    return "subsection Model\n set Dimension = 3\nend\n"
           "subsection Building 1\n set Type = mesh\n set Mesh file = " + mesh + "\n"
           " set Group ids = 1, 2\n set Group E = 3e10\n set Group G = 1.25e10\n"
           " set Group A = 0.16, 0.12\n set Group I = 2.1e-3, 1.6e-3\n"
           " set Group Iz = 1.5e-3, 9e-4\n set Group J = 3e-3, 1.9e-3\n"
           " set Group mass per length = 400, 300\n set Floor masses = 6e4, 3e4\n"
           " subsection Plan\n  set Rotation = 10\n  set Mass eccentricity = 0.4, -0.3\n end\n" +
           hinges + tail;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(mesh_building_3d)

BOOST_AUTO_TEST_CASE(convex_hull_and_polygon_properties)
{
  // an L of three unit squares: its hull is the pentagon without the
  // notch corner; a 6 x 4 rectangle: A = 24, J = A (36 + 16) / 12 = 104
  const std::vector<Point2> hull =
    convex_hull({{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}});
  BOOST_TEST(hull.size() == 5u);
  BOOST_TEST(std::none_of(hull.begin(), hull.end(),
                          [](const Point2 &q) { return q.x == 1 && q.y == 1; }));
  const PolygonProperties r = polygon_properties(convex_hull({{3, 1}, {9, 1}, {9, 5}, {3, 5}}));
  BOOST_TEST(r.area == 24, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(r.centroid.x == 6, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(r.centroid.y == 3, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(r.polar_moment == 104, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(convex_hull({{0, 0}, {1, 1}, {2, 2}}).size() == 2u); // a line
}

BOOST_AUTO_TEST_CASE(mesh_of_a_generated_frame_is_the_generated_frame)
{
  // second method: the generator. The same members, sections, floors,
  // hinges and masses in another numbering; the modes and the floors'
  // (ux, uy, θz) histories agree to round-off (tolerance 1e-10: Newton
  // stops at 1e-12 in both, round-off amplified by the time stepping)
  const InputParameters pg = poundfe_test::input_of("mesh3d_generated", generated_text());
  const InputParameters pm = poundfe_test::input_of("mesh3d_mesh", mesh_text());
  const Analysis        ag = prepare_analysis(pg), am = prepare_analysis(pm);
  BOOST_REQUIRE_EQUAL(ag.model.members_3d.size(), am.model.members_3d.size());
  BOOST_REQUIRE_EQUAL(ag.model.hinges_3d.size(), am.model.hinges_3d.size());
  BOOST_REQUIRE_EQUAL(ag.model.n_equations(), am.model.n_equations());
  BOOST_REQUIRE_EQUAL(am.model.buildings[0].floors.size(), 2u);
  BOOST_REQUIRE_GE(am.modes.n_modes(), 8u);
  double worst_mode = 0;
  for (unsigned int i = 0; i < 8; ++i)
    worst_mode = std::max(worst_mode, std::abs(am.modes.omega[i] / ag.modes.omega[i] - 1));
  BOOST_TEST_MESSAGE("largest relative difference of the 8 frequencies " << worst_mode);
  BOOST_TEST(worst_mode <= 1e-10);
  for (unsigned int i = 0; i < 2; ++i)
    {
      const PlanFloor &g = ag.model.buildings[0].plan[i], &m = am.model.buildings[0].plan[i];
      BOOST_TEST(std::abs(g.mass_centre.x - m.mass_centre.x) <= 1e-12);
      BOOST_TEST(std::abs(g.mass_centre.y - m.mass_centre.y) <= 1e-12);
    }

  const auto rg = poundfe_test::recorded_run(ag, pg), rm = poundfe_test::recorded_run(am, pm);
  BOOST_REQUIRE_EQUAL(rg.u.size(), rm.u.size());
  double worst = 0;
  for (unsigned int i = 0; i < 2; ++i)
    for (const Component c : {Component::ux, Component::uy, Component::rz})
      {
        const int eg = ag.model.equation(Model::dof(ag.model.buildings[0].floors[i].nodes[0], c));
        const int em = am.model.equation(Model::dof(am.model.buildings[0].floors[i].nodes[0], c));
        BOOST_REQUIRE(eg >= 0 && em >= 0);
        double peak = 0, difference = 0;
        for (unsigned int s = 0; s < rg.u.size(); ++s)
          {
            peak       = std::max(peak, std::abs(rg.u[s][eg]));
            difference = std::max(difference, std::abs(rg.u[s][eg] - rm.u[s][em]));
          }
        BOOST_REQUIRE(peak > 0);
        worst = std::max(worst, difference / peak);
      }
  BOOST_TEST_MESSAGE("largest relative history difference of the floors " << worst
                     << "; hysteretic energy " << rm.energy.hysteretic << " J of input "
                     << rm.energy.input << " J");
  BOOST_TEST(worst <= 1e-10);
  // the hinges yield: the comparison covers the nonlinear path (more than
  // 1 % of the input dissipated by them)
  BOOST_TEST(rm.energy.hysteretic > 0.01 * rm.energy.input);
  BOOST_TEST(std::abs(rm.energy.hysteretic / rg.energy.hysteretic - 1) <= 1e-10);
}

BOOST_AUTO_TEST_CASE(mesh_and_generator_agree_on_a_foundation_and_without_diaphragm)
{
  // the same pair of models (a) on a compliant foundation (Gazetas, under
  // the plan centre: the basemat and its rocking node take the bases) and
  // (b) with Diaphragm = none (every joint free, the floor mass in equal
  // shares): the 8 lowest frequencies agree to round-off (1e-10)
  const std::string foundation = " subsection Foundation\n  set Type = gazetas\n"
                                 "  set Shear-wave velocity = 150\n  set Soil density = 1900\n"
                                 "  set Poisson ratio = 0.3\n  set Length = 14\n"
                                 "  set Width = 7\n  set Mass = 1e5\n  set Rotary inertia = 1.5e6\n"
                                 "  set Rotary inertia x = 6e5\n  set Polar inertia = 2e6\n end\n";
  for (const std::string &extra : {foundation, std::string(" set Diaphragm = none\n")})
    {
      const auto with = [&](std::string text) {
        return text.replace(text.find(" subsection Plan"), 0, extra);
      };
      const Analysis ag =
        prepare_analysis(poundfe_test::input_of("mesh3d_generated_b", with(generated_text())));
      const Analysis am =
        prepare_analysis(poundfe_test::input_of("mesh3d_mesh_b", with(mesh_text())));
      BOOST_REQUIRE_EQUAL(ag.model.n_equations(), am.model.n_equations());
      BOOST_REQUIRE_GE(am.modes.n_modes(), 8u);
      double worst = 0;
      for (unsigned int i = 0; i < 8; ++i)
        worst = std::max(worst, std::abs(am.modes.omega[i] / ag.modes.omega[i] - 1));
      BOOST_TEST_MESSAGE("largest relative difference of the 8 frequencies " << worst << " with "
                                                                               << extra);
      BOOST_TEST(worst <= 1e-10);
    }
}

BOOST_AUTO_TEST_CASE(one_storey_portal_matches_the_closed_form)
{
  // four columns at the corners of a 6 m x 4 m bay, h = 3 m, beams and
  // axial stiffness 1e6-1e7 times the columns' bending: each column clamped
  // at both ends sways 12 E Iy / h^3 along x and 12 E Iz / h^3 along y
  // (default axes: Group I resists sway along x), twists G J / h. Mass m
  // at the plan centre, I = m (a^2 + c^2) / 12 (the hull's): uncoupled,
  // ω_x^2 = 4 k_x / m, ω_y^2 = 4 k_y / m, ω_θ^2 = (4 k_x (c/2)^2 + 4 k_y
  // (a/2)^2 + 4 G J / h) / I. Turned by 30 degrees: the same frequencies.
  const double a = 6, c = 4, h = 3, E = 3e10, G = 1.2e10, Iy = 2e-3, Iz = 1e-3, J = 1.5e-3,
               m = 5e4;
  std::vector<DrawnLine> lines;
  for (const double x : {0.0, a})
    for (const double y : {0.0, c})
      lines.push_back({{{x, y, 0}}, {{x, y, h}}, 7});
  lines.push_back({{{0, 0, h}}, {{a, 0, h}}, 9});
  lines.push_back({{{0, c, h}}, {{a, c, h}}, 9});
  lines.push_back({{{0, 0, h}}, {{0, c, h}}, 9});
  lines.push_back({{{a, 0, h}}, {{a, c, h}}, 9});
  const std::string mesh = poundfe_test::temporary_file("mesh3d_portal.msh", gmsh_22(lines));
  const std::string text =
    "subsection Model\n set Dimension = 3\nend\n"
    "subsection Building 1\n set Type = mesh\n set Mesh file = " + mesh + "\n"
    " set Group ids = 7, 9\n set Group E = 3e10\n set Group G = 1.2e10\n"
    " set Group A = 1e4\n set Group I = 2e-3, 1e4\n set Group Iz = 1e-3, 1e4\n"
    " set Group J = 1.5e-3, 1e4\n set Floor masses = 5e4\n"
    " subsection Plan\n  set Rotation = 30\n end\n"
    " subsection Damping\n  set Type = none\n end\nend\n"
    "subsection Ground motion\n set Type = none\nend\n"
    "subsection Output\n set Number of modes = 3\nend\n";
  const double kx = 12 * E * Iy / (h * h * h), ky = 12 * E * Iz / (h * h * h);
  const double I = m * (a * a + c * c) / 12;
  std::vector<double> expected{std::sqrt(4 * kx / m), std::sqrt(4 * ky / m),
                               std::sqrt((4 * kx * c * c / 4 + 4 * ky * a * a / 4 +
                                          4 * G * J / h) / I)};
  std::sort(expected.begin(), expected.end());
  const Analysis analysis = prepare_analysis(poundfe_test::input_of("mesh3d_portal", text));
  BOOST_REQUIRE_GE(analysis.modes.n_modes(), 3u);
  for (unsigned int i = 0; i < 3; ++i)
    {
      BOOST_TEST_MESSAGE("portal mode " << i + 1 << ": " << analysis.modes.omega[i]
                                        << " rad/s, closed form " << expected[i]
                                        << ", relative difference "
                                        << std::abs(analysis.modes.omega[i] / expected[i] - 1));
      // tolerance: the beams and the axial stiffness are 1e6-1e7 times the
      // columns' bending stiffness, which leaves ~1e-7
      BOOST_TEST(analysis.modes.omega[i] == expected[i], boost::test_tools::tolerance(1e-6));
    }
}

BOOST_AUTO_TEST_SUITE_END()
