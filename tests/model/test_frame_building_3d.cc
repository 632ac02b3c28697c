// 3D frame buildings (Model/Dimension = 3, Type = frame; model/
// frame_building_3d.h): a symmetric 3D frame shaken along x against the
// planar frame (with and without hinges), the rigid diaphragm of a
// one-storey frame against Chopra's closed form, and the bad input a 3D
// frame refuses (doc/verification.md, "3D frame buildings").
#include <poundfe/assembly/linear_system.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/model/model_builder.h>

#include "../dynamics/time_history_helpers.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

using namespace poundfe;

namespace
{
  /// A 3-storey, 2-bay frame: in 2D, or in 3D as two such frames 5 m apart
  /// along y joined by beams along y (no diaphragm: the planar frame's beams
  /// stretch), twice the floor mass so that each x frame carries the 2D
  /// frame's. Columns carry mass; the beams none (the y beams would add
  /// mass the planar frame has not).
  std::string
  frame_text(const unsigned int dimension, const std::string &mass_matrix, const bool hinges,
             const bool p_delta = false)
  {
    const bool  three_d = dimension == 3;
    std::string text    = "subsection Model\n set Dimension = " + std::to_string(dimension) +
                       "\n set Mass matrix = " + mass_matrix +
                       (p_delta ? "\n set Geometric nonlinearity = p-delta" : "") +
                       "\nend\n"
                       "subsection Building 1\n set Type = frame\n set Number of storeys = 3\n"
                       " set Storey heights = 3.5, 3, 3\n set Number of bays = 2\n"
                       " set Bay widths = 6, 4\n set Column E = 3e10\n set Column A = 0.16\n"
                       " set Column I = 2.1e-3, 1.8e-3, 1.5e-3\n set Beam E = 3e10\n"
                       " set Beam A = 0.12\n set Beam I = 1.6e-3\n"
                       " set Column mass per length = 400\n set Floor masses = " +
                       std::string(three_d ? "4e4, 4e4, 3e4" : "2e4, 2e4, 1.5e4") + "\n";
    if (three_d)
      text += " set Number of bays y = 1\n set Bay widths y = 5\n set Diaphragm = "
              "none\n"
              " set Column G = 1.25e10\n set Column Iz = 2.6e-3\n set Column J = "
              "3.6e-3\n"
              " set Beam G = 1.25e10\n set Beam Iz = 9e-4\n set Beam J = 1.9e-3\n";
    if (hinges)
      text += " subsection Hinges\n  set Locations = column bases, beam ends\n"
              "  set Yield moment = 1.5e5\n end\n";
    text += " subsection Damping\n  set Type = coefficients\n  set a0 = 0.3\n  "
            "set a1 = 0.003\n"
            " end\nend\n"
            "subsection Ground motion\n set Type = kanai-tajimi\n subsection "
            "Stochastic\n"
            "  set Target PGA = 0.5\n  set Duration = 3\n  set Seed = 7\n"
            "  set Method = spectral-representation\n  set Cutoff frequency = "
            "100\n end\nend\n"
            "subsection Time integration\n set Time step = 0.005\n"
            " set Newton residual tolerance = 1e-12\nend\n"
            "subsection Output\n set Number of modes = 3\nend\n";
    return text;
  }

  /// The 3D equation of each planar (node, component): a 2D node (x, y)
  /// is the 3D joint at (x, z) = (x, y) (either x frame: the first found);
  /// ux -> ux, uy -> uz, rz -> ry (sign -1: rz of the x-z plane with z up is
  /// a rotation about -y).
  struct Equivalent
  {
    int    equation_3d = -1;
    double sign        = 1;
  };

