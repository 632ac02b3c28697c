// The response-spectrum route of `separation` (theory §7.1b) against
// references computed here, independently of the code under test:
//   - the Eurocode 8 type 1 spectrum on ground B written out from EN 1998-1
//     Table 3.2 and eq. 3.2-3.6 (S = 1.2, TB = 0.15 s, TC = 0.5 s, TD = 2 s);
//   - a one-storey building: u = Sd(T, zeta) at its own damping ratio;
//   - a two-storey shear building: the 2-DOF eigenvalues in closed form
//     (the roots of m1 m2 l^2 - (m1 k2 + m2 (k1 + k2)) l + k1 k2 = 0), the
//     shapes [1, a], a = (k1 + k2 - l m1) / k2, Gamma phi = (m1 + m2 a) /
//     (m1 + m2 a^2) [1, a], SRSS and CQC with the equal-damping form of
//     Der Kiureghian's correlation, 8 z^2 (1 + r) r^1.5 / ((1 - r^2)^2 +
//     4 z^2 r (1 + r)^2), at each floor and at a level between them;
//   - CQC -> SRSS for well separated, lightly damped modes, within the bounds
//     sqrt(1 - rho_12) <= CQC/SRSS <= sqrt(1 + rho_12) that follow from
//     2 |u1 u2| <= u1^2 + u2^2;
//   - the mode count of EN 1998-1 §4.3.3.3.1(3) on effective masses worked
//     by hand, and on a five-storey building.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/separation/separation_spectrum.h>
#include <poundfe/output/floor_response.h>

#include <cmath>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  constexpr double g  = 9.80665;
  constexpr double ag = 0.25 * g;

  /// EN 1998-1 eq. 3.2-3.5, type 1, ground B (Table 3.2), eta of eq. 3.6.
  double
  ec8_type_1_ground_b(const double T, const double zeta)
  {
    const double S = 1.2, TB = 0.15, TC = 0.5, TD = 2.0;
    const double eta = std::max(0.55, std::sqrt(10 / (5 + 100 * zeta)));
    if (T <= TB)
      return ag * S * (1 + T / TB * (2.5 * eta - 1));
    if (T <= TC)
      return 2.5 * ag * S * eta;
    if (T <= TD)
      return 2.5 * ag * S * eta * TC / T;
    return 2.5 * ag * S * eta * TC * TD / (T * T);
  }

  double
  sd_by_hand(const double T, const double zeta)
  {
    return ec8_type_1_ground_b(T, zeta) * T * T / (4 * M_PI * M_PI);
  }

  /// A two-storey shear building (floor masses m1, m2, storey stiffnesses
  /// k1, k2), Rayleigh damping zeta on its two modes, under the EC8 target.
  InputParameters
  two_storey(const double m1, const double m2, const double k1, const double k2,
             const double zeta)
  {
    InputParameters p = poundfe_test::shear_building_input(2, m1, k1, zeta);
    BuildingParameters &b = p.model.buildings[0];
    b.floor_masses        = {m1, m2};
    b.storey_stiffnesses  = {k1, k2};
    p.output.n_modes      = 0;
    p.spectrum.target     = DesignSpectrum::ec8_type_1;
    p.spectrum.ground_type = GroundType::B;
    p.spectrum.design_ground_acceleration = 0.25;
    return p;
  }

  /// Floor f of the only building.
  LevelInterpolation
  at_floor(const Model &model, const unsigned int f)
  {
    const unsigned int i = FloorResponse(model).index(0, f);
    return {int(i), int(i), 0};
  }

  /// The modal peaks of the two-storey building in closed form.
  struct TwoStoreyReference
  {
    double omega[2], u[2][2]; // u[mode][floor]
  };

  TwoStoreyReference
  two_storey_reference(const double m1, const double m2, const double k1, const double k2,
                       const double zeta)
  {
    const double a = m1 * m2, b = m1 * k2 + m2 * (k1 + k2), c = k1 * k2;
    const double root = std::sqrt(b * b - 4 * a * c);
    // the smaller root as c / (a l_2): no cancellation
    const double lambda[2] = {2 * c / (b + root), (b + root) / (2 * a)};
    TwoStoreyReference r;
    for (unsigned int i = 0; i < 2; ++i)
      {
        r.omega[i]         = std::sqrt(lambda[i]);
        const double shape = (k1 + k2 - lambda[i] * m1) / k2;
        const double gamma = (m1 + m2 * shape) / (m1 + m2 * shape * shape);
        const double sd    = sd_by_hand(2 * M_PI / r.omega[i], zeta);
        r.u[i][0]          = gamma * sd;
        r.u[i][1]          = gamma * shape * sd;
      }
    return r;
  }

  double
  equal_damping_correlation(const double omega_i, const double omega_j, const double zeta)
  {
    const double r = omega_j / omega_i;
    return 8 * zeta * zeta * (1 + r) * std::pow(r, 1.5) /
           ((1 - r * r) * (1 - r * r) + 4 * zeta * zeta * r * (1 + r) * (1 + r));
  }
} // namespace

