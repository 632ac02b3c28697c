// Gravity first (Model/Gravity analysis = static; dynamics/gravity_state.cc,
// integration/static_analysis.h): the columns' axial forces against statics
// by hand, a run without excitation that stays at the gravity state, an
// elastic run that is the run without gravity plus the static offset, the
// P-Delta periods of the gravity state against the closed form, hinges
// that start from their gravity moments, and the members' distributed
// self-weight (elastic and fibre members) carried to the base and held.
#include <poundfe/assembly/linear_system.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/integration/static_analysis.h>
#include <poundfe/output/storey_forces.h>

#include "time_history_helpers.h"

#include <boost/test/unit_test.hpp>

#include <Eigen/SparseCholesky>

#include <cmath>
#include <string>

using namespace poundfe;

namespace
{
  /// A 2-storey, 2-bay elastic frame with equal columns, joint masses and
  /// extra floor loads; hinges and P-Delta as asked.
  std::string
  gravity_frame(const std::string &gravity, const std::string &extra, const std::string &motion)
  {
    return "subsection Model\n set Geometric nonlinearity = none\n"
           " subsection Gravity analysis\n  set Type = " + gravity + "\n  set Number of steps = 4\n"
           "  set Tolerance = 1e-12\n end\nend\n"
           "subsection Building 1\n set Name = F\n set Type = frame\n"
           " set Number of storeys = 2\n set Number of bays = 2\n set Storey heights = 3.5, 3\n"
           " set Bay widths = 5\n set Column E = 3e10\n set Column A = 0.16\n"
           " set Column I = 2.1e-3\n set Beam E = 3e10\n set Beam A = 0.15\n"
           " set Beam I = 3.1e-3\n set Floor masses = 3e4, 2e4\n set Floor loads = 6e4, 3e4\n" +
           extra +
           " subsection Damping\n  set Type = coefficients\n  set a0 = 0.3\n  set a1 = 0.002\n"
           " end\nend\n" + motion;
  }

  const std::string motionless = "subsection Ground motion\n set Type = none\nend\n"
                            "subsection Time integration\n set End time = 0.5\n"
                            " set Time step = 0.01\nend\n";

  const std::string gravity_shaking = "subsection Ground motion\n set Type = kanai-tajimi\n"
                              " subsection Stochastic\n  set Target PGA = 0.3\n  set Duration = 1\n"
                              "  set Seed = 7\n  set Second seed = 8\n"
                              "  set Method = spectral-representation\n"
                              "  set Cutoff frequency = 50\n end\nend\n"
                              "subsection Time integration\n set Time step = 0.005\nend\n";

  /// The largest |u_t - u_ref| over every step, and the largest |u_ref|.
  std::array<double, 2>
  largest_difference(const poundfe_test::StepRecorder &run, const Vector &reference)
  {
    double difference = 0;
    for (const Vector &u : run.u)
      difference = std::max(difference, (u - reference).lpNorm<Eigen::Infinity>());
    return {{difference, reference.lpNorm<Eigen::Infinity>()}};
  }
} // namespace

BOOST_AUTO_TEST_SUITE(gravity)

// Equal columns under equal joint loads shorten equally, so the beams do
// not bend and each column of a storey carries a third of the weight and
// floor loads above it: storey 1, (m1 g + q1 + m2 g + q2) / 3; storey 2,
// (m2 g + q2) / 3 (compression). The gravity state's axial forces to 1e-9.
BOOST_AUTO_TEST_CASE(columns_carry_their_tributary_loads)
{
  const Analysis a = prepare_analysis(
    poundfe_test::input_of("gravity_columns", gravity_frame("static", "", motionless)));
  BOOST_REQUIRE(a.gravity.active);
  const double g = 9.81, top = (2e4 * g + 3e4) / 3, bottom = top + (3e4 * g + 6e4) / 3;
  const std::vector<double> forces = member_axial_forces_at(a.model, a.gravity.displacement);
  unsigned int columns = 0;
  for (unsigned int m = 0; m < a.model.members.size(); ++m)
    if (a.model.members[m].kind == MemberKind::column)
      {
        const double expected = a.model.members[m].group == 1 ? -bottom : -top;
        BOOST_TEST(forces[m] == expected, boost::test_tools::tolerance(1e-9));
        ++columns;
      }
  BOOST_TEST(columns == 6u);
  BOOST_TEST(a.gravity.base_reactions[0] == 3 * bottom, boost::test_tools::tolerance(1e-12));
}

