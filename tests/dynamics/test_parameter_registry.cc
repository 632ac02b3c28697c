// The registry of model parameters (model/parameter_registry.h) against the
// paths poundfe could vary before each model part registered its own: every
// path of that list (written out below) is registered, is named by the list
// of known paths an error message gives, and in a model that has it resolves,
// gets the value the builder set, sets and gets back a new one, and enters
// what it entered before (M, K or C, or nonlinear elements only).
#include <poundfe/dynamics/model_parameter.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include "../test_utilities.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <regex>

using namespace poundfe;

namespace
{
  /// The paths the list of known paths named, one per entry.
  const std::vector<std::string> former_paths = [] {
    std::vector<std::string> paths = {
      "Building b/Storey stiffnesses[i]", "Building b/Storey damping[i]",
      "Building b/Storey yield drifts[i]", "Building b/Hinges/Yield moment",
      "Building b/Damping/Damping ratio", "Building b/Floor masses[i]", "Model/Separations[i]",
      "Contact/Barriers/gap[i]", "Contact/Stiffness", "Contact/Damping",
      "Friction/Static coefficient", "Friction/Kinetic coefficient",
      "Links/Viscous dampers[i]", "Bumpers/Stiffness", "Bumpers/Thickness",
      "Building b/Hinges/Stiffness", "Building b/Hinges/Stiffness factor",
      "Building b/Hinges/Yield rotation", "Building b/Damping/a0", "Building b/Damping/a1",
      "Building b/Damping/Modal ratios[i]", "Building b/Plan/Polar moments[i]",
      "Building b/Plan/Resisting planes/k[i]", "Building b/Plan/Resisting planes/u_y[i]",
      "Contact/Coefficient of restitution"};
    for (const char *field : {"Viscous dampers/c", "Viscous dampers/alpha", "Kelvin-Voigt links/k",
                              "Kelvin-Voigt links/c", "Kelvin-Voigt links/alpha",
                              "Maxwell links/k", "Maxwell links/c", "Elastic-plastic links/k",
                              "Elastic-plastic links/Fy", "Elastic-plastic links/r",
                              "Soil coupling/k", "Soil coupling/c", "Rocking soil coupling/k",
                              "Rocking soil coupling/c"})
      paths.push_back(std::string("Links/") + field + "[i]");
    for (const char *field : {"SD springs/K", "SD springs/L", "SD springs/H", "Cubic springs/k1",
                              "Cubic springs/k3"})
      paths.push_back(std::string("Springs/") + field + "[i]");
    for (const char *member : {"Column", "Beam"})
      for (const char *field : {"E", "G", "A", "I", "Iz", "J", "Avy", "Avz", "mass per length"})
        paths.push_back(std::string("Building b/") + member + " " + field + "[i]");
    for (const char *field : {"E", "G", "A", "I", "Iz", "J", "mass per length"})
      paths.push_back(std::string("Building b/Group ") + field + "[i]");
    for (const char *shape : {"alpha", "A", "beta", "gamma", "n", "delta A", "delta nu", "delta eta"})
      paths.push_back(std::string("Building b/Bouc-Wen/") + shape);
    for (const char *entry :
         {"Shear-wave velocity", "Soil density", "Poisson ratio", "Length", "Width", "Embedment",
          "Horizontal stiffness", "Rocking stiffness", "Vertical stiffness", "Horizontal damping",
          "Rocking damping", "Vertical damping", "Mass", "Rotary inertia",
          "Horizontal stiffness y", "Rocking stiffness x", "Torsional stiffness",
          "Horizontal damping y", "Rocking damping x", "Torsional damping", "Rotary inertia x",
          "Polar inertia"})
      paths.push_back(std::string("Building b/Foundation/") + entry);
    for (const char *entry : {"Stribeck velocity", "Belt velocity", "Normal force",
                              "Normal force per displacement", "Normal force per velocity",
                              "Normal force per velocity cubed", "Stick stiffness",
                              "Regularization velocity"})
      paths.push_back(std::string("Friction/") + entry);
    return paths;
  }();
} // namespace

