// Set-backs of 3D frame buildings (Building <i>/Set-backs; model/
// set_backs.h; doc/verification.md, "Set-backs"): the floors' masses, mass
// centres, polar moments and slab outlines of a set-back frame against the
// hand computation of its reduced plans; its columns stand on the joints of
// the storey below; its modes are finite; a set-back symmetric about the
// plan centre does not twist under shaking along x.
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>

#include "../dynamics/time_history_helpers.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

using namespace poundfe;

namespace
{
  /// A 4-storey frame, 4 bays of 5 m along x and 2 of 6 m along y
  /// (grid lines x = -10, -5, 0, 5, 10 and y = -6, 0, 6 from the plan
  /// centre), storeys of 3 m, lumped masses, with the given set-backs and
  /// mass eccentricity.
  std::string
  set_back_text(const std::string &set_backs, const std::string &eccentricity)
  {
    return "subsection Model\n set Dimension = 3\nend\n"
           "subsection Building 1\n set Type = frame\n set Number of storeys = 4\n"
           " set Storey heights = 3\n set Number of bays = 4\n set Bay widths = 5\n"
           " set Number of bays y = 2\n set Bay widths y = 6\n"
           " set Floor masses = 8e4, 8e4, 6e4, 3e4\n"
           " set Column E = 3e10\n set Column G = 1.25e10\n set Column A = 0.2\n"
           " set Column I = 3.3e-3\n set Column Iz = 2.7e-3\n set Column J = 5.2e-3\n"
           " set Beam E = 3e10\n set Beam G = 1.25e10\n set Beam A = 0.15\n"
           " set Beam I = 3.1e-3\n set Beam Iz = 1.1e-3\n set Beam J = 2.6e-3\n"
           " set Column mass per length = 400\n set Beam mass per length = 300\n"
           " set Set-backs = " + set_backs + "\n"
           " subsection Plan\n  set Mass eccentricity = " + eccentricity + "\n end\n"
           " subsection Damping\n  set Type = coefficients\n  set a0 = 0.3\n  set a1 = 0.002\n"
           " end\nend\n"
           "subsection Ground motion\n set Type = kanai-tajimi\n subsection Stochastic\n"
           "  set Target PGA = 0.3\n  set Duration = 1\n  set Seed = 3\n"
           "  set Method = spectral-representation\n  set Cutoff frequency = 100\n end\nend\n"
           "subsection Time integration\n set Time step = 0.005\nend\n"
           "subsection Output\n set Number of modes = 8\nend\n";
  }

  bool
  near(const double a, const double b)
  {
    return std::abs(a - b) <= 1e-12 * std::max({std::abs(a), std::abs(b), 1.0});
  }
} // namespace

