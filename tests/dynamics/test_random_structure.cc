// Random parameters that the model builder maps before they reach M, K, C
// or an element (dynamics/model_parameter.h, issue 24): the sections of a
// 3D frame (its hinges' k = f 6 E I / L follows E, Iy, Iz) and of a 2D or
// 3D mesh building's groups, the Bouc-Wen shape of 3D hinges (uniaxial and
// biaxial) and resisting planes, a 3D shear building's storeys (its planes'
// k/2 and u_y; typed planes' k and u_y), typed polar moments, 3D floor masses (the polar moment m (Lx^2 + Ly^2)/12
// follows the mass, a typed one stays), masses with friction elements (the
// stick dashpot 2 sqrt(k_s M_ii) follows), the friction law's entries, the
// contact restitution (the damping calibrated again), compliant
// foundations (the impedances from the soil, or typed, and the inertias),
// springs to the ground (K, k1 in the linear K; a friction element's N from
// the SD spring follows), every field of every kind of link and soil
// coupling, the bumper in the gaps and the rigid barriers' gaps.
// Each realization, written in place, must give the responses of the model
// built from the file with the sampled values (overrides), under the same
// loading normals: the independent route is the whole builder,
// prepare_analysis and a fresh engine. Tolerance 1e-9 relative: the two
// routes differ only by rounding (the in-place polar moment J m'/m against
// m' c, the hinge's f 6 E' I / L against the builder's product).
#include <poundfe/base/exceptions.h>
#include <poundfe/dynamics/model_parameter.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/reliability/random_parameters.h>
#include <poundfe/reliability/statistics.h>

#include "../test_utilities.h"
#include "rebuilt_model.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>

using namespace poundfe;

BOOST_AUTO_TEST_SUITE(random_structure)

namespace
{
  const std::string shear_pair = "tests/dynamics/uncertain-shear-pair.prm";
  const std::string pair_3d    = "tests/dynamics/uncertain-3d-pair.prm";
  // the same without Building 1's entries of its own Type, for --set Type
  const std::string shear_pair_any_type = "tests/dynamics/uncertain-pair-any-type.prm";
  const std::string pair_3d_any_type    = "tests/dynamics/uncertain-3d-pair-any-type.prm";

  using poundfe_test::compare_with_rebuilt;
  using poundfe_test::Overrides;
  using poundfe_test::OverridesOf;

  std::string
  text_of(const double x)
  {
    return poundfe_test::exact_text(x);
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
  compare_with_rebuilt(pair_3d, {}, values, 4);
}

namespace
{
  /// Building 1 of the shear pair as the set-back mesh (meshes/setback.msh:
  /// physical group 1 the columns, 2 the beams; floors at 3.5, 6.5, 9.5 m),
  /// hinges at its column bases and beam ends, under P-Delta.
  Overrides
  mesh_pair(const std::string &variables)
  {
    return {{"Building 1/Type", "mesh"},
            {"Building 1/Mesh file", "../../meshes/setback.msh"},
            {"Building 1/Group ids", "1, 2"},
            {"Building 1/Group E", "3e10, 3e10"},
            {"Building 1/Group A", "0.04, 0.04"},
            {"Building 1/Group I", "1e-4, 2e-4"},
            {"Building 1/Group mass per length", "50, 0"},
            {"Building 1/Hinges/Locations", "column bases, beam ends"},
            {"Building 1/Hinges/Yield moment", "3e3"},
            {"Model/Geometric nonlinearity", "p-delta"},
            {"Model/Separations", "0.004"},
            {"Random parameters/Correlation", ""},
            {"Random parameters/Limit states", ""},
            {"Random parameters/Variables", variables}};
  }
} // namespace

// The groups of a 2D mesh building (E of the columns, I of the beams, A of
// every group, the beams' mass per length: K, M, K_G, the hinges' k) and a
// mesh floor's mass.
BOOST_AUTO_TEST_CASE(random_mesh_groups)
{
  const std::string variables =
    "E: Building 1/Group E[1] ~ lognormal mean 3e10 cov 0.15; "
    "I: Building 1/Group I[2] ~ lognormal mean 2e-4 cov 0.2; "
    "A: Building 1/Group A ~ uniform lower 0.03 upper 0.05; "
    "mb: Building 1/Group mass per length[2] ~ uniform lower 0 upper 100; "
    "m: Building 1/Floor masses[1] ~ lognormal mean 1000 cov 0.3";
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Building 1/Group E", text_of(x[0]) + ", 3e10"},
                     {"Building 1/Group I", "1e-4, " + text_of(x[1])},
                     {"Building 1/Group A", text_of(x[2])},
                     {"Building 1/Group mass per length", "50, " + text_of(x[3])},
                     {"Building 1/Floor masses", list_with(x[4], 0, 3, "1000")}};
  };
  compare_with_rebuilt(shear_pair_any_type, mesh_pair(variables), values, 4);
}

namespace
{
  /// The shear pair with a friction element under floor 1 of building 2
  /// (elastic-plastic, automatic stick spring) and a Hertz-damp contact whose
  /// damping is calibrated to the restitution.
  Overrides
  friction_pair(const std::string &variables, const Overrides &extra = {})
  {
    Overrides o = {{"Friction/Surfaces", "2 1 0"},
                   {"Model/Separations", "0.002"},
                   {"Friction/Static coefficient", "0.35"},
                   {"Friction/Kinetic coefficient", "0.25"},
                   {"Friction/Normal force", "1e4"},
                   {"Contact/Law", "hertz-damp"},
                   {"Contact/Stiffness", "5e9"},
                   {"Contact/Damping from", "calibrated"},
                   {"Random parameters/Correlation", ""},
                   {"Random parameters/Limit states", ""},
                   {"Random parameters/Variables", variables}};
    o.insert(o.end(), extra.begin(), extra.end());
    return o;
  }
} // namespace

// Masses and a storey stiffness with a friction element (its automatic
// k_s = 1e4 K_ii and c_s = 2 sqrt(k_s M_ii) follow), the friction law's
// entries, and the contact's stiffness and restitution (the Hertz-damp
// damping calibrated again, as the builder does, on the new k and m_e).
BOOST_AUTO_TEST_CASE(random_masses_with_friction_friction_entries_and_restitution)
{
  const std::string variables =
    "m: Building 2/Floor masses[1] ~ lognormal mean 1000 cov 0.2; "
    "k: Building 2/Storey stiffnesses[1] ~ lognormal mean 3e6 cov 0.2; "
    "mus: Friction/Static coefficient ~ uniform lower 0.3 upper 0.4; "
    "muk: Friction/Kinetic coefficient ~ uniform lower 0.1 upper 0.3; "
    "N: Friction/Normal force ~ lognormal mean 1e4 cov 0.3; "
    "N1: Friction/Normal force per displacement ~ uniform lower 0 upper 1e5; "
    "vs: Friction/Stribeck velocity ~ uniform lower 0.01 upper 0.1; "
    "v0: Friction/Belt velocity ~ uniform lower -0.01 upper 0.01; "
    "e: Contact/Coefficient of restitution ~ uniform lower 0.5 upper 0.8; "
    "kc: Contact/Stiffness ~ lognormal mean 5e9 cov 0.3";
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Building 2/Floor masses", text_of(x[0]) + ", 1000"},
                     {"Building 2/Storey stiffnesses", text_of(x[1]) + ", 3e6"},
                     {"Friction/Static coefficient", text_of(x[2])},
                     {"Friction/Kinetic coefficient", text_of(x[3])},
                     {"Friction/Normal force", text_of(x[4])},
                     {"Friction/Normal force per displacement", text_of(x[5])},
                     {"Friction/Stribeck velocity", text_of(x[6])},
                     {"Friction/Belt velocity", text_of(x[7])},
                     {"Contact/Coefficient of restitution", text_of(x[8])},
                     {"Contact/Stiffness", text_of(x[9])}};
  };
  BOOST_TEST(compare_with_rebuilt(shear_pair, friction_pair(variables), values, 4) > 0u);
}

