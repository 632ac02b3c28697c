// The realization of a model with sampled parameters
// (dynamics/model_parameter.h): each value is written by its registration
// (model/parameter_registry.h) where the model builder put the entry's
// value, so a realization equals the model built from a file with that value
// (tests/dynamics/test_model_parameters.cc checks exactly that).
#include <poundfe/dynamics/modal_damping_assembly.h>
#include <poundfe/dynamics/model_parameter.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <utility>

namespace poundfe
{
  ModelRealization::ModelRealization(const Analysis &base, std::vector<ModelParameter> parameters,
                                     const Eigensolver eigensolver_)
    : working(base)
    , targets(std::move(parameters))
    , eigensolver(eigensolver_)
  {
    for (const ModelParameter &p : targets)
      {
        linear = linear || p.enters_linear_part();
        if (p.inputs && !has_inputs)
          {
            inputs     = *p.inputs;
            has_inputs = true;
            for (BuildingParameters &b : inputs.model.buildings) // the foundations as typed
              b.foundation = b.foundation.as_typed(base.model.dimension == 3);
          }
      }
    // with gravity, a damping fitted at modes is fitted on the gravity
    // tangent, which a parameter of a nonlinear element changes too
    const auto fitted = [](const Building &b) {
      return b.damping.kind == RayleighDamping::Kind::modes || b.damping.is_modal();
    };
    linear = linear || (base.model.gravity_analysis.enabled &&
                        std::any_of(base.model.buildings.begin(), base.model.buildings.end(), fitted));
  }

  bool
  ModelRealization::write(const std::vector<double> &values, Model &model, ModelInputs &to) const
  {
    AssertDimension(values.size(), targets.size());
    bool matrices_changed = false; // M or K: the modes change
    // what follows once every value is written: once a building
    std::vector<const ModelParameter *> follow_ups;
    for (unsigned int i = 0; i < targets.size(); ++i)
      {
        const ModelParameter &p = targets[i];
        p.set(values[i], model, to);
        matrices_changed = matrices_changed || p.enters_matrices();
        const ParameterFollowUp follow_up = p.registration->follow_up;
        if (follow_up && std::none_of(follow_ups.begin(), follow_ups.end(),
                                      [&](const ModelParameter *q) {
                                        return q->registration->follow_up == follow_up &&
                                               q->building == p.building;
                                      }))
          follow_ups.push_back(&p);
      }
    for (const ModelParameter *p : follow_ups)
      p->registration->follow_up(*p, model, has_inputs ? &to : nullptr);
    return matrices_changed;
  }

  void
  ModelRealization::apply(const std::vector<double> &values)
  {
    const bool matrices_changed = write(values, working.model, inputs);
    if (matrices_changed)
      assemble_matrices();
    if (!working.model.friction_surfaces.empty()) // k_s (automatic) and c_s of the new K, M
      fit_stick_laws(working.system, working.model);
    set_gravity_state(working); // the gravity state of the new model (nothing when off)
    // as prepare_analysis: damping fitted at modes after gravity, on its
    // tangent, which any parameter of an element may change
    if (linear)
      assemble_damping_of_modes(matrices_changed || working.gravity.active);
  }

  void
  ModelRealization::check(const std::vector<double> &values) const
  {
    Model       model = working.model;
    ModelInputs to    = inputs;
    write(values, model, to);
  }

  void
  ModelRealization::assemble_matrices()
  {
    // M and K as prepare_analysis assembles them (with P-Delta, K_G of the
    // unchanged gravity loads on the new K_E)
    LinearSystem fresh = assemble_mass_and_stiffness(working.model);
    LinearSystem &system       = working.system;
    system.mass                = std::move(fresh.mass);
    system.stiffness           = std::move(fresh.stiffness);
    system.geometric_stiffness = std::move(fresh.geometric_stiffness);
    system.structure_mass      = std::move(fresh.structure_mass);
    system.structure_stiffness = std::move(fresh.structure_stiffness);
  }

  void
  ModelRealization::assemble_damping_of_modes(const bool modes_changed)
  {
    const Model  &model  = working.model;
    LinearSystem &system = working.system;
    // the modes of the state the dynamics start from, as prepare_analysis
    const SparseMatrix &modal_stiffness =
      working.gravity.active ? working.gravity.tangent : system.stiffness;
    std::vector<std::array<double, 2>> coefficients = system.rayleigh;
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const RayleighDamping &d = model.buildings[b].damping;
        if (d.kind == RayleighDamping::Kind::coefficients)
          coefficients[b] = {{d.a0, d.a1}};
        if (d.kind != RayleighDamping::Kind::modes && !d.is_modal())
          continue;
        Modes &modes = working.building_modes[b];
        if (modes_changed)
          {
            const auto range = model.equation_range(b);
            modes = compute_modes(block(system.mass, range), block(modal_stiffness, range),
                                  system.influence.segment(range[0], range[1] - range[0]),
                                  modes.n_modes(), eigensolver);
          }
        if (d.kind == RayleighDamping::Kind::modes)
          coefficients[b] = rayleigh_coefficients(d.damping_ratio, modes.omega[d.first_mode - 1],
                                                  modes.omega[d.second_mode - 1]);
      }
    assemble_damping(model, coefficients, system);
    assemble_modal_damping(working); // modal buildings: from their new modes
  }
} // namespace poundfe
