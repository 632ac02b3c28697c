// A compliant foundation under a 2D building (doc/theory.md §1.16).
//
// Shear building: the base node's sway u_0 (ux) and rocking θ (rz) stand on
// the sway and rocking springs and dashpots, with the foundation's mass on
// u_0 and its rotary inertia on θ.
//
// Frame: a rigid foundation node O at the centre of the base, (x_O, base
// level), with u_0, the vertical v_0 (uy) and θ, on the sway, vertical and
// rocking springs and dashpots (the mass on u_0 and v_0, plus Wolf's trapped
// soil on v_0). Every column base at (x_j, base level) moves with the
// foundation as a rigid body,
//   ux_j = u_0,   uy_j = v_0 + (x_j - x_O) θ,   rz_j = θ
// (a pinned base keeps its own rz), by exact master-slave constraints
// (Model::constraints; Cook, Malkus, Plesha & Witt, Concepts and
// Applications of Finite Element Analysis, 4th ed. 2002, §9.2), not by
// penalty springs: the element matrices enter as Tᵀ K T. Source of the
// rigid foundation's three DOFs: J.P. Wolf, Dynamic Soil-Structure
// Interaction, Prentice Hall 1985, §2.1; the impedances:
// laws/foundation_impedance.h.
#ifndef poundfe_model_frame_foundation_h
#define poundfe_model_frame_foundation_h

#include <poundfe/model/foundation_parameters.h>
#include <poundfe/model/model.h>

namespace poundfe
{
  /// Put node `node` of building b on the foundation of `p`: frees its
  /// DOFs and adds the sway and rocking parts on its ux and rz and, with
  /// `vertical`, the vertical part on its uy.
  void add_planar_foundation(Model &model, const FoundationParameters &p, unsigned int b,
                             unsigned int node, bool vertical);

  /// The foundation record add_planar_foundation adds (its springs,
  /// dashpots and inertias from p's impedance, mass and rotary inertia).
  Foundation planar_foundation(const FoundationParameters &p, unsigned int b, unsigned int node,
                               bool vertical);

  /// Put the 2D frame b (its supports are its column bases) on a rigid
  /// foundation at the centre of its base. Returns the foundation's node.
  unsigned int add_frame_foundation(Model &model, const FoundationParameters &p, unsigned int b,
                                    const Building &building);
} // namespace poundfe

#endif
