// Uniaxial stress-strain materials for the fibres of fibre sections
// (deformation = strain, force = stress, tangent = dsigma/deps), after
// OpenSees's uniaxial materials, and the registry that makes them by name.
// Each material is one file, source/laws/<material>.cc, whose opening
// comment gives its equations and sources (doc/theory.md §12); it defines
// its class, its parameter struct and materials::<material>() (its
// MaterialType), listed by one line in source/laws/material_registry.cc.
// UniaxialMaterial<State> below is the common frame: a material's whole
// history is one State, the trial state is a pure function of the committed
// state and the trial strain, so revert() is a copy and exact.
#ifndef poundfe_laws_material_registry_h
#define poundfe_laws_material_registry_h

#include <poundfe/laws/uniaxial_law.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  /// A stress-strain law whose history is one State holding at least
  /// `strain`, `stress` and `tangent`. A material defines respond(committed,
  /// strain) -> trial and virgin(), and calls reset() in its constructor.
  template <class State>
  class UniaxialMaterial : public UniaxialLaw
  {
  public:
    /// Refuses (false, failure() says why) a strain or a stress that is not
    /// finite: the trial state must then not be used.
    bool set_trial(const double strain, const double /*rate*/) final
    {
      trial = respond(committed, strain);
      return std::isfinite(strain) && std::isfinite(trial.stress) && std::isfinite(trial.tangent);
    }
    std::string failure() const final
    {
      return "stress-strain material: strain " + std::to_string(trial.strain) + ", stress " +
             std::to_string(trial.stress) + ", tangent " + std::to_string(trial.tangent) +
             " (not all finite)";
    }
    double force() const final { return trial.stress; }
    double tangent() const final { return trial.tangent; }
    /// The energy released by unloading at the initial modulus.
    double stored_energy() const override
    {
      return 0.5 * trial.stress * trial.stress / initial_stiffness();
    }
    void commit() final { committed = trial; }
    void revert() final { trial = committed; }
    void reset() final { committed = trial = virgin(); }

    /// The trial strain (the deformation of the last set_trial).
    double strain() const { return trial.strain; }

  protected:
    virtual State respond(const State &from, double strain) const = 0;
    virtual State virgin() const = 0;

    State committed, trial;
  };

  /// A material as the input names it: the registered name and its
  /// parameters by OpenSees's names ("fy", "E0", "b", ...).
  struct MaterialParameters
  {
    std::string                   material;
    std::map<std::string, double> values;
  };

  /// One parameter of a material: its name, default (NaN: required) and meaning.
  struct MaterialParameter
  {
    std::string name;
    double      default_value = std::numeric_limits<double>::quiet_NaN();
    std::string meaning;
  };

  /// A material as the program knows it: the registry holds one per name.
  struct MaterialType
  {
    std::string                    name;
    std::string                    description; // the law and its source
    std::vector<MaterialParameter> parameters;
    /// Makes the material from every parameter's value (defaults filled in);
    /// throws InputError naming a parameter whose value the law refuses.
    std::function<std::unique_ptr<UniaxialLaw>(const std::map<std::string, double> &)> make;
  };

  /// The registered material of that name; InputError (parameter "Material")
  /// if none.
  const MaterialType &material_type(const std::string &name);

  /// Registered material names, in the order of the registry's list.
  std::vector<std::string> material_names();

  /// The material of `parameters`: unknown parameter names, missing required
  /// ones and values the law refuses are InputErrors naming the parameter.
  std::unique_ptr<UniaxialLaw> make_material(const MaterialParameters &parameters);

  /// Checks shared by the materials' constructors: an InputError naming
  /// `parameter` (problem prefixed by `material`) unless the value is finite
  /// and positive / non-negative / in [low, high).
  void require_positive(const char *material, const char *parameter, double value);
  void require_non_negative(const char *material, const char *parameter, double value);
  void require_in(const char *material, const char *parameter, double value, double low,
                  double high);
  /// An InputError naming `parameter`: "<material>: <problem>".
  [[noreturn]] void refuse_parameter(const char *material, const char *parameter,
                                     const std::string &problem);
} // namespace poundfe

#endif
