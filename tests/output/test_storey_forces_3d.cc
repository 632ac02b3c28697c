// Storey forces of 3D models (output/storey_forces.h, doc/theory.md §10):
// under static loads at the floors' mass centres the shears and the torque
// of every storey are, by equilibrium of the building above the cut,
//   V_x = Σ_{f ≥ s} F_x,f,  V_y = Σ_{f ≥ s} F_y,f,
//   T   = Σ_{f ≥ s} (M_z,f + (C_f - C_s) × F_f)   (about C_s at rest),
// for a 3D frame (rigid diaphragms, base hinges, eccentric masses, turned
// in plan) from its columns' element forces and for a torsionally coupled
// shear building from its resisting planes (doc/verification.md, "Storey
// forces of 3D models").
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/output/storey_forces.h>

#include "../dynamics/time_history_helpers.h"

#include <Eigen/SparseLU>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;

namespace
{
  /// One building of three storeys, its plan away from the origin, turned,
  /// its masses eccentric; `plan`: more Plan entries.
  std::string
  common(const std::string &plan)
  {
    return "subsection Model\n set Dimension = 3\nend\n"
           "subsection Building 1\n set Number of storeys = 3\n"
           " set Storey heights = 4, 3.2, 3.2\n set Floor masses = 9e4, 8e4, 6e4\n"
           " subsection Plan\n  set Position = 3, -2\n  set Rotation = 20\n"
           "  set Mass eccentricity = 1.1, -0.7\n" + plan + " end\n";
  }

  const std::string frame = common("") + " set Type = frame\n set Number of bays = 2\n"
                                     " set Bay widths = 6, 4\n set Number of bays y = 1\n"
                                     " set Bay widths y = 5\n set Column E = 3e10\n"
                                     " set Column G = 1.25e10\n set Column A = 0.2\n"
                                     " set Column I = 3.3e-3\n set Column Iz = 2.1e-3\n"
                                     " set Column J = 4.2e-3\n set Beam E = 3e10\n"
                                     " set Beam G = 1.25e10\n set Beam A = 0.15\n"
                                     " set Beam I = 3.1e-3\n set Beam Iz = 1.1e-3\n"
                                     " set Beam J = 2.6e-3\n"
                                     " subsection Hinges\n  set Locations = column bases\n"
                                     "  set Yield moment = 3e5\n end\nend\n";

  const std::string shear = common("  set Plan dimensions = 12, 8\n"
                                   "  set Resisting planes = -6 0 90 3e7; 6 0 90 1e7; "
                                   "0 -4 0 2.5e7; 0 4 0 1.5e7; 2 1 30 5e6\n") +
                            " set Type = shear\n set Storey stiffnesses = 4e7, 3e7, 2e7\nend\n";

  /// Loads (F_x, F_y, M_z) at the mass centre of each floor; solves K u = f
  /// and compares every storey's forces with the equilibrium of the
  /// building above its cut.
  void
  check_storeys(const std::string &name, const std::string &text)
  {
    const Analysis     a     = prepare_analysis(poundfe_test::input_of(name, text));
    const Model       &model = a.model;
    const Building    &b     = model.buildings.front();
    const unsigned int n     = b.floors.size();
    const double       loads[3][3] = {{1e5, -4e4, 2e5}, {-3e4, 7e4, -5e4}, {6e4, 2e4, 1e5}};
    Vector             f = Vector::Zero(model.n_equations());
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int c = 0; c < 3; ++c)
        f[model.equation(Model::dof(b.floors[i].nodes[0], static_cast<Component>(c)))] =
          loads[i][c];
    Eigen::SparseLU<SparseMatrix> lu(a.system.stiffness);
    BOOST_REQUIRE(lu.info() == Eigen::Success);
    const Vector u = lu.solve(f);

    const NonlinearElements elements = make_nonlinear_elements(model);
    const StoreyForces      forces(model, elements);
    for (unsigned int s = 0; s < n; ++s)
      {
        std::array<double, 3> expected{{0, 0, 0}};
        const Point2         &Cs = b.plan[s].mass_centre;
        for (unsigned int i = s; i < n; ++i)
          {
            const Point2 &Ci = b.plan[i].mass_centre;
            expected[0] += loads[i][0];
            expected[1] += loads[i][1];
            expected[2] +=
              loads[i][2] + (Ci.x - Cs.x) * loads[i][1] - (Ci.y - Cs.y) * loads[i][0];
          }
        const std::array<double, 3> V = forces.plan_forces(forces.index(0, s), u);
        const double scale = std::hypot(expected[0], expected[1]) * 10 + std::abs(expected[2]);
        for (unsigned int c = 0; c < 3; ++c)
          {
            BOOST_TEST_MESSAGE(name << " storey " << s + 1 << " component " << c << ": " << V[c]
                                    << " against " << expected[c] << ", difference "
                                    << std::abs(V[c] - expected[c]) / scale);
            // tolerance: the solve's round-off (measured ~1e-15); κ(K) ~1e6
            // (axial against bending stiffness) bounds it by ~1e-10
            BOOST_TEST(std::abs(V[c] - expected[c]) <= 1e-10 * scale);
          }
        BOOST_TEST(forces.storey_shear(forces.index(0, s), u, Vector::Zero(u.size())) == V[0]);
      }
  }
} // namespace

BOOST_AUTO_TEST_CASE(frame_storey_forces_balance_the_loads_above)
{
  check_storeys("storey_forces_frame_3d", frame);
}

BOOST_AUTO_TEST_CASE(shear_building_storey_forces_balance_the_loads_above)
{
  check_storeys("storey_forces_shear_3d", shear);
}