// A given stick stiffness (its dashpot 2 sqrt(k_s M_ii) follows it and the
// sampled mass) and the normal force's velocity terms; the regularized
// law's velocity.
BOOST_AUTO_TEST_CASE(random_stick_stiffness_and_normal_force_terms)
{
  const std::string variables =
    "ks: Friction/Stick stiffness ~ lognormal mean 1e9 cov 0.3; "
    "m: Building 2/Floor masses[1] ~ lognormal mean 1000 cov 0.2; "
    "N2: Friction/Normal force per velocity ~ uniform lower -2e3 upper 0; "
    "N3: Friction/Normal force per velocity cubed ~ uniform lower 0 upper 1e4";
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Friction/Stick stiffness", text_of(x[0])},
                     {"Building 2/Floor masses", text_of(x[1]) + ", 1000"},
                     {"Friction/Normal force per velocity", text_of(x[2])},
                     {"Friction/Normal force per velocity cubed", text_of(x[3])}};
  };
  compare_with_rebuilt(shear_pair, friction_pair(variables), values, 4);
  const std::string regularized = "eps: Friction/Regularization velocity ~ uniform lower 1e-3 "
                                  "upper 1e-2";
  compare_with_rebuilt(shear_pair,
                       friction_pair(regularized, {{"Friction/Model", "regularized"}}),
                       [](const std::vector<double> &x) {
                         return Overrides{{"Friction/Regularization velocity", text_of(x[0])}};
                       },
                       2);
}

// Compliant foundations of the 2D shear pair: building 1's from the soil by
// Gazetas' formulas (shear-wave velocity, density, Poisson ratio,
// embedment: every spring, dashpot and the inertias follow), building 2's
// typed (a spring, a dashpot alone: no new M, K) and both masses.
BOOST_AUTO_TEST_CASE(random_foundations)
{
  const std::string variables =
    "vs: Building 1/Foundation/Shear-wave velocity ~ lognormal mean 200 cov 0.2; "
    "nu: Building 1/Foundation/Poisson ratio ~ uniform lower 0.25 upper 0.4; "
    "rho: Building 1/Foundation/Soil density ~ uniform lower 1600 upper 2000; "
    "d: Building 1/Foundation/Embedment ~ uniform lower 0 upper 1; "
    "m0: Building 1/Foundation/Mass ~ lognormal mean 2000 cov 0.2; "
    "kh: Building 2/Foundation/Horizontal stiffness ~ lognormal mean 1e8 cov 0.3; "
    "cr: Building 2/Foundation/Rocking damping ~ uniform lower 5e5 upper 2e6; "
    "i0: Building 2/Foundation/Rotary inertia ~ uniform lower 3e3 upper 8e3";
  const Overrides base = {{"Building 1/Foundation/Type", "gazetas"},
                          {"Building 1/Foundation/Shear-wave velocity", "200"},
                          {"Building 1/Foundation/Soil density", "1800"},
                          {"Building 1/Foundation/Poisson ratio", "0.3"},
                          {"Building 1/Foundation/Length", "6"},
                          {"Building 1/Foundation/Width", "6"},
                          {"Building 1/Foundation/Embedment", "0.5"},
                          {"Building 1/Foundation/Mass", "2000"},
                          {"Building 1/Foundation/Rotary inertia", "1e4"},
                          {"Building 2/Foundation/Type", "given"},
                          {"Building 2/Foundation/Horizontal stiffness", "1e8"},
                          {"Building 2/Foundation/Rocking stiffness", "1e9"},
                          {"Building 2/Foundation/Horizontal damping", "1e5"},
                          {"Building 2/Foundation/Rocking damping", "1e6"},
                          {"Building 2/Foundation/Mass", "1000"},
                          {"Building 2/Foundation/Rotary inertia", "5e3"},
                          {"Random parameters/Correlation", ""},
                          {"Random parameters/Limit states", ""},
                          {"Random parameters/Variables", variables}};
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Building 1/Foundation/Shear-wave velocity", text_of(x[0])},
                     {"Building 1/Foundation/Poisson ratio", text_of(x[1])},
                     {"Building 1/Foundation/Soil density", text_of(x[2])},
                     {"Building 1/Foundation/Embedment", text_of(x[3])},
                     {"Building 1/Foundation/Mass", text_of(x[4])},
                     {"Building 2/Foundation/Horizontal stiffness", text_of(x[5])},
                     {"Building 2/Foundation/Rocking damping", text_of(x[6])},
                     {"Building 2/Foundation/Rotary inertia", text_of(x[7])}};
  };
  compare_with_rebuilt(shear_pair, base, values, 4);
}

// 3D foundations: the frame's on Wolf's cones (a vertical spring too), the
// torsionally coupled building's typed (a 3D spring, a 3D dashpot, the
// polar inertia).
BOOST_AUTO_TEST_CASE(random_3d_foundations)
{
  const std::string variables =
    "vs: Building 1/Foundation/Shear-wave velocity ~ lognormal mean 250 cov 0.2; "
    "kt: Building 2/Foundation/Torsional stiffness ~ lognormal mean 5e9 cov 0.3; "
    "crx: Building 2/Foundation/Rocking damping x ~ uniform lower 1e6 upper 5e6; "
    "j0: Building 2/Foundation/Polar inertia ~ uniform lower 1e5 upper 3e5";
  const Overrides base = {{"Building 1/Foundation/Type", "cone"},
                          {"Building 1/Foundation/Shear-wave velocity", "250"},
                          {"Building 1/Foundation/Soil density", "1800"},
                          {"Building 1/Foundation/Poisson ratio", "0.3"},
                          {"Building 1/Foundation/Length", "7"},
                          {"Building 1/Foundation/Width", "6"},
                          {"Building 1/Foundation/Mass", "5e4"},
                          {"Building 1/Foundation/Rotary inertia", "2e5"},
                          {"Building 1/Foundation/Rotary inertia x", "2e5"},
                          {"Building 1/Foundation/Polar inertia", "3e5"},
                          {"Building 2/Foundation/Type", "given"},
                          {"Building 2/Foundation/Horizontal stiffness", "2e9"},
                          {"Building 2/Foundation/Horizontal stiffness y", "2e9"},
                          {"Building 2/Foundation/Rocking stiffness", "3e10"},
                          {"Building 2/Foundation/Rocking stiffness x", "3e10"},
                          {"Building 2/Foundation/Torsional stiffness", "5e9"},
                          {"Building 2/Foundation/Horizontal damping", "1e7"},
                          {"Building 2/Foundation/Horizontal damping y", "1e7"},
                          {"Building 2/Foundation/Rocking damping", "3e6"},
                          {"Building 2/Foundation/Rocking damping x", "3e6"},
                          {"Building 2/Foundation/Torsional damping", "1e6"},
                          {"Building 2/Foundation/Mass", "4e4"},
                          {"Building 2/Foundation/Rotary inertia", "1.5e5"},
                          {"Building 2/Foundation/Rotary inertia x", "1.5e5"},
                          {"Building 2/Foundation/Polar inertia", "2e5"},
                          {"Random parameters/Variables", variables}};
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Building 1/Foundation/Shear-wave velocity", text_of(x[0])},
                     {"Building 2/Foundation/Torsional stiffness", text_of(x[1])},
                     {"Building 2/Foundation/Rocking damping x", text_of(x[2])},
                     {"Building 2/Foundation/Polar inertia", text_of(x[3])}};
  };
  compare_with_rebuilt(pair_3d, base, values, 3);
}

