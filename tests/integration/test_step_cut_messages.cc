// The message of a run that stops numerically (issue 14 item 8): a run was
// seen ending "failed even at dt = 0 s ...: A3-B2@3.5:" with nothing after
// the gap's label. Every path that refuses a step must say why: the laws
// that can refuse a trial state (contact, friction) give the values that
// are not finite, the Newton failure names each criterion against its
// tolerance, and the times are the exact ones (number_text), not 6 digits.
// Reference: the cause is known by construction in each case (an overflow
// built into the input, one Newton iteration allowed).
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/laws/friction.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

using namespace poundfe;

namespace
{
  /// The NumericalError message of running `input` to its end time, empty
  /// when it completes.
  std::string
  failure_of(const InputParameters &input)
  {
    const Analysis    analysis   = prepare_analysis(input);
    const Excitation  excitation = make_excitation(analysis, input);
    NonlinearElements elements   = make_nonlinear_elements(analysis.model);
    NewmarkIntegrator integrator(analysis.system, "eigen-ldlt", input.time_integration.newmark,
                                 &elements);
    Vector load(analysis.system.n_equations());
    excitation.load(0, load);
    integrator.initialize(load);
    const long n = std::lround(input.time_integration.end_time /
                               input.time_integration.newmark.time_step);
    try
      {
        for (long i = 1; i <= n; ++i)
          integrator.advance([&](double t, Vector &p) { excitation.load(t, p); });
      }
    catch (const NumericalError &e)
      {
        return e.what();
      }
    return "";
  }

  /// What follows "): " in the step-cut message: its cause.
  std::string
  cause_of(const std::string &message)
  {
    const std::size_t at = message.find("step cuts, Maximum step cuts = ");
    const std::size_t colon = message.find("): ", at);
    return colon == std::string::npos ? "" : message.substr(colon + 3);
  }
} // namespace

BOOST_AUTO_TEST_CASE(every_contact_law_says_why_it_refuses_a_state)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const std::string &name : contact_law_names())
    {
      ContactLawParameters p;
      p.law            = name;
      p.stiffness      = 1e308; // k delta^n overflows at delta = 10 m for every n >= 1
      p.damping        = 0.1;
      p.effective_mass = 1000;
      p.initial_gap    = 0.01;
      auto law         = make_contact_law(p);
      BOOST_TEST_CONTEXT(name)
      {
        BOOST_TEST(!law->set_trial(10, 1));
        BOOST_TEST_MESSAGE(name << ": " << law->failure());
        BOOST_TEST(law->failure().find("contact force is not finite") != std::string::npos);
        BOOST_TEST(law->failure().find("closure 10 m (initial gap 0.01 m)") != std::string::npos);
        law->revert();
        BOOST_TEST(!law->set_trial(nan, 1));
        BOOST_TEST(law->failure().find("deformation is not finite: closure nan m") !=
                   std::string::npos);
      }
    }
}

BOOST_AUTO_TEST_CASE(friction_says_why_it_refuses_a_state)
{
  FrictionLawParameters p;
  p.stick_stiffness   = 1e6;
  p.normal.constant   = std::numeric_limits<double>::quiet_NaN();
  Friction friction(p);
  BOOST_TEST(!friction.set_trial(0.5, 2)); // no limit to compare with: mu N = nan
  BOOST_TEST_MESSAGE(friction.failure());
  BOOST_TEST(friction.failure().find("friction force is not finite") != std::string::npos);
  BOOST_TEST(friction.failure().find("displacement of 0.5 m, velocity 2 m/s, normal force nan N") !=
             std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_last_cut_names_the_newton_criterion_and_the_exact_step)
{
  // One Newton iteration allowed: the first yielding step fails at every
  // size down to Time step / 4, of a time step (1/3000 s) that 6 digits
  // would print rounded.
  InputParameters input = read_parameters("input/bouc-wen-sdof.prm");
  auto           &newmark = input.time_integration.newmark;
  newmark.time_step               = 1.0 / 3000;
  newmark.newton.max_iterations   = 1;
  newmark.newton.max_step_cuts    = 2;
  input.time_integration.end_time = 1;
  const std::string message = failure_of(input);
  BOOST_TEST_MESSAGE(message);
  const double dt = newmark.time_step / 4;
  BOOST_TEST(message.find("failed even at dt = " + number_text(dt) + " s (2 step cuts, "
                          "Maximum step cuts = 2): ") != std::string::npos);
  BOOST_TEST(number_text(dt).size() > 10u); // the exact text, not 8.33333e-05
  const std::string cause = cause_of(message);
  BOOST_TEST(cause.find("Newton did not converge in 1 iteration: residual norm") == 0u);
  BOOST_TEST(cause.find("Newton residual tolerance") != std::string::npos);
  BOOST_TEST(cause.find("Newton energy tolerance") != std::string::npos);
  BOOST_TEST(cause.find("not met") != std::string::npos);
  BOOST_TEST(cause.find("the largest residual is at equation 0") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(an_overflowing_gap_is_named_with_its_cause)
{
  // Two shear buildings pounding through a Hertz gap under a ground motion
  // scaled by 1e100: the residual's norm overflows though its entries are
  // finite (it used to stop there, "the residual became non-finite"), and
  // the first contact's closure then overflows at every step size; the gap
  // used to be named with nothing after it ("shear3-shear2@3: ").
  InputParameters input = read_parameters("input/shear-pair-pounding.prm");
  input.contact.law                                   = "hertz";
  input.ground_motion.scale_factor                    = 1e100;
  input.time_integration.end_time                     = 1;
  input.time_integration.newmark.newton.max_step_cuts = 4;
  const std::string message = failure_of(input);
  BOOST_TEST_MESSAGE(message);
  const double dt = input.time_integration.newmark.time_step / 16;
  BOOST_TEST(message.find("failed even at dt = " + number_text(dt) + " s (4 step cuts") !=
             std::string::npos);
  const std::string cause = cause_of(message);
  BOOST_TEST(cause.find("shear3-shear2@3: the hertz contact") == 0u);
  BOOST_TEST(cause.find("is not finite") != std::string::npos);
  BOOST_TEST(cause.back() != ' ');
}

BOOST_AUTO_TEST_CASE(the_reported_empty_cause_is_a_contact_force_that_overflows)
{
  // The symptom of issue 14 item 8 reproduced: a Hertz gap of stiffness
  // 1e300 under a motion scaled by 1e60 (the residual's norm stays finite):
  // before, "failed even at dt = 6.25e-05 s (4 step cuts): shear3-shear2@3: "
  // and nothing more.
  InputParameters input = read_parameters("input/shear-pair-pounding.prm");
  input.contact.law                                   = "hertz";
  input.contact.stiffness                             = 1e300;
  input.ground_motion.scale_factor                    = 1e60;
  input.time_integration.end_time                     = 1;
  input.time_integration.newmark.newton.max_step_cuts = 4;
  const std::string message = failure_of(input);
  BOOST_TEST_MESSAGE(message);
  const std::string cause = cause_of(message);
  BOOST_TEST(cause.find("shear3-shear2@3: the hertz contact force is not finite (inf N) at "
                        "closure ") == 0u);
  BOOST_TEST(cause.find("the stiffness 1e+300 or the motion is out of range") !=
             std::string::npos);
}
