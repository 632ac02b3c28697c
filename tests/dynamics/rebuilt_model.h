// The second route of the random-parameter tests (test_model_parameters.cc,
// test_random_structure.cc): a realization whose sampled values are written
// in place against the model built from the file with those values as
// overrides (the model builder, prepare_analysis, a fresh engine), under
// the same loading normals of every component.
#ifndef poundfe_tests_dynamics_rebuilt_model_h
#define poundfe_tests_dynamics_rebuilt_model_h

#include <poundfe/dynamics/realization.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/reliability/random_parameters.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace poundfe_test
{
  /// x to the last bit, as an entry's text.
  inline std::string
  exact_text(const double x)
  {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
  }

  using Overrides   = std::vector<poundfe::ParameterOverride>;
  using OverridesOf = std::function<Overrides(const std::vector<double> &)>;
  using RowCheck =
    std::function<void(poundfe::RealizationRunner &, std::uint64_t, const std::vector<double> &)>;

  /// Runs `n` realizations of `file` with the `base` overrides and the
  /// random parameters written in place, and compares every response with
  /// the file built with the sampled values (`with_values`, after `base`)
  /// to 1e-9 relative; `check_row` (when given) checks a row on the rebuilt
  /// model by a route of its own. Returns how many realizations pound.
  inline unsigned int
  compare_with_rebuilt(const std::string &file, const Overrides &base,
                       const OverridesOf &with_values, const unsigned int n,
                       const RowCheck &check_row = {})
  {
    using namespace poundfe;
    const InputParameters input    = read_parameters(file, base);
    const Analysis        analysis = prepare_analysis(input);
    RealizationRunner     runner(analysis, time_history_parameters(input));
    const unsigned int    n_load = runner.n_load_variables();
    attach_random_parameters(runner, input.random_parameters, input, input.model, input.contact,
                             input.modal.eigensolver);
    const unsigned int n_x = input.random_parameters.names.size();
    BOOST_TEST(runner.n_parameters() == n_x);
    BOOST_TEST(runner.n_variables() == n_load + n_x);
    const unsigned int first_x = runner.response_names().size() - n_x;
    BOOST_TEST(runner.response_names()[first_x] == input.random_parameters.names[0]);
    unsigned int n_impacting = 0;
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
        BOOST_TEST(reference.n_variables() == n_load);
        std::vector<double> xi(n_load + n_x);
        reference.stochastic_load().standard_normals(r, xi); // every component's
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
        if (check_row)
          check_row(reference, r, responses);
      }
    BOOST_TEST_MESSAGE(n_impacting << " of " << n << " realizations pound");
    return n_impacting;
  }
} // namespace poundfe_test

#endif
