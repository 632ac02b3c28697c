// Fibre members in 3D frame buildings (Model/Dimension = 3, Type = frame,
// Member model = fibre; model/frame_building_3d.h, elements/member_element.h):
//   - a fibre frame on elastic fibres (EA, EIz, EIy exact, GJ given) is the
//     elastic 3D frame of the same rigidities: its modes and a time history
//     under a horizontal pair to round-off;
//   - a corner column of a square frame on a section symmetric about its
//     diagonal, its floor pushed at 45° past yield, bends about its two
//     local axes alike (|Mz| = |My| at both ends);
//   - the input a 3D fibre frame refuses.
// doc/verification.md, "Fibre members in 3D frames".
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/elements/member_element.h>
#include <poundfe/input/engine_parameters.h>

#include "../dynamics/time_history_helpers.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

using namespace poundfe;

namespace
{
  /// Two storeys, 2 x 1 bays, rigid floors; `members`: the member entries,
  /// `sections`: the Sections input; a horizontal stochastic pair at 30°.
  std::string
  frame_3d_text(const std::string &members, const std::string &sections)
  {
    return "subsection Model\n set Dimension = 3\nend\n"
           "subsection Building 1\n set Type = frame\n set Number of storeys = 2\n"
           " set Storey heights = 3.5, 3\n set Number of bays = 2\n set Bay widths = 6, 4\n"
           " set Number of bays y = 1\n set Bay widths y = 5\n set Floor masses = 6e4, 4e4\n"
           " set Column mass per length = 400\n set Beam mass per length = 300\n" +
           members +
           " subsection Damping\n  set Type = coefficients\n  set a0 = 0.3\n"
           "  set a1 = 0.003\n end\nend\n" +
           sections +
           "subsection Ground motion\n set Type = kanai-tajimi\n set Components = 2\n"
           " set Incidence angle = 30\n subsection Stochastic\n  set Target PGA = 0.4\n"
           "  set Duration = 2\n  set Seed = 11\n end\nend\n"
           "subsection Time integration\n set Time step = 0.005\n"
           " set Newton residual tolerance = 1e-12\nend\n"
           "subsection Output\n set Number of modes = 6\nend\n";
  }

  /// Four elastic fibres: EA = 3e10 0.16, EIz = 3e10 8e-4 (fibres on y =
  /// ±0.1), EIy = 3e10 1.8e-3 (on z = ±0.15), GJ = 1.25e10 3e-3.
  const std::string elastic_fibres =
    "subsection Sections\n set Number of sections = 1\n set Materials = el: Elastic E=3e10\n"
    " subsection Section 1\n  set Name = four\n  set Type = fibres\n"
    "  set Fibres = fiber 0.1 0 0.04 el; fiber -0.1 0 0.04 el; fiber 0 0.15 0.04 el; "
    "fiber 0 -0.15 0.04 el\n  set Torsional rigidity = 3.75e7\n end\nend\n";

  const std::string fibre_members =
    " set Member model = fibre\n set Column sections = four\n set Beam sections = four\n";

  /// The same rigidities as elastic members: a column's section y axis is
  /// its local y (Iz: sway along y), a fibre beam's y axis is vertical, so
  /// its EIz bends it in the vertical plane (the elastic beam's Beam I).
  const std::string elastic_members =
    " set Column E = 3e10\n set Column G = 1.25e10\n set Column A = 0.16\n"
    " set Column I = 1.8e-3\n set Column Iz = 8e-4\n set Column J = 3e-3\n"
    " set Beam E = 3e10\n set Beam G = 1.25e10\n set Beam A = 0.16\n"
    " set Beam I = 8e-4\n set Beam Iz = 1.8e-3\n set Beam J = 3e-3\n";
} // namespace

BOOST_AUTO_TEST_SUITE(fibre_frame_3d)

BOOST_AUTO_TEST_CASE(elastic_fibre_frame_is_the_elastic_frame)
{
  const InputParameters pe =
    poundfe_test::input_of("elastic_frame_3d", frame_3d_text(elastic_members, ""));
  const InputParameters pf = poundfe_test::input_of(
    "fibre_frame_3d", frame_3d_text(fibre_members, elastic_fibres));
  const Analysis ae = prepare_analysis(pe), af = prepare_analysis(pf);
  BOOST_REQUIRE_EQUAL(af.model.n_equations(), ae.model.n_equations());
  BOOST_TEST(make_nonlinear_elements(af.model).size() == af.model.members_3d.size());
  // tolerance: the force-based element on elastic fibres has the elastic
  // element's stiffness to round-off (test_beam_column_geometry), the
  // masses are the same matrices
  BOOST_REQUIRE_GE(af.modes.n_modes(), 6u);
  for (unsigned int i = 0; i < 6; ++i)
    {
      BOOST_TEST_MESSAGE("mode " << i + 1 << ": " << af.modes.omega[i] << " rad/s, elastic "
                                 << ae.modes.omega[i]);
      BOOST_TEST(af.modes.omega[i] == ae.modes.omega[i], boost::test_tools::tolerance(1e-9));
    }
  const auto re = poundfe_test::recorded_run(ae, pe), rf = poundfe_test::recorded_run(af, pf);
  BOOST_REQUIRE_EQUAL(re.u.size(), rf.u.size());
  double peak = 0, difference = 0;
  for (unsigned int s = 0; s < re.u.size(); ++s)
    {
      peak       = std::max(peak, re.u[s].lpNorm<Eigen::Infinity>());
      difference = std::max(difference, (re.u[s] - rf.u[s]).lpNorm<Eigen::Infinity>());
    }
  BOOST_TEST_MESSAGE("largest difference " << difference << " of a peak " << peak);
  BOOST_REQUIRE(peak > 1e-4);
  // tolerance: Newton stops each step at 1e-12 of the residual; the
  // fibre members' force correction is round-off of K_ref u
  BOOST_TEST(difference <= 1e-9 * peak);
}

