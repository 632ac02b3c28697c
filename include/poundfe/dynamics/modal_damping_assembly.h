// The modal part of C of every building whose Damping/Type is modal or
// bands, from its modes in Analysis::building_modes (theory §1.9a;
// assembly/modal_damping.h). Used by prepare_analysis and, when random
// structural parameters change the modes, by ModelRealization.
#ifndef poundfe_dynamics_modal_damping_assembly_h
#define poundfe_dynamics_modal_damping_assembly_h

#include <poundfe/dynamics/analysis.h>

namespace poundfe
{
  /// Replaces analysis.system.modal_damping by U D U^T of the modal buildings.
  void assemble_modal_damping(Analysis &analysis);

  /// The ratio of each of the first modes of a building with modal
  /// damping (`modes` its modes): as listed, or its frequency's band (0
  /// outside every band).
  std::vector<double> modal_damping_ratios(const RayleighDamping &d, const Modes &modes);
} // namespace poundfe

#endif
