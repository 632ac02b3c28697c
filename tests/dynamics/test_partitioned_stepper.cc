// A run partitioned by building steps through the program's one time loop
// (TimeHistory::run over a PartitionedStepper, dynamics/partitioned_stepper.h),
// here on one rank:
//  - every step's time, u, v and a are those of the whole model's run
//    through TimeHistory with the integrator of a partitioned run (the same
//    Krylov-Newton iterations; only the order of sums may differ), the
//    same impacts;
//  - an observer that cannot write at step 40 stops the run at the start of
//    the next step, failed for its output with its message, the 40 steps
//    kept, and every observer still finishes.
#include <poundfe/base/exceptions.h>
#include <poundfe/dynamics/partitioned_history.h>
#include <poundfe/dynamics/partitioned_stepper.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/input/engine_parameters.h>

#include <cerrno>
#include <string>

#include "time_history_helpers.h"

using namespace poundfe;

// the partitioned history's communicator (MPI_COMM_SELF here) needs MPI:
// the first test of unit/dynamics to run over ranks
using poundfe_test::MpiFixture;
BOOST_GLOBAL_FIXTURE(MpiFixture);

namespace
{
  /// Two shear buildings of 3 and 2 Bouc-Wen storeys, 1 mm apart, pounding
  /// (Hertz-damp, 2 impacts) under 1 s of a Kanai-Tajimi motion of 0.6 g: made for
  /// this test.
  const std::string pounding_pair = [] {
    std::string text = "subsection Model\n  set Number of buildings = 2\n  set Separations = 0.001\nend\n";
    const char *masses[]      = {"30000, 30000, 30000", "20000, 20000"};
    const char *stiffnesses[] = {"3e7, 2.7e7, 2.4e7", "5e7, 4.5e7"};
    for (unsigned int b = 0; b < 2; ++b)
      text += "subsection Building " + std::to_string(b + 1) + "\n  set Name = S" +
              std::to_string(b + 1) + "\n  set Type = shear\n  set Number of storeys = " +
              std::to_string(3 - b) + "\n  set Storey heights = 3.0\n  set Floor masses = " +
              masses[b] + "\n  set Storey stiffnesses = " + stiffnesses[b] +
              "\n  set Storey yield drifts = 0.004\n  subsection Bouc-Wen\n    set alpha = 0.05\n"
              "  end\nend\n";
    return text +
           "subsection Ground motion\n  set Type = kanai-tajimi\n  subsection Stochastic\n"
           "    set Soil = soft\n    set Target PGA = 0.6\n    set Duration = 4\n    set Seed = 77\n"
           "  end\nend\n"
           "subsection Contact\n  set Law = hertz-damp\n  set Stiffness = 2e9\n"
           "  set Damping from = calibrated\n  set Coefficient of restitution = 0.6\nend\n"
           "subsection Time integration\n  set Time step = 0.002\n  set End time = 1.0\n"
           "  set Newton residual tolerance = 1e-11\n  set Nonlinear solver = krylov-newton\nend\n";
  }();

  /// The parameters of a partitioned run's integrator (whatever the input
  /// says: partitioned_newmark_parameters), for the whole model's reference.
  TimeHistoryParameters
  as_partitioned(TimeHistoryParameters parameters)
  {
    TimeIntegrationParameters &t = parameters.time_integration;
    t.newmark       = partitioned_newmark_parameters(t);
    t.linear_solver = partitioned_block_solver(t.linear_solver);
    return parameters;
  }

  /// Throws an OutputError when it sees step `failing`; counts its finishes.
  struct FailingWriter : StepObserver
  {
    explicit FailingWriter(const unsigned long failing)
      : failing(failing)
    {}
    void
    observe_step(const ResponseView &state) override
    {
      if (state.step() == failing)
        throw OutputError("write", "failing.csv", ENOSPC);
    }
    void finish(const ResponseView &, const RunStatus &) override { ++finished; }
    const unsigned long failing;
    unsigned int        finished = 0;
  };
} // namespace

BOOST_AUTO_TEST_SUITE(partitioned_stepper)

BOOST_AUTO_TEST_CASE(steps_through_time_history_as_the_whole_model)
{
  const InputParameters input = poundfe_test::input_of("partitioned-stepper", pounding_pair);
  const TimeHistoryParameters parameters = time_history_parameters(input);

  const Analysis    whole = prepare_analysis(input);
  const Excitation  excitation = make_excitation(whole, parameters);
  TimeHistory       reference(whole, as_partitioned(parameters));
  poundfe_test::StepRecorder expected;
  BOOST_REQUIRE(reference.run(excitation, {&expected}).completed());

  Analysis           mine = prepare_rank_analysis(input, MPI_COMM_SELF);
  PartitionedStepper stepper(mine, parameters, MPI_COMM_SELF);
  TimeHistory        history(mine, parameters, stepper);
  poundfe_test::StepRecorder seen;
  const RunStatus    status = history.run(stepper.excitation(), {&seen});
  BOOST_REQUIRE(status.completed());
  BOOST_TEST(status.steps == 500u);
  BOOST_TEST(stepper.history().statistics().steps == reference.state().statistics().steps);

  BOOST_REQUIRE_EQUAL(seen.t.size(), expected.t.size());
  BOOST_REQUIRE_GT(reference.state().impact_log().impacts().size(), 0u); // the pair pounds
  BOOST_TEST(stepper.impact_log().impacts().size() == reference.state().impact_log().impacts().size());
  double peak = 0, largest = 0;
  for (const Vector &u : expected.u)
    peak = std::max(peak, u.lpNorm<Eigen::Infinity>());
  for (std::size_t i = 0; i < seen.t.size(); ++i)
    {
      BOOST_TEST(seen.t[i] == expected.t[i]);
      largest = std::max(largest, (seen.u[i] - expected.u[i]).lpNorm<Eigen::Infinity>());
    }
  BOOST_TEST(largest <= 1e-9 * peak);
  BOOST_TEST_MESSAGE("largest difference of u: " << largest / peak << " of its peak " << peak << " m");
  BOOST_TEST(seen.energy.input == expected.energy.input, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(a_rank_that_cannot_write_stops_at_the_next_step)
{
  const InputParameters input = poundfe_test::input_of("partitioned-stepper-full", pounding_pair);
  const TimeHistoryParameters parameters = time_history_parameters(input);
  Analysis           mine = prepare_rank_analysis(input, MPI_COMM_SELF);
  PartitionedStepper stepper(mine, parameters, MPI_COMM_SELF);
  TimeHistory        history(mine, parameters, stepper);
  FailingWriter      writer(40);
  poundfe_test::StepRecorder seen;
  const RunStatus status = history.run(stepper.excitation(), {&seen, &writer});
  BOOST_TEST(std::string(status.name()) == "failed");
  BOOST_TEST(status.output_failed);
  BOOST_TEST(status.message.find("failing.csv") != std::string::npos);
  BOOST_TEST(status.steps == 40u);
  BOOST_TEST(status.end_time == 40 * 0.002);
  BOOST_TEST(seen.t.size() == 41u); // the initial state and 40 steps
  BOOST_TEST(writer.finished == 1u);
}

BOOST_AUTO_TEST_SUITE_END()
