// Filippov switching analysis (integration/filippov.h) on systems whose
// crossing and sliding sets are known in closed form: the Coulomb (relay)
// oscillator, whose amplitude falls by 2 mu N / k per half cycle until it
// sticks, and a block on a moving belt, whose stick interval starts where
// the slip velocity first reaches zero and ends where the spring force
// reaches mu N.
#include <poundfe/integration/filippov.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;

namespace
{
  /// m x'' + k x = -s mu N, s the side of the slip velocity x' - v_belt;
  /// m = k = mu N = 1.
  FilippovSystem
  block_on_belt(const double v_belt)
  {
    SwitchingSurface slip{"slip", Vector::Unit(2, 1), v_belt};
    return FilippovSystem({slip}, [](double, const Vector &x, const std::vector<int> &s, Vector &dx) {
      dx.resize(2);
      dx[0] = x[1];
      dx[1] = -x[0] - s[0];
    });
  }
} // namespace

BOOST_AUTO_TEST_CASE(switching_classes_follow_the_signs_of_the_normal_components)
{
  BOOST_TEST((classify_switching(1, 2, 1e-8) == SwitchingClass::crossing));
  BOOST_TEST((classify_switching(-1, -2, 1e-8) == SwitchingClass::crossing));
  BOOST_TEST((classify_switching(1, -2, 1e-8) == SwitchingClass::attracting_sliding));
  BOOST_TEST((classify_switching(-1, 2, 1e-8) == SwitchingClass::repulsive_sliding));
  BOOST_TEST((classify_switching(1e-12, -2, 1e-8) == SwitchingClass::grazing));
}

BOOST_AUTO_TEST_CASE(coulomb_oscillator_crosses_twice_then_sticks)
{
  // From x = 4.5 at rest (on the surface x' = 0): about +1 to x = -2.5 at
  // t = pi (|x| > 1: crossing), about -1 to x = 0.5 at t = 2 pi (|x| < 1:
  // attracting sliding, stuck for good: lambda = (1 - x) / 2 = 0.25).
  FilippovSystem system = block_on_belt(0);
  system.run(Vector::Unit(2, 0) * 4.5, 8);
  const std::vector<SwitchingEvent> &log = system.log();
  BOOST_REQUIRE_EQUAL(log.size(), 3u);
  BOOST_TEST_MESSAGE("Coulomb oscillator: crossing " << log[1].time - M_PI << " s, sticking "
                     << log[2].time - 2 * M_PI << " s off; rest at " << system.state()[0] - 0.5);
  BOOST_TEST(log[0].time == 0);
  BOOST_TEST((log[0].kind == SwitchingClass::crossing));
  BOOST_TEST(log[0].region_after == -1);
  BOOST_TEST(std::abs(log[1].time - M_PI) < 1e-9);
  BOOST_TEST(std::abs(log[1].state[0] + 2.5) < 1e-9);
  BOOST_TEST((log[1].kind == SwitchingClass::crossing));
  BOOST_TEST(log[1].region_before == -1);
  BOOST_TEST(log[1].region_after == 1);
  BOOST_TEST(std::abs(log[1].normal_minus - 3.5) < 1e-8); // 1 - x
  BOOST_TEST(std::abs(log[1].normal_plus - 1.5) < 1e-8);  // -1 - x
  BOOST_TEST(std::abs(log[2].time - 2 * M_PI) < 1e-9);
  BOOST_TEST((log[2].kind == SwitchingClass::attracting_sliding));
  BOOST_TEST(log[2].region_after == 0);
  BOOST_TEST(std::abs(system.state()[0] - 0.5) < 1e-9);
  BOOST_TEST(std::abs(system.state()[1]) < 1e-12);
  const auto counts = system.counts();
  BOOST_TEST(counts.at("slip").at("crossing") == 2u);
  BOOST_TEST(counts.at("slip").at("attracting-sliding") == 1u);
  BOOST_TEST(system.log_csv().find("2,slip,-1,1,") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(block_on_a_belt_sticks_over_its_closed_form_interval)
{
  // From rest at x = 0 under a belt at v = 0.5: slip (s = -1), x = 1 - cos t,
  // x' = sin t reaches 0.5 at t1 = pi/6 with x1 = 1 - cos(pi/6) < 1: attracting
  // sliding; stuck to the belt (x' = 0.5) until x = 1 (spring force = mu N)
  // at t2 = t1 + (1 - x1) / 0.5, where a = 1 - x vanishes: it leaves into
  // s = -1, x = 1 + 0.5 sin(t - t2). Half a cycle later it is at (1, -0.5).
  const double   v = 0.5, t1 = M_PI / 6, x1 = 1 - std::cos(t1), t2 = t1 + (1 - x1) / v;
  FilippovSystem system = block_on_belt(v);
  system.run(Vector::Zero(2), t2 + M_PI);
  const std::vector<SwitchingEvent> &log = system.log();
  BOOST_REQUIRE_EQUAL(log.size(), 2u);
  BOOST_TEST_MESSAGE("block on a belt: stick " << log[0].time - t1 << " s to " << log[1].time - t2
                     << " s off; end state off by " << system.state()[0] - 1 << ", "
                     << system.state()[1] + 0.5);
  BOOST_TEST((log[0].kind == SwitchingClass::attracting_sliding));
  BOOST_TEST(std::abs(log[0].time - t1) < 1e-9);
  BOOST_TEST(std::abs(log[0].state[0] - x1) < 1e-9);
  BOOST_TEST(std::abs(log[0].normal_minus - (1 - x1)) < 1e-8);
  BOOST_TEST(std::abs(log[0].normal_plus - (-1 - x1)) < 1e-8);
  BOOST_TEST((log[1].kind == SwitchingClass::sliding_exit));
  BOOST_TEST(std::abs(log[1].time - t2) < 1e-9);
  BOOST_TEST(std::abs(log[1].state[0] - 1) < 1e-9);
  BOOST_TEST(log[1].region_after == -1);
  BOOST_TEST(std::abs(system.state()[0] - 1) < 1e-8);
  BOOST_TEST(std::abs(system.state()[1] + 0.5) < 1e-8);
}