// The hinges of a 3D frame (both bending axes at every hinged member end):
// their yield moment and their stiffness factor k = f 6 E I / L (u_y = M_y / k
// follows both), with the section's E of the ground storey random too, so
// that k follows E and f at once.
BOOST_AUTO_TEST_CASE(random_3d_frame_hinges)
{
  const std::string variables =
    "My: Building 1/Hinges/Yield moment ~ lognormal mean 1.5e5 cov 0.25; "
    "f: Building 1/Hinges/Stiffness factor ~ uniform lower 5 upper 20; "
    "E1: Building 1/Column E[1] ~ lognormal mean 3e10 cov 0.15";
  const Overrides base = {{"Building 1/Hinges/Stiffness factor", "10"},
                          {"Random parameters/Variables", variables}};
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Building 1/Hinges/Yield moment", text_of(x[0])},
                     {"Building 1/Hinges/Stiffness factor", text_of(x[1])},
                     {"Building 1/Column E", list_with(x[2], 0, 2, "3e10")}};
  };
  compare_with_rebuilt(pair_3d, base, values, 4);
}

namespace
{
  /// Building 1 of the 3D pair as the L-shaped 3D mesh (meshes/frame3d-l.msh:
  /// physical group 1 the columns, 2 the beams; floors at 3.5 and 6.5 m, as
  /// building 2's with these storey heights), hinges at its column bases and
  /// beam ends (k = 10 x 6 E I / L about each bending axis).
  Overrides
  mesh_3d_pair(const std::string &variables, const Overrides &extra = {})
  {
    Overrides o = {{"Building 1/Type", "mesh"},
                   {"Building 1/Mesh file", "../../meshes/frame3d-l.msh"},
                   {"Building 1/Group ids", "1, 2"},
                   {"Building 1/Group E", "3e10, 3e10"},
                   {"Building 1/Group G", "1.25e10, 1.25e10"},
                   {"Building 1/Group A", "0.16, 0.12"},
                   {"Building 1/Group I", "2.1e-3, 1.6e-3"},
                   {"Building 1/Group Iz", "2.1e-3, 9e-4"},
                   {"Building 1/Group J", "3.6e-3, 1.9e-3"},
                   {"Building 1/Group mass per length", "400, 300"},
                   {"Building 1/Hinges/Stiffness factor", "10"},
                   {"Building 2/Storey heights", "3.5, 3"},
                   {"Random parameters/Variables", variables}};
    o.insert(o.end(), extra.begin(), extra.end());
    return o;
  }
} // namespace

// The groups of a 3D mesh building: E of the columns, G of both groups, Iy
// of the beams, Iz of the columns, J of the beams, A of both, the beams'
// mass per length (K, M with the rotary inertias rho I, the hinges' k = f
// 6 E I_y|z / L about both bending axes), and a floor mass.
BOOST_AUTO_TEST_CASE(random_3d_mesh_groups)
{
  const std::string variables =
    "E: Building 1/Group E[1] ~ lognormal mean 3e10 cov 0.15; "
    "G: Building 1/Group G ~ lognormal mean 1.25e10 cov 0.15; "
    "I: Building 1/Group I[2] ~ lognormal mean 1.6e-3 cov 0.2; "
    "Iz: Building 1/Group Iz[1] ~ lognormal mean 2.1e-3 cov 0.2; "
    "J: Building 1/Group J[2] ~ lognormal mean 1.9e-3 cov 0.2; "
    "A: Building 1/Group A ~ uniform lower 0.12 upper 0.18; "
    "mb: Building 1/Group mass per length[2] ~ uniform lower 0 upper 600; "
    "m: Building 1/Floor masses[2] ~ lognormal mean 6e4 cov 0.2";
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Building 1/Group E", text_of(x[0]) + ", 3e10"},
                     {"Building 1/Group G", text_of(x[1]) + ", " + text_of(x[1])},
                     {"Building 1/Group I", "2.1e-3, " + text_of(x[2])},
                     {"Building 1/Group Iz", text_of(x[3]) + ", 9e-4"},
                     {"Building 1/Group J", "3.6e-3, " + text_of(x[4])},
                     {"Building 1/Group A", text_of(x[5]) + ", " + text_of(x[5])},
                     {"Building 1/Group mass per length", "400, " + text_of(x[6])},
                     {"Building 1/Floor masses", list_with(x[7], 1, 2, "6e4")}};
  };
  BOOST_TEST(compare_with_rebuilt(pair_3d_any_type, mesh_3d_pair(variables), values, 4) > 0u);
}

// The Bouc-Wen shape of 3D hinges (the generated frame's, uniaxial about
// each bending axis, with degradation) and of a 3D shear building's
// hysteretic resisting planes; a random Hinges/Stiffness makes k given,
// so the column E sampled after it leaves k as it is (as the file does).
// Then the bidirectional laws: the frame's biaxial hinges (Park-Wen-Ang)
// and the shear building's paired planes, n >= 2.
BOOST_AUTO_TEST_CASE(random_3d_bouc_wen)
{
  const std::string uniaxial =
    "alpha: Building 1/Bouc-Wen/alpha ~ uniform lower 0.02 upper 0.2; "
    "A: Building 1/Bouc-Wen/A ~ uniform lower 0.9 upper 1.1; "
    "beta: Building 1/Bouc-Wen/beta ~ uniform lower 0.4 upper 0.7; "
    "gamma: Building 1/Bouc-Wen/gamma ~ uniform lower 0.2 upper 0.5; "
    "n: Building 1/Bouc-Wen/n ~ uniform lower 1 upper 3; "
    "dA: Building 1/Bouc-Wen/delta A ~ uniform lower 0 upper 0.2; "
    "k: Building 1/Hinges/Stiffness ~ lognormal mean 2e8 cov 0.3; "
    "E1: Building 1/Column E[1] ~ lognormal mean 3e10 cov 0.15; "
    "alpha2: Building 2/Bouc-Wen/alpha ~ uniform lower 0.02 upper 0.2; "
    "n2: Building 2/Bouc-Wen/n ~ uniform lower 1 upper 3";
  const Overrides planes = {{"Building 2/Storey yield drifts", "0.004, 0.003"},
                            {"Random parameters/Variables", uniaxial}};
  compare_with_rebuilt(pair_3d, planes, [](const std::vector<double> &x) {
    return Overrides{{"Building 1/Bouc-Wen/alpha", text_of(x[0])},
                     {"Building 1/Bouc-Wen/A", text_of(x[1])},
                     {"Building 1/Bouc-Wen/beta", text_of(x[2])},
                     {"Building 1/Bouc-Wen/gamma", text_of(x[3])},
                     {"Building 1/Bouc-Wen/n", text_of(x[4])},
                     {"Building 1/Bouc-Wen/delta A", text_of(x[5])},
                     {"Building 1/Hinges/Stiffness", text_of(x[6])},
                     {"Building 1/Column E", list_with(x[7], 0, 2, "3e10")},
                     {"Building 2/Bouc-Wen/alpha", text_of(x[8])},
                     {"Building 2/Bouc-Wen/n", text_of(x[9])}};
  }, 3);

  const std::string bidirectional =
    "alpha: Building 1/Bouc-Wen/alpha ~ uniform lower 0.02 upper 0.2; "
    "beta: Building 1/Bouc-Wen/beta ~ uniform lower 0.4 upper 0.7; "
    "gamma: Building 1/Bouc-Wen/gamma ~ uniform lower 0.2 upper 0.5; "
    "n: Building 1/Bouc-Wen/n ~ uniform lower 2 upper 4; "
    "A: Building 1/Bouc-Wen/A ~ uniform lower 0.9 upper 1.1; "
    "n2: Building 2/Bouc-Wen/n ~ uniform lower 2 upper 4; "
    "beta2: Building 2/Bouc-Wen/beta ~ uniform lower 0.4 upper 0.7";
  const Overrides biaxial = {{"Building 1/Hinges/Biaxial interaction", "true"},
                             {"Building 2/Storey yield drifts", "0.004, 0.003"},
                             {"Building 2/Plan/Storey law", "bidirectional Bouc-Wen"},
                             {"Random parameters/Variables", bidirectional}};
  compare_with_rebuilt(pair_3d, biaxial, [](const std::vector<double> &x) {
    return Overrides{{"Building 1/Bouc-Wen/alpha", text_of(x[0])},
                     {"Building 1/Bouc-Wen/beta", text_of(x[1])},
                     {"Building 1/Bouc-Wen/gamma", text_of(x[2])},
                     {"Building 1/Bouc-Wen/n", text_of(x[3])},
                     {"Building 1/Bouc-Wen/A", text_of(x[4])},
                     {"Building 2/Bouc-Wen/n", text_of(x[5])},
                     {"Building 2/Bouc-Wen/beta", text_of(x[6])}};
  }, 3);

  // the 3D mesh's hinges, biaxial
  const std::string mesh = "alpha: Building 1/Bouc-Wen/alpha ~ uniform lower 0.02 upper 0.2; "
                           "n: Building 1/Bouc-Wen/n ~ uniform lower 2 upper 4";
  compare_with_rebuilt(pair_3d_any_type,
                       mesh_3d_pair(mesh, {{"Building 1/Hinges/Biaxial interaction", "true"}}),
                       [](const std::vector<double> &x) {
                         return Overrides{{"Building 1/Bouc-Wen/alpha", text_of(x[0])},
                                          {"Building 1/Bouc-Wen/n", text_of(x[1])}};
                       },
                       2);
}

