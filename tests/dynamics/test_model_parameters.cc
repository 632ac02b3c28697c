// Random model parameters written into the built model (dynamics/
// model_parameter.h, RealizationRunner::set_random_parameters) against a
// second route: the model built from the file with the sampled values set as
// overrides (the model builder, prepare_analysis, a fresh engine), under the
// same loading normals. Both must give the same responses to rounding: the
// in-place route assembles M, K, C again for the stiffness and damping ratio
// and only remakes the nonlinear elements for the yield drifts, gap and
// contact stiffness.
#include <poundfe/dynamics/model_parameter.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/reliability/nataf.h>
#include <poundfe/reliability/random_parameters.h>
#include <poundfe/reliability/statistics.h>

#include "../test_utilities.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

using namespace poundfe;

namespace
{
  const std::string file = "tests/dynamics/uncertain-shear-pair.prm";

  std::string
  exact(const double x)
  {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
  }

  /// The overrides that give the file the values x of the file's variables
  /// (k1, zeta, uy2, gap, kc in that order; zeta of building `damped`).
  std::vector<ParameterOverride>
  overrides_of(const std::vector<double> &x, const unsigned int damped = 1)
  {
    return {{"Building 1/Storey stiffnesses", exact(x[0]) + ", 4e6, 3e6"},
            {"Building " + std::to_string(damped) + "/Damping/Damping ratio", exact(x[1])},
            {"Building 2/Storey yield drifts", exact(x[2]) + ", " + exact(x[2])},
            {"Model/Separations", exact(x[3])},
            {"Contact/Stiffness", exact(x[4])}};
  }

  /// Runs 6 realizations with the random parameters written in place and
  /// compares every response with the file built with the sampled values
  /// (and `base`, overrides that both routes share; zeta that of building
  /// `damped`).
  void
  check_in_place_against_rebuilt(const std::vector<ParameterOverride> &base,
                                 const unsigned int                    damped = 1)
  {
    const InputParameters input    = read_parameters(file, base);
    const Analysis        analysis = prepare_analysis(input);
    RealizationRunner     runner(analysis, time_history_parameters(input));
    const unsigned int    n_load = runner.n_load_variables();
    attach_random_parameters(runner, input.random_parameters, input, input.modal.eigensolver);
    BOOST_TEST(runner.n_parameters() == 5u);
    BOOST_TEST(runner.n_variables() == n_load + 5);
    const unsigned int first_x = runner.response_names().size() - 5;
    BOOST_TEST(runner.response_names()[first_x] == "k1");

    unsigned int n_impacting = 0;
    for (std::uint64_t r = 0; r < 6; ++r)
      {
        std::vector<double> responses;
        BOOST_TEST(runner.run(r, responses));
        const std::vector<double> x(responses.begin() + first_x, responses.end());

        // the second route: the file with the sampled values, the same load normals
        std::vector<ParameterOverride> with_values = base;
        for (const ParameterOverride &o : overrides_of(x, damped))
          with_values.push_back(o);
        const InputParameters fixed = read_parameters(file, with_values);
        const Analysis        fixed_analysis = prepare_analysis(fixed);
        RealizationRunner     reference(fixed_analysis, time_history_parameters(fixed));
        BOOST_TEST(reference.n_variables() == n_load);
        std::vector<double> xi(n_load + 5);
        standard_normals(reference.stochastic_load().seed(), r, xi);
        xi.resize(n_load); // the loading's normals come first
        std::vector<double> expected;
        BOOST_TEST(reference.run(xi, expected));
        BOOST_TEST_REQUIRE(expected.size() == first_x);
        for (unsigned int c = 0; c < first_x; ++c)
          BOOST_TEST(responses[c] == expected[c], boost::test_tools::tolerance(1e-9));
        n_impacting += responses[runner.column("n_impacts")] > 0;
      }
    // the test exercises the contact law: some realizations pound, some not
    BOOST_TEST_MESSAGE(n_impacting << " of 6 realizations pound");
    BOOST_TEST(n_impacting > 0u);
  }
} // namespace

BOOST_AUTO_TEST_CASE(random_parameters_in_place_equal_the_model_built_with_them)
{
  check_in_place_against_rebuilt({});
}

