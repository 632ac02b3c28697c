// The vertical ground-motion component (Ground motion/Components = 3,
// Record/Third file; doc/theory.md, "The vertical component"; doc/
// verification.md, "Vertical ground motion"):
//  1. a one-storey, one-bay 3D frame with a rigid diaphragm and massless
//     members, shaken only vertically by a_z = A sin(Omega t): its load is
//     the inertial force -m_j a_z on the uz of each of the four joints and
//     nothing else (hinge rotations excluded), and each joint's uz is the
//     axial SDOF m_j u'' + (EA/h) u = -m_j a_z in closed form (the beams
//     translate rigidly by symmetry, so the columns only shorten);
//  2. a symmetric linear 2D frame: the response to x and z together is the
//     sum of the responses to each (superposition), the response to z alone
//     is mirror-symmetric (ux of mirrored nodes opposite, uy equal), so the
//     floors' mean horizontal motion is that of x alone, and a zero third
//     record changes nothing.
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>

#include "time_history_helpers.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <sstream>
#include <string>

using namespace poundfe;

namespace
{
  /// A two-column record (time, acceleration in m/s^2) of f on [0, duration].
  template <typename F>
  std::string
  record_file(const std::string &name, const double dt, const double duration, F &&f)
  {
    std::ostringstream text;
    text.precision(17);
    const unsigned int n = std::lround(duration / dt);
    for (unsigned int k = 0; k <= n; ++k)
      text << k * dt << " " << f(k * dt) << "\n";
    poundfe_test::temporary_file(name, text.str());
    return "poundfe_" + name; // relative to the parameter file, in the same directory
  }

  std::string
  record_section(const std::string &files)
  {
    return "subsection Ground motion\n set Type = record\n set Components = 3\n"
           " subsection Record\n  set Format = text\n  set Units = m/s^2\n" +
           files + " end\nend\n";
  }

  constexpr double floor_mass = 1e5, column_area = 1e-3, youngs_modulus = 3e10, height = 3;
  constexpr double amplitude = 0.8, forcing = 13; // a_z = A sin(Omega t), m/s^2, rad/s
  constexpr double step = 1e-3, duration = 2;

  /// The one-bay 3D frame; `foundation`: a Foundation subsection of its
  /// building, or empty (clamped).
  std::string
  frame_3d_text(const std::string &foundation = "")
  {
    const std::string zero =
      record_file("vertical_zero.txt", step, duration, [](double) { return 0.0; });
    const std::string up = record_file("vertical_sine.txt", step, duration, [](const double t) {
      return amplitude * std::sin(forcing * t);
    });
    std::ostringstream text;
    text << "subsection Model\n set Dimension = 3\nend\n"
            "subsection Building 1\n set Type = frame\n set Number of storeys = 1\n"
            " set Storey heights = " << height << "\n set Number of bays = 1\n set Bay widths = 6\n"
            " set Number of bays y = 1\n set Bay widths y = 5\n set Floor masses = "
         << floor_mass << "\n set Column E = " << youngs_modulus << "\n set Column G = 1.25e10\n"
            " set Column A = " << column_area
         << "\n set Column I = 3.3e-3\n set Column Iz = 2.7e-3\n"
            " set Column J = 5.2e-3\n set Beam E = 3e10\n set Beam G = 1.25e10\n"
            " set Beam A = 0.15\n"
            " set Beam I = 3.1e-3\n set Beam Iz = 1.1e-3\n set Beam J = 2.6e-3\n"
            " subsection Hinges\n  set Locations = column bases, beam ends\n"
            "  set Yield moment = 3e5\n end\n"
            " subsection Damping\n  set Type = none\n end\n"
         << foundation << "end\n"
         << record_section("  set File = " + zero + "\n  set Second file = " + zero +
                           "\n  set Third file = " + up + "\n")
         << "subsection Time integration\n set Time step = " << step << "\nend\n";
    return text.str();
  }
} // namespace

// The load -M r_z a_z of the vertical component, against the inertial force
// computed here: m_j = floor mass / 4 on each joint's uz (massless members),
// 0 on every other equation (the diaphragm's ux, uy, theta_z, the joints'
// rotations, the hinges' relative rotations). Exact up to rounding.
BOOST_AUTO_TEST_CASE(vertical_load_is_the_joints_inertial_force)
{
  const InputParameters p        = poundfe_test::input_of("vertical_3d", frame_3d_text());
  const Analysis        analysis = prepare_analysis(p);
  const Excitation      excitation =
    make_excitation(analysis, time_history_parameters(p));
  BOOST_REQUIRE(excitation.has_vertical());
  BOOST_REQUIRE(!analysis.model.hinges_3d.empty()); // the hinge nodes are there to be skipped
  // a sample of the record (between samples it is interpolated linearly)
  const double t = 123 * step, a_z = amplitude * std::sin(forcing * t), m_j = floor_mass / 4;
  Vector load(analysis.system.n_equations());
  excitation.load(t, load);
  unsigned int n_loaded = 0;
  for (unsigned int e = 0; e < load.size(); ++e)
    if (load[e] != 0)
      {
        ++n_loaded;
        BOOST_TEST(std::abs(load[e] + m_j * a_z) <= 1e-12 * m_j * std::abs(a_z));
      }
  BOOST_TEST(n_loaded == 4u); // the four joints' uz, nothing else
  BOOST_TEST(std::abs(load.sum() + floor_mass * a_z) <= 1e-12 * floor_mass * std::abs(a_z));
}