// The storeys of a 3D shear building (its default four resisting planes
// per storey, k/2 each, hysteretic): the stiffness of storey 1, then of
// every storey, the yield drift of storey 2 (K, the modes of no one: it
// has given Rayleigh coefficients; the planes' laws).
BOOST_AUTO_TEST_CASE(random_3d_shear_storeys)
{
  const std::string variables =
    "k: Building 2/Storey stiffnesses ~ lognormal mean 3e7 cov 0.2; "
    "uy2: Building 2/Storey yield drifts[2] ~ uniform lower 0.002 upper 0.005; "
    "k1: Building 2/Storey stiffnesses[1] ~ lognormal mean 4e7 cov 0.2";
  const Overrides planes = {{"Building 2/Storey yield drifts", "0.004, 0.003"},
                            {"Random parameters/Variables", variables}};
  compare_with_rebuilt(pair_3d, planes, [](const std::vector<double> &x) {
    // k of every storey, then k1 of storey 1 written over it
    return Overrides{{"Building 2/Storey stiffnesses", text_of(x[2]) + ", " + text_of(x[0])},
                     {"Building 2/Storey yield drifts", "0.004, " + text_of(x[1])}};
  }, 3);
  const std::string first = "k1: Building 2/Storey stiffnesses[1] ~ lognormal mean 4e7 cov 0.2";
  compare_with_rebuilt(pair_3d,
                       {{"Building 2/Storey yield drifts", "0.004, 0.003"},
                        {"Random parameters/Variables", first}},
                       [](const std::vector<double> &x) {
                         return Overrides{
                           {"Building 2/Storey stiffnesses", text_of(x[0]) + ", 3e7"}};
                       },
                       2);
}

namespace
{
  /// Typed resisting planes of the shear building (6 m x 5 m), hysteretic,
  /// stiffer in y; 'x y angle k u_y' as `Plan/Resisting planes` reads them.
  const std::string typed_planes =
    "0 -2.5 0 2e7 0.004; 0 2.5 0 2.5e7 0.003; -3 0 90 1.5e7 0.004; 3 0 90 1.5e7 0.005";

  /// typed_planes with k[i] and u_y[i] (1-based) given.
  std::string
  planes_with(const std::vector<double> &k, const std::vector<double> &u_y)
  {
    const char *const places[] = {"0 -2.5 0 ", "0 2.5 0 ", "-3 0 90 ", "3 0 90 "};
    std::string text;
    for (unsigned int i = 0; i < 4; ++i)
      text += (i ? "; " : "") + std::string(places[i]) + text_of(k[i]) + " " + text_of(u_y[i]);
    return text;
  }
} // namespace

// The typed resisting planes of a 3D shear building: k of every plane, then
// of plane 2 (written after it), u_y of every plane, then of plane 1, each
// in both storeys (K, the planes' Bouc-Wen laws); then k[3] alone, with
// the planes paired in bidirectional Bouc-Wen elements.
BOOST_AUTO_TEST_CASE(random_typed_resisting_planes)
{
  const std::string variables =
    "k: Building 2/Plan/Resisting planes/k ~ lognormal mean 2e7 cov 0.2; "
    "k2: Building 2/Plan/Resisting planes/k[2] ~ lognormal mean 2.5e7 cov 0.2; "
    "uy: Building 2/Plan/Resisting planes/u_y ~ uniform lower 0.002 upper 0.005; "
    "uy1: Building 2/Plan/Resisting planes/u_y[1] ~ uniform lower 0.002 upper 0.005";
  compare_with_rebuilt(pair_3d,
                       {{"Building 2/Plan/Resisting planes", typed_planes},
                        {"Random parameters/Variables", variables}},
                       [](const std::vector<double> &x) {
                         return Overrides{{"Building 2/Plan/Resisting planes",
                                           planes_with({x[0], x[1], x[0], x[0]},
                                                       {x[3], x[2], x[2], x[2]})}};
                       },
                       3);
  const std::string third = "k3: Building 2/Plan/Resisting planes/k[3] ~ lognormal mean 1.5e7 "
                            "cov 0.3";
  compare_with_rebuilt(pair_3d,
                       {{"Building 2/Plan/Resisting planes", typed_planes},
                        {"Building 2/Plan/Storey law", "bidirectional Bouc-Wen"},
                        {"Random parameters/Variables", third}},
                       [](const std::vector<double> &x) {
                         return Overrides{{"Building 2/Plan/Resisting planes",
                                           planes_with({2e7, 2.5e7, x[0], 1.5e7},
                                                       {0.004, 0.003, 0.004, 0.005})}};
                       },
                       2);
}

// Typed polar moments: the generated 3D frame's floor 2 (one typed value
// for both floors), every floor of the shear building (with its floor
// masses random too: the typed polar moment stays), then the 3D mesh's
// floor 1 (M; the frame's modes and Rayleigh C fitted at them again).
BOOST_AUTO_TEST_CASE(random_polar_moments)
{
  const std::string variables =
    "J1: Building 1/Plan/Polar moments[2] ~ lognormal mean 5e5 cov 0.3; "
    "J2: Building 2/Plan/Polar moments ~ uniform lower 1.5e5 upper 4e5; "
    "m2: Building 2/Floor masses[1] ~ lognormal mean 5e4 cov 0.2";
  const Overrides frame = {{"Building 1/Plan/Polar moments", "5e5"},
                           {"Model/Geometric nonlinearity", "p-delta"},
                           {"Random parameters/Variables", variables}};
  compare_with_rebuilt(pair_3d, frame, [](const std::vector<double> &x) {
    return Overrides{{"Building 1/Plan/Polar moments", "5e5, " + text_of(x[0])},
                     {"Building 2/Plan/Polar moments", text_of(x[1]) + ", " + text_of(x[1])},
                     {"Building 2/Floor masses", list_with(x[2], 0, 2, "5e4")}};
  }, 3);
  const std::string mesh = "J: Building 1/Plan/Polar moments[1] ~ lognormal mean 1.2e6 cov 0.3";
  compare_with_rebuilt(pair_3d_any_type,
                       mesh_3d_pair(mesh, {{"Building 1/Plan/Polar moments", "1.2e6, 9e5"}}),
                       [](const std::vector<double> &x) {
                         return Overrides{
                           {"Building 1/Plan/Polar moments", text_of(x[0]) + ", 9e5"}};
                       },
                       2);
}