// No excitation: the gravity loads held and the state of the gravity
// analysis are an equilibrium, so every step stays at u_g to round-off
// (1e-12 of the largest gravity displacement), elastic and with hinges.
BOOST_AUTO_TEST_CASE(a_run_without_excitation_stays_at_the_gravity_state)
{
  for (const std::string hinges :
       {std::string(""), std::string(" subsection Hinges\n  set Locations = column bases, beam "
                                     "ends\n  set Yield moment = 4e4\n end\n")})
    {
      const InputParameters p =
        poundfe_test::input_of("gravity_still", gravity_frame("static", hinges, motionless));
      const Analysis a = prepare_analysis(p);
      const poundfe_test::StepRecorder run = poundfe_test::recorded_run(a, p);
      BOOST_REQUIRE(run.u.size() >= 50u);
      const auto [difference, scale] = largest_difference(run, a.gravity.displacement);
      BOOST_TEST(scale > 1e-4);
      BOOST_TEST(difference <= 1e-12 * scale);
    }
}

// Linear and without P-Delta, gravity first only adds the constant static
// displacement K^-1 f_g (solved here by Cholesky): u_gravity(t) =
// u_none(t) + u_s at every step, to 1e-9 of the response.
BOOST_AUTO_TEST_CASE(an_elastic_run_is_offset_by_the_static_displacement)
{
  const InputParameters with = poundfe_test::input_of("gravity_on", gravity_frame("static", "", gravity_shaking));
  const InputParameters without = poundfe_test::input_of("gravity_off", gravity_frame("none", "", gravity_shaking));
  const Analysis a = prepare_analysis(with), b = prepare_analysis(without);
  BOOST_REQUIRE(!b.gravity.active);
  const Eigen::SimplicialLDLT<SparseMatrix> ldlt(b.system.stiffness);
  const Vector static_u = ldlt.solve(total_gravity_loads(b.model));
  const poundfe_test::StepRecorder r = poundfe_test::recorded_run(a, with);
  const poundfe_test::StepRecorder s = poundfe_test::recorded_run(b, without);
  BOOST_REQUIRE_EQUAL(r.u.size(), s.u.size());
  double difference = 0, scale = 0;
  for (unsigned int i = 0; i < r.u.size(); ++i)
    {
      difference = std::max(difference, (r.u[i] - s.u[i] - static_u).lpNorm<Eigen::Infinity>());
      scale      = std::max(scale, (s.u[i]).lpNorm<Eigen::Infinity>());
    }
  BOOST_TEST(scale > 1e-4);
  BOOST_TEST(difference <= 1e-9 * scale);
}

// A one-storey shear building under P-Delta with a floor load q: the
// storey loses (m g + q) / h, omega^2 = (k - (m g + q) / h) / m, to 1e-10;
// and gravity first on a linear model leaves the linearised P-Delta's
// period as it was.
BOOST_AUTO_TEST_CASE(p_delta_period_of_the_gravity_state)
{
  const double m = 5e4, k = 2e7, h = 3.2, q = 2e5, g = 9.81;
  const auto text = [&](const std::string &type) {
    return "subsection Model\n set Geometric nonlinearity = p-delta\n"
           " subsection Gravity analysis\n  set Type = " + type + "\n end\nend\n"
           "subsection Building 1\n set Type = shear\n set Number of storeys = 1\n"
           " set Storey heights = 3.2\n set Floor masses = 5e4\n set Storey stiffnesses = 2e7\n"
           " set Floor loads = 2e5\n subsection Damping\n  set Type = none\n end\nend\n"
           "subsection Ground motion\n set Type = none\nend\n"
           "subsection Output\n set Number of modes = 1\nend\n";
  };
  const Analysis with = prepare_analysis(poundfe_test::input_of("pdelta_on", text("static")));
  const Analysis without = prepare_analysis(poundfe_test::input_of("pdelta_off", text("none")));
  BOOST_REQUIRE(with.gravity.active);
  const double expected = std::sqrt((k - (m * g + q) / h) / m);
  BOOST_TEST(with.modes.omega[0] == expected, boost::test_tools::tolerance(1e-10));
  BOOST_TEST(without.modes.omega[0] == expected, boost::test_tools::tolerance(1e-10));
}

