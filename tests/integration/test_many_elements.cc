// Many nonlinear elements (integration/newmark.h, Tangent update = hybrid,
// Woodbury columns, Nonlinear solver = modified-newton; assembly/low_rank_update.h):
//  - a row of 12 shear buildings of 30 storeys pounding through 330 linear
//    gaps: the hybrid update (Woodbury on a bounded set of columns of
//    A^-1 B while the closed gaps fit, else the assembled tangent
//    refactorised) gives the trajectory of pure refactorisation and of the
//    full Woodbury update to solver round-off (1e-9 of the peak: three
//    direct solves of the same equations), also with only 4 columns kept,
//    which forces both paths and the replacement of kept columns;
//  - modified Newton on Bouc-Wen storeys converges to the same trajectory
//    within the Newton tolerance (1e-6 of the peak: each step's residual is
//    below 1e-8 of its first, and the steps' errors add up over the run),
//    with one factorisation per step, or fewer factorisations than steps
//    when K_0 is kept across steps.
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/integration/newmark.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace poundfe;

namespace
{
  /// A row of n shear buildings of s storeys, alternately stiff and soft,
  /// 5 mm apart with linear gaps at every floor; Bouc-Wen storeys if
  /// `hysteretic`. Written to a file (read back through the checks).
  InputParameters
  row_of_buildings(const unsigned int n, const unsigned int s, const bool hysteretic,
                   const std::vector<ParameterOverride> &overrides)
  {
    std::ostringstream prm;
    prm << "subsection Model\n  set Number of buildings = " << n
        << "\n  set Separations = 0.005\nend\n";
    for (unsigned int b = 1; b <= n; ++b)
      {
        prm << "subsection Building " << b << "\n  set Name = S" << b
            << "\n  set Type = shear\n  set Number of storeys = " << s
            << "\n  set Storey heights = 3\n  set Floor masses = 1000\n  set Storey stiffnesses = "
            << (b % 2 ? 4e7 : 2.5e7) << "\n";
        if (hysteretic)
          prm << "  set Storey yield drifts = 0.004\n";
        prm << "  subsection Damping\n    set Type = modes\n    set Damping ratio = 0.02\n"
               "    set Modes = 1, 2\n  end\nend\n";
      }
    prm << "subsection Ground motion\n  set Type = kanai-tajimi\n  subsection Stochastic\n"
           "    set Target PGA = 0.5\n    set Duration = 3\n    set Seed = 5\n  end\nend\n"
           "subsection Contact\n  set Law = linear\n  set Stiffness = 1e8\nend\n"
           "subsection Time integration\n  set Time step = 0.005\nend\n";
    const std::string file = "/tmp/poundfe-test-many-elements.prm";
    std::ofstream(file) << prm.str();
    InputParameters input = read_parameters(file, overrides);
    std::remove(file.c_str());
    return input;
  }

  struct History
  {
    std::vector<Vector> u;
    IterationStatistics statistics;
    TangentUpdate       update = TangentUpdate::automatic;
    double              peak   = 0;
  };

  History
  run(const InputParameters &input, const std::string &solver)
  {
    const Analysis    analysis   = prepare_analysis(input);
    const Excitation  excitation = make_excitation(analysis, input);
    NonlinearElements elements   = make_nonlinear_elements(analysis.model);
    NewmarkIntegrator integrator(analysis.system, solver, input.time_integration.newmark,
                                 &elements);
    Vector load(analysis.system.n_equations());
    excitation.load(0, load);
    integrator.initialize(load);
    History            history;
    const unsigned int n_steps =
      std::lround(excitation.ground_motion().duration() / input.time_integration.newmark.time_step);
    for (unsigned int i = 0; i < n_steps; ++i)
      {
        integrator.advance([&](double t, Vector &p) { excitation.load(t, p); });
        history.u.push_back(integrator.displacement());
        history.peak = std::max(history.peak, history.u.back().lpNorm<Eigen::Infinity>());
      }
    history.statistics = integrator.statistics();
    history.update     = integrator.tangent_update();
    return history;
  }

  double
  largest_difference(const History &a, const History &b)
  {
    BOOST_TEST_REQUIRE(a.u.size() == b.u.size());
    double worst = 0;
    for (std::size_t i = 0; i < a.u.size(); ++i)
      worst = std::max(worst, (a.u[i] - b.u[i]).lpNorm<Eigen::Infinity>());
    return worst;
  }
} // namespace

