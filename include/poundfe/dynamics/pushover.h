// The pushover of a model (static nonlinear analysis): after the gravity
// state (Model/Gravity analysis; else from rest), the lateral loads
// p_c + lambda p_ref, p_c the gravity loads held and p_ref each building's
// pattern (dynamics/pushover_parameters.h) scaled so that it sums to 1 (lambda
// is then each building's applied base shear), pushed by displacement
// control of the control node's ux to each target drift in turn, with arc
// length where displacement control fails (integration/static_analysis.h).
// Two buildings side by side are pushed together; their gaps close and
// carry force as in the dynamics (the same nonlinear elements). The curve's
// equivalent system (EN 1998-1 Annex B: dynamics/capacity_curve.h) is of the
// control building's pattern shape Phi (Phi = 1 at the control node); ASCE
// 41's coefficient method (dynamics/asce41_target.h) takes the building's
// first mode.
#ifndef poundfe_dynamics_pushover_h
#define poundfe_dynamics_pushover_h

#include <poundfe/base/input_file.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/pushover_parameters.h>
#include <poundfe/output/section_limit_states.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  /// One committed point of the curve.
  struct PushoverPoint
  {
    double              lambda               = 0;
    double              control_displacement = 0; // m, total (the gravity state's included)
    std::vector<double> base_shears;  // N, per building: its supports' horizontal reaction
    std::vector<double> drifts;       // every storey of every building (PushoverResult::storeys)
    std::vector<double> element_forces, element_deformations; // hinges and storeys
    /// With fibre members: each storey's damage state so far, the worst
    /// limit of its members (output/section_limits.h; -1 none), in the order of
    /// `drifts`; else empty.
    std::vector<int> storey_damage;
    bool                arc_length = false; // reached by an arc-length step
  };

  struct PushoverResult
  {
    std::vector<PushoverPoint> points; // the first: the start (gravity state or rest)
    std::vector<std::string>   storeys;  // "B1 storey 1"
    std::vector<std::string>   elements; // the hinges' and hysteretic storeys' labels
    unsigned int               control_equation = 0;
    std::string                control_name;
    double                     control_height = 0; // m, above the base
    /// The equivalent system of the control building (Annex B).
    double                     gamma = 1, equivalent_mass = 0;
    /// ASCE 41 (asked by Target method): the control building's mass along
    /// x (kg, W / g), its first mode's period T_i (s) and C0, the mode's
    /// participation factor times its ordinate at the control node.
    double                     building_mass = 0, first_period = 0, first_mode_c0 = 1;
    bool                       completed = true;
    std::string                failure; // why it stopped early (completed false)
    unsigned int               iterations = 0, arc_length_steps = 0, step_cuts = 0;
    /// The limit states of the fibre members along the push, their first
    /// times the control displacements (m) that reach them; nullptr
    /// without fibre members or limits asked for. Its elements are gone:
    /// read it, do not observe with it.
    std::shared_ptr<const SectionLimitStates> section_limits;
  };

  /// The pushover of `analysis`'s model. InputError (file, line, entry) for
  /// a control floor the building has not, a 3D model or a partitioned one;
  /// a numerical failure ends the curve early with `failure` set.
  /// With `limits`, the fibre members' limit states are followed from the
  /// start (their yield curvatures at its axial forces) through every point.
  PushoverResult run_pushover(const Analysis &analysis, const PushoverParameters &parameters,
                              const InputFile &input,
                              const SectionLimitParameters *limits = nullptr);

  /// The lateral load pattern p_ref (on the ux equations, each building's
  /// summing to 1) of `analysis`'s model; `shapes` gets Phi of the control
  /// building's equations (others 0), 1 at `control_equation`.
  Vector lateral_load_pattern(const Analysis &analysis, const PushoverParameters &parameters,
                              unsigned int control_equation, Vector &shapes);
} // namespace poundfe

#endif