// Per-mode damping (Damping/Type = modal) with a random storey stiffness: the
// in-place route must rebuild C = M Phi diag(2 zeta omega) Phi^T M from the
// new modes (assemble_modal_damping), as the file built with the sampled
// stiffness does. (Building 1 has no damping ratio then: zeta is building 2's.)
BOOST_AUTO_TEST_CASE(random_stiffness_with_modal_damping_rebuilds_the_modal_part)
{
  const std::string variables =
    "k1: Building 1/Storey stiffnesses[1] ~ lognormal mean 5e6 cov 0.2; "
    "zeta: Building 2/Damping/Damping ratio ~ uniform lower 0.01 upper 0.05; "
    "uy2: Building 2/Storey yield drifts ~ truncated normal mu 0.003 sigma 0.001 lower 0.001 "
    "upper 0.01; gap: Model/Separations[1] ~ lognormal mean 0.01 cov 0.5; "
    "kc: Contact/Stiffness ~ Weibull mean 5e8 cov 0.3";
  check_in_place_against_rebuilt({{"Building 1/Damping/Type", "modal"},
                                  {"Building 1/Damping/Modal ratios", "0.02, 0.04, 0.05"},
                                  {"Random parameters/Variables", variables}},
                                 2);
}

BOOST_AUTO_TEST_CASE(random_parameter_values_follow_their_joint_distribution)
{
  // the values a realization takes are T(u) for the realization's
  // standard normals after the loading's: the lognormal's sample mean and
  // COV, and the Nataf correlation of uy2 and gap, within sampling error
  const InputParameters input    = read_parameters(file);
  const Analysis        analysis = prepare_analysis(input);
  RealizationRunner     runner(analysis, time_history_parameters(input));
  const unsigned int    n_load = runner.n_load_variables();
  attach_random_parameters(runner, input.random_parameters, input, input.modal.eigensolver);
  const NatafTransformation nataf(input.random_parameters.distributions,
                                  input.random_parameters.correlation);
  const unsigned int        n = 4000;
  std::vector<double>       k1, uy2, gap;
  std::vector<double>       xi(runner.n_variables()), u, x;
  for (unsigned int r = 0; r < n; ++r)
    {
      standard_normals(runner.stochastic_load().seed(), r, xi);
      u.assign(xi.begin() + n_load, xi.end());
      nataf.to_physical(u, x);
      k1.push_back(x[0]), uy2.push_back(x[2]), gap.push_back(x[3]);
    }
  const SampleStatistics s = describe(k1);
  // standard error of the mean: 0.2 / sqrt(4000) = 0.32 %; of the sd ~ 1.2 %
  BOOST_TEST(std::abs(s.mean / 5e6 - 1) < 4 * 0.2 / std::sqrt(n));
  BOOST_TEST(std::abs(s.standard_deviation / 1e6 - 1) < 0.06);
  double mu = 0, mg = 0, cov = 0, vu = 0, vg = 0;
  for (unsigned int r = 0; r < n; ++r)
    mu += uy2[r] / n, mg += gap[r] / n;
  for (unsigned int r = 0; r < n; ++r)
    {
      cov += (uy2[r] - mu) * (gap[r] - mg);
      vu += (uy2[r] - mu) * (uy2[r] - mu);
      vg += (gap[r] - mg) * (gap[r] - mg);
    }
  const double rho = cov / std::sqrt(vu * vg);
  // the sample correlation's standard error is (1 - rho^2)/sqrt(n) = 0.012
  BOOST_TEST_MESSAGE("sample correlation of uy2 and gap " << rho << " (given -0.5)");
  BOOST_TEST(std::abs(rho + 0.5) < 4 * 0.75 / std::sqrt(n));
}

BOOST_AUTO_TEST_CASE(paths_the_model_does_not_have_are_refused)
{
  const InputParameters input    = read_parameters(file);
  const Analysis        analysis = prepare_analysis(input);
  const Model          &model    = analysis.model;
  for (const std::string path :
       {"Building 3/Storey stiffnesses", "Building 1/Storey stiffnesses[4]",
        "Building 1/Name", "Building 1/Hinges/Yield moment", "Friction/Kinetic coefficient",
        "Model/Separations[2]", "Contact/Stiffness[1]", "Output/Directory",
        "Building 1/Storey stiffnesses[0]", "Links/Viscous dampers"})
    BOOST_CHECK_THROW(model_parameter(path, model), std::invalid_argument);
  const ModelParameter p = model_parameter("Building 2/Storey yield drifts[2]", model);
  BOOST_TEST(model_parameter_value(p, model) == 0.003);
  BOOST_TEST(!p.enters_linear_part());
  BOOST_TEST(model_parameter("Building 1/Storey stiffnesses", model).enters_linear_part());
}
