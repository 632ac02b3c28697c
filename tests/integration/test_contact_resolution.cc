// Contact resolved in time (Contact/Steps per contact, integration/newmark.h):
// the step-convergence study of input/shear-pair-pounding.prm, two shear
// buildings pounding through gaps at their common floors under a motion
// given by a sum of cosines (the same at every step).
//  - Linear gaps (k = 5e8 N/m, m_e = 500 kg: an impact lasts
//    pi sqrt(m_e / k) = 3.1 ms, three steps of 1 ms): the peaks at
//    dt = 1e-3 s (drift ratio and absolute acceleration of every floor,
//    including the pounding floors; peak contact force and impulse of every
//    gap) are within 0.5 % of those at dt = 1e-4 s, the reference (second
//    order, so its own error is about 1 % of that at 1e-3).
//  - Without sub-stepping (Steps per contact = 0) at dt = 5e-4 s a peak is
//    off by more than 0.5 %: what the sub-stepping buys.
//  - Jankowski's law (beta = 2.75e9 N/m^1.5) at dt = 1e-2 s: no step cut and
//    at most 4 Newton iterations in any step; at dt = 1e-3 s within 0.5 % of
//    dt = 1e-4 s.
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/output/peak_response.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace poundfe;

namespace
{
  struct StudyRun
  {
    std::map<std::string, double> peaks; // by name, for the comparison
    unsigned long                 step_cuts = 0, n_impacts = 0;
    unsigned int                  max_iterations = 0;
  };

  /// The pair at time step dt with the given overrides; the peaks compared.
  StudyRun
  run_pair(const double dt, std::vector<ParameterOverride> overrides)
  {
    overrides.push_back({"Time integration/Time step", std::to_string(dt)});
    const InputParameters input      = read_parameters("input/shear-pair-pounding.prm", overrides);
    const Analysis        analysis   = prepare_analysis(input);
    const Excitation      excitation = make_excitation(analysis, input);
    TimeHistory           history(analysis, time_history_parameters(input));
    PeakResponse          peaks(analysis.model, history.nonlinear_elements());
    const RunStatus       status = history.run(excitation, {&peaks});
    BOOST_TEST_REQUIRE(status.completed());

    StudyRun             result;
    const FloorResponse &floors = peaks.floors();
    for (unsigned int f = 0; f < floors.n_floors(); ++f)
      {
        result.peaks["drift ratio " + std::to_string(f)]  = floors.peak_drift_ratio()[f];
        result.peaks["acceleration " + std::to_string(f)] = floors.peak_acceleration()[f];
      }
    const std::vector<Impact> &impacts = history.state().impact_log().impacts();
    for (const Impact &impact : impacts)
      {
        const std::string gap = std::to_string(impact.element);
        double           &force = result.peaks["peak force " + gap];
        force = std::max(force, impact.peak_force);
        result.peaks["impulse " + gap] += impact.impulse;
      }
    const IterationStatistics &stats = history.state().statistics();
    result.step_cuts      = stats.step_cuts;
    result.max_iterations = stats.max_iterations;
    result.n_impacts      = impacts.size();
    return result;
  }

  /// The largest relative difference of a peak from the reference's.
  double
  worst_difference(const StudyRun &run, const StudyRun &reference)
  {
    double worst = 0;
    for (const auto &[name, value] : reference.peaks)
      {
        BOOST_TEST_REQUIRE(run.peaks.count(name) == 1u, name);
        const double difference = std::abs(run.peaks.at(name) - value) / value;
        BOOST_TEST_MESSAGE("  " << name << ": " << run.peaks.at(name) << " against " << value
                                << " (" << 100 * difference << " %)");
        worst = std::max(worst, difference);
      }
    return worst;
  }
} // namespace

BOOST_AUTO_TEST_CASE(linear_gaps_converge_at_one_millisecond)
{
  const StudyRun reference = run_pair(1e-4, {});
  BOOST_TEST_REQUIRE(reference.n_impacts >= 3u); // it pounds
  const StudyRun resolved = run_pair(1e-3, {});
  BOOST_TEST(resolved.n_impacts == reference.n_impacts);
  BOOST_TEST(worst_difference(resolved, reference) < 0.005);

  const StudyRun unresolved = run_pair(5e-4, {{"Contact/Steps per contact", "0"}});
  BOOST_TEST(worst_difference(unresolved, reference) > 0.005);
}

BOOST_AUTO_TEST_CASE(jankowski_gaps_at_ten_milliseconds_without_step_cuts)
{
  const std::vector<ParameterOverride> jankowski{{"Contact/Law", "jankowski"},
                                                 {"Contact/Stiffness", "2.75e9"}};
  const StudyRun coarse = run_pair(1e-2, jankowski);
  BOOST_TEST(coarse.n_impacts > 0u);
  BOOST_TEST(coarse.step_cuts == 0u);
  BOOST_TEST(coarse.max_iterations <= 4u);

  const StudyRun reference = run_pair(1e-4, jankowski);
  const StudyRun resolved  = run_pair(1e-3, jankowski);
  BOOST_TEST(resolved.n_impacts == reference.n_impacts);
  BOOST_TEST(worst_difference(resolved, reference) < 0.005);
}

// Contact onset from acceleration: the rate at which an open gap closes on
// the parabola delta + rate t + acceleration t^2 / 2 within a step h, from
// the closed form of the crossing (t solves the quadratic; v = rate +
// acceleration t, i.e. v^2 = rate^2 - 2 acceleration delta).
BOOST_AUTO_TEST_CASE(a_gap_closes_on_the_parabola_of_its_rate_and_acceleration)
{
  const double h = 1e-2, delta = -1e-3;
  // a constant rate that closes it: the rate itself
  BOOST_CHECK_CLOSE(predicted_closing_rate(delta, 0.2, 0, h), 0.2, 1e-12);
  // too slow alone (delta + rate h = -5e-4), closed by the acceleration
  const double t = (-0.05 + std::sqrt(0.05 * 0.05 + 2 * 20 * 1e-3)) / 20;
  BOOST_TEST(t < h);
  BOOST_CHECK_CLOSE(predicted_closing_rate(delta, 0.05, 20, h), 0.05 + 20 * t, 1e-10);
  // decelerating, crossing before h: the rate at the crossing
  BOOST_CHECK_CLOSE(predicted_closing_rate(delta, 0.2, -10, h), std::sqrt(0.04 - 0.02), 1e-10);
  // decelerating, turning back at t = 4e-3 s 0.6 mm short of contact
  BOOST_TEST(predicted_closing_rate(delta, 0.2, -50, h) == 0);
  // opening, and approaching too slowly with no acceleration
  BOOST_TEST(predicted_closing_rate(delta, -0.1, 5, h) == 0);
  BOOST_TEST(predicted_closing_rate(delta, 0.05, 0, h) == 0);
  // closed already: the closing rate, not negative
  BOOST_TEST(predicted_closing_rate(1e-4, -0.3, 0, h) == 0);
}