BOOST_AUTO_TEST_CASE(hybrid_update_matches_refactorisation_on_hundreds_of_gaps)
{
  const History refactorized = run(row_of_buildings(12, 30, false, {{"Time integration/Tangent update", "refactorize"}}), "umfpack");
  const History automatic    = run(row_of_buildings(12, 30, false, {}), "umfpack");
  const History woodbury = run(row_of_buildings(12, 30, false, {{"Time integration/Tangent update", "woodbury"}}), "umfpack");
  const History few = run(row_of_buildings(12, 30, false, {{"Time integration/Woodbury columns", "4"}}), "umfpack");
  BOOST_TEST(tangent_update_names().name(automatic.update) == "hybrid"); // 330 gaps > 100 columns
  BOOST_TEST(refactorized.statistics.woodbury_solves == 0u);
  BOOST_TEST(refactorized.statistics.refactorizations > 0u);
  BOOST_TEST(woodbury.statistics.refactorizations == 0u);
  BOOST_TEST(automatic.statistics.woodbury_solves > 0u);
  BOOST_TEST(few.statistics.woodbury_solves > 0u); // both paths taken
  BOOST_TEST(few.statistics.refactorizations > 0u);
  BOOST_TEST(refactorized.peak > 0.005); // the gaps close
  for (const History *h : {&automatic, &woodbury, &few})
    {
      const double difference = largest_difference(*h, refactorized);
      BOOST_TEST_MESSAGE(tangent_update_names().name(h->update)
                         << ": " << h->statistics.woodbury_solves << " Woodbury solves, "
                         << h->statistics.refactorizations << " factorisations, "
                         << h->statistics.iterations << " iterations; difference "
                         << difference / refactorized.peak << " of the peak");
      BOOST_TEST(difference < 1e-9 * refactorized.peak);
    }
}

BOOST_AUTO_TEST_CASE(modified_newton_converges_to_the_same_trajectory)
{
  const std::vector<ParameterOverride> refactorize = {
    {"Time integration/Tangent update", "refactorize"}};
  const History full = run(row_of_buildings(3, 30, true, refactorize), "umfpack");
  // the classical form: K_0 formed at each step's first iteration and kept
  // for the step (a ratio of 10: re-formed only if the residual grows ten-fold)
  std::vector<ParameterOverride> per_step = refactorize;
  per_step.insert(per_step.end(), {{"Time integration/Nonlinear solver", "modified-newton"},
                                   {"Time integration/Keep tangent across steps", "false"},
                                   {"Time integration/Refactorisation ratio", "10"},
                                   {"Time integration/Newton maximum iterations", "100"}});
  const History modified = run(row_of_buildings(3, 30, true, per_step), "umfpack");
  // K_0 kept across steps: re-formed only when an iteration contracts by
  // less than 0.5. Five factorisations for the run: iterations stop just
  // under the tolerance every step, so it is 1e-10 here (at 1e-8 the steps'
  // errors add up to 1.3e-6 of the peak)
  std::vector<ParameterOverride> kept = refactorize;
  kept.insert(kept.end(), {{"Time integration/Nonlinear solver", "modified-newton"},
                           {"Time integration/Newton residual tolerance", "1e-10"},
                           {"Time integration/Newton maximum iterations", "100"}});
  const History across = run(row_of_buildings(3, 30, true, kept), "umfpack");
  for (const History *h : {&modified, &across})
    {
      const double difference = largest_difference(*h, full);
      BOOST_TEST_MESSAGE("modified Newton" << (h == &across ? " (K_0 kept across steps): " : ": ")
                                           << h->statistics.iterations << " iterations, "
                                           << h->statistics.refactorizations
                                           << " factorisations in " << h->statistics.steps
                                           << " steps; full: " << full.statistics.iterations
                                           << ", " << full.statistics.refactorizations
                                           << "; difference " << difference / full.peak
                                           << " of the peak");
      BOOST_TEST(difference < 1e-6 * full.peak);
      BOOST_TEST(h->statistics.full_newton_retries == 0u);
    }
  // one factorisation per attempt of a step (accepted, or redone around an
  // event or cut) against one per iteration
  const IterationStatistics &m = modified.statistics;
  BOOST_TEST(m.refactorizations <= m.steps + m.event_refinements + m.step_cuts);
  BOOST_TEST(m.refactorizations < full.statistics.refactorizations);
  BOOST_TEST(full.statistics.refactorizations >= full.statistics.iterations);
  // kept across steps: fewer factorisations than steps
  BOOST_TEST(across.statistics.refactorizations < across.statistics.steps);
}
