// The parts of a 3D frame building: joints, rigid floors, members, hinges
// (include/poundfe/model/frame_3d_assembler.h; doc/theory.md §1.15).
#include <poundfe/model/frame_3d_assembler.h>
#include <poundfe/model/plan_builder.h>
#include <poundfe/model/plan_foundation.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  Eigen::Matrix3d
  member_local_axes(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &v)
  {
    Eigen::Matrix3d       axes;
    const Eigen::Vector3d x = (b - a).normalized();
    const Eigen::Vector3d y = v.cross(x).normalized();
    axes.row(0)             = x.transpose();
    axes.row(1)             = y.transpose();
    axes.row(2)             = x.cross(y).transpose();
    return axes;
  }

  FrameAssembler3D::FrameAssembler3D(Model &model, const BuildingParameters &p,
                                     const unsigned int b, Building &building)
      : model(model)
      , p(p)
      , b(b)
      , building(building)
      , rigid(p.diaphragm == "rigid")
  {
  }

  unsigned int
  FrameAssembler3D::add_node(const Point2 &position, const bool generalized)
  {
    Node node;
    node.position    = position;
    node.building    = b;
    node.generalized = generalized;
    model.nodes.push_back(node);
    return model.nodes.size() - 1;
  }

  void
  FrameAssembler3D::add_foundation(const Point2 &centre, const double level, const double angle)
  {
    basemat        = add_node({centre.x, level}, false);
    basemat_centre = centre;
    rocking        = add_plan_foundation(model, p.foundation, b, basemat, angle, true);
  }

  FrameAssembler3D::Rows
  FrameAssembler3D::joint_rows(const FrameJoint3D &j) const
  {
    Rows rows;
    if (j.h >= 0)
      {
        rows[0][Model::dof(j.h, Component::ux)] = 1;
        rows[1][Model::dof(j.h, Component::uy)] = 1;
        rows[5][Model::dof(j.h, Component::rz)] = 1;
      }
    else if (j.master >= 0)
      {
        const unsigned int theta                     = Model::dof(j.master, Component::rz);
        rows[0][Model::dof(j.master, Component::ux)] = 1;
        rows[0][theta]                               = -(j.position.y() - j.centre.y);
        rows[1][Model::dof(j.master, Component::uy)] = 1;
        rows[1][theta]                               = j.position.x() - j.centre.x;
        rows[5][theta]                               = 1;
      }
    if (j.v >= 0)
      for (unsigned int c = 0; c < 3; ++c)
        rows[2 + c][n_dofs_per_node * j.v + c] = 1;
    if (j.on_basemat) // u_z = u_0z + θ_x (y - O_y) - θ_y (x - O_x)
      {
        rows[2][n_dofs_per_node * j.v + 1] = j.position.y() - j.centre.y;
        rows[2][n_dofs_per_node * j.v + 2] = -(j.position.x() - j.centre.x);
      }
    return rows;
  }

  void
  FrameAssembler3D::make_base(FrameJoint3D &j)
  {
    if (basemat >= 0)
      {
        j.master     = basemat;
        j.centre     = basemat_centre;
        j.v          = rocking;
        j.on_basemat = true;
        return;
      }
    if (p.base_fixity == BaseFixity::fixed)
      return; // clamped: every DOF is the ground
    const Point2 at{j.position.x(), j.position.z()};
    j.h                                  = add_node(at, false);
    j.v                                  = add_node(at, true);
    model.nodes[j.v].joint_translation_z = true;
    model.nodes[j.h].fixed               = {{true, true, false}};
    model.nodes[j.v].fixed               = {{true, false, false}};
  }

  void
  FrameAssembler3D::make_floor(const FrameSlab3D &slab, const std::vector<FrameJoint3D *> &joints)
  {
    const TorsionalFloor &f       = slab.floor;
    const unsigned int    n_joint = joints.size();
    Floor                 floor;
    floor.level         = slab.level;
    floor.storey_height = slab.storey_height;
    if (rigid)
      {
        const unsigned int master = add_node({f.mass_centre.x, floor.level}, false);
        model.masses.push_back({master, f.mass, f.polar_moment});
        floor.nodes = {master};
      }
    for (FrameJoint3D *j : joints)
      {
        const Point2 at{j->position.x(), j->position.z()};
        if (rigid)
          {
            j->master = floor.nodes.front();
            j->centre = f.mass_centre;
          }
        else
          {
            j->h = add_node(at, false);
            model.masses.push_back({unsigned(j->h), f.mass / n_joint, 0});
            floor.nodes.push_back(j->h);
          }
        j->v                                  = add_node(at, true);
        model.nodes[j->v].joint_translation_z = true;
        // uz: its share of the floor's weight always, of its inertia unless
        // Vertical floor mass = none
        model.dof_masses.push_back(
          {n_dofs_per_node * unsigned(j->v), f.mass / n_joint, p.vertical_floor_mass == "joints"});
      }
    building.floors.push_back(floor);
    building.plan.push_back({f.mass_centre, slab.outline});
  }

  void
  FrameAssembler3D::make_free_joint(FrameJoint3D &j)
  {
    const Point2 at{j.position.x(), j.position.z()};
    j.h                                  = add_node(at, false);
    j.v                                  = add_node(at, true);
    model.nodes[j.v].joint_translation_z = true;
  }

  bool
  FrameAssembler3D::wants_hinge(const char *location) const
  {
    return std::find(p.hinge_locations.begin(), p.hinge_locations.end(), location) !=
           p.hinge_locations.end();
  }

  /// Whether end k of a member of `kind` in `group` gets a hinge.
  bool
  FrameAssembler3D::hinged(const MemberKind kind, const unsigned int group, const unsigned int k,
                           const FrameJoint3D &joint, unsigned int &group_index) const
  {
    if (p.hinge_locations.empty() || kind == MemberKind::other)
      return false;
    group_index = 0;
    if (!p.hinge_groups.empty())
      {
        const auto it = std::find(p.hinge_groups.begin(), p.hinge_groups.end(), group);
        if (it == p.hinge_groups.end())
          return false;
        group_index = it - p.hinge_groups.begin();
      }
    const bool on_ground = (joint.h < 0 && joint.master < 0) || joint.on_basemat;
    if (joint.h >= 0 && model.nodes[joint.h].fixed[0])
      return false; // a pinned support already releases the rotations
    if (kind == MemberKind::beam)
      return wants_hinge("beam ends");
    return wants_hinge("column ends") || (k == 1 && wants_hinge("column tops")) ||
           (k == 0 && on_ground && wants_hinge("column bases"));
  }

  /// A hinge node at end k of `member` (axes its local axes): adds α_y e_y +
  /// α_z e_z to the end's rotations and a Bouc-Wen element on each α.
  void
  FrameAssembler3D::add_hinge(Member3D &member, const unsigned int k,
                              const unsigned int group_index, const Eigen::Matrix3d &axes,
                              Rows &rows)
  {
    const Point2       at{member.ends[k][0], member.ends[k][2]};
    const unsigned int node = add_node(at, true);
    model.nodes[node].fixed = {{false, false, true}};
    const double length =
      std::hypot(member.ends[1][0] - member.ends[0][0], member.ends[1][1] - member.ends[0][1],
                 member.ends[1][2] - member.ends[0][2]);
    const char *where = member.kind == MemberKind::column ? (k == 0 ? "_bottom" : "_top") :
                                                            (k == 0 ? "_start" : "_end");
    for (unsigned int a = 0; a < 2; ++a)
      {
        const Eigen::Vector3d e = axes.row(1 + a).transpose();
        for (unsigned int c = 0; c < 3; ++c)
          rows[3 + c][n_dofs_per_node * node + a] = e[c];
        const double second_moment =
          a == 0 ? member.section.second_moment_y : member.section.second_moment_z;
        const double k_given      = value_for(p.hinge_stiffnesses, group_index);
        const double stiffness    = k_given > 0 ? k_given :
                                                  p.hinge_stiffness_factor * 6 *
                                                 member.section.youngs_modulus * second_moment /
                                                 length;
        const double yield_moment = value_for(p.hinge_yield_moments, group_index);
        Hinge3D      hinge;
        hinge.node                  = node;
        hinge.slot                  = a;
        hinge.building              = b;
        hinge.member                = model.members_3d.size(); // pushed after its hinges
        hinge.label                 = member.label + where + (a == 0 ? "_y" : "_z");
        hinge.biaxial               = p.hinge_biaxial;
        hinge.law                   = p.hysteresis;
        hinge.law.stiffness         = stiffness;
        hinge.law.yield_deformation = yield_moment > 0 ?
                                        yield_moment / stiffness :
                                        value_for(p.hinge_yield_rotations, group_index);
        model.hinges_3d.push_back(hinge);
      }
  }

  void
  FrameAssembler3D::add_member(const std::array<const FrameJoint3D *, 2> &ends,
                               const Eigen::Vector3d &orientation, const Section3D &section,
                               const MemberKind kind, const unsigned int group,
                               const std::string &label, const FibreMember &fibre)
  {
    Member3D member;
    member.section  = section;
    member.fibre    = fibre;
    member.building = b;
    member.group    = group;
    member.kind     = kind;
    member.label    = building.name + "_" + label;
    for (unsigned int c = 0; c < 3; ++c)
      {
        member.ends[0][c]     = ends[0]->position[c];
        member.ends[1][c]     = ends[1]->position[c];
        member.orientation[c] = orientation[c];
      }
    const Eigen::Matrix3d axes =
      member_local_axes(ends[0]->position, ends[1]->position, orientation);
    std::array<std::map<unsigned int, double>, 12> rows;
    for (unsigned int k = 0; k < 2; ++k)
      {
        Rows         end         = joint_rows(*ends[k]);
        unsigned int group_index = 0;
        if (hinged(kind, group, k, *ends[k], group_index))
          add_hinge(member, k, group_index, axes, end);
        std::copy(end.begin(), end.end(), rows.begin() + 6 * k);
      }
    for (const auto &row : rows)
      for (const auto &[dof, coefficient] : row)
        if (std::find(member.dofs.begin(), member.dofs.end(), dof) == member.dofs.end())
          member.dofs.push_back(dof);
    const unsigned int n = member.dofs.size();
    member.map.assign(12 * n, 0);
    for (unsigned int i = 0; i < 12; ++i)
      for (const auto &[dof, coefficient] : rows[i])
        member.map[i * n + (std::find(member.dofs.begin(), member.dofs.end(), dof) -
                            member.dofs.begin())] = coefficient;
    model.members_3d.push_back(member);
  }
} // namespace poundfe