  std::vector<Equivalent>
  equivalents(const Model &planar, const Model &spatial)
  {
    std::vector<Equivalent> map(planar.n_equations());
    for (unsigned int n = 0; n < planar.n_nodes(); ++n)
      {
        if (planar.nodes[n].tied_to >= 0)
          continue; // a 2D hinge's member-end rotation
        const Point2 at = planar.nodes[n].position;
        int          h = -1, v = -1;
        for (unsigned int m = 0; m < spatial.n_nodes(); ++m)
          if (std::abs(spatial.nodes[m].position.x - at.x) < 1e-9 &&
              std::abs(spatial.nodes[m].position.y - at.y) < 1e-9)
            {
              int &slot = spatial.nodes[m].generalized ? v : h;
              if (slot < 0)
                slot = m;
            }
        if (h < 0 || v < 0)
          continue;
        const std::array<std::pair<unsigned int, double>, 3> to{
            {{Model::dof(h, Component::ux), 1.0},
             {n_dofs_per_node * v + 0, 1.0},
             {n_dofs_per_node * v + 2, -1.0}}};
        for (unsigned int c = 0; c < 3; ++c)
          if (const int e = planar.equation(n_dofs_per_node * n + c); e >= 0)
            map[e] = {spatial.equation(to[c].first), to[c].second};
      }
    return map;
  }

  /// Largest relative difference of the peaks |u| of every equivalent DOF,
  /// and of the whole histories against the DOF's peak.
  void
  check_equivalent(const bool hinges, const std::string &mass_matrix, const bool p_delta = false)
  {
    const std::string name =
        "frame3d_" + mass_matrix + (hinges ? "_hinges" : "") + (p_delta ? "_p_delta" : "");
    const InputParameters p2 =
        poundfe_test::input_of(name + "_2d", frame_text(2, mass_matrix, hinges, p_delta));
    const InputParameters p3 =
        poundfe_test::input_of(name + "_3d", frame_text(3, mass_matrix, hinges, p_delta));
    const Analysis a2 = prepare_analysis(p2), a3 = prepare_analysis(p3);
    const auto     map = equivalents(a2.model, a3.model);
    const auto     r2 = poundfe_test::recorded_run(a2, p2), r3 = poundfe_test::recorded_run(a3, p3);
    BOOST_REQUIRE_EQUAL(r2.u.size(), r3.u.size());
    unsigned int n_compared = 0;
    double       worst_peak = 0, worst_history = 0;
    for (unsigned int e = 0; e < map.size(); ++e)
      {
        if (map[e].equation_3d < 0)
          continue;
        ++n_compared;
        double peak2 = 0, peak3 = 0, difference = 0;
        for (unsigned int s = 0; s < r2.u.size(); ++s)
          {
            const double u2 = r2.u[s][e], u3 = map[e].sign * r3.u[s][map[e].equation_3d];
            peak2      = std::max(peak2, std::abs(u2));
            peak3      = std::max(peak3, std::abs(u3));
            difference = std::max(difference, std::abs(u2 - u3));
          }
        BOOST_REQUIRE(peak2 > 0);
        worst_peak    = std::max(worst_peak, std::abs(peak3 - peak2) / peak2);
        worst_history = std::max(worst_history, difference / peak2);
      }
    BOOST_TEST_MESSAGE(name << ": " << n_compared << " DOFs, largest relative peak difference "
                            << worst_peak << ", history " << worst_history);
    BOOST_TEST(n_compared == a2.model.n_equations() - (hinges ? a2.model.hinges.size() : 0));
    // tolerance: the same equations in another numbering and with the
    // out-of-plane DOFs (exactly 0) added: round-off, amplified by the
    // time stepping, stays far below 1e-10. With hinges Newton stops each
    // step at its residual tolerance, here 1e-12 in both models (at the
    // default 1e-8 the histories differ by ~2e-9 of their peaks).
    BOOST_TEST(worst_peak <= 1e-10);
    BOOST_TEST(worst_history <= 1e-10);
  }