BOOST_AUTO_TEST_CASE(every_former_path_is_registered_and_listed)
{
  const ParameterRegistry &registry = parameter_registry();
  const std::string        known    = registry.known_paths();
  static const std::regex  form(R"(^(Building b/)?(.*?)(\[i\])?$)");
  for (const std::string &path : former_paths)
    {
      std::smatch match;
      BOOST_REQUIRE(std::regex_match(path, match, form));
      const ParameterRegistration *r =
        registry.find(registry.resolve_alias(match[2]), match[1].matched);
      BOOST_TEST_REQUIRE(r != nullptr, path << " is not registered");
      BOOST_TEST(r->takes_index == (match[3].matched || r->name != match[2].str()), path);
      // the list names the path, or its family's first path and its label
      const ParameterRegistration *head = r;
      for (const ParameterRegistration &other : registry.registrations())
        if (!r->family.empty() && other.family == r->family && other.listed)
          {
            head = &other;
            break;
          }
      BOOST_TEST(r->listed, path);
      BOOST_TEST(known.find(head->pattern()) != std::string::npos, path);
      if (head != r)
        BOOST_TEST((known.find("(" + r->label) != std::string::npos ||
                    known.find(", " + r->label) != std::string::npos),
                   path);
    }
  BOOST_TEST(registry.registrations().size() >= former_paths.size() - 1); // an alias
}

namespace
{
  /// A path, the value the model built from the file has there, and what it
  /// entered before the registry: M or K (matrices), M, C (linear part).
  struct Case
  {
    std::string path;
    double      built;
    bool        linear, matrices, mass;
  };

  /// Each case resolves in the model of `file` with `overrides`, gets its
  /// built value, sets 1.25 times it and gets that back, and enters what it did.
  void
  check_cases(const std::string &file, const std::vector<ParameterOverride> &overrides,
              const std::vector<Case> &cases)
  {
    const InputParameters input    = read_parameters(file, overrides);
    const Analysis        analysis = prepare_analysis(input);
    const auto            origins  = std::make_shared<const std::vector<HingeOrigin>>(
      hinge_origins(analysis.model, input.model));
    const auto inputs = std::make_shared<const ModelInputs>(ModelInputs{input.model, input.contact});
    for (const Case &c : cases)
      {
        BOOST_TEST_CONTEXT(c.path)
        {
          const ModelParameter p = model_parameter(c.path, analysis.model, origins, inputs);
          BOOST_TEST(p.value(analysis.model) == c.built, boost::test_tools::tolerance(1e-12));
          BOOST_TEST(p.enters_linear_part() == c.linear);
          BOOST_TEST(p.enters_matrices() == c.matrices);
          BOOST_TEST(p.enters_mass() == c.mass);
          Model       model = analysis.model;
          ModelInputs to    = *inputs;
          p.set(1.25 * c.built, model, to);
          // a value the builder maps (a foundation's) is read from its input
          const ModelParameter q = [&] {
            ModelParameter copy = p;
            copy.inputs         = std::make_shared<const ModelInputs>(to);
            return copy;
          }();
          BOOST_TEST(q.value(model) == 1.25 * c.built, boost::test_tools::tolerance(1e-12));
        }
      }
  }

  const std::string shear_pair = "tests/dynamics/uncertain-shear-pair.prm";
} // namespace