BOOST_AUTO_TEST_CASE(spectral_displacement_is_the_ec8_spectrum_times_period_over_two_pi_squared)
{
  SpectrumParameters s;
  s.target                     = DesignSpectrum::ec8_type_1;
  s.ground_type                = GroundType::B;
  s.design_ground_acceleration = 0.25;
  // every branch, and damping ratios above, at and below 5 %, and eta's floor 0.55
  for (const double T : {0.1, 0.3, 0.8, 3.0})
    for (const double zeta : {0.02, 0.05, 0.1, 0.4})
      BOOST_TEST(spectral_displacement(s, T, zeta) == sd_by_hand(T, zeta),
                 boost::test_tools::tolerance(1e-13));
}

BOOST_AUTO_TEST_CASE(one_storey_building_gives_sd_at_its_own_damping)
{
  // m = 2500 kg, k = 8e6 N/m: T = 2 pi sqrt(m / k) = 0.1111 s (rising branch);
  // k = 1e5 N/m: T = 0.9935 s (descending). Storey damping c = 2 zeta sqrt(k m),
  // zeta = 0.03 (eta = sqrt(10 / 8)).
  for (const double k : {8e6, 1e5})
    {
      const double    m = 2500, zeta = 0.03;
      InputParameters p = poundfe_test::shear_building_input(1, m, k, 0);
      p.model.buildings[0].storey_damping = {2 * zeta * std::sqrt(k * m)};
      p.output.n_modes                    = 0;
      p.spectrum.target                   = DesignSpectrum::ec8_type_1;
      p.spectrum.ground_type              = GroundType::B;
      p.spectrum.design_ground_acceleration = 0.25;
      const Analysis              analysis = prepare_analysis(p);
      const SpectrumModalResponse r        = spectrum_modal_response(analysis, 0, 0, p.spectrum, p.modal.eigensolver, p);
      BOOST_TEST_REQUIRE(r.n_modes() == 1u);
      BOOST_TEST(r.damping_ratio[0] == zeta, boost::test_tools::tolerance(1e-12));
      const double               T = 2 * M_PI * std::sqrt(m / k);
      const CombinedDisplacement u = combined_displacement(r, at_floor(analysis.model, 0));
      BOOST_TEST_MESSAGE("T = " << T << " s: u = " << u.srss << " m");
      BOOST_TEST(u.srss == sd_by_hand(T, zeta), boost::test_tools::tolerance(1e-12));
      BOOST_TEST(u.cqc == sd_by_hand(T, zeta), boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(two_storey_shear_building_against_closed_form_modes)
{
  // T1 = 0.856 s (descending branch), T2 = 0.369 s (plateau), zeta = 0.05 on both
  const double m1 = 40000, m2 = 30000, k1 = 5e6, k2 = 3.75e6, zeta = 0.05;
  const InputParameters       p        = two_storey(m1, m2, k1, k2, zeta);
  const Analysis              analysis = prepare_analysis(p);
  const SpectrumModalResponse r        = spectrum_modal_response(analysis, 0, 0, p.spectrum, p.modal.eigensolver, p);
  const TwoStoreyReference    ref      = two_storey_reference(m1, m2, k1, k2, zeta);
  // the first mode alone carries under 95 %: both are taken
  BOOST_TEST_REQUIRE(r.n_modes() == 2u);
  for (unsigned int i = 0; i < 2; ++i)
    {
      BOOST_TEST(r.omega[i] == ref.omega[i], boost::test_tools::tolerance(1e-10));
      BOOST_TEST(r.damping_ratio[i] == zeta, boost::test_tools::tolerance(1e-10));
    }
  const double rho = equal_damping_correlation(ref.omega[0], ref.omega[1], zeta);
  BOOST_TEST_MESSAGE("T = " << 2 * M_PI / ref.omega[0] << ", " << 2 * M_PI / ref.omega[1]
                            << " s, rho_12 = " << rho);
  // at each floor, then at a level 0.4 of the way from floor 1 to floor 2
  for (unsigned int f = 0; f < 3; ++f)
    {
      const double w = 0.4;
      double       u[2];
      for (unsigned int i = 0; i < 2; ++i)
        u[i] = f < 2 ? ref.u[i][f] : (1 - w) * ref.u[i][0] + w * ref.u[i][1];
      LevelInterpolation where = at_floor(analysis.model, std::min(f, 1u));
      if (f == 2)
        where = {at_floor(analysis.model, 0).below, at_floor(analysis.model, 1).above, w};
      const CombinedDisplacement c = combined_displacement(r, where);
      BOOST_TEST(c.srss == std::hypot(u[0], u[1]), boost::test_tools::tolerance(1e-10));
      BOOST_TEST(c.cqc == std::sqrt(u[0] * u[0] + u[1] * u[1] + 2 * rho * u[0] * u[1]),
                 boost::test_tools::tolerance(1e-10));
    }
}

BOOST_AUTO_TEST_CASE(cqc_tends_to_srss_for_separated_lightly_damped_modes)
{
  // T2 / T1 = 0.43, zeta = 0.02: rho_12 ~ 2e-3; |CQC^2 - SRSS^2| = 2 rho |u1 u2|
  // <= rho (u1^2 + u2^2), so sqrt(1 - rho) <= CQC / SRSS <= sqrt(1 + rho), the
  // sign that of u1 u2 (mode 2 changes sign up the height).
  const double m1 = 40000, m2 = 30000, k1 = 5e6, k2 = 3.75e6, zeta = 0.02;
  const InputParameters       p        = two_storey(m1, m2, k1, k2, zeta);
  const Analysis              analysis = prepare_analysis(p);
  const SpectrumModalResponse r        = spectrum_modal_response(analysis, 0, 0, p.spectrum, p.modal.eigensolver, p);
  const double rho = equal_damping_correlation(r.omega[0], r.omega[1], zeta);
  BOOST_TEST_MESSAGE("rho_12 = " << rho);
  BOOST_TEST(rho < 2e-3);
  for (unsigned int f = 0; f < 2; ++f)
    {
      const CombinedDisplacement c = combined_displacement(r, at_floor(analysis.model, f));
      BOOST_TEST_MESSAGE("floor " << f + 1 << ": CQC / SRSS - 1 = " << c.cqc / c.srss - 1);
      BOOST_TEST(c.cqc >= c.srss * std::sqrt(1 - rho));
      BOOST_TEST(c.cqc <= c.srss * std::sqrt(1 + rho));
      BOOST_TEST(c.cqc == c.srss, boost::test_tools::tolerance(1e-3));
    }
}

BOOST_AUTO_TEST_CASE(mode_count_of_ec8_4_3_3_3_1)
{
  // 0.8 + 0.06 < 0.9 <= 0.8 + 0.06 + 0.1; the fourth is below 5 %
  BOOST_TEST(modes_for_mass({0.8, 0.06, 0.1, 0.04}) == 3u);
  // 90 % by the first, but the third carries 6 %
  BOOST_TEST(modes_for_mass({0.92, 0.02, 0.06}) == 3u);
  // below 90 % in all: cannot tell
  BOOST_TEST(modes_for_mass({0.7, 0.1}) == 0u);
  // 93 %, but the 7 % left out could be one mode above 5 %: cannot tell
  BOOST_TEST(modes_for_mass({0.91, 0.02}) == 0u);

  // five equal storeys: the modes taken satisfy the rule, one fewer does not
  InputParameters p = poundfe_test::shear_building_input(5, 1000, 5e6, 0.05);
  p.output.n_modes  = 5;
  p.spectrum.target = DesignSpectrum::ec8_type_1;
  const Analysis              analysis = prepare_analysis(p);
  const SpectrumModalResponse r        = spectrum_modal_response(analysis, 0, 0, p.spectrum, p.modal.eigensolver, p);
  const std::vector<double>  &all      = analysis.building_modes[0].participating_mass_ratio;
  double                      taken    = 0;
  for (unsigned int i = 0; i < r.n_modes(); ++i)
    taken += all[i];
  BOOST_TEST_MESSAGE(r.n_modes() << " of 5 modes, " << 100 * taken << " % of the mass");
  BOOST_TEST(taken >= 0.9);
  for (unsigned int i = r.n_modes(); i < 5; ++i)
    BOOST_TEST(all[i] <= 0.05);
  BOOST_TEST((taken - all[r.n_modes() - 1] < 0.9 || all[r.n_modes() - 1] > 0.05));
  // a given number
  BOOST_TEST(spectrum_modal_response(analysis, 0, 4, p.spectrum, p.modal.eigensolver, p).n_modes() == 4u);
}