BOOST_AUTO_TEST_CASE(column_pushed_at_45_degrees_bends_alike_about_both_axes)
{
  // one storey, one 5 m x 5 m bay; a concrete square with three bars on
  // each face, symmetric about its diagonal
  const std::string sections =
    "subsection Sections\n set Number of sections = 1\n"
    " set Materials = c: Concrete02 fpc=-30e6 epsc0=-0.002 fpcu=-6e6 epscu=-0.006 ft=3e6 "
    "Ets=1.5e9; s: Steel02 fy=420e6 E0=200e9 b=0.01\n"
    " subsection Section 1\n  set Name = square\n  set Type = fibres\n"
    "  set Fibres = patch rect c 12 12 -0.2 -0.2 0.2 0.2; "
    "layer straight s 3 3.1e-4 0.16 -0.16 0.16 0.16; "
    "layer straight s 3 3.1e-4 -0.16 -0.16 -0.16 0.16; fiber 0 -0.16 3.1e-4 s; "
    "fiber 0 0.16 3.1e-4 s\n  set Torsional rigidity = 1e8\n end\nend\n";
  const std::string text =
    "subsection Model\n set Dimension = 3\nend\n"
    "subsection Building 1\n set Type = frame\n set Number of storeys = 1\n"
    " set Storey heights = 3\n set Number of bays = 1\n set Bay widths = 5\n"
    " set Number of bays y = 1\n set Bay widths y = 5\n set Floor masses = 4e4\n" +
    fibre_members.substr(0, fibre_members.find(" set Column sections")) +
    " set Column sections = square\n set Beam sections = square\n"
    " subsection Damping\n  set Type = none\n end\nend\n" +
    sections + "subsection Ground motion\n set Type = none\nend\n";
  const Analysis    a        = prepare_analysis(poundfe_test::input_of("push_45", text));
  NonlinearElements elements = make_nonlinear_elements(a.model);
  const auto *column = dynamic_cast<const MemberElement<3> *>(&elements[0]);
  BOOST_REQUIRE(column != nullptr);
  BOOST_TEST(column->label.find("C1.1.1") != std::string::npos);
  // the floor's master moves along (1, 1)/√2, the joints' (uz, rx, ry) stay:
  // each column is clamped at both ends, its top drifted at 45°
  const unsigned int master = a.model.buildings[0].floors[0].nodes[0];
  const int          ex     = a.model.equation(Model::dof(master, Component::ux));
  const int          ey     = a.model.equation(Model::dof(master, Component::uy));
  BOOST_REQUIRE(ex >= 0 && ey >= 0);
  NonlinearElement &element = elements[0];
  Eigen::VectorXd   u = Eigen::VectorXd::Zero(element.n_dofs()), v = u;
  double            largest_moment = 0, worst = 0;
  for (unsigned int step = 1; step <= 40; ++step)
    {
      const double drift = 0.015 * 3 * step / 40 / std::sqrt(2.0); // to 1.5 % at 45°
      for (unsigned int i = 0; i < element.n_dofs(); ++i)
        u[i] = element.equations()[i] == ex || element.equations()[i] == ey ? drift : 0.0;
      BOOST_REQUIRE(element.set_trial(u, v));
      element.commit();
      // basic forces (N, Mz_I, Mz_J, My_I, My_J, T)
      for (const unsigned int end : {1u, 2u})
        {
          const double mz = column->force_component(end), my = column->force_component(end + 2);
          largest_moment  = std::max(largest_moment, std::abs(mz));
          worst           = std::max(worst, std::abs(std::abs(mz) - std::abs(my)));
        }
    }
  BOOST_TEST_MESSAGE("largest |Mz| " << largest_moment << " N m, largest ||Mz| - |My|| "
                                     << worst);
  // past yield: the bars' yield moment about one axis is roughly
  // 3 A_s fy 0.32 = 1.25e5 N m
  BOOST_TEST(largest_moment > 1.25e5);
  // tolerance: the same fibres summed in another order, through the
  // element's iteration
  BOOST_TEST(worst <= 1e-8 * largest_moment);
}

BOOST_AUTO_TEST_CASE(bad_3d_fibre_frames_are_refused)
{
  const std::string base = frame_3d_text(fibre_members, elastic_fibres);
  auto              with = [&](const std::string &from, const std::string &to) {
    std::string text = base;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  // an elastic rigidity of the 3D frame in a fibre building
  const std::string iz = poundfe_test::input_error_of([&] {
    prepare_analysis(poundfe_test::input_of(
      "fibre_iz", with(" set Column sections", " set Column Iz = 1e-3\n set Column sections")));
  });
  BOOST_TEST(iz.find("Building 1/Column Iz") != std::string::npos);
  BOOST_TEST(iz.find("takes its rigidities from its sections") != std::string::npos);
  // a section without its GJ: a member in space twists
  const std::string gj = poundfe_test::input_error_of([&] {
    prepare_analysis(poundfe_test::input_of(
      "fibre_gj", with("  set Torsional rigidity = 3.75e7\n", "")));
  });
  BOOST_TEST(gj.find("Sections/Section 1/Torsional rigidity") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
