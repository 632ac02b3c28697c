// The `Springs` section (nonlinear elastic springs to the ground: the SD
// oscillator's spring, Duffing's cubic spring) and the `Friction` section
// (dry-friction elements between floors and the ground or a moving belt),
// each declaring and checking its own entries (deal.II step-33 style). The
// model builder places them (model/model_builder.h); the laws are in
// laws/elastic_springs.h and laws/friction.h.
#ifndef poundfe_model_friction_parameters_h
#define poundfe_model_friction_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/laws/friction.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  const NameTable<FrictionModel> &friction_model_names();

  struct SpringParameters
  {
    std::vector<std::string> sd;    // 'building floor node K L H'
    std::vector<std::string> cubic; // 'building floor node k1 k3'

    /// Declare the entries in the current subsection (`Springs`); the
    /// entries are checked against the model by the model builder.
    void declare(dealii::ParameterHandler &prm);
  };

  /// The largest |Belt velocity| accepted, m/s (the speed of sound in air:
  /// no belt or ground surface moves faster).
  constexpr double maximum_belt_velocity = 343.0;

  struct FrictionParameters
  {
    std::vector<std::string> surfaces; // 'building floor node'
    FrictionLawParameters    law;
    /// N takes the vertical reaction of the SD spring at the same node.
    bool normal_force_from_sd_spring = false;

    /// Declare the entries in the current subsection (`Friction`).
    void declare(dealii::ParameterHandler &prm);
    /// Throws InputError.
    void check(const InputFile &input) const;
  };
} // namespace poundfe

#endif
