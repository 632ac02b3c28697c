// ReplayedStepper (integration/replayed_stepper.h) against the integrator
// whose accepted states it replays. A pounding row (tests/cli/
// city-block-small.prm: three frames with 57 Bouc-Wen hinges and 8
// Hertz-damp gaps) runs on one process through NewmarkIntegrator with Event
// refinement and Steps per contact, so that contacts cut steps into
// sub-steps; an observer hands a ReplayedStepper, over a second set of the
// model's elements made independently, the state of every accepted
// (sub)step, as each rank of a partitioned run does for its elements (report/run_outputs.cc). Its elements' force and history variable, their work and the
// impact log must equal the integrator's to the last bit: the replay does
// the same operations on the same numbers. A replay at a state the owner did
// not commit, or a sub-step missed or replayed twice, changes a Bouc-Wen z
// and the impacts' times at O(1) of their size.
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/integration/replayed_stepper.h>

#include <boost/test/unit_test.hpp>

#include <fstream>
#include <sstream>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  /// The small city block with a one-process solver and contacts that cut steps.
  InputParameters
  pounding_row()
  {
    std::ifstream      file("tests/cli/city-block-small.prm");
    std::ostringstream text;
    text << file.rdbuf();
    std::string prm = text.str();
    const auto replace = [&prm](const std::string &from, const std::string &to) {
      const std::size_t at = prm.find(from);
      BOOST_REQUIRE(at != std::string::npos);
      prm.replace(at, from.size(), to);
    };
    replace("set Linear solver = petsc-mumps", "set Linear solver = umfpack");
    replace("subsection Contact\n", "subsection Contact\n  set Event refinement = 2\n"
                                    "  set Steps per contact = 8\n");
    replace("set End time      = 1.5", "set End time = 1.2");
    return read_parameters(poundfe_test::temporary_file("replayed_row.prm", prm));
  }

  /// Replays every state `integrator` accepts and counts where the replay
  /// and the integrator differ.
  class Replayer
  {
  public:
    Replayer(const Model &model, const NewmarkIntegrator &integrator,
             const NonlinearElements &integrated)
      : integrator(integrator)
      , integrated(integrated)
      , elements(make_nonlinear_elements(model))
      , stepper(elements, model.n_equations())
    {}

    void
    start()
    {
      copy_state();
      stepper.start();
      compare();
    }
    void
    replay()
    {
      copy_state();
      stepper.replay(integrator.time(), integrator.last_step_length(),
                     integrator.statistics().steps);
      compare();
    }

    /// The impact logs, field by field.
    void
    compare_impacts()
    {
      const std::vector<Impact> &ours   = stepper.impact_log().impacts();
      const std::vector<Impact> &theirs = integrator.impact_log().impacts();
      n_impacts                         = theirs.size();
      BOOST_REQUIRE_EQUAL(ours.size(), theirs.size());
      for (std::size_t i = 0; i < ours.size(); ++i)
        {
          const Impact &a = ours[i], &b = theirs[i];
          BOOST_TEST(a.element == b.element);
          BOOST_TEST(a.start_time == b.start_time);
          BOOST_TEST(a.end_time == b.end_time);
          BOOST_TEST(a.max_penetration_time == b.max_penetration_time);
          BOOST_TEST(a.approach_velocity == b.approach_velocity);
          BOOST_TEST(a.separation_velocity == b.separation_velocity);
          BOOST_TEST(a.max_penetration == b.max_penetration);
          BOOST_TEST(a.peak_force == b.peak_force);
          BOOST_TEST(a.impulse == b.impulse);
        }
    }

    unsigned long n_states = 0, n_differences = 0;
    std::size_t   n_impacts = 0;

  private:
    /// The integrator's state into the replay's (as each rank places its own).
    void
    copy_state()
    {
      const std::array<Vector *, 3> to = stepper.state_to_fill();
      *to[0]                           = integrator.displacement();
      *to[1]                           = integrator.velocity();
      *to[2]                           = integrator.acceleration();
    }
    void
    compare()
    {
      ++n_states;
      BOOST_REQUIRE_EQUAL(elements.size(), integrated.size());
      BOOST_REQUIRE(stepper.time() == integrator.time());
      for (unsigned int h = 0; h < elements.size(); ++h)
        if (elements[h].force() != integrated[h].force() ||
            elements[h].history_variable() != integrated[h].history_variable() ||
            stepper.element_work(h) != integrator.element_work(h))
          ++n_differences;
    }

    const NewmarkIntegrator &integrator;
    const NonlinearElements &integrated;
    NonlinearElements        elements;
    ReplayedStepper          stepper;
  };
} // namespace

BOOST_AUTO_TEST_CASE(a_replay_of_the_accepted_states_is_the_integrators_history)
{
  const InputParameters       input      = pounding_row();
  const Analysis              analysis   = prepare_analysis(input);
  const TimeHistoryParameters parameters = time_history_parameters(input);
  const Excitation            excitation = make_excitation(analysis, parameters);
  NonlinearElements           elements   = make_nonlinear_elements(analysis.model);
  NewmarkIntegrator newmark(analysis.system, "umfpack", parameters.time_integration.newmark,
                            &elements);
  const LoadFunction load = [&excitation](const double t, Vector &p) { excitation.load(t, p); };
  Vector             p0(analysis.system.n_equations());
  load(0, p0);
  newmark.initialize(p0);
  Replayer      replayer(analysis.model, newmark, elements);
  unsigned long n_substeps = 0;
  newmark.set_substep_callback([&]() {
    ++n_substeps;
    replayer.replay();
  });
  replayer.start();
  const unsigned long n_steps = n_steps_of(parameters, excitation);
  for (unsigned long step = 0; step < n_steps; ++step)
    {
      newmark.advance(load);
      replayer.replay(); // after a cut step: its last sub-step again, as the step
    }
  replayer.compare_impacts();
  // the test engages: sub-steps, impacts and yielding hinges
  BOOST_TEST(n_substeps > 0u);
  BOOST_TEST(replayer.n_impacts > 0u);
  double largest_z = 0;
  for (const NonlinearElement &e : elements)
    if (e.kind == ElementKind::hinge)
      largest_z = std::max(largest_z, std::abs(e.history_variable()));
  BOOST_TEST(largest_z > 0.1);
  BOOST_TEST(replayer.n_differences == 0u);
  BOOST_TEST_MESSAGE("replayed " << replayer.n_states << " states (" << n_substeps
                                 << " sub-steps), " << replayer.n_impacts
                                 << " impacts, largest hinge |z| " << largest_z);
}