// On a compliant foundation free to move vertically the foundation's mass
// m_0 is shaken too: the load sums to -(m + m_0) a_z, m_0 on the basemat's
// vertical equation (before: the basemat's u_z had no influence, so the
// foundation's inertia was left out of the vertical load). Exact up to
// rounding.
BOOST_AUTO_TEST_CASE(vertical_load_reaches_the_foundation_mass)
{
  constexpr double m_0 = 3.7e4;
  const std::string foundation =
    " subsection Foundation\n  set Type = given\n  set Horizontal stiffness = 2e9\n"
    "  set Horizontal stiffness y = 2e9\n  set Vertical stiffness = 4e9\n"
    "  set Rocking stiffness = 5e10\n  set Rocking stiffness x = 5e10\n"
    "  set Torsional stiffness = 6e10\n  set Mass = 3.7e4\n  set Rotary inertia = 2e5\n"
    "  set Rotary inertia x = 2e5\n  set Polar inertia = 4e5\n end\n";
  const InputParameters p = poundfe_test::input_of("vertical_3d_foundation", frame_3d_text(foundation));
  const Analysis        analysis = prepare_analysis(p);
  BOOST_REQUIRE(analysis.model.foundations.size() == 1u);
  const Excitation excitation = make_excitation(analysis, time_history_parameters(p));
  const double     t = 123 * step, a_z = amplitude * std::sin(forcing * t);
  Vector           load(analysis.system.n_equations());
  excitation.load(t, load);
  const int vertical = analysis.model.equation(n_dofs_per_node * analysis.model.foundations[0].rocking_node);
  BOOST_REQUIRE(vertical >= 0);
  BOOST_TEST(std::abs(load[vertical] + m_0 * a_z) <= 1e-12 * m_0 * std::abs(a_z));
  BOOST_TEST(std::abs(load.sum() + (floor_mass + m_0) * a_z) <=
             1e-12 * (floor_mass + m_0) * std::abs(a_z));
}

// Each joint's uz against the undamped SDOF from rest,
//   u(t) = -A / (omega^2 - Omega^2) (sin Omega t - (Omega / omega) sin omega t),
// omega^2 = (EA/h) / m_j = 400 (rad/s)^2. Newmark's average acceleration
// lengthens the period by (omega dt)^2 / 12 = 3.3e-5, a phase error of
// about 1.3e-3 rad at t = 2 s: tolerance 3e-3 of the peak.
BOOST_AUTO_TEST_CASE(vertical_shaking_drives_the_axial_sdof)
{
  const InputParameters p        = poundfe_test::input_of("vertical_3d_run", frame_3d_text());
  const Analysis        analysis = prepare_analysis(p);
  const auto            run      = poundfe_test::recorded_run(analysis, p);
  const double          m_j   = floor_mass / 4;
  const double          omega = std::sqrt(youngs_modulus * column_area / height / m_j);
  // the four uz equations: where the vertical load acts
  std::vector<unsigned int> uz;
  for (unsigned int e = 0; e < analysis.system.n_equations(); ++e)
    if (analysis.system.influence_z[e] == 1)
      uz.push_back(e);
  BOOST_REQUIRE(uz.size() == 4u);
  double worst = 0, peak = 0;
  for (unsigned int k = 0; k < run.t.size(); ++k)
    {
      const double t = run.t[k];
      const double exact = -amplitude / (omega * omega - forcing * forcing) *
                           (std::sin(forcing * t) - forcing / omega * std::sin(omega * t));
      peak = std::max(peak, std::abs(exact));
      for (const unsigned int e : uz)
        worst = std::max(worst, std::abs(run.u[k][e] - exact));
    }
  BOOST_TEST_MESSAGE("vertical SDOF: omega " << omega << " rad/s, peak " << peak
                                             << " m, largest error " << worst / peak
                                             << " of the peak");
  BOOST_TEST(worst <= 3e-3 * peak);
  BOOST_TEST(peak > 1e-4); // the shaking moved the floor
}

