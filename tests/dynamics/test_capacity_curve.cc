// The equal-energy bilinear idealisation and the N2 target displacement
// (dynamics/capacity_curve.h) against EN 1998-1 Annex B written out here.
#include <poundfe/dynamics/capacity_curve.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

using namespace poundfe;

namespace
{
  /// A smooth hardening-then-softening capacity curve F(d) = F0 tanh(d /
  /// d0) (1 - 0.1 d / dm) on n + 1 points to dm.
  void
  sample_curve(std::vector<double> &d, std::vector<double> &F)
  {
    const double F0 = 3e5, d0 = 0.02, dm = 0.12;
    for (unsigned int i = 0; i <= 40; ++i)
      {
        const double x = dm * i / 40.0;
        d.push_back(x);
        F.push_back(F0 * std::tanh(x / d0) * (1 - 0.1 * x / dm));
      }
  }

  /// EN 1998-1 type 1 elastic spectrum, ground C (S 1.15, TB 0.2, TC 0.6,
  /// TD 2.0), a_g = 0.3 g, 5 % damping (eta = 1), eq. 3.2-3.5.
  double
  se_type1_c(const double T)
  {
    const double ag = 0.3 * 9.81, S = 1.15, TB = 0.2, TC = 0.6, TD = 2.0;
    if (T <= TB)
      return ag * S * (1 + T / TB * (2.5 - 1));
    if (T <= TC)
      return ag * S * 2.5;
    if (T <= TD)
      return ag * S * 2.5 * TC / T;
    return ag * S * 2.5 * TC * TD / (T * T);
  }
} // namespace

BOOST_AUTO_TEST_SUITE(capacity_curve)

// The elastic-perfectly plastic curve has the area of the curve (the
// trapezoidal sum computed here): F_y (d_m - d_y / 2) = E_m, to 1e-12;
// F_y is the curve's largest force.
BOOST_AUTO_TEST_CASE(the_bilinear_idealisation_keeps_the_energy)
{
  std::vector<double> d, F;
  sample_curve(d, F);
  double area = 0, peak = 0;
  for (unsigned int i = 1; i < d.size(); ++i)
    area += 0.5 * (F[i] + F[i - 1]) * (d[i] - d[i - 1]);
  for (const double f : F)
    peak = std::max(peak, f);
  const BilinearCurve b = ec8_bilinear(d, F);
  BOOST_TEST(b.yield_force == peak);
  BOOST_TEST(b.ultimate_displacement == d.back());
  const double epp_area =
    b.yield_force * b.yield_displacement / 2 + b.yield_force * (d.back() - b.yield_displacement);
  BOOST_TEST(epp_area == area, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(b.yield_displacement > 0);
  BOOST_TEST(b.yield_displacement < d.back());
}

// N2 (Annex B.5) by hand for a short period (T* < T_C, with reduction)
// and a long one (T* >= T_C, equal displacements), to 1e-12.
BOOST_AUTO_TEST_CASE(n2_target_displacement_by_hand)
{
  const double  gamma = 1.3, TC = 0.6;
  BilinearCurve stiff;
  stiff.yield_force        = 2e5;
  stiff.yield_displacement = 0.01;
  const double m_stiff     = 1.5e5; // T* = 2 pi sqrt(m d_y / F_y) = 0.544 s < T_C
  const double T      = 2 * M_PI * std::sqrt(m_stiff * 0.01 / 2e5);
  const double Se     = se_type1_c(T);
  const double d_et   = Se * std::pow(T / (2 * M_PI), 2);
  BOOST_REQUIRE(T < TC);
  BOOST_REQUIRE(2e5 / m_stiff < Se); // yields: q_u > 1
  const double q_u    = Se * m_stiff / 2e5;
  const double d_t    = std::max(d_et, d_et / q_u * (1 + (q_u - 1) * TC / T));
  const N2Target short_period = ec8_n2_target(stiff, m_stiff, gamma, se_type1_c, TC);
  BOOST_TEST(short_period.period == T, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(short_period.reduction == q_u, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(short_period.target_sdof == d_t, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(short_period.target == gamma * d_t, boost::test_tools::tolerance(1e-12));

  BilinearCurve flexible;
  flexible.yield_force        = 1e5;
  flexible.yield_displacement = 0.08;
  const double m_flexible     = 1e5; // T* = 1.78 s >= T_C
  const double T2             = 2 * M_PI * std::sqrt(m_flexible * 0.08 / 1e5);
  BOOST_REQUIRE(T2 >= TC);
  const N2Target long_period = ec8_n2_target(flexible, m_flexible, gamma, se_type1_c, TC);
  BOOST_TEST(long_period.target ==
               gamma * se_type1_c(T2) * std::pow(T2 / (2 * M_PI), 2),
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(long_period.reduction == 1.0);
}

BOOST_AUTO_TEST_SUITE_END()