// What a realization cannot vary, with the reason: geometry (the nodes, the
// numbering), an entry the model's Type does not use, a law without it.
BOOST_AUTO_TEST_CASE(refused_paths_say_why)
{
  const InputParameters input    = read_parameters(pair_3d);
  const Analysis        analysis = prepare_analysis(input);
  const auto            origins  = std::make_shared<const std::vector<HingeOrigin>>(
    hinge_origins(analysis.model, input.model));
  const auto inputs = std::make_shared<const ModelInputs>(ModelInputs{input.model, input.contact});
  const auto refused = [&](const std::string &path, const std::string &reason) {
    try
      {
        model_parameter(path, analysis.model, origins, inputs);
        BOOST_ERROR("'" << path << "' was accepted");
      }
    catch (const std::invalid_argument &e)
      {
        BOOST_TEST_MESSAGE(e.what());
        BOOST_TEST(std::string(e.what()).find(reason) != std::string::npos, e.what());
      }
  };
  refused("Building 1/Bay widths y", "geometry");
  refused("Building 1/Plan/Mass eccentricity", "geometry");
  refused("Building 2/Plan/Plan dimensions", "geometry");
  refused("Building 1/Set-backs", "geometry");
  refused("Building 1/Column Q", "not a parameter");
  refused("Building 1/Column E[3]", "storeys 1..2");
  refused("Building 2/Group E[1]", "not a mesh building");
  refused("Building 1/Foundation/Mass", "no compliant foundation");
  refused("Contact/Coefficient of restitution", "does not come from the restitution");
  refused("Friction/Belt velocity", "no friction surfaces");
  refused("Building 2/Hinges/Yield moment", "has no hinges");
  refused("Building 2/Bouc-Wen/alpha", "no Bouc-Wen hinges");
  refused("Building 1/Plan/Polar moments", "has no Plan/Polar moments");
  refused("Building 2/Plan/Polar moments[3]", "floors 1..2");
  refused("Building 2/Storey damping[1]", "no dashpots");
  refused("Building 2/Storey yield drifts", "is elastic");
  // without the input, what the builder maps from it cannot follow
  BOOST_CHECK_THROW(model_parameter("Building 2/Floor masses", analysis.model, origins),
                    std::invalid_argument);
  const ModelParameter iz =
    model_parameter("Building 1/Beam Iz[2]", analysis.model, origins, inputs);
  BOOST_TEST(model_parameter_value(iz, analysis.model) == 1.1e-3);
  BOOST_TEST(iz.enters_mass()); // the rotary inertia rho I, rho = m / A
  BOOST_TEST(!model_parameter("Building 1/Column J", analysis.model, origins, inputs).enters_mass());
}

// The same on the 3D mesh: its members' shear areas (not entries), a group
// it does not have, degradation of a bidirectional law, n < 2 for it
// (its range), the polar moment of joints without a rigid slab, the
// storey entries of a 3D shear building whose planes are typed.
BOOST_AUTO_TEST_CASE(refused_3d_mesh_paths_say_why)
{
  const auto check = [](const Overrides &extra,
                        const std::vector<std::pair<std::string, std::string>> &paths) {
    const InputParameters input    = read_parameters(pair_3d_any_type, mesh_3d_pair("", extra));
    const Analysis        analysis = prepare_analysis(input);
    const auto            origins  = std::make_shared<const std::vector<HingeOrigin>>(
      hinge_origins(analysis.model, input.model));
    const auto inputs =
      std::make_shared<const ModelInputs>(ModelInputs{input.model, input.contact});
    for (const auto &[path, reason] : paths)
      try
        {
          model_parameter(path, analysis.model, origins, inputs);
          BOOST_ERROR("'" << path << "' was accepted");
        }
      catch (const std::invalid_argument &e)
        {
          BOOST_TEST_MESSAGE(e.what());
          BOOST_TEST(std::string(e.what()).find(reason) != std::string::npos, e.what());
        }
    return analysis;
  };
  const Analysis analysis =
    check({{"Building 1/Hinges/Biaxial interaction", "true"}},
          {{"Building 1/Group Avy", "no shear areas"},
           {"Building 1/Group E[3]", "groups 1..2"},
           {"Building 1/Group Q", "not a parameter"},
           {"Building 1/Bouc-Wen/delta nu", "no degradation"},
           {"Building 1/Plan/Polar moments", "has no Plan/Polar moments"}});
  const ModelParameter n = model_parameter("Building 1/Bouc-Wen/n", analysis.model);
  BOOST_TEST(n.range().lower == 2.0); // Park-Wen-Ang's interaction
  BOOST_TEST(model_parameter_value(n, analysis.model) == 2.0);
  check({{"Building 1/Diaphragm", "none"},
         {"Building 1/Plan/Polar moments", "1e6, 1e6"},
         {"Contact/Law", "none"}},
        {{"Building 1/Plan/Polar moments[1]", "no rigid slabs"}});
  check({{"Building 2/Plan/Resisting planes",
          "0 -2.5 0 2e7 0.004; 0 2.5 0 2e7 0.004; -3 0 90 2e7 0.004; 3 0 90 2e7 0.004"}},
        {{"Building 2/Storey stiffnesses[1]", "Resisting planes/k[i]"},
         {"Building 2/Storey yield drifts", "Resisting planes typed"}});
  // typed planes: their place is geometry, a plane not listed, a field
  // they do not have, the u_y of an elastic plane (plane 3 has none)
  check({{"Building 2/Plan/Resisting planes",
          "0 -2.5 0 2e7 0.004; 0 2.5 0 2e7 0.004; -3 0 90 2e7; 3 0 90 2e7 0.004"}},
        {{"Building 2/Plan/Resisting planes/angle[1]", "geometry"},
         {"Building 2/Plan/Resisting planes/x", "geometry"},
         {"Building 2/Plan/Resisting planes/k[5]", "resisting planes 1..4"},
         {"Building 2/Plan/Resisting planes/K", "FIELD one of k, u_y"},
         {"Building 2/Plan/Resisting planes/u_y", "plane 3 of building 'S' is elastic"},
         {"Building 2/Plan/Resisting planes/u_y[3]", "is elastic"},
         {"Building 1/Plan/Resisting planes/k", "not a 3D shear building"}});
  // the default planes follow the storey entries
  check({}, {{"Building 2/Plan/Resisting planes/k[1]", "no typed Plan/Resisting planes"}});
}