  /// One storey (h = 3.5 m), 2 x 1 bays of 6 m x 5 m; mass 8e4 kg with its
  /// centre e along x from the plan centre; beams and columns axially
  /// 1e6 times stiffer than in bending (the closed form's shear-frame
  /// columns: clamped at both ends, not shortening).
  std::string
  one_storey_frame(const double e, const std::string &hinges = "", const std::string &model = "")
  {
    return "subsection Model\n set Dimension = 3\n" + model + "end\n"
           "subsection Building 1\n set Type = frame\n set Number of storeys = "
           "1\n"
           " set Storey heights = 3.5\n set Number of bays = 2\n set Bay widths "
           "= 6\n"
           " set Number of bays y = 1\n set Bay widths y = 5\n set Floor masses "
           "= 8e4\n"
           " set Column E = 3e10\n set Column A = 1e4\n set Column I = 2e-3\n"
           " set Column Iz = 1e-3\n set Column G = 1.2e10\n set Column J = "
           "1.5e-3\n"
           " set Beam E = 3e10\n set Beam A = 1e4\n set Beam I = 1e4\n set Beam "
           "Iz = 1e4\n"
           " set Beam G = 1.2e10\n set Beam J = 1e4\n"
           " subsection Plan\n  set Mass eccentricity = " +
           std::to_string(e) + ", 0\n end\n" + hinges +
           " subsection Damping\n  set Type = none\n end\nend\n"
           "subsection Ground motion\n set Type = none\nend\n"
           "subsection Output\n set Number of modes = 3\nend\n";
  }

  /// kx, ky: each column's lateral stiffness along x, y; k_twist: its
  /// torsional stiffness (G J / h without P-Delta).
  void
  check_chopra(const std::string &text, const double kx, const double ky, const std::string &name,
               const double k_twist = 1.2e10 * 1.5e-3 / 3.5)
  {
    const double e = 1.3, m = 8e4;
    const double I  = m * (144 + 25) / 12.0;
    const double Kx = 6 * kx, Ky = 6 * ky;
    const double k_theta = 6 * kx * 2.5 * 2.5 + 4 * ky * 36 + 6 * k_twist + e * e * Ky;
    const double wy2 = Ky / m, wt2 = k_theta / I, r2 = I / m;
    const double mean = 0.5 * (wy2 + wt2);
    const double root = std::sqrt(0.25 * (wy2 - wt2) * (wy2 - wt2) + wy2 * wy2 * e * e / r2);
    std::vector<double> expected{std::sqrt(mean - root), std::sqrt(Kx / m), std::sqrt(mean + root)};
    std::sort(expected.begin(), expected.end());
    const Analysis a = prepare_analysis(poundfe_test::input_of(name, text));
    BOOST_REQUIRE_GE(a.modes.n_modes(), 3u);
    for (unsigned int i = 0; i < 3; ++i)
      {
        BOOST_TEST_MESSAGE("mode " << i + 1 << ": " << a.modes.omega[i] << " rad/s, closed form "
                                   << expected[i] << ", relative difference "
                                   << std::abs(a.modes.omega[i] / expected[i] - 1));
        // tolerance: the closed form's columns are clamped at the top and do
        // not shorten; here the beams and the axial stiffness are 1e6-1e7
        // times the columns' bending stiffness, which leaves ~1e-7
        BOOST_TEST(a.modes.omega[i] == expected[i], boost::test_tools::tolerance(1e-6));
      }
  }
} // namespace

BOOST_AUTO_TEST_SUITE(frame_building_3d)

BOOST_AUTO_TEST_CASE(symmetric_frame_along_x_is_the_planar_frame)
{
  check_equivalent(false, "lumped");
  check_equivalent(false, "consistent");
}

BOOST_AUTO_TEST_CASE(symmetric_frame_with_hinges_along_x_is_the_planar_frame)
{
  check_equivalent(true, "lumped");
}

BOOST_AUTO_TEST_CASE(rigid_diaphragm_matches_chopra)
{
  // Chopra (2012) ch. 9, one storey with an unsymmetric plan, DOFs (ux, uy,
  // θ) at the mass centre C, e east of the stiffness centre (the plan
  // centre). Six columns clamped at both ends (rigid beams): along x each
  // 12 E I_y / h^3, along y 12 E I_z / h^3, twisting G J / h; x = -6, 0, 6,
  // y = ±2.5. K_y = Σ k_y, K_θR = Σ k_x y^2 + Σ k_y x^2 + Σ G J / h,
  // K_θ(C) = K_θR + e^2 K_y; I = m (12^2 + 5^2) / 12; u_x uncouples.
  check_chopra(one_storey_frame(1.3), 12 * 3e10 * 2e-3 / std::pow(3.5, 3),
               12 * 3e10 * 1e-3 / std::pow(3.5, 3), "chopra_frame_3d");
}

