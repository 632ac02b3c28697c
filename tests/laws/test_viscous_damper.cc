// OpenSees's ViscousDamper and Series materials (laws/viscous_damper.h,
// laws/combined_materials.h) against closed forms written here:
// - a linear damper (Alpha = 1) is a Maxwell element, whose force under a
//   velocity ramped from 0 to v over the first step and then held is
//     F(t) = K a tau (t - tau (1 - exp(-t/tau))) (t <= dt, a = v/dt, tau = C/K),
//     F(t) = C v + (F(dt) - C v) exp(-(t - dt)/tau) after;
//   Dormand-Prince and Rosenbrock within 1e-8 of C v (RelTol 1e-12: the
//   error estimates' own accuracy; measured 1.2e-13 and 1.4e-9),
//   Adams-Bashforth-Moulton within 1e-5 (its first sub-steps are Euler's
//   predictor and corrector, of first order, which its estimate, the last
//   predictor minus corrector, does not see: measured 1.5e-6);
// - a nonlinear damper (Alpha = 0.5) held at velocity v tends to C v^Alpha;
// - LGap: no force while the strain is within the gap after a reversal;
// - Series of two elastic springs: k1 k2 / (k1 + k2) to round-off; of a
//   spring and a bilinear bar under monotonic strain, the bilinear series
//   law (1e-12 of fy: each trial's one stress correction is exact on a
//   linear branch, and the yield point falls between trials);
// - both: a trial reverted and tried again gives the same numbers bit for
//   bit; bad parameters refused by name.
#include <poundfe/base/exceptions.h>
#include <poundfe/laws/combined_materials.h>
#include <poundfe/laws/material_registry.h>
#include <poundfe/laws/viscous_damper.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace poundfe;

namespace
{
  constexpr double K = 2.0e8, C = 4.0e6, dt = 0.005;

  std::unique_ptr<UniaxialLaw>
  damper(const double alpha, const double method, const double &step, const double gap = 0)
  {
    return make_viscous_damper({{"K", K},
                                {"C", C},
                                {"Alpha", alpha},
                                {"LGap", gap},
                                {"NM", method},
                                {"RelTol", 1e-12},
                                {"AbsTol", 1e-12},
                                {"MaxHalf", 15}},
                               step);
  }

  /// The law at strain `strain` and rate `rate`, committed; its force.
  double
  advance(UniaxialLaw &law, const double strain, const double rate)
  {
    BOOST_REQUIRE(law.set_trial(strain, rate));
    law.commit();
    return law.force();
  }

  std::unique_ptr<UniaxialLaw>
  elastic(const double E)
  {
    return make_material({"Elastic", {{"E", E}}});
  }
} // namespace

BOOST_AUTO_TEST_CASE(linear_viscous_damper_is_a_maxwell_element)
{
  const double v = 0.2, tau = C / K, a = v / dt;
  const double f_dt = K * a * tau * (dt - tau * (1 - std::exp(-dt / tau)));
  for (const double method : {1.0, 2.0, 3.0})
    {
      const double tolerance = method == 2 ? 1e-5 : 1e-8;
      const double time_step = dt;
      auto         law       = damper(1.0, method, time_step);
      double       strain    = 0.5 * v * dt; // the ramp's displacement
      BOOST_TEST(std::abs(advance(*law, strain, v) - f_dt) <= tolerance * C * v);
      for (unsigned int i = 2; i <= 40; ++i)
        {
          strain += v * dt;
          const double t = i * dt;
          const double F = C * v + (f_dt - C * v) * std::exp(-(t - dt) / tau);
          BOOST_TEST(std::abs(advance(*law, strain, v) - F) <= tolerance * C * v,
                     "NM " << method << " step " << i);
        }
    }
}

