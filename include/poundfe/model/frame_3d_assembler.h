// The parts every 3D frame building is made of, shared by the generated
// grid (model/frame_building_3d.h) and the frame drawn in Gmsh
// (model/mesh_building_3d.h), so that both give the same Model data and
// everything downstream (assembly, hinges, damping, contact in plan,
// recorders, VTU) treats them alike (doc/theory.md §1.15):
//   a joint's six DOFs (ux, uy, uz, rx, ry, rz) are rows of T over model
//   DOFs: a rigid floor's joint at (x, y) moves with its master q_i =
//   (ux, uy, θz) at the mass centre C_i,
//     ux = ux_C - (y - C_y) θz,  uy = uy_C + (x - C_x) θz,  rz = θz,
//   its (uz, rx, ry) on a generalized node of its own; a free joint has
//   both nodes of its own; a clamped base joint none; a pinned one its
//   rotations; a base on a compliant foundation moves with the basemat.
//   A member adds T_eᵀ K_e T_e (Cook et al. 2002, §9.2, multipoint
//   constraints by transformation; Wilson 2002, ch. 7, rigid diaphragms).
//   Hinges: Bouc-Wen about both local bending axes of a member end.
// Eigen is included: this header is for the model builders only.
#ifndef poundfe_model_frame_3d_assembler_h
#define poundfe_model_frame_3d_assembler_h

#include <poundfe/model/model.h>
#include <poundfe/model/parameters.h>
#include <poundfe/model/torsional_shear_building.h>

#include <Eigen/Core>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace poundfe
{
  /// The model nodes that carry a joint's motion: `h` its (ux, uy, rz), `v`
  /// its (uz, rx, ry) (a generalized node), or the floor's `master` at
  /// `centre` (a rigid diaphragm); -1: none (the ground). A column base on
  /// a compliant foundation (`on_basemat`): `master` is the basemat's node
  /// at its centre and `v` its rocking node (model/plan_foundation.h). A
  /// joint of a grid line its storey's set-back removed is absent.
  struct FrameJoint3D
  {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    int             h = -1, v = -1, master = -1;
    Point2          centre;
    bool            on_basemat = false;
    bool            present    = true;
  };

  /// A floor's slab as the diaphragm takes it: its mass, polar moment and
  /// mass centre (site), its level, the storey below's height and the slab
  /// outline in plan (site, counter-clockwise) for contact.
  struct FrameSlab3D
  {
    TorsionalFloor      floor;
    double              level         = 0;
    double              storey_height = 0;
    std::vector<Point2> outline;
  };

  /// Adds the nodes, masses, floors, members and hinges of building b of a
  /// 3D frame to `model` and `building` (p: its parameters).
  class FrameAssembler3D
  {
  public:
    FrameAssembler3D(Model &model, const BuildingParameters &p, unsigned int b,
                     Building &building);

    /// A compliant foundation (p.foundation enabled): the basemat's node at
    /// `centre` at `level`, its axes turned by `angle` (rad).
    void add_foundation(const Point2 &centre, double level, double angle);
    /// A column base: clamped, pinned (Base fixity) or on the basemat.
    void make_base(FrameJoint3D &joint);
    /// Floor `slab` holding `joints` (the present ones): with Diaphragm =
    /// rigid, a master node at the mass centre with the mass and polar
    /// moment, the joints slaved to it; with none, each joint free with an
    /// equal share. Each joint carries an equal share on uz.
    void make_floor(const FrameSlab3D &slab, const std::vector<FrameJoint3D *> &joints);
    /// A massless joint off the floors and the base (a mesh's brace node).
    void make_free_joint(FrameJoint3D &joint);
    /// A member from ends[0] to ends[1] with local x-z plane through
    /// `orientation`, of `kind`, hinge group `group`, labelled
    /// "<building>_<label>" (columns: ends[0] the bottom); `fibre`: its
    /// beam-column on a fibre section (Member model = fibre).
    void add_member(const std::array<const FrameJoint3D *, 2> &ends,
                    const Eigen::Vector3d &orientation, const Section3D &section, MemberKind kind,
                    unsigned int group, const std::string &label, const FibreMember &fibre = {});

  private:
    Model                    &model;
    const BuildingParameters &p;
    const unsigned int        b;
    Building                 &building;
    const bool                rigid;
    int                       basemat = -1, rocking = -1; // a compliant foundation's nodes
    Point2                    basemat_centre;

    unsigned int add_node(const Point2 &position, bool generalized);
    bool wants_hinge(const char *location) const;
    bool hinged(MemberKind kind, unsigned int group, unsigned int k, const FrameJoint3D &joint,
                unsigned int &group_index) const;
    /// One row of T per DOF of a member end: model DOF -> coefficient.
    using Rows = std::array<std::map<unsigned int, double>, 6>;
    Rows joint_rows(const FrameJoint3D &joint) const;
    void add_hinge(Member3D &member, unsigned int k, unsigned int group_index,
                   const Eigen::Matrix3d &axes, Rows &rows);
  };

  /// The member's local axes (rows x, y, z; OpenSees's convention, as
  /// elements/frame_element_3d.h): x from a to b, y = v × x, z = x × y.
  Eigen::Matrix3d member_local_axes(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                                    const Eigen::Vector3d &v);
} // namespace poundfe

#endif
