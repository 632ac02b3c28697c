// Random parameters that the model builder maps before they reach M, K, C
// or an element (dynamics/model_parameter.h, issue 24): the sections of a
// 3D frame (its hinges' k = f 6 E I / L follows E, Iy, Iz) and of a 2D mesh
// building's groups, 3D floor masses (the polar moment m (Lx^2 + Ly^2)/12
// follows the mass, a typed one stays), masses with friction elements (the
// stick dashpot 2 sqrt(k_s M_ii) follows), the friction law's entries, the
// contact restitution (the damping calibrated again) and compliant
// foundations (the impedances from the soil, or typed, and the inertias).
// Each realization, written in place, must give the responses of the model
// built from the file with the sampled values (overrides), under the same
// loading normals: the independent route is the whole builder,
// prepare_analysis and a fresh engine. Tolerance 1e-9 relative: the two
// routes differ only by rounding (the in-place polar moment J m'/m against
// m' c, the hinge's f 6 E' I / L against the builder's product).
#include <poundfe/dynamics/model_parameter.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/reliability/random_parameters.h>
#include <poundfe/reliability/statistics.h>

#include "../test_utilities.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

using namespace poundfe;

BOOST_AUTO_TEST_SUITE(random_structure)

namespace
{
  const std::string shear_pair = "tests/dynamics/uncertain-shear-pair.prm";
  const std::string pair_3d    = "tests/dynamics/uncertain-3d-pair.prm";

  std::string
  text_of(const double x)
  {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
  }

  using Overrides   = std::vector<ParameterOverride>;
  using OverridesOf = std::function<Overrides(const std::vector<double> &)>;

  /// Runs `n` realizations of `file` with `base` overrides, the random
  /// parameters written in place, and compares every response with the
  /// file built with the sampled values (`with_values`). Returns how many
  /// realizations pound.
  unsigned int
  compare_with_rebuilt(const std::string &file, const Overrides &base,
                       const OverridesOf &with_values, const unsigned int n = 4)
  {
    const InputParameters input    = read_parameters(file, base);
    const Analysis        analysis = prepare_analysis(input);
    RealizationRunner     runner(analysis, time_history_parameters(input));
    const unsigned int    n_load = runner.n_load_variables();
    attach_random_parameters(runner, input.random_parameters, input, input.model, input.contact,
                             input.modal.eigensolver);
    const unsigned int n_x     = input.random_parameters.names.size();
    const unsigned int first_x = runner.response_names().size() - n_x;
    unsigned int       n_impacting = 0;
    for (std::uint64_t r = 0; r < n; ++r)
      {
        std::vector<double> responses;
        BOOST_TEST_REQUIRE(runner.run(r, responses));
        const std::vector<double> x(responses.begin() + first_x, responses.end());
        Overrides fixed_overrides = base;
        for (const ParameterOverride &o : with_values(x))
          fixed_overrides.push_back(o);
        fixed_overrides.push_back({"Random parameters/Variables", ""});
        fixed_overrides.push_back({"Random parameters/Correlation", ""});
        const InputParameters fixed          = read_parameters(file, fixed_overrides);
        const Analysis        fixed_analysis = prepare_analysis(fixed);
        RealizationRunner     reference(fixed_analysis, time_history_parameters(fixed));
        reference.add_optional_responses(runner.response_names());
        std::vector<double> xi(n_load + n_x);
        standard_normals(reference.stochastic_load().seed(), r, xi);
        xi.resize(n_load); // the loading's normals come first
        std::vector<double> expected;
        BOOST_TEST_REQUIRE(reference.run(xi, expected));
        BOOST_TEST_REQUIRE(expected.size() == first_x);
        double worst = 0;
        for (unsigned int c = 0; c < first_x; ++c)
          {
            BOOST_TEST(responses[c] == expected[c], boost::test_tools::tolerance(1e-9));
            if (expected[c] != 0)
              worst = std::max(worst, std::abs(responses[c] / expected[c] - 1));
          }
        BOOST_TEST_MESSAGE("realization " << r << ": largest relative difference " << worst);
        n_impacting += responses[runner.column("n_impacts")] > 0;
      }
    BOOST_TEST_MESSAGE(n_impacting << " of " << n << " realizations pound");
    return n_impacting;
  }

  /// "a, b" with x at entry i (0-based) of n and `other` elsewhere.
  std::string
  list_with(const double x, const unsigned int i, const unsigned int n, const std::string &other)
  {
    std::string text;
    for (unsigned int k = 0; k < n; ++k)
      text += (k ? ", " : "") + (k == i ? text_of(x) : other);
    return text;
  }
} // namespace

// 3D frame sections (E of storey 1's columns, every column's G, Iy and J,
// Iz of floor 2's beams, every beam's A, the mass per length of every
// column and of floor 1's beams: K, M, the hinges' k) and 3D floor masses
// (the frame's polar moment follows, the shear building's typed one
// stays; the joints' vertical masses and the gaps' effective masses follow).
BOOST_AUTO_TEST_CASE(random_3d_frame_sections_and_3d_floor_masses)
{
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Building 1/Column E", list_with(x[0], 0, 2, "3e10")},
                     {"Building 1/Column G", text_of(x[1])},
                     {"Building 1/Column I", text_of(x[2])},
                     {"Building 1/Beam Iz", list_with(x[3], 1, 2, "1.1e-3")},
                     {"Building 1/Column J", text_of(x[4])},
                     {"Building 1/Beam A", text_of(x[5])},
                     {"Building 1/Column mass per length", text_of(x[6])},
                     {"Building 1/Beam mass per length", list_with(x[7], 0, 2, "0")},
                     {"Building 1/Floor masses", list_with(x[8], 1, 2, "6e4")},
                     {"Building 2/Floor masses", text_of(x[9])}};
  };
  compare_with_rebuilt(pair_3d, {}, values);
}