// A frame of heavy beams (consistent mass: their weight gives the fixed-end
// moments w L^2 / 12) with elastic-range hinges at the beam ends: at t = 0
// of a run the hinge moments are those of the static solution K u = f_g
// (K with the hinges' initial stiffness; solved here), to 1e-4 (the
// Bouc-Wen law's departure from linear at this small fraction of yield).
BOOST_AUTO_TEST_CASE(hinges_start_from_their_gravity_moments)
{
  const std::string hinges = " set Beam mass per length = 2000\n"
                             " subsection Hinges\n  set Locations = beam ends\n"
                             "  set Yield moment = 5e6\n end\n";
  std::string text = gravity_frame("static", hinges, motionless);
  const std::string none = " set Geometric nonlinearity = none\n";
  text.replace(text.find(none), none.size(), none + " set Mass matrix = consistent\n");
  const InputParameters p = poundfe_test::input_of("gravity_hinges", text);
  const Analysis a = prepare_analysis(p);
  const Eigen::SimplicialLDLT<SparseMatrix> ldlt(a.system.stiffness);
  const Vector              static_u = ldlt.solve(total_gravity_loads(a.model));
  const TimeHistoryParameters parameters = time_history_parameters(p);
  TimeHistory                 history(a, parameters);
  struct AtStart : StepObserver
  {
    std::vector<double> moments;
    void observe_step(const ResponseView &) override {}
    void initialize(const ResponseView &s) override
    {
      for (const NonlinearElement &e : s.elements)
        moments.push_back(e.force());
    }
  } start;
  BOOST_REQUIRE(history.run(make_excitation(a, parameters), {&start}).completed());
  const NonlinearElements elements = make_nonlinear_elements(a.model);
  BOOST_REQUIRE_EQUAL(start.moments.size(), elements.size());
  double largest = 0;
  for (const NonlinearElement &e : elements)
    largest = std::max(largest, std::abs(e.initial_stiffness() * e.deformation(static_u)));
  BOOST_TEST(largest > 1e3);
  for (unsigned int h = 0; h < elements.size(); ++h)
    BOOST_TEST(std::abs(start.moments[h] -
                        elements[h].initial_stiffness() * elements[h].deformation(static_u)) <=
               1e-4 * largest);
}

namespace
{
  /// A two-storey, one-bay frame with its members' weight distributed
  /// (unit weight 25e3 N/m^3), elastic members or fibre members on a
  /// two-fibre elastic section of the same EA and EI (Linear columns).
  std::string
  self_weight_frame(const bool fibre, const std::string &element = "force",
                    const std::string &extra = "")
  {
    const std::string members =
      fibre ? " set Member model = fibre\n set Member element = " + element +
                "\n set Member transformation = Linear\n set Column sections = two-fibres\n"
                " set Beam sections = two-fibres\n" :
              " set Column E = 3e10\n set Column A = 0.16\n set Column I = 1.6e-3\n"
              " set Beam E = 3e10\n set Beam A = 0.16\n set Beam I = 1.6e-3\n";
    return "subsection Model\n subsection Gravity analysis\n  set Type = static\n"
           "  set Number of steps = 4\n  set Tolerance = 1e-12\n end\nend\n"
           "subsection Sections\n set Number of sections = 1\n"
           " set Materials = el: Elastic E=3e10\n subsection Section 1\n"
           "  set Name = two-fibres\n  set Type = fibres\n"
           "  set Fibres = fiber 0.1 0 0.08 el; fiber -0.1 0 0.08 el\n end\nend\n"
           "subsection Building 1\n set Name = F\n set Type = frame\n"
           " set Number of storeys = 2\n set Number of bays = 1\n set Storey heights = 3.5, 3\n"
           " set Bay widths = 5\n set Floor masses = 3e4, 2e4\n"
           " set Member self-weight = distributed\n set Member unit weight = 25e3\n" +
           members + extra + " subsection Damping\n  set Type = coefficients\n  set a0 = 0.3\n"
           "  set a1 = 0.002\n end\nend\n" + motionless;
  }

  /// The local end forces of member `label` at the gravity state.
  Vector6
  gravity_end_forces(const Analysis &a, const std::string &label)
  {
    NonlinearElements elements = make_nonlinear_elements(a.model);
    restore_static_state(a.gravity.path, a.gravity.path_factors, elements);
    const StoreyForces forces(a.model, elements);
    BOOST_REQUIRE(forces.has_member(label));
    return forces.member_end_forces(label, a.gravity.displacement);
  }