BOOST_AUTO_TEST_CASE(shear_pair_paths_get_set_and_enter_as_before)
{
  check_cases(shear_pair, {{"Building 1/Storey damping", "1e4"}},
              {{"Building 1/Storey stiffnesses[2]", 4e6, true, true, false},
               {"Building 1/Storey damping[3]", 1e4, true, false, false},
               {"Building 2/Storey yield drifts", 0.003, false, false, false},
               {"Building 1/Floor masses[1]", 1000, true, true, true},
               {"Building 2/Damping/Damping ratio", 0.03, true, false, false},
               {"Model/Separations", 0.01, false, false, false},
               {"Contact/Stiffness", 5e8, false, false, false}});
  check_cases(shear_pair,
              {{"Building 1/Damping/Type", "coefficients"},
               {"Building 1/Damping/a0", "0.25"},
               {"Building 1/Damping/a1", "0.002"},
               {"Building 2/Damping/Type", "modal"},
               {"Building 2/Damping/Modal ratios", "0.02, 0.04"}},
              {{"Building 1/Damping/a0", 0.25, true, false, false},
               {"Building 1/Damping/a1", 0.002, true, false, false},
               {"Building 2/Damping/Modal ratios[2]", 0.04, true, false, false}});
}

BOOST_AUTO_TEST_CASE(device_paths_get_set_and_enter_as_before)
{
  check_cases(shear_pair,
              {{"Springs/SD springs", "2 1 0 1e6 0.05 0.1"},
               {"Springs/Cubic springs", "1 2 0 5e5 5e7"},
               {"Friction/Surfaces", "2 1 0"},
               {"Friction/Static coefficient", "0.35"},
               {"Friction/Kinetic coefficient", "0.25"},
               {"Friction/Normal force", "1e5"},
               {"Links/Viscous dampers", "1 2 0 2 2 0 2e4 0.5"},
               {"Links/Maxwell links", "1 2 0 2 2 0 2e6 3e4"},
               {"Links/Elastic-plastic links", "1 1 0 2 1 0 1e6 3e3 0.1"},
               {"Bumpers/Law", "linear"},
               {"Bumpers/Thickness", "0.004"},
               {"Bumpers/Stiffness", "2e7"}},
              {{"Springs/SD springs/K", 1e6, true, true, false},
               {"Springs/SD springs/L[1]", 0.05, false, false, false},
               {"Springs/Cubic springs/k1", 5e5, true, true, false},
               {"Springs/Cubic springs/k3", 5e7, false, false, false},
               {"Friction/Kinetic coefficient", 0.25, false, false, false},
               {"Friction/Normal force", 1e5, false, false, false},
               {"Links/Viscous dampers", 2e4, false, false, false},
               {"Links/Viscous dampers/alpha[1]", 0.5, false, false, false},
               {"Links/Maxwell links/c", 3e4, false, false, false},
               {"Links/Elastic-plastic links/Fy", 3e3, false, false, false},
               {"Bumpers/Thickness", 0.004, false, false, false},
               {"Bumpers/Stiffness", 2e7, false, false, false}});
}

BOOST_AUTO_TEST_CASE(foundation_and_frame_paths_get_set_and_enter_as_before)
{
  check_cases(shear_pair,
              {{"Building 1/Foundation/Type", "given"},
               {"Building 1/Foundation/Horizontal stiffness", "2e8"},
               {"Building 1/Foundation/Rocking stiffness", "2e9"},
               {"Building 1/Foundation/Horizontal damping", "2e5"},
               {"Building 1/Foundation/Rocking damping", "2e6"},
               {"Building 1/Foundation/Mass", "2000"},
               {"Building 1/Foundation/Rotary inertia", "1e4"}},
              {{"Building 1/Foundation/Horizontal stiffness", 2e8, true, true, true},
               {"Building 1/Foundation/Rocking damping", 2e6, false, false, false},
               {"Building 1/Foundation/Mass", 2000, true, true, true}});
  check_cases("input/two-buildings.prm", {},
              {{"Building 1/Column E[1]", 3e10, true, true, false},
               {"Building 2/Beam I", 1.6e-3, true, true, false},
               {"Building 1/Hinges/Yield moment", 180e3, false, false, false},
               {"Building 2/Bouc-Wen/alpha", 0.005, false, false, false},
               {"Building 1/Damping/Damping ratio", 0.05, true, false, false}});
}