BOOST_AUTO_TEST_CASE(nonlinear_damper_tends_to_c_v_to_the_alpha)
{
  const double time_step = dt, v = 0.3;
  auto         law       = damper(0.5, 1, time_step);
  double       force     = 0;
  for (unsigned int i = 1; i <= 400; ++i)
    force = advance(*law, i * v * dt, v);
  BOOST_TEST(force == C * std::sqrt(v), boost::test_tools::tolerance(1e-9));
  auto backwards = damper(0.5, 1, time_step);
  for (unsigned int i = 1; i <= 400; ++i)
    force = advance(*backwards, -(i * v * dt), -v);
  BOOST_TEST(force == -C * std::sqrt(v), boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(damper_gap_holds_no_force_after_a_reversal)
{
  const double time_step = dt, v = 0.3, gap = 0.004;
  auto         law       = damper(1.0, 1, time_step, gap);
  double       strain    = 0;
  for (unsigned int i = 1; i <= 20; ++i)
    advance(*law, strain += v * dt, v);
  BOOST_TEST(law->force() > 0);
  // reversed: the force would turn negative, and the pin's play holds it at
  // zero until the strain has moved a gap past where it changed sign
  unsigned int zero_steps = 0;
  for (unsigned int i = 1; i <= 40; ++i)
    zero_steps += advance(*law, strain -= v * dt, -v) == 0;
  BOOST_TEST(zero_steps >= 2);
  BOOST_TEST(zero_steps <= static_cast<unsigned int>(std::ceil(gap / (v * dt))) + 1);
  BOOST_TEST(law->force() < 0);
}

BOOST_AUTO_TEST_CASE(damper_revert_is_exact)
{
  double time_step = dt;
  auto   law       = damper(0.4, 1, time_step);
  advance(*law, 0.001, 0.2);
  BOOST_REQUIRE(law->set_trial(0.002, 0.25));
  const double first = law->force();
  BOOST_REQUIRE(law->set_trial(0.0035, 0.4));
  law->revert();
  BOOST_REQUIRE(law->set_trial(0.002, 0.25));
  BOOST_TEST(law->force() == first);
  // the time step is read when a trial is set, not when the damper is made
  time_step = 2 * dt;
  BOOST_REQUIRE(law->set_trial(0.002, 0.25));
  BOOST_TEST(law->force() != first);
  BOOST_TEST(law->tangent() == 0);
  BOOST_TEST(law->damping_tangent() == 0);
}

BOOST_AUTO_TEST_CASE(damper_refuses_bad_parameters_by_name)
{
  const double time_step = dt;
  const std::map<std::string, double> good{{"K", K}, {"C", C}, {"Alpha", 0.5}};
  // A list, not a map: one parameter is tried with several bad values.
  for (const auto &[name, value] : std::vector<std::pair<std::string, double>>{
         {"K", 0}, {"C", -1}, {"Alpha", 0}, {"NM", 4}, {"MaxHalf", 2.5}, {"MaxHalf", 21},
         {"RelTol", -1.0}, {"RelTol", 0.0}, {"AbsTol", -1.0}, {"LGap", -1}})
    {
      auto bad  = good;
      bad[name] = value;
      try
        {
          make_viscous_damper(bad, time_step);
          BOOST_ERROR(name << " = " << value << " accepted");
        }
      catch (const InputError &e)
        {
          BOOST_TEST(e.parameter() == name, e.what());
        }
    }
}

BOOST_AUTO_TEST_CASE(series_of_springs_is_their_series_stiffness)
{
  std::vector<std::unique_ptr<UniaxialLaw>> parts;
  parts.push_back(elastic(3.0e8));
  parts.push_back(elastic(6.0e8));
  SeriesUniaxial series(std::move(parts), 1, 1e-10);
  const double   k = 3.0e8 * 6.0e8 / 9.0e8;
  BOOST_TEST(series.initial_stiffness() == k, boost::test_tools::tolerance(1e-15));
  for (const double e : {0.001, 0.003, -0.002, 0.0005})
    {
      BOOST_TEST(advance(series, e, 0) == k * e, boost::test_tools::tolerance(1e-13));
      BOOST_TEST(series.tangent() == k, boost::test_tools::tolerance(1e-13));
    }
}

BOOST_AUTO_TEST_CASE(series_with_a_yielding_bar_is_bilinear)
{
  // a spring k1 and a bilinear bar (Steel01: fy, E, b): k = k1 E / (k1 + E)
  // up to the yield force, k1 b E / (k1 + b E) after
  const double k1 = 4.0e8, E = 1.0e8, b = 0.05, fy = 2.0e5;
  std::vector<std::unique_ptr<UniaxialLaw>> parts;
  parts.push_back(elastic(k1));
  parts.push_back(make_material({"Steel01", {{"fy", fy}, {"E0", E}, {"b", b}}}));
  SeriesUniaxial series(std::move(parts), 10, 1e-20);
  const double   k = k1 * E / (k1 + E), k_post = k1 * b * E / (k1 + b * E), e_y = fy / k;
  for (double e = 0.0004; e < 0.01; e += 0.0004)
    BOOST_TEST(std::abs(advance(series, e, 0) - (e <= e_y ? k * e : fy + k_post * (e - e_y))) <=
                 1e-12 * fy,
               "strain " << e);
  // revert: the same trial after another gives the same numbers
  BOOST_REQUIRE(series.set_trial(0.004, 0));
  const double first = series.force(), first_tangent = series.tangent();
  BOOST_REQUIRE(series.set_trial(-0.003, 0));
  series.revert();
  BOOST_REQUIRE(series.set_trial(0.004, 0));
  BOOST_TEST(series.force() == first);
  BOOST_TEST(series.tangent() == first_tangent);
}