  /// The sum of the base columns' axial end forces (local x at their
  /// lower ends, up) at the gravity state.
  double
  base_column_forces(const Analysis &a)
  {
    return gravity_end_forces(a, "F_C1.1")[0] + gravity_end_forces(a, "F_C1.2")[0];
  }
} // namespace

// Member self-weight = distributed: the elastic members' consistent nodal
// loads and the force-based and displacement-based fibre members' element
// loads (their sections carry s_p, or their q0) on the same rigidities give
// the same gravity state (to 1e-9: the elements' iterations against the
// linear solve), and the base columns' lower-end axial forces (elastic: K_e
// u plus the fixed-end forces) carry the whole weight by statics: the
// floors' m g and every member's 25e3 A L (to 1e-9).
BOOST_AUTO_TEST_CASE(distributed_self_weight_is_carried_to_the_base)
{
  const double total = 9.81 * 5e4 + 25e3 * 0.16 * (2 * (3.5 + 3) + 2 * 5);
  const Analysis elastic =
    prepare_analysis(poundfe_test::input_of("weight_elastic", self_weight_frame(false)));
  BOOST_REQUIRE(elastic.gravity.active);
  BOOST_TEST(base_column_forces(elastic) == total, boost::test_tools::tolerance(1e-9));
  const double scale = elastic.gravity.displacement.lpNorm<Eigen::Infinity>();
  BOOST_TEST(scale > 1e-5);
  for (const std::string element : {"force", "displacement"})
    {
      const Analysis fibre = prepare_analysis(
        poundfe_test::input_of("weight_fibre_" + element, self_weight_frame(true, element)));
      BOOST_TEST((fibre.gravity.displacement - elastic.gravity.displacement)
                     .lpNorm<Eigen::Infinity>() <= 1e-9 * scale);
      BOOST_TEST(base_column_forces(fibre) == total, boost::test_tools::tolerance(1e-9));
    }
}

// The self-weight is held through the dynamics: a fibre frame's run
// without excitation stays at its gravity state (1e-12 of its largest
// displacement), the elements replaying their load factors.
BOOST_AUTO_TEST_CASE(a_run_holds_the_distributed_self_weight)
{
  for (const std::string element : {"force", "displacement"})
    {
      const InputParameters p =
        poundfe_test::input_of("weight_still_" + element, self_weight_frame(true, element));
      const Analysis                   a   = prepare_analysis(p);
      const poundfe_test::StepRecorder run = poundfe_test::recorded_run(a, p);
      BOOST_REQUIRE(run.u.size() >= 50u);
      const auto [difference, scale] = largest_difference(run, a.gravity.displacement);
      BOOST_TEST(scale > 1e-5);
      BOOST_TEST(difference <= 1e-12 * scale);
    }
}

// A beam split into 3 elements (Elements per member = 3) reports the end
// forces of the unsplit beam at both its ends, its label naming every piece
// and no piece of another bay (before, the middle and last pieces were
// placed in bay 2, so end J read 0): against the unsplit member to 1e-9 of
// the largest force (uniform loads are exact in each element), and each
// end's shear against the closed form q L / 2 of the symmetric frame (q =
// 25e3 A, L = 5; to 1e-9).
BOOST_AUTO_TEST_CASE(split_beams_keep_their_end_forces)
{
  const double half_span_load = 25e3 * 0.16 * 5 / 2;
  for (const bool fibre : {false, true})
    {
      const Analysis whole = prepare_analysis(
        poundfe_test::input_of("weight_whole", self_weight_frame(fibre)));
      const Analysis split = prepare_analysis(poundfe_test::input_of(
        "weight_split", self_weight_frame(fibre, "force", " set Elements per member = 3\n")));
      BOOST_REQUIRE(split.model.members.size() == 3 * whole.model.members.size());
      for (const std::string label : {"F_B1.1", "F_B2.1"})
        {
          const Vector6 reference = gravity_end_forces(whole, label);
          const Vector6 pieces    = gravity_end_forces(split, label);
          const double  largest   = reference.lpNorm<Eigen::Infinity>();
          BOOST_TEST(largest > 1e3);
          BOOST_TEST((pieces - reference).lpNorm<Eigen::Infinity>() <= 1e-9 * largest);
          BOOST_TEST(std::abs(pieces[1]) == half_span_load, boost::test_tools::tolerance(1e-9));
          BOOST_TEST(std::abs(pieces[4]) == half_span_load, boost::test_tools::tolerance(1e-9));
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