// Storey 3 loses the +x bay, storey 4 keeps x in [-5, 0] and y in [-6, 0]:
// the slabs (centre from the plan centre; sides) are
//   floors 1, 2: (0, 0), 20 x 12;  floor 3: (-2.5, 0), 15 x 12;
//   floor 4: (-2.5, -3), 5 x 6,
// the mass centres those plus the eccentricity (1, 0.5), the polar moments
// m (L_x^2 + L_y^2) / 12. The members: 15, 15, 12 and 4 columns of 3 m;
// beams of 5 m along x: 12, 12, 9, 2; of 6 m along y: 10, 10, 8, 2. The
// mass along x of the assembled (lumped) M, r_x^T M r_x, is the floors'
// plus the members' less the half of the first storey's columns lumped at
// the clamped base. All to 1e-12 (rounding).
BOOST_AUTO_TEST_CASE(set_back_floors_follow_the_reduced_plan)
{
  const InputParameters p =
    poundfe_test::input_of("set_backs", set_back_text("3: 0 1 0 0; 4: 1 2 0 1", "1, 0.5"));
  const Analysis  analysis = prepare_analysis(p);
  const Model    &model    = analysis.model;
  const Building &building = model.buildings[0];
  BOOST_REQUIRE(building.plan.size() == 4u);
  const double masses[4] = {8e4, 8e4, 6e4, 3e4};
  const double centres[4][2] = {{0, 0}, {0, 0}, {-2.5, 0}, {-2.5, -3}};
  const double sides[4][2]   = {{20, 12}, {20, 12}, {15, 12}, {5, 6}};
  // the plan centre on the site: floor 1's mass centre less the eccentricity
  const Point2 origin{building.plan[0].mass_centre.x - 1, building.plan[0].mass_centre.y - 0.5};
  for (unsigned int i = 0; i < 4; ++i)
    {
      const PlanFloor &floor  = building.plan[i];
      const unsigned int node = building.floors[i].nodes[0]; // the diaphragm's master
      BOOST_TEST(near(floor.mass_centre.x - origin.x, centres[i][0] + 1));
      BOOST_TEST(near(floor.mass_centre.y - origin.y, centres[i][1] + 0.5));
      BOOST_TEST(near(model.nodes[node].position.x, floor.mass_centre.x));
      const auto mass = std::find_if(model.masses.begin(), model.masses.end(),
                                     [&](const NodalMass &m) { return m.node == node; });
      BOOST_REQUIRE(mass != model.masses.end());
      BOOST_TEST(near(mass->mass, masses[i]));
      BOOST_TEST(near(mass->polar_moment,
                      masses[i] * (sides[i][0] * sides[i][0] + sides[i][1] * sides[i][1]) / 12));
      // the outline: the rectangle of the kept grid lines, counter-clockwise
      BOOST_REQUIRE(floor.outline.size() == 4u);
      const double hx = 0.5 * sides[i][0], hy = 0.5 * sides[i][1];
      const double corners[4][2] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
      for (unsigned int k = 0; k < 4; ++k)
        {
          BOOST_TEST(near(floor.outline[k].x - origin.x, centres[i][0] + corners[k][0]));
          BOOST_TEST(near(floor.outline[k].y - origin.y, centres[i][1] + corners[k][1]));
        }
    }
  unsigned int columns[4] = {0, 0, 0, 0}, beams_x[4] = {0, 0, 0, 0}, beams_y[4] = {0, 0, 0, 0};
  for (const Member3D &m : model.members_3d)
    {
      const unsigned int floor = std::lround(m.ends[1][2] / 3) - 1;
      if (m.kind == MemberKind::column)
        {
          ++columns[floor];
          // it stands on the top of a column of the storey below (or the ground)
          const bool supported =
            floor == 0 || std::any_of(model.members_3d.begin(), model.members_3d.end(),
                                      [&](const Member3D &c) {
                                        return c.kind == MemberKind::column &&
                                               near(c.ends[1][0], m.ends[0][0]) &&
                                               near(c.ends[1][1], m.ends[0][1]) &&
                                               near(c.ends[1][2], m.ends[0][2]);
                                      });
          BOOST_TEST(supported, m.label << " stands on no column");
        }
      else
        ++(std::abs(m.ends[1][0] - m.ends[0][0]) > 1 ? beams_x : beams_y)[floor];
    }
  const unsigned int expected_columns[4] = {15, 15, 12, 4}, expected_x[4] = {12, 12, 9, 2},
                     expected_y[4] = {10, 10, 8, 2};
  double members = 0;
  for (unsigned int i = 0; i < 4; ++i)
    {
      BOOST_TEST(columns[i] == expected_columns[i]);
      BOOST_TEST(beams_x[i] == expected_x[i]);
      BOOST_TEST(beams_y[i] == expected_y[i]);
      members += 400 * 3 * expected_columns[i] + 300 * (5 * expected_x[i] + 6 * expected_y[i]);
    }
  const double total = 8e4 + 8e4 + 6e4 + 3e4 + members;
  BOOST_TEST(near(model.total_mass(0), total));
  const Vector &r = analysis.system.influence;
  BOOST_TEST(near(r.dot(analysis.system.mass * r), total - 0.5 * 400 * 3 * 15));
  // the modes of the set-back frame: finite, positive, increasing
  BOOST_REQUIRE(analysis.modes.omega.size() == 8u);
  for (unsigned int k = 0; k < 8; ++k)
    {
      BOOST_TEST(std::isfinite(analysis.modes.omega[k]));
      BOOST_TEST(analysis.modes.omega[k] > 0);
    }
}

// A set-back symmetric about the plan centre (storeys 3 and 4 lose one bay
// on each side along x) with no eccentricity: the mass and stiffness are
// symmetric about the x-z plane, so shaking along x does not twist the
// floors. |theta_z| times the half plan width stays below 1e-10 of the peak
// floor displacement (rounding). Storeys 3 and 4 set back along y instead
// (their mass centres 3 m south of the lower storeys' stiffness centre) do
// twist under the same shaking: checked here so that the test can fail.
BOOST_AUTO_TEST_CASE(symmetric_set_back_does_not_twist)
{
  const auto twist = [](const std::string &name, const std::string &set_backs) {
    const InputParameters p = poundfe_test::input_of(name, set_back_text(set_backs, "0, 0"));
    const Analysis        analysis = prepare_analysis(p);
    const auto            run      = poundfe_test::recorded_run(analysis, p);
    double                rotation = 0, displacement = 0;
    for (const Floor &floor : analysis.model.buildings[0].floors)
      {
        const int ux = analysis.model.equation(Model::dof(floor.nodes[0], Component::ux));
        const int rz = analysis.model.equation(Model::dof(floor.nodes[0], Component::rz));
        for (const Vector &u : run.u)
          {
            rotation     = std::max(rotation, std::abs(u[rz]) * 10);
            displacement = std::max(displacement, std::abs(u[ux]));
          }
      }
    return rotation / displacement;
  };
  const double symmetric  = twist("set_backs_symmetric", "3: 1 1 0 0");
  const double asymmetric = twist("set_backs_asymmetric", "3: 0 0 0 1");
  BOOST_TEST_MESSAGE("set-backs: twist " << symmetric << " (symmetric), " << asymmetric
                                         << " (asymmetric) of the peak floor displacement");
  BOOST_TEST(symmetric <= 1e-10);
  BOOST_TEST(asymmetric > 1e-4);
}