namespace
{
  /// -1, 0 (where the path needs > 0), infinity and NaN written into `path`
  /// of the 3D pair (mesh_3d_pair with `typed`), and 1e308 sampled through
  /// a realization's run, are refused naming the path (and the 1e150
  /// bound), never a crash or a hang.
  void
  refuses_hostile_values(const std::string &path, const Overrides &typed)
  {
    // a distribution that can sample beyond 1e150 in size, which no
    // parameter file may hold, is refused at its line (exit 1 in the
    // commands), before any realization
    {
      const InputParameters input =
        read_parameters(pair_3d_any_type, mesh_3d_pair("x: " + path + " ~ uniform lower 1e308 upper "
                                              "1.5e308", typed));
      const Analysis    analysis = prepare_analysis(input);
      RealizationRunner runner(analysis, time_history_parameters(input));
      BOOST_CHECK_EXCEPTION(attach_random_parameters(runner, input.random_parameters, input,
                                                     input.model, input.contact,
                                                     input.modal.eigensolver),
                            InputError, [&](const InputError &e) {
                              return std::string(e.what()).find(path) != std::string::npos &&
                                     std::string(e.what()).find("1e150") != std::string::npos;
                            });
    }
    // and the values themselves, as a realization receives them
    const InputParameters input =
      read_parameters(pair_3d_any_type, mesh_3d_pair("x: " + path + " ~ uniform lower 1 upper 2", typed));
    const Analysis analysis = prepare_analysis(input);
    const auto     origins  = std::make_shared<const std::vector<HingeOrigin>>(
      hinge_origins(analysis.model, input.model));
    const auto inputs =
      std::make_shared<const ModelInputs>(ModelInputs{input.model, input.contact});
    std::vector<ModelParameter> parameter{model_parameter(path, analysis.model, origins, inputs)};
    settle_hinge_origins(parameter, *origins, analysis.model);
    ModelRealization realization(analysis, parameter, input.modal.eigensolver);
    for (const double x : {-1.0, 0.0, std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN(), 1e308})
      if (x != 0 || !parameter[0].can_be_zero())
        BOOST_CHECK_EXCEPTION(realization.apply({x}), std::invalid_argument,
                              [&](const std::invalid_argument &e) {
                                return std::string(e.what()).find(path) != std::string::npos;
                              });
  }
} // namespace

// Hostile sampled values on the new paths: -1, 0 (where a value must be
// > 0), infinity, NaN and 1e308 (beyond the 1e150 a file may hold) are
// refused naming the path (exit 1 in the commands), never a crash or a
// hang.
BOOST_AUTO_TEST_CASE(hostile_values_on_3d_paths)
{
  const Overrides typed = {{"Building 1/Plan/Polar moments", "1.2e6, 9e5"},
                           {"Building 2/Storey yield drifts", "0.004, 0.003"}};
  for (const std::string path :
       {"Building 1/Group E[1]", "Building 1/Group G", "Building 1/Group A[2]",
        "Building 1/Group I", "Building 1/Group Iz", "Building 1/Group J",
        "Building 1/Group mass per length", "Building 1/Plan/Polar moments[1]",
        "Building 2/Plan/Polar moments", "Building 1/Bouc-Wen/A", "Building 1/Bouc-Wen/n",
        "Building 2/Storey stiffnesses[1]", "Building 2/Storey yield drifts"})
    refuses_hostile_values(path, typed);
  // the typed resisting planes' k and u_y, of one plane and of every one
  const Overrides planes = {{"Building 2/Plan/Resisting planes", typed_planes}};
  for (const std::string path :
       {"Building 2/Plan/Resisting planes/k[1]", "Building 2/Plan/Resisting planes/k",
        "Building 2/Plan/Resisting planes/u_y[2]", "Building 2/Plan/Resisting planes/u_y"})
    refuses_hostile_values(path, planes);
}

namespace
{
  /// The shear pair's Random parameters set to `variables`, after `devices`.
  Overrides
  with_variables(Overrides devices, const std::string &variables)
  {
    devices.push_back({"Random parameters/Correlation", ""});
    devices.push_back({"Random parameters/Limit states", ""});
    devices.push_back({"Random parameters/Variables", variables});
    return devices;
  }

  /// An SD spring under floor 1 of building 2, whose vertical reaction a
  /// friction element there takes into its N, and a Duffing spring under
  /// floor 2 of building 1.
  const Overrides spring_devices = {{"Springs/SD springs", "2 1 0 1e6 0.05 0.1"},
                             {"Springs/Cubic springs", "1 2 0 5e5 5e7"},
                             {"Friction/Surfaces", "2 1 0"},
                             {"Friction/Static coefficient", "0.35"},
                             {"Friction/Kinetic coefficient", "0.25"},
                             {"Friction/Normal force", "1e5"},
                             {"Friction/Normal force from SD spring", "true"}};

  /// Links of every kind between the two buildings (two Kelvin-Voigt ones).
  const Overrides link_devices = {{"Links/Viscous dampers", "1 2 0 2 2 0 2e4 0.5"},
                           {"Links/Kelvin-Voigt links",
                            "1 1 0 2 1 0 1e6 1e4 1; 1 2 0 2 2 0 1e6 1e4 0.6"},
                           {"Links/Maxwell links", "1 2 0 2 2 0 2e6 3e4"},
                           {"Links/Elastic-plastic links", "1 1 0 2 1 0 1e6 3e3 0.1"}};

  /// Both buildings on typed foundations, coupled through the soil in sway
  /// and in rocking.
  const Overrides coupled_foundations = {{"Building 1/Foundation/Type", "given"},
                                   {"Building 1/Foundation/Horizontal stiffness", "2e8"},
                                   {"Building 1/Foundation/Rocking stiffness", "2e9"},
                                   {"Building 1/Foundation/Horizontal damping", "2e5"},
                                   {"Building 1/Foundation/Rocking damping", "2e6"},
                                   {"Building 1/Foundation/Mass", "2000"},
                                   {"Building 1/Foundation/Rotary inertia", "1e4"},
                                   {"Building 2/Foundation/Type", "given"},
                                   {"Building 2/Foundation/Horizontal stiffness", "1e8"},
                                   {"Building 2/Foundation/Rocking stiffness", "1e9"},
                                   {"Building 2/Foundation/Horizontal damping", "1e5"},
                                   {"Building 2/Foundation/Rocking damping", "1e6"},
                                   {"Building 2/Foundation/Mass", "1000"},
                                   {"Building 2/Foundation/Rotary inertia", "5e3"},
                                   {"Links/Soil coupling", "1 2 5e7 5e4"},
                                   {"Links/Rocking soil coupling", "1 2 5e8 5e5"}};

  /// A linear bumper 4 mm thick in the 10 mm gap.
  const Overrides linear_bumper = {{"Bumpers/Law", "linear"},
                            {"Bumpers/Thickness", "0.004"},
                            {"Bumpers/Stiffness", "2e7"}};

  Overrides
  joined(std::initializer_list<Overrides> parts)
  {
    Overrides all;
    for (const Overrides &part : parts)
      all.insert(all.end(), part.begin(), part.end());
    return all;
  }
} // namespace

// SD and Duffing springs to the ground: K and k1 enter the linear K
// (assembled again; the modes and Rayleigh C follow), L, H and k3 only the
// element, and the friction element's N takes the sampled SD spring's
// K, L, H, as the builder copies them.
BOOST_AUTO_TEST_CASE(random_springs)
{
  const std::string variables = "K: Springs/SD springs/K[1] ~ lognormal mean 1e6 cov 0.3; "
                                "L: Springs/SD springs/L ~ uniform lower 0.02 upper 0.08; "
                                "H: Springs/SD springs/H[1] ~ uniform lower 0.08 upper 0.15; "
                                "k1: Springs/Cubic springs/k1 ~ lognormal mean 5e5 cov 0.3; "
                                "k3: Springs/Cubic springs/k3[1] ~ normal mean 5e7 sd 2e7";
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Springs/SD springs", "2 1 0 " + text_of(x[0]) + " " + text_of(x[1]) +
                                              " " + text_of(x[2])},
                     {"Springs/Cubic springs", "1 2 0 " + text_of(x[3]) + " " + text_of(x[4])}};
  };
  compare_with_rebuilt(shear_pair, with_variables(spring_devices, variables), values, 4);
}

