// A realization of a built model in which some of its registered parameters
// take sampled values (uncertain structures). Each model part registers the
// paths it lets vary, with get, set, the matrices they enter and their range
// (model/parameter_registry.h; what each path does to the model is said at
// the top of its part's file, source/model/*_registration.cc).
// A realization writes the sampled values into a working copy of the built
// Analysis (never the file, never the model builder), then runs what the
// registrations ask to follow (a contact damping fitted again, a foundation
// made again, the checks of two values together). Only when a value enters
// the linear part (M, K, C) are M, K (and, for Rayleigh damping fitted at
// modes, the building's modes) and C assembled again; a value that enters a
// nonlinear element only leaves M, K, C and their factorisations as they are,
// unless the model has a gravity analysis and a damping fitted at modes: as
// in prepare_analysis, gravity comes first and the modes are those of its
// tangent, which every element's parameter changes, so C is fitted again.
#ifndef poundfe_dynamics_model_parameter_h
#define poundfe_dynamics_model_parameter_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/model/parameter_registry.h>

#include <string>
#include <vector>

namespace poundfe
{
  /// The built model with some parameters sampled: owns a working copy of
  /// the analysis the time history of a realization runs on.
  class ModelRealization
  {
  public:
    /// `eigensolver` recomputes a building's modes when its K changes and
    /// its Rayleigh damping is fitted at modes.
    ModelRealization(const Analysis &base, std::vector<ModelParameter> parameters,
                     Eigensolver eigensolver);

    const std::vector<ModelParameter> &parameters() const { return targets; }
    /// The analysis with the values last applied (the base's before any).
    const Analysis &analysis() const { return working; }
    /// Whether a realization changes the linear part: a parameter enters
    /// it, or a damping fitted at modes is fitted on the gravity tangent.
    bool changes_linear_part() const { return linear; }

    /// Writes values[p] into parameter p; assembles M, K, C again when a
    /// parameter enters them. Throws std::invalid_argument for a value the
    /// model cannot take (a stiffness, yield drift, mass or ratio <= 0, a
    /// negative damping or gap, a bumper thicker than a gap) naming the
    /// parameter, and NumericalError when
    /// the sampled K has no modes (a mechanism).
    void apply(const std::vector<double> &values);
    /// Throws as apply() would for `values` (their ranges, the checks of
    /// values together), on a copy: the analysis stays as it is.
    void check(const std::vector<double> &values) const;

  private:
    /// Writes `values` into `model` and `to` (the working input sections)
    /// and runs what follows them; whether M or K changed.
    bool write(const std::vector<double> &values, Model &model, ModelInputs &to) const;
    /// M and K of the working model again.
    void assemble_matrices();
    /// C again: a damping fitted at modes (Type = modes, modal, bands) from
    /// the modes of the state the dynamics start from (the gravity tangent
    /// when there is one), computed again when `modes_changed`.
    void assemble_damping_of_modes(bool modes_changed);

    Analysis                    working;
    /// The input sections the parameters write into before the builder's
    /// formulas map them (foundations as typed, the contact's restitution).
    ModelInputs                 inputs;
    bool                        has_inputs = false;
    std::vector<ModelParameter> targets;
    Eigensolver                 eigensolver;
    bool                        linear = false;
  };
} // namespace poundfe

#endif
