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
#include "rebuilt_model.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

using namespace poundfe;

namespace
{
  const std::string file = "tests/dynamics/uncertain-shear-pair.prm";
  // the same without Building 1's shear entries, for --set Building 1/Type = frame
  const std::string frame_file = "tests/dynamics/uncertain-pair-any-type.prm";
  using poundfe_test::exact_text;

  /// The overrides that give the file the values x of the file's variables
  /// (k1, zeta, uy2, gap, kc in that order; zeta of building `damped`).
  std::vector<ParameterOverride>
  overrides_of(const std::vector<double> &x, const unsigned int damped = 1)
  {
    return {{"Building 1/Storey stiffnesses", exact_text(x[0]) + ", 4e6, 3e6"},
            {"Building " + std::to_string(damped) + "/Damping/Damping ratio", exact_text(x[1])},
            {"Building 2/Storey yield drifts", exact_text(x[2]) + ", " + exact_text(x[2])},
            {"Model/Separations", exact_text(x[3])},
            {"Contact/Stiffness", exact_text(x[4])}};
  }

  using poundfe_test::OverridesOf;

  /// Runs 6 realizations with the random parameters written in place and
  /// compares every response with the file built with the sampled values
  /// (and `base`, overrides that both routes share; zeta that of building
  /// `damped`; rebuilt_model.h). `overrides` (when given) writes the
  /// sampled values of a file whose variables are not the default five;
  /// `check_row` (when given) checks a row of the rebuilt model by a route
  /// of its own.
  void
  check_in_place_against_rebuilt(const std::vector<ParameterOverride> &base,
                                 const unsigned int damped = 1, OverridesOf overrides = {},
                                 const poundfe_test::RowCheck &check_row = {},
                                 const std::string &parameter_file = file)
  {
    if (!overrides)
      overrides = [damped](const std::vector<double> &x) { return overrides_of(x, damped); };
    // the test exercises the contact law: some realizations pound, some not
    BOOST_TEST(poundfe_test::compare_with_rebuilt(parameter_file, base, overrides, 6, check_row) >
               0u);
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
  attach_random_parameters(runner, input.random_parameters, input, input.model, input.contact, input.modal.eigensolver);
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

namespace
{
  /// The drift ratios of a shear building's storeys at the last step, from
  /// the displacements of its floor nodes: (u_i - u_{i-1})/h_i, u_0 = 0.
  class LastDrift : public StepObserver
  {
  public:
    LastDrift(const Model &model, const unsigned int building)
      : model(model)
      , building(building)
    {}
    void
    observe_step(const ResponseView &state) override
    {
      drift.clear();
      double below = 0;
      for (const Floor &floor : model.buildings[building].floors)
        {
          const double u = state.displacement()[model.equation(
            Model::dof(floor.nodes.front(), Component::ux))];
          drift.push_back((u - below) / floor.storey_height);
          below = u;
        }
    }
    const Model        &model;
    const unsigned int  building;
    std::vector<double> drift;
  };
} // namespace

// Random floor masses, one floor of building A and every floor of B, with a
// random storey stiffness and gap, and limit states that name the optional
// responses (residual drift ratios, the peak contact force of each gap):
// (1) every response equals that of the file built with the sampled masses
// (M, the modes and Rayleigh C, -M r a_g and the gaps' effective masses, on
// which the Kelvin contact's dashpot depends, all follow the mass); (2) the residual drift ratio equals |drift| at the last
// step (signed) computed from the floor displacements by an observer of the rebuilt
// model; (3) the peak contact force is the largest of the gaps' peaks.
BOOST_AUTO_TEST_CASE(random_floor_masses_and_optional_responses)
{
  const std::string variables =
    "mA2: Building 1/Floor masses[2] ~ lognormal mean 1000 cov 0.4; "
    "mB: Building 2/Floor masses ~ uniform lower 500 upper 1500; "
    "k1: Building 1/Storey stiffnesses[1] ~ lognormal mean 5e6 cov 0.2; "
    "gap: Model/Separations[1] ~ lognormal mean 0.01 cov 0.5";
  const std::string limit_states =
    "r: 0.01 - abs(A_storey1_residual_drift_ratio) - abs(B_storey2_residual_drift_ratio); "
    "f: 1e6 - gap1_peak_contact_force - gap2_peak_contact_force";
  const OverridesOf overrides = [](const std::vector<double> &x) {
    return std::vector<ParameterOverride>{
      {"Building 1/Floor masses", "1000, " + exact_text(x[0]) + ", 1000"},
      {"Building 2/Floor masses", exact_text(x[1])},
      {"Building 1/Storey stiffnesses", exact_text(x[2]) + ", 4e6, 3e6"},
      {"Model/Separations", exact_text(x[3])}};
  };
  unsigned int n_residual = 0;
  const auto   check_row  = [&](RealizationRunner &reference, const std::uint64_t r,
                             const std::vector<double> &row) {
    LastDrift a(reference.model(), 0), b(reference.model(), 1);
    BOOST_TEST(reference.run(r, Observers{&a, &b}));
    BOOST_TEST(row[reference.column("A_storey1_residual_drift_ratio")] == a.drift[0],
               boost::test_tools::tolerance(1e-9));
    BOOST_TEST(row[reference.column("B_storey2_residual_drift_ratio")] == b.drift[1],
               boost::test_tools::tolerance(1e-9));
    n_residual += std::abs(row[reference.column("B_storey2_residual_drift_ratio")]) > 1e-5;
    BOOST_TEST(row[reference.column("peak_contact_force")] ==
               std::max(row[reference.column("gap1_peak_contact_force")],
                        row[reference.column("gap2_peak_contact_force")]));
  };
  // a Kelvin contact: its dashpot 2 xi sqrt(k m_e) follows the floors' masses
  check_in_place_against_rebuilt({{"Contact/Law", "kelvin-voigt"},
                                  {"Contact/Damping from", "given"},
                                  {"Contact/Damping", "0.2"},
                                  {"Random parameters/Variables", variables},
                                  {"Random parameters/Correlation", ""},
                                  {"Random parameters/Limit states", limit_states}},
                                 1, overrides, check_row);
  // building B yields (u_y = 0.003): some realizations keep a residual drift
  BOOST_TEST_MESSAGE(n_residual << " of 6 realizations keep a residual drift > 1e-5 in B");
  BOOST_TEST(n_residual > 0u);
}

BOOST_AUTO_TEST_CASE(floor_mass_paths)
{
  const InputParameters input    = read_parameters(file);
  const Analysis        analysis = prepare_analysis(input);
  const Model          &model    = analysis.model;
  const ModelParameter  p        = model_parameter("Building 1/Floor masses[3]", model);
  BOOST_TEST(model_parameter_value(p, model) == 1000);
  BOOST_TEST(p.enters_linear_part());
  BOOST_TEST(!p.can_be_zero());
  BOOST_CHECK_THROW(model_parameter("Building 2/Floor masses[3]", model), std::invalid_argument);
}

namespace
{
  /// Building 1 of the shear pair as a generated frame (3 storeys, 1 bay,
  /// Bouc-Wen hinges at the column bases and beam ends), flexible enough to
  /// pound on building 2 and to yield; with `extra` overrides after.
  std::vector<ParameterOverride>
  frame_pair(const std::vector<ParameterOverride> &extra)
  {
    std::vector<ParameterOverride> o = {{"Building 1/Type", "frame"},
                                        {"Building 1/Number of storeys", "3"},
                                        {"Building 1/Storey heights", "3.0"},
                                        {"Building 1/Number of bays", "1"},
                                        {"Building 1/Bay widths", "5"},
                                        {"Building 1/Column E", "3e10"},
                                        {"Building 1/Column A", "0.04"},
                                        {"Building 1/Column I", "1e-4"},
                                        {"Building 1/Beam E", "3e10"},
                                        {"Building 1/Beam A", "0.04"},
                                        {"Building 1/Beam I", "2e-4"},
                                        {"Building 1/Column mass per length", "50"},
                                        {"Building 1/Hinges/Locations", "column bases, beam ends"},
                                        {"Building 1/Hinges/Yield moment", "3e3"},
                                        {"Model/Separations", "0.004"},
                                        {"Random parameters/Correlation", ""},
                                        {"Random parameters/Limit states", ""}};
    o.insert(o.end(), extra.begin(), extra.end());
    return o;
  }

  /// "a, b, c" with x at entry i (0-based) of n and `other` elsewhere.
  std::string
  list_with(const double x, const unsigned int i, const std::string &other)
  {
    std::string text;
    for (unsigned int k = 0; k < 3; ++k)
      text += (k ? ", " : "") + (k == i ? exact_text(x) : other);
    return text;
  }
} // namespace

// The sections of a frame's columns and beams (E, A, I, mass per length: K,
// M and, under P-Delta, K_G of the new gravity loads), the stiffness factor
// of its hinges (k = f 6 E I / L follows E and I, and u_y = M_y / k follows
// k) and Bouc-Wen shape parameters of the hinges of building 1 and the
// storeys of building 2, against the file built with the sampled values.
BOOST_AUTO_TEST_CASE(random_frame_sections_hinges_and_bouc_wen_shapes)
{
  // the factor first: the hinges' k must then follow E and I written after it
  const std::string variables =
    "f: Building 1/Hinges/Stiffness factor ~ uniform lower 5 upper 15; "
    "E1: Building 1/Column E[1] ~ lognormal mean 3e10 cov 0.1; "
    "I: Building 1/Column I ~ lognormal mean 1e-4 cov 0.2; "
    "Ab: Building 1/Beam A[2] ~ uniform lower 0.03 upper 0.05; "
    "Ib: Building 1/Beam I[3] ~ lognormal mean 2e-4 cov 0.2; "
    "mc: Building 1/Column mass per length[1] ~ uniform lower 0 upper 100; "
    "alpha: Building 1/Bouc-Wen/alpha ~ uniform lower 0.01 upper 0.2; "
    "gamma: Building 1/Bouc-Wen/gamma ~ uniform lower 0.3 upper 0.5; "
    "n: Building 2/Bouc-Wen/n ~ uniform lower 1 upper 3; "
    "beta: Building 2/Bouc-Wen/beta ~ uniform lower 0.5 upper 0.7; "
    "A: Building 2/Bouc-Wen/A ~ uniform lower 0.9 upper 1.1";
  const OverridesOf overrides = [](const std::vector<double> &x) {
    return std::vector<ParameterOverride>{
      {"Building 1/Hinges/Stiffness factor", exact_text(x[0])},
      {"Building 1/Column E", list_with(x[1], 0, "3e10")},
      {"Building 1/Column I", exact_text(x[2])},
      {"Building 1/Beam A", list_with(x[3], 1, "0.04")},
      {"Building 1/Beam I", list_with(x[4], 2, "2e-4")},
      {"Building 1/Column mass per length", list_with(x[5], 0, "50")},
      {"Building 1/Bouc-Wen/alpha", exact_text(x[6])},
      {"Building 1/Bouc-Wen/gamma", exact_text(x[7])},
      {"Building 2/Bouc-Wen/n", exact_text(x[8])},
      {"Building 2/Bouc-Wen/beta", exact_text(x[9])},
      {"Building 2/Bouc-Wen/A", exact_text(x[10])}};
  };
  check_in_place_against_rebuilt(frame_pair({{"Model/Geometric nonlinearity", "p-delta"},
                                             {"Random parameters/Variables", variables}}),
                                 1, overrides, {}, frame_file);
}

// Hinges with a given stiffness and yield rotation, given Rayleigh
// coefficients (building 1) and modal damping ratios (building 2) and a
// Baber-Noori degradation parameter.
BOOST_AUTO_TEST_CASE(random_hinge_stiffness_yield_rotation_and_damping_coefficients)
{
  const std::string variables =
    "k: Building 1/Hinges/Stiffness ~ lognormal mean 2e6 cov 0.2; "
    "r: Building 1/Hinges/Yield rotation ~ lognormal mean 0.002 cov 0.3; "
    "a0: Building 1/Damping/a0 ~ uniform lower 0.1 upper 0.5; "
    "a1: Building 1/Damping/a1 ~ uniform lower 0 upper 0.002; "
    "z1: Building 2/Damping/Modal ratios[1] ~ uniform lower 0.01 upper 0.05; "
    "dA: Building 2/Bouc-Wen/delta A ~ uniform lower 0 upper 0.1";
  const OverridesOf overrides = [](const std::vector<double> &x) {
    return std::vector<ParameterOverride>{{"Building 1/Hinges/Stiffness", exact_text(x[0])},
                                          {"Building 1/Hinges/Yield rotation", exact_text(x[1])},
                                          {"Building 1/Damping/a0", exact_text(x[2])},
                                          {"Building 1/Damping/a1", exact_text(x[3])},
                                          {"Building 2/Damping/Modal ratios", exact_text(x[4]) + ", 0.03"},
                                          {"Building 2/Bouc-Wen/delta A", exact_text(x[5])}};
  };
  check_in_place_against_rebuilt(frame_pair({{"Building 1/Hinges/Yield moment", "0"},
                                             {"Building 1/Hinges/Yield rotation", "0.002"},
                                             {"Building 1/Hinges/Stiffness", "2e6"},
                                             {"Building 1/Damping/Type", "coefficients"},
                                             {"Building 1/Damping/a0", "0.3"},
                                             {"Building 1/Damping/a1", "0.001"},
                                             {"Building 2/Damping/Type", "modal"},
                                             {"Building 2/Damping/Modal ratios", "0.02, 0.03"},
                                             {"Random parameters/Variables", variables}}),
                                 1, overrides, {}, frame_file);
}

BOOST_AUTO_TEST_CASE(section_hinge_and_bouc_wen_paths)
{
  const InputParameters input    = read_parameters(frame_file, frame_pair({}));
  const Analysis        analysis = prepare_analysis(input);
  const Model          &model    = analysis.model;
  const auto            origins  = std::make_shared<const std::vector<HingeOrigin>>(
    hinge_origins(model, input.model));
  const ModelParameter e = model_parameter("Building 1/Column E[2]", model, origins);
  BOOST_TEST(model_parameter_value(e, model) == 3e10);
  BOOST_TEST(e.enters_matrices());
  BOOST_TEST(!e.enters_mass());
  BOOST_TEST(model_parameter("Building 1/Beam mass per length", model).enters_mass());
  const ModelParameter alpha = model_parameter("Building 2/Bouc-Wen/alpha", model);
  BOOST_TEST(!alpha.enters_linear_part());
  BOOST_TEST(alpha.range().upper == 1);
  BOOST_TEST(model_parameter_value(alpha, model) == 0.1); // the default
  BOOST_TEST(model_parameter("Building 1/Bouc-Wen/beta", model).can_be_zero());
  // what the model does not have, what is not numeric, what is geometry
  for (const std::string path :
       {"Building 1/Column E[4]", "Building 2/Column E", "Building 1/Column Z",
        "Building 1/Bouc-Wen/zeta", "Building 1/Storey heights", "Building 1/Bay widths[1]",
        "Building 1/Damping/a0", "Building 2/Damping/Modal ratios[1]",
        "Building 2/Hinges/Stiffness", "Building 1/Hinges/Yield rotation",
        "Building 1/Hinges/Stiffness[1]", "Building 1/Hinges/Locations", "Building 1/Name"})
    BOOST_CHECK_THROW(model_parameter(path, model, origins), std::invalid_argument);
  const ModelParameter f = model_parameter("Building 1/Hinges/Stiffness factor", model, origins);
  BOOST_TEST(f.enters_matrices());
  BOOST_TEST(model_parameter_value(f, model) == 10, boost::test_tools::tolerance(1e-12));
  // a sampled beta that breaks beta >= |gamma| or gamma >= |beta|
  ModelRealization realization(analysis, {model_parameter("Building 2/Bouc-Wen/beta", model)},
                               input.modal.eigensolver);
  BOOST_CHECK_THROW(realization.apply({-0.6}), std::invalid_argument);
}