// Every field of every kind of link between the buildings, by entry
// (`Kelvin-Voigt links/k[2]`) or for all the entries of a list
// (`Kelvin-Voigt links/c`), and the viscous damper's c by its short path.
BOOST_AUTO_TEST_CASE(random_links)
{
  const std::string variables =
    "cd: Links/Viscous dampers[1] ~ lognormal mean 2e4 cov 0.3; "
    "a: Links/Viscous dampers/alpha ~ uniform lower 0.3 upper 1; "
    "kv: Links/Kelvin-Voigt links/k[2] ~ lognormal mean 1e6 cov 0.3; "
    "cv: Links/Kelvin-Voigt links/c ~ lognormal mean 1e4 cov 0.3; "
    "av: Links/Kelvin-Voigt links/alpha[1] ~ uniform lower 0.5 upper 1; "
    "km: Links/Maxwell links/k ~ lognormal mean 2e6 cov 0.3; "
    "cm: Links/Maxwell links/c[1] ~ lognormal mean 3e4 cov 0.3; "
    "ke: Links/Elastic-plastic links/k ~ lognormal mean 1e6 cov 0.2; "
    "fy: Links/Elastic-plastic links/Fy ~ lognormal mean 3e3 cov 0.3; "
    "r: Links/Elastic-plastic links/r ~ uniform lower 0 upper 0.5";
  const OverridesOf values = [](const std::vector<double> &x) {
    const auto t = [&x](const unsigned int i) { return " " + text_of(x[i]); };
    return Overrides{
      {"Links/Viscous dampers", "1 2 0 2 2 0" + t(0) + t(1)},
      {"Links/Kelvin-Voigt links",
       "1 1 0 2 1 0 1e6" + t(3) + t(4) + "; 1 2 0 2 2 0" + t(2) + t(3) + " 0.6"},
      {"Links/Maxwell links", "1 2 0 2 2 0" + t(5) + t(6)},
      {"Links/Elastic-plastic links", "1 1 0 2 1 0" + t(7) + t(8) + t(9)}};
  };
  compare_with_rebuilt(shear_pair, with_variables(link_devices, variables), values, 4);
}

// The soil between two compliant foundations: the sway and rocking
// couplings' k and c (Kelvin-Voigt laws like a link's, named by their own
// entries).
BOOST_AUTO_TEST_CASE(random_soil_coupling)
{
  const std::string variables = "ks: Links/Soil coupling/k ~ lognormal mean 5e7 cov 0.3; "
                                "cs: Links/Soil coupling/c[1] ~ uniform lower 0 upper 1e5; "
                                "kr: Links/Rocking soil coupling/k[1] ~ lognormal mean 5e8 "
                                "cov 0.3; "
                                "cr: Links/Rocking soil coupling/c ~ uniform lower 1e5 upper 1e6";
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Links/Soil coupling", "1 2 " + text_of(x[0]) + " " + text_of(x[1])},
                     {"Links/Rocking soil coupling", "1 2 " + text_of(x[2]) + " " + text_of(x[3])}};
  };
  compare_with_rebuilt(shear_pair, with_variables(coupled_foundations, variables), values, 4);
}

// The bumper in the gap: a linear one's stiffness and thickness, then a
// Hertz one's stiffness; the buildings must reach it.
BOOST_AUTO_TEST_CASE(random_bumpers)
{
  const std::string variables = "kb: Bumpers/Stiffness ~ lognormal mean 2e7 cov 0.3; "
                                "t: Bumpers/Thickness ~ uniform lower 0.001 upper 0.008";
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Bumpers/Stiffness", text_of(x[0])}, {"Bumpers/Thickness", text_of(x[1])}};
  };
  BOOST_TEST(
    compare_with_rebuilt(shear_pair, with_variables(linear_bumper, variables), values, 4) > 0u);
  Overrides hertz = linear_bumper;
  hertz.push_back({"Bumpers/Law", "hertz"});
  hertz.push_back({"Bumpers/Stiffness", "1e9"});
  BOOST_TEST(compare_with_rebuilt(shear_pair,
                                  with_variables(hertz, "kb: Bumpers/Stiffness ~ lognormal mean "
                                                        "1e9 cov 0.5"),
                                  [](const std::vector<double> &x) {
                                    return Overrides{{"Bumpers/Stiffness", text_of(x[0])}};
                                  },
                                  2) > 0u);
}

// Sampled values no file could hold, written into a model with every
// device: a negative value, 0 and 1e308 are refused with the path named
// unless the builder accepts them too (a negative k3; 0 where the entry
// may be 0), and a bumper thicker than the gap, sampled or left so by a
// sampled separation, is refused as a sampled mu_k > mu_s is.
BOOST_AUTO_TEST_CASE(hostile_values_of_springs_links_and_bumpers)
{
  const InputParameters input =
    read_parameters(shear_pair, with_variables(joined({spring_devices, link_devices,
                                                       coupled_foundations, linear_bumper}),
                                               ""));
  const Analysis analysis = prepare_analysis(input);
  const auto     origins  = std::make_shared<const std::vector<HingeOrigin>>(
    hinge_origins(analysis.model, input.model));
  const auto inputs = std::make_shared<const ModelInputs>(ModelInputs{input.model, input.contact});
  const auto realization = [&](const std::vector<std::string> &paths) {
    std::vector<ModelParameter> parameters;
    for (const std::string &path : paths)
      parameters.push_back(model_parameter(path, analysis.model, origins, inputs));
    return ModelRealization(analysis, parameters, input.modal.eigensolver);
  };
  struct Case
  {
    std::string path;
    bool        negative_accepted, zero_accepted;
  };
  const std::vector<Case> cases = {{"Springs/SD springs/K", false, false},
                                   {"Springs/SD springs/L[1]", false, true},
                                   {"Springs/SD springs/H", false, true},
                                   {"Springs/Cubic springs/k1[1]", false, false},
                                   {"Springs/Cubic springs/k3", true, true},
                                   {"Links/Viscous dampers/c", false, true},
                                   {"Links/Viscous dampers/alpha[1]", false, false},
                                   {"Links/Kelvin-Voigt links/k[2]", false, true},
                                   {"Links/Kelvin-Voigt links/c", false, false},
                                   {"Links/Kelvin-Voigt links/alpha", false, false},
                                   {"Links/Maxwell links/k", false, false},
                                   {"Links/Maxwell links/c[1]", false, false},
                                   {"Links/Elastic-plastic links/k", false, false},
                                   {"Links/Elastic-plastic links/Fy", false, false},
                                   {"Links/Elastic-plastic links/r", false, true},
                                   {"Links/Soil coupling/k", false, true},
                                   {"Links/Soil coupling/c[1]", false, true},
                                   {"Links/Rocking soil coupling/k", false, true},
                                   {"Links/Rocking soil coupling/c", false, true},
                                   {"Bumpers/Stiffness", false, false},
                                   {"Bumpers/Thickness", false, true}};
  for (const Case &c : cases)
    for (const double value : {-1.0, 0.0, 1e308, 0.5})
      {
        ModelRealization r = realization({c.path});
        const bool accepted = value == -1  ? c.negative_accepted :
                              value == 0   ? c.zero_accepted :
                              value == 0.5 ? c.path != "Bumpers/Thickness" : // > the gap
                                            false;
        try
          {
            r.apply({value});
            BOOST_TEST(accepted, "'" << c.path << "' took " << value);
            BOOST_TEST(model_parameter_value(r.parameters()[0], r.analysis().model) == value);
          }
        catch (const std::invalid_argument &e)
          {
            BOOST_TEST(!accepted, "'" << c.path << "' refused " << value << ": " << e.what());
            const std::string what = e.what();
            BOOST_TEST((what.find(c.path) != std::string::npos ||
                        what.find("Bumpers/Thickness") != std::string::npos),
                       what);
          }
      }
  // a sampled separation under the bumper's 4 mm leaves it thicker than the gap
  ModelRealization gap_and_bumper = realization({"Model/Separations", "Bumpers/Thickness"});
  BOOST_CHECK_NO_THROW(gap_and_bumper.apply({0.005, 0.005}));
  BOOST_CHECK_THROW(gap_and_bumper.apply({0.003, 0.002 + 0.002}), std::invalid_argument);
  BOOST_CHECK_THROW(realization({"Model/Separations"}).apply({0.003}), std::invalid_argument);
}

