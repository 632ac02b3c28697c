// The compliant foundation of a 3D (torsionally coupled) shear building
// (doc/theory.md §1.16, "In 3D"): a rigid foundation whose motion is the
// base node's (u_x, u_y, θ_z) about the foundation's centre O and a
// generalized node's rotations (θ_x, θ_y) (its u_z is held: a shear
// building carries no vertical motion; under a 3D frame u_z is free on the
// vertical spring, and the column bases ride the basemat by exact
// master-slave maps, model/frame_building_3d.h). A point at height z above O moves
// rigidly by u_0 + θ × (r - O), horizontally
//   u_x = u_0x + z θ_y - θ_z (y - O_y),  u_y = u_0y - z θ_x + θ_z (x - O_x),
// so a resisting plane of direction d in storey i (height h_i) deforms by
// its 2D-in-plan value minus h_i (d_x θ_y - d_y θ_x) (the rigid part
// cancels between the floors for the other terms): the rocking
// coefficients (h d_y, -h d_x) on (θ_x, θ_y) (model.h, PlaneLink).
// The foundation's springs, dashpots and inertias act along its local axes
// x', y' (the building's plan rotated by α): sway along x' on
// (cos α, sin α)·(u_x, u_y), along y' on (-sin α, cos α)·(u_x, u_y), rocking
// about x' and y' likewise on (θ_x, θ_y), torsion on θ_z; the mass on both
// sways (m I), the rotary inertias about x' and y', the polar one on θ_z.
// Source: J.P. Wolf, Dynamic Soil-Structure Interaction, Prentice Hall
// 1985, §2.1 and ch. 3 (the rigid basemat's six DOFs), with the
// impedances of laws/foundation_impedance.h.
#ifndef poundfe_model_plan_foundation_h
#define poundfe_model_plan_foundation_h

#include <poundfe/model/foundation_parameters.h>
#include <poundfe/model/model.h>

namespace poundfe
{
  /// Put building b's base node `base` on the foundation of `p` (finalized
  /// for 3D), its local x at `angle` (rad, counter-clockwise) from the
  /// site's x: frees the base node, adds the rocking node and the
  /// foundation to the model; with `vertical` (a frame) the rocking node's
  /// u_z is free too, on the vertical spring and dashpot with the mass (and
  /// Wolf's trapped soil). Returns the rocking node.
  unsigned int add_plan_foundation(Model &model, const FoundationParameters &p, unsigned int b,
                                   unsigned int base, double angle, bool vertical = false);

  /// The foundation record add_plan_foundation adds on the base node `base`
  /// and the rocking node `rocking_node`, its local x along `direction`
  /// (cos, sin of the angle).
  Foundation plan_foundation(const FoundationParameters &p, unsigned int b, unsigned int base,
                             unsigned int rocking_node, const std::array<double, 2> &direction,
                             bool vertical);
} // namespace poundfe

#endif