BOOST_AUTO_TEST_CASE(floor_mass_at_the_master_only_matches_chopra_with_three_modes)
{
  // Vertical floor mass = none: the floor mass at the diaphragm's master
  // alone. The massless columns leave the master's three DOFs the only
  // massive ones: exactly three modes, at Chopra's closed form (rigid beams:
  // the joints do not move vertically in sway, so the frequencies are those
  // with the joints' vertical mass too); with it, the joints' vertical modes
  // follow. The floor's weight loads the joints either way.
  const std::string none = one_storey_frame(1.3, " set Vertical floor mass = none\n");
  check_chopra(none, 12 * 3e10 * 2e-3 / std::pow(3.5, 3), 12 * 3e10 * 1e-3 / std::pow(3.5, 3),
               "chopra_master_only_3d");
  const auto six_modes = [](std::string text) {
    const std::string three = "Number of modes = 3";
    return text.replace(text.find(three), three.size(), "Number of modes = 6");
  };
  const Analysis master = prepare_analysis(poundfe_test::input_of("master_only", six_modes(none)));
  const Analysis joints =
    prepare_analysis(poundfe_test::input_of("joints", six_modes(one_storey_frame(1.3))));
  BOOST_TEST(master.modes.n_modes() == 3u);
  BOOST_TEST(joints.modes.n_modes() == 6u);
  const double weight = -master.model.gravity * 8e4;
  BOOST_TEST(total_gravity_loads(master.model).sum() == weight, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(total_gravity_loads(joints.model).sum() == weight, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(base_hinges_about_both_axes_match_chopra)
{
  // the same storey with elastic hinges k_s = 2e7 N m/rad about both local
  // axes at every column base: a column clamped at the top on a rotational
  // spring at the base has the lateral stiffness (slope-deflection)
  //   (E I / h^3) (12 - 36 (E I / h) / (4 E I / h + k_s)),
  // about each axis with its own I; the twist passes the hinge (G J / h)
  const double ks = 2e7, h = 3.5, E = 3e10;
  const auto   k = [&](const double I) {
    return E * I / (h * h * h) * (12 - 36 * (E * I / h) / (4 * E * I / h + ks));
  };
  check_chopra(one_storey_frame(1.3, " subsection Hinges\n  set Locations = column bases\n"
                                     "  set Yield moment = 1e9\n  set Stiffness = 2e7\n end\n"),
               k(2e-3), k(1e-3), "chopra_hinges_3d");
}

BOOST_AUTO_TEST_CASE(shear_deformation_matches_chopra_with_timoshenko_columns)
{
  // the same storey with shear areas: a clamped-guided Timoshenko column
  // sways with k = 12 E I / (h^3 (1 + Phi)), Phi = 12 E I / (G Av h^2)
  // (Przemieniecki ch. 5), Avz with Column I (along x), Avy with Column Iz
  // (along y); small shear areas (Phi = 0.49, 0.24) make it matter. The
  // beams' shear areas are large enough (G Av / L ~ 2e13 N/m) to keep them
  // rigid, as the closed form has them
  const double h = 3.5, E = 3e10, G = 1.2e10, avz = 0.01, avy = 0.01;
  const auto   k = [&](const double I, const double av) {
    const double phi = 12 * E * I / (G * av * h * h);
    return 12 * E * I / (h * h * h * (1 + phi));
  };
  std::string text = one_storey_frame(1.3);
  text.replace(text.find(" subsection Plan"), 0,
               " set Column Avz = 0.01\n set Column Avy = 0.01\n"
               " set Beam Avz = 2e4\n set Beam Avy = 1e4\n");
  check_chopra(text, k(2e-3, avz), k(1e-3, avy), "chopra_shear_3d");
  // the beams take their own shear areas (Avy: horizontal shear, local y)
  const Analysis a = prepare_analysis(poundfe_test::input_of("shear_areas_3d", text));
  unsigned int   n_beams = 0;
  for (const Member3D &member : a.model.members_3d)
    if (member.kind == MemberKind::beam)
      {
        ++n_beams;
        BOOST_TEST(member.section.shear_area_y == 1e4);
        BOOST_TEST(member.section.shear_area_z == 2e4);
      }
  BOOST_TEST(n_beams == 7u);
}

BOOST_AUTO_TEST_CASE(p_delta_softens_the_storey_as_the_closed_form)
{
  // the storey under its weight with P-Delta: equal joint weights on equal
  // columns (axially 1e6 times stiffer than in bending, beams rigid) give
  // P = m g / 6 in every column; a clamped-guided column of one cubic
  // element with the consistent geometric stiffness sways with
  // k = 12 E I / h^3 - 6 P / (5 h) (Przemieniecki ch. 11), twists with
  // G J / h - P Ip / (A h) (Wagner; Ip = Iy + Iz), and the storey is
  // Chopra's with these stiffnesses. g = 300 m/s^2 puts P at 0.32 of the
  // element's critical load along y (10 E Iz / h^2) to make the change large
  const double h = 3.5, E = 3e10, G = 1.2e10, g = 300, P = 8e4 * g / 6;
  const auto   k = [&](const double I) { return 12 * E * I / (h * h * h) - 1.2 * P / h; };
  const double k_twist = G * 1.5e-3 / h - P * 3e-3 / (1e4 * h);
  const std::string model =
      " set Geometric nonlinearity = p-delta\n set Gravity = " + std::to_string(g) + "\n";
  check_chopra(one_storey_frame(1.3, "", model), k(2e-3), k(1e-3), "chopra_p_delta_3d", k_twist);
  // against the exact stability function of the clamped-guided column,
  // k = (E I / h^3) a^3 sin a / (2 - 2 cos a - a sin a), a = h sqrt(P/(E I))
  // (Timoshenko & Gere ch. 1) = 12 - 6 a^2/5 - a^4/700 - ... in units of
  // E I / h^3: the cubic element's linearised k lacks the a^4 term, here
  // (a^2 = 1.63) 3.8e-4 of k, 1.9e-4 of omega; held to 5e-4
  const Analysis a = prepare_analysis(
      poundfe_test::input_of("p_delta_exact_3d", one_storey_frame(0, "", model)));
  const double alpha = h * std::sqrt(P / (E * 1e-3));
  const double exact = E * 1e-3 / (h * h * h) * std::pow(alpha, 3) * std::sin(alpha) /
                       (2 - 2 * std::cos(alpha) - alpha * std::sin(alpha));
  const double omega_y = std::sqrt(6 * exact / 8e4);
  BOOST_TEST_MESSAGE("P-Delta, sway along y: omega " << a.modes.omega[0]
                                                     << " rad/s, exact stability function "
                                                     << omega_y << ", relative difference "
                                                     << a.modes.omega[0] / omega_y - 1);
  BOOST_TEST(a.modes.omega[0] == omega_y, boost::test_tools::tolerance(5e-4));
  // a weight past the element's critical load (10 E Iz / h^2 per column) is refused
  const double      g_buckling = 1.05 * 10 * E * 1e-3 / (h * h) * 6 / 8e4;
  const std::string buckled    = poundfe_test::input_error_of([&] {
    prepare_analysis(poundfe_test::input_of(
        "p_delta_buckled_3d",
        one_storey_frame(0, "",
                         " set Geometric nonlinearity = p-delta\n set Gravity = " +
                             std::to_string(g_buckling) + "\n")));
  });
  BOOST_TEST(buckled.find("buckles under its own weight") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(symmetric_frame_with_p_delta_along_x_is_the_planar_frame)
{
  check_equivalent(false, "consistent", true);
}

BOOST_AUTO_TEST_CASE(hinge_tangent_matches_central_differences)
{
  // a hinge of the one-storey frame (Bouc-Wen on one relative rotation):
  // the tangent change K_t - K_ref = B D B^T against central differences
  // of the force correction f - K_ref u at a yielded trial state
  const Analysis    a        = prepare_analysis(poundfe_test::input_of(
                "tangent_3d", one_storey_frame(0, " subsection Hinges\n  set Locations = column bases\n"
                                                            "  set Yield moment = 2e4\n end\n")));
  NonlinearElements elements = make_nonlinear_elements(a.model);
  BOOST_REQUIRE(!elements.empty());
  NonlinearElement &hinge = elements[1]; // the first column's base, about local z
  BOOST_TEST(hinge.label.find("_bottom_z") != std::string::npos);
  const unsigned int n     = hinge.n_dofs();
  const double       yield = hinge.yield_deformation();
  Eigen::VectorXd    u = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n);
  u[0] = 3 * yield; // beyond yield, from the virgin state
  BOOST_REQUIRE(hinge.set_trial(u, v));
  Eigen::MatrixXd d(hinge.rank(), hinge.rank());
  hinge.tangent_change(0, d);
  const Eigen::MatrixXd tangent = hinge.tangent_basis() * d * hinge.tangent_basis().transpose();
  Eigen::MatrixXd       differences(n, n);
  const double          step = 1e-6 * yield;
  for (unsigned int j = 0; j < n; ++j)
    {
      Eigen::VectorXd plus(n), minus(n), du = Eigen::VectorXd::Zero(n);
      du[j] = step;
      BOOST_REQUIRE(hinge.set_trial(u + du, v));
      hinge.force_correction(plus);
      BOOST_REQUIRE(hinge.set_trial(u - du, v));
      hinge.force_correction(minus);
      differences.col(j) = (plus - minus) / (2 * step);
    }
  // the ground entry (-1) is not a DOF: the element reads it as 0, so
  // only the hinge's own equation (entry 0) is compared
  BOOST_TEST_MESSAGE("hinge tangent change " << tangent(0, 0) << ", central differences "
                                             << differences(0, 0) << ", initial stiffness "
                                             << hinge.initial_stiffness());
  // tolerance: O(h^2) truncation and round-off ~1e-16 k u / h on a
  // tangent of size k: 1e-6 relative to k
  BOOST_TEST(std::abs(tangent(0, 0) - differences(0, 0)) <= 1e-6 * hinge.initial_stiffness());
  // it has yielded: the tangent K_t = k + (K_t - k) is far below k
  BOOST_TEST(hinge.initial_stiffness() + tangent(0, 0) < 0.2 * hinge.initial_stiffness());
}

BOOST_AUTO_TEST_CASE(bad_3d_frames_are_refused)
{
  const std::string base = one_storey_frame(0);
  auto              with = [&](const std::string &from, const std::string &to) {
    std::string text = base;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  // all columns on one line: a singular diaphragm
  const std::string line = poundfe_test::input_error_of([&] {
    prepare_analysis(
        poundfe_test::input_of("line_3d", with("Number of bays y = 1", "Number of bays y = 0")));
  });
  BOOST_TEST(line.find("Building 1/Number of bays y") != std::string::npos);
  BOOST_TEST(line.find("singular") != std::string::npos);
  // a section without its torsion constant
  const std::string missing = poundfe_test::input_error_of([&] {
    prepare_analysis(poundfe_test::input_of("missing_3d", with(" set Column J = 1.5e-3\n", "")));
  });
  BOOST_TEST(missing.find("Building 1/Column J") != std::string::npos);
  // a negative second moment
  const std::string negative = poundfe_test::input_error_of([&] {
    prepare_analysis(
        poundfe_test::input_of("negative_3d", with("Column Iz = 1e-3", "Column Iz = -1e-3")));
  });
  BOOST_TEST(negative.find("Building 1/Column Iz") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