// Rigid barriers: every barrier's gap, then barrier 2's (written after it),
// with the separation between the buildings random too (the element's gap;
// no assembly). Then hostile gaps: -1, infinity, NaN, 1e308 refused naming
// the path, 0 (a barrier touching the floor) taken; under a 4 mm bumper a
// 3 mm gap refused naming Bumpers/Thickness.
BOOST_AUTO_TEST_CASE(random_barrier_gaps)
{
  const Overrides barriers = {{"Contact/Barriers", "1 2 left 0.006; 2 1 right 0.008"}};
  const std::string variables =
    "g: Contact/Barriers/gap ~ lognormal mean 0.006 cov 0.4; "
    "g2: Contact/Barriers/gap[2] ~ uniform lower 0.002 upper 0.01; "
    "s: Model/Separations ~ lognormal mean 0.01 cov 0.4";
  const OverridesOf values = [](const std::vector<double> &x) {
    return Overrides{{"Contact/Barriers", "1 2 left " + text_of(x[0]) + "; 2 1 right " +
                                            text_of(x[1])},
                     {"Model/Separations", text_of(x[2])}};
  };
  BOOST_TEST(compare_with_rebuilt(shear_pair, with_variables(barriers, variables), values, 4) >
             0u);

  const InputParameters input =
    read_parameters(shear_pair, with_variables(joined({barriers, linear_bumper}), ""));
  const Analysis analysis = prepare_analysis(input);
  for (const std::string path : {"Contact/Barriers/gap", "Contact/Barriers/gap[1]"})
    {
      const ModelParameter gap = model_parameter(path, analysis.model);
      BOOST_TEST(!gap.enters_linear_part());
      BOOST_TEST(model_parameter_value(gap, analysis.model) == 0.006);
      ModelRealization r(analysis, {gap}, input.modal.eigensolver);
      for (const double x : {-1.0, std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::quiet_NaN(), 1e308})
        BOOST_CHECK_EXCEPTION(r.apply({x}), std::invalid_argument,
                              [&](const std::invalid_argument &e) {
                                return std::string(e.what()).find(path) != std::string::npos;
                              });
      BOOST_CHECK_EXCEPTION(r.apply({0.003}), std::invalid_argument,
                            [](const std::invalid_argument &e) {
                              return std::string(e.what()).find("Bumpers/Thickness") !=
                                     std::string::npos;
                            });
      BOOST_CHECK_NO_THROW(r.apply({0.005}));
      BOOST_TEST(model_parameter_value(r.parameters()[0], r.analysis().model) == 0.005);
    }
  const InputParameters bare_input =
    read_parameters(shear_pair, with_variables(barriers, ""));
  const Analysis   bare = prepare_analysis(bare_input);
  ModelRealization touching(bare, {model_parameter("Contact/Barriers/gap[2]", bare.model)},
                            bare_input.modal.eigensolver);
  BOOST_CHECK_NO_THROW(touching.apply({0.0}));
}

// Paths of springs, links and bumpers that the model does not have, or that
// name no field, say why.
BOOST_AUTO_TEST_CASE(refused_device_paths_say_why)
{
  const InputParameters input    = read_parameters(shear_pair, with_variables(spring_devices, ""));
  const Analysis        analysis = prepare_analysis(input);
  const auto refused = [&](const std::string &path, const std::string &reason) {
    try
      {
        model_parameter(path, analysis.model);
        BOOST_ERROR("'" << path << "' was accepted");
      }
    catch (const std::invalid_argument &e)
      {
        BOOST_TEST_MESSAGE(e.what());
        BOOST_TEST(std::string(e.what()).find(reason) != std::string::npos, e.what());
      }
  };
  refused("Springs/SD springs", "FIELD one of K, L, H");
  refused("Springs/SD springs/M", "FIELD one of K, L, H");
  refused("Springs/SD springs/K[2]", "SD springs 1..1");
  refused("Springs/Cubic springs/k3[0]", "count from 1");
  refused("Links/Maxwell links/k", "no entries of 'Links/Maxwell links'");
  refused("Links/Viscous dampers[1]", "no entries of 'Links/Viscous dampers'");
  refused("Links/Regularization velocity", "not a parameter");
  refused("Links/Soil coupling/alpha", "FIELD one of k, c");
  refused("Bumpers/Thickness", "no bumper");
  refused("Friction/Normal force from SD spring", "not a parameter");
  refused("Contact/Barriers/gap", "no Contact/Barriers");
  refused("Contact/Barriers", "'Contact/Barriers/gap[i]'");
  const InputParameters barrier_input =
    read_parameters(shear_pair, with_variables({{"Contact/Barriers", "1 2 left 0.006"}}, ""));
  const Analysis barrier = prepare_analysis(barrier_input);
  BOOST_CHECK_EXCEPTION(model_parameter("Contact/Barriers/gap[2]", barrier.model),
                        std::invalid_argument, [](const std::invalid_argument &e) {
                          return std::string(e.what()).find("barriers 1..1") != std::string::npos;
                        });
  BOOST_CHECK_EXCEPTION(model_parameter("Contact/Barriers/floor[1]", barrier.model),
                        std::invalid_argument, [](const std::invalid_argument &e) {
                          return std::string(e.what()).find("place a barrier") != std::string::npos;
                        });
  const InputParameters table_input = read_parameters(
    shear_pair, with_variables({{"Bumpers/Law", "table"},
                                {"Bumpers/Thickness", "0.004"},
                                {"Bumpers/Table", "0.002 1e4; 0.005 5e4"}},
                               ""));
  const Analysis table = prepare_analysis(table_input);
  BOOST_CHECK_THROW(model_parameter("Bumpers/Stiffness", table.model), std::invalid_argument);
  BOOST_CHECK_THROW(model_parameter("Bumpers/Thickness[1]", table.model), std::invalid_argument);
  // a table bumper stays within its table
  ModelRealization r(table, {model_parameter("Bumpers/Thickness", table.model)},
                     table_input.modal.eigensolver);
  BOOST_CHECK_NO_THROW(r.apply({0.005}));
  BOOST_CHECK_THROW(r.apply({0.006}), std::invalid_argument);
  const ModelParameter k = model_parameter("Springs/SD springs/K", analysis.model);
  BOOST_TEST(k.enters_matrices());
  BOOST_TEST(!k.enters_mass());
  BOOST_TEST(!model_parameter("Springs/SD springs/H", analysis.model).enters_linear_part());
  BOOST_TEST(!model_parameter("Springs/Cubic springs/k3", analysis.model).enters_linear_part());
}

BOOST_AUTO_TEST_SUITE_END()