namespace
{
  /// A symmetric linear 2D frame (2 storeys, 2 bays of 5 m, Rayleigh
  /// damping), shaken along x by `x` and vertically by `z` (records; "" for
  /// Components = 1).
  std::string
  frame_2d_text(const std::string &x, const std::string &z)
  {
    return "subsection Building 1\n set Type = frame\n set Number of storeys = 2\n"
           " set Storey heights = 3.5, 3\n set Number of bays = 2\n set Bay widths = 5\n"
           " set Column E = 3e10\n set Column A = 0.16\n set Column I = 2.1e-3\n"
           " set Beam E = 3e10\n set Beam A = 0.12\n set Beam I = 1.6e-3\n"
           " set Column mass per length = 400\n set Beam mass per length = 300\n"
           " set Floor masses = 2e4\n"
           " subsection Damping\n  set Type = coefficients\n  set a0 = 0.3\n  set a1 = 0.003\n"
           " end\nend\n" +
           (z.empty() ? "subsection Ground motion\n set Type = record\n subsection Record\n"
                        "  set Format = text\n  set Units = m/s^2\n  set File = " + x +
                          "\n end\nend\n" :
                        record_section("  set File = " + x + "\n  set Third file = " + z + "\n")) +
           "subsection Time integration\n set Time step = 0.005\nend\n";
  }
} // namespace

// Superposition and symmetry of a linear symmetric frame without P-Delta:
// u(x + z) = u(x) + u(z) and the mirror relations of u(z) to 1e-10 of the
// peak (linear solves of one matrix: rounding only); a zero vertical record
// leaves every displacement bit for bit.
BOOST_AUTO_TEST_CASE(vertical_component_superposes_on_a_symmetric_2d_frame)
{
  const double dt = 0.005, length = 1.5;
  const std::string x = record_file("vertical_2d_x.txt", dt, length, [](const double t) {
    return 2.5 * std::sin(9 * t) * std::exp(-t) + 1.2 * std::sin(23 * t);
  });
  const std::string z = record_file("vertical_2d_z.txt", dt, length, [](const double t) {
    return 1.7 * std::sin(31 * t) + 0.6 * std::cos(7 * t) * t;
  });
  const std::string zero =
    record_file("vertical_2d_zero.txt", dt, length, [](double) { return 0.0; });
  const auto run = [](const std::string &name, const std::string &text) {
    const InputParameters p = poundfe_test::input_of(name, text);
    const Analysis        a = prepare_analysis(p);
    return std::make_pair(poundfe_test::recorded_run(a, p), a.model);
  };
  const auto [only_x, model] = run("vertical_2d_only_x", frame_2d_text(x, ""));
  const auto both            = run("vertical_2d_both", frame_2d_text(x, z)).first;
  const auto only_z          = run("vertical_2d_only_z", frame_2d_text(zero, z)).first;
  const auto zero_z          = run("vertical_2d_zero_z", frame_2d_text(x, zero)).first;
  BOOST_REQUIRE(both.u.size() == only_x.u.size() && only_z.u.size() == only_x.u.size());

  double peak = 0, superposition = 0, unchanged = 0;
  for (unsigned int k = 0; k < both.u.size(); ++k)
    {
      peak          = std::max(peak, both.u[k].cwiseAbs().maxCoeff());
      superposition = std::max(superposition,
                               (both.u[k] - only_x.u[k] - only_z.u[k]).cwiseAbs().maxCoeff());
      unchanged = std::max(unchanged, (zero_z.u[k] - only_x.u[k]).cwiseAbs().maxCoeff());
    }
  // the mirror of each node about the frame's axis x = 5 m
  const auto equation = [&](const Point2 &at, const Component c) {
    for (unsigned int n = 0; n < model.n_nodes(); ++n)
      if (std::abs(model.nodes[n].position.x - at.x) < 1e-9 &&
          std::abs(model.nodes[n].position.y - at.y) < 1e-9)
        return model.equation(Model::dof(n, c));
    return -1;
  };
  double       mirror = 0, vertical_peak = 0;
  unsigned int n_pairs = 0;
  for (unsigned int n = 0; n < model.n_nodes(); ++n)
    {
      const Point2 at = model.nodes[n].position, image{10 - at.x, at.y};
      const int    ux = model.equation(Model::dof(n, Component::ux));
      const int    uy = model.equation(Model::dof(n, Component::uy));
      const int    ux_image = equation(image, Component::ux);
      const int    uy_image = equation(image, Component::uy);
      if (ux < 0 || ux_image < 0 || uy < 0 || uy_image < 0)
        continue;
      ++n_pairs;
      for (const Vector &u : only_z.u)
        {
          vertical_peak = std::max(vertical_peak, std::abs(u[uy]));
          mirror        = std::max(
            {mirror, std::abs(u[ux] + u[ux_image]), std::abs(u[uy] - u[uy_image])});
        }
    }
  BOOST_TEST_MESSAGE("2D frame: superposition " << superposition / peak << ", mirror "
                                                << mirror / vertical_peak << " over " << n_pairs
                                                << " nodes, zero third record " << unchanged);
  BOOST_TEST(n_pairs >= 6u);
  BOOST_TEST(vertical_peak > 0);
  BOOST_TEST(superposition <= 1e-10 * peak);
  BOOST_TEST(mirror <= 1e-10 * vertical_peak);
  BOOST_TEST(unchanged == 0);
}
