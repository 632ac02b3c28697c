// 3D frame buildings from parameters (Model/Dimension = 3, Type = frame):
// storeys x bays along x x bays along y of 3D beam-columns
// (elements/frame_element_3d.h), placed in plan like the torsionally
// coupled shear buildings (model/plan_builder.h).
//   Rigid floor diaphragm (exact master-slave reduction, no penalty): the
//   in-plane motion of a joint at (x, y) on floor i is that of the rigid
//   slab moving q_i = (ux, uy, θz) at the floor's mass centre C_i,
//     ux = ux_C - (y - C_y) θz,  uy = uy_C + (x - C_x) θz,  rz = θz,
//   and its uz, rx, ry stay free. Each member's 12 end DOFs are u_e = T_e q
//   over the model DOFs it touches, so that it adds T_eᵀ K_e T_e and
//   T_eᵀ M_e T_e (doc/theory.md §1.15). C_i carries the floor mass on ux,
//   uy and its polar moment on θz; each joint carries an equal share of the
//   floor mass on uz. The master is the node of the floor, as for a shear
//   building, so the contact between slab outlines, the plan response and
//   the impact log work unchanged.
//   Hinges (Bouc-Wen about both local bending axes of a member end, torsion
//   and axial rigid in the hinge): the member end's rotation is the joint's
//   plus α_y e_y + α_z e_z (e_y, e_z the member's local bending axes), with
//   α_y, α_z two DOFs of a hinge node; each α is a uniaxial Bouc-Wen
//   element, its initial stiffness in K.
// Sources: Cook, Malkus, Plesha & Witt, Concepts and Applications of Finite
// Element Analysis, 4th ed. (2002), §9.2 (multipoint constraints by
// transformation); Wilson, Three-Dimensional Static and Dynamic Analysis of
// Structures, 3rd ed. (2002), ch. 7 (rigid diaphragms, master node at the
// mass centre); Chopra, Dynamics of Structures, 4th ed. (2012), ch. 9.
#ifndef poundfe_model_frame_building_3d_h
#define poundfe_model_frame_building_3d_h

#include <poundfe/model/model.h>
#include <poundfe/model/parameters.h>

namespace poundfe
{
  /// Building b (0-based) of a 3D model with its plan centre at `centre`.
  void build_frame_3d(Model &model, const BuildingParameters &p, unsigned int b, Building &building,
                      const Point2 &centre);
} // namespace poundfe

#endif
