// P-Delta of torsionally coupled shear buildings (doc/theory.md §1.12,
// assembly/linear_system.h): a one-storey system with an eccentric mass
// against the closed form of its three frequencies when the storey loses
// m g / h in both translations and I g / h in torsion (the weight carried
// down at the floor's mass: P r^2 / h, r^2 = I / m), and a two-storey one
// whose translational geometric stiffness is -P_i / h_i per storey.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/model/model_builder.h>

#include "../test_utilities.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

using namespace poundfe;

namespace
{
  /// One storey of height 3.5 m: a 10 x 6 m slab of 8e4 kg, frames on its
  /// edges (2e7 N/m per x frame, 3e7 N/m per y frame), mass centre e east.
  std::string
  p_delta_storey(const double e, const bool p_delta)
  {
    return std::string("subsection Model\n set Dimension = 3\n set Geometric nonlinearity = ") +
           (p_delta ? "p-delta" : "none") +
           "\nend\n"
           "subsection Building 1\n set Type = shear\n set Number of storeys = 1\n"
           " set Storey heights = 3.5\n set Floor masses = 8e4\n subsection Plan\n"
           "  set Plan dimensions = 10, 6\n  set Mass eccentricity = " +
           std::to_string(e) +
           ", 0\n  set Resisting planes = 0 -3 0 2e7; 0 3 0 2e7; -5 0 90 3e7; 5 0 90 3e7\n end\n"
           " subsection Damping\n  set Type = none\n end\nend\n"
           "subsection Ground motion\n set Type = none\nend\n"
           "subsection Output\n set Number of modes = 3\nend\n";
  }
} // namespace

BOOST_AUTO_TEST_SUITE(plan_p_delta)

// Chopra (2012) ch. 9 about the mass centre C (e east of the stiffness
// centre): K_y = 6e7, K_yθ = e K_y, K_θ(C) = K_θR + e^2 K_y; P-Delta
// subtracts m g / h from K_x and K_y and I g / h from K_θ (the coupling
// stays: the weight acts at C). Frequencies of [K_y', e K_y; e K_y, K_θ']
// over diag(m, I) and sqrt(K_x' / m), to 1e-10 (a dense eigensolver).
BOOST_AUTO_TEST_CASE(one_storey_frequencies_are_lowered_as_the_closed_form)
{
  const double e = 1.2, m = 8e4, I = m * (100 + 36) / 12.0, g = 9.81, h = 3.5;
  const double ky = 6e7, kx = 4e7, k_theta = 2 * (2e7 * 9 + 3e7 * 25) + e * e * ky;
  const double a = (ky - m * g / h) / m, d = (k_theta - I * g / h) / I;
  const double b = e * ky / std::sqrt(m * I);
  const double mean = 0.5 * (a + d), root = std::sqrt(0.25 * (a - d) * (a - d) + b * b);
  std::vector<double> expected{std::sqrt(mean - root), std::sqrt((kx - m * g / h) / m),
                               std::sqrt(mean + root)};
  std::sort(expected.begin(), expected.end());
  const Analysis with = prepare_analysis(
    read_parameters(poundfe_test::temporary_file("plan_p_delta.prm", p_delta_storey(e, true))));
  const Analysis without = prepare_analysis(read_parameters(
    poundfe_test::temporary_file("plan_no_p_delta.prm", p_delta_storey(e, false))));
  BOOST_REQUIRE_EQUAL(with.modes.n_modes(), 3u);
  for (unsigned int i = 0; i < 3; ++i)
    {
      BOOST_TEST(with.modes.omega[i] == expected[i], boost::test_tools::tolerance(1e-10));
      BOOST_TEST(with.modes.omega[i] < without.modes.omega[i]);
    }
}

BOOST_AUTO_TEST_SUITE_END()
