// 3D frame buildings with rigid floor diaphragms and hinges
// (include/poundfe/model/frame_building_3d.h; doc/theory.md §1.15).
#include <poundfe/model/frame_building_3d.h>
#include <poundfe/model/plan_builder.h>
#include <poundfe/model/plan_foundation.h>
#include <poundfe/model/set_backs.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>

namespace poundfe
{
  namespace
  {
    /// The model nodes that carry a joint's motion: `h` its (ux, uy, rz),
    /// `v` its (uz, rx, ry) (a generalized node), or the floor's `master`
    /// at `centre` (a rigid diaphragm); -1: none (the ground). A column
    /// base on a compliant foundation (`on_basemat`): `master` is the
    /// basemat's node at its centre and `v` its rocking node, and the joint
    /// moves rigidly with it (model/plan_foundation.h). A joint of a grid
    /// line its storey's set-back removed is absent.
    struct Joint
    {
      Eigen::Vector3d position;
      int             h = -1, v = -1, master = -1;
      Point2          centre;
      bool            on_basemat = false;
      bool            present    = true;
    };

    /// One row of T: model DOF -> coefficient.
    using Row = std::map<unsigned int, double>;

    /// The rows of T of a joint's six DOFs (ux, uy, uz, rx, ry, rz).
    std::array<Row, 6>
    joint_rows(const Joint &j)
    {
      std::array<Row, 6> rows;
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

    /// The member's local axes (rows x, y, z; OpenSees's convention, as
    /// elements/frame_element_3d.h): x along it, y = v × x, z = x × y.
    Eigen::Matrix3d
    local_axes(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &v)
    {
      Eigen::Matrix3d       axes;
      const Eigen::Vector3d x = (b - a).normalized();
      const Eigen::Vector3d y = v.cross(x).normalized();
      axes.row(0)             = x.transpose();
      axes.row(1)             = y.transpose();
      axes.row(2)             = x.cross(y).transpose();
      return axes;
    }

    class FrameBuilder
    {
    public:
      FrameBuilder(Model &model, const BuildingParameters &p, const unsigned int b,
                   Building &building, const Point2 &centre)
          : model(model)
          , p(p)
          , b(b)
          , building(building)
          , plan(site_plan(p, centre))
          , rigid(p.diaphragm == "rigid")
      {
      }

      void
      build()
      {
        building.left  = plan.centre.x - plan_half_width(p);
        building.right = plan.centre.x + plan_half_width(p);
        if (p.foundation.enabled())
          {
            basemat = add_node({plan.centre.x, 0.0}, false);
            rocking = add_plan_foundation(model, p.foundation, b, basemat, plan.angle, true);
          }
        make_joints();
        for (unsigned int i = 1; i <= p.n_storeys; ++i)
          add_members(i);
      }

    private:
      Model                    &model;
      const BuildingParameters &p;
      const unsigned int        b;
      Building                 &building;
      const SitePlan            plan;
      const bool                rigid;
      int                       basemat = -1, rocking = -1; // a compliant foundation's nodes
      // joints[level][line x][line y]
      std::vector<std::vector<std::vector<Joint>>> joints;

      unsigned int
      add_node(const Point2 &position, const bool generalized)
      {
        Node node;
        node.position    = position;
        node.building    = b;
        node.generalized = generalized;
        model.nodes.push_back(node);
        return model.nodes.size() - 1;
      }

      void
      make_base(Joint &j)
      {
        if (basemat >= 0)
          {
            j.master     = basemat;
            j.centre     = plan.centre;
            j.v          = rocking;
            j.on_basemat = true;
            return;
          }
        if (p.base_fixity == BaseFixity::fixed)
          return; // clamped: every DOF is the ground
        const Point2 at{j.position.x(), j.position.z()};
        j.h                    = add_node(at, false);
        j.v                    = add_node(at, true);
        model.nodes[j.v].joint_translation_z = true;
        model.nodes[j.h].fixed = {{true, true, false}};
        model.nodes[j.v].fixed = {{true, false, false}};
      }

      void
      make_floor(const unsigned int i, std::vector<std::vector<Joint>> &level)
      {
        const TorsionalFloor &f       = plan.building.floors[i - 1];
        unsigned int          n_joint = 0;
        for (const auto &line : level)
          n_joint += std::count_if(line.begin(), line.end(),
                                   [](const Joint &j) { return j.present; });
        Floor                 floor;
        floor.level         = level[0][0].position.z();
        floor.storey_height = value_for(p.storey_heights, i - 1);
        if (rigid)
          {
            const unsigned int master = add_node({f.mass_centre.x, floor.level}, false);
            model.masses.push_back({master, f.mass, f.polar_moment});
            floor.nodes = {master};
          }
        for (auto &line : level)
          for (Joint &j : line)
            {
              if (!j.present)
                continue;
              const Point2 at{j.position.x(), j.position.z()};
              if (rigid)
                {
                  j.master = floor.nodes.front();
                  j.centre = f.mass_centre;
                }
              else
                {
                  j.h = add_node(at, false);
                  model.masses.push_back({unsigned(j.h), f.mass / n_joint, 0});
                  floor.nodes.push_back(j.h);
                }
              j.v = add_node(at, true);
              model.nodes[j.v].joint_translation_z = true;
              model.dof_masses.push_back({n_dofs_per_node * unsigned(j.v), f.mass / n_joint}); // uz
            }
        building.floors.push_back(floor);
        building.plan.push_back({f.mass_centre, slab_outline(p, plan, i)});
      }

      void
      make_joints()
      {
        const std::vector<double> xs = grid_lines(p.bay_widths, p.n_bays);
        const std::vector<double> ys = grid_lines(p.bay_widths_y, p.n_bays_y);
        double                    z  = 0;
        for (unsigned int i = 0; i <= p.n_storeys; ++i)
          {
            if (i > 0)
              z += value_for(p.storey_heights, i - 1);
            std::vector<std::vector<Joint>> level(xs.size(), std::vector<Joint>(ys.size()));
            const KeptGrid kept = kept_grid(p, std::max(i, 1u)); // the base: storey 1's
            for (unsigned int jx = 0; jx < xs.size(); ++jx)
              for (unsigned int jy = 0; jy < ys.size(); ++jy)
                {
                  const Point2 at        = plan.place({xs[jx], ys[jy]});
                  level[jx][jy].position = {at.x, at.y, z};
                  level[jx][jy].present  = kept.keeps(jx, jy);
                  if (i == 0)
                    make_base(level[jx][jy]);
                }
            if (i > 0)
              make_floor(i, level);
            joints.push_back(level);
          }
      }

      bool
      wants_hinge(const char *location) const
      {
        return std::find(p.hinge_locations.begin(), p.hinge_locations.end(), location) !=
               p.hinge_locations.end();
      }

      /// Whether end k of a member of `kind` in `group` gets a hinge.
      bool
      hinged(const MemberKind kind, const unsigned int group, const unsigned int k,
             const Joint &joint, unsigned int &group_index) const
      {
        if (p.hinge_locations.empty())
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

      /// A hinge node at end k of `member` (axes its local axes): adds
      /// α_y e_y + α_z e_z to the end's rotations and a Bouc-Wen element
      /// on each α.
      void
      add_hinge(Member3D &member, const unsigned int k, const unsigned int group_index,
                const Eigen::Matrix3d &axes, std::array<Row, 6> &rows)
      {
        const Point2       at{member.ends[k][0], member.ends[k][2]};
        const unsigned int node = add_node(at, true);
        model.nodes[node].fixed = {{false, false, true}};
        const double length =
            std::hypot(member.ends[1][0] - member.ends[0][0], member.ends[1][1] - member.ends[0][1],
                       member.ends[1][2] - member.ends[0][2]);
        const char *where = member.kind == MemberKind::column ? (k == 0 ? "_bottom" : "_top")
                                                              : (k == 0 ? "_start" : "_end");
        for (unsigned int a = 0; a < 2; ++a)
          {
            const Eigen::Vector3d e = axes.row(1 + a).transpose();
            for (unsigned int c = 0; c < 3; ++c)
              rows[3 + c][n_dofs_per_node * node + a] = e[c];
            const double second_moment =
                a == 0 ? member.section.second_moment_y : member.section.second_moment_z;
            const double k_given      = value_for(p.hinge_stiffnesses, group_index);
            const double stiffness    = k_given > 0 ? k_given
                                                    : p.hinge_stiffness_factor * 6 *
                                                       member.section.youngs_modulus *
                                                       second_moment / length;
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
            hinge.law.yield_deformation = yield_moment > 0
                                              ? yield_moment / stiffness
                                              : value_for(p.hinge_yield_rotations, group_index);
            model.hinges_3d.push_back(hinge);
          }
      }

      void
      add_member(const std::array<const Joint *, 2> &ends, const Eigen::Vector3d &orientation,
                 const Section3D &section, const MemberKind kind, const unsigned int group,
                 const std::string &label)
      {
        Member3D member;
        member.section  = section;
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
        const Eigen::Matrix3d axes = local_axes(ends[0]->position, ends[1]->position, orientation);
        std::array<Row, 12>   rows;
        for (unsigned int k = 0; k < 2; ++k)
          {
            std::array<Row, 6> end         = joint_rows(*ends[k]);
            unsigned int       group_index = 0;
            if (hinged(kind, group, k, *ends[k], group_index))
              add_hinge(member, k, group_index, axes, end);
            std::copy(end.begin(), end.end(), rows.begin() + 6 * k);
          }
        for (const Row &row : rows)
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

      /// The columns of storey i and the beams of floor i (groups 2i-1, 2i).
      void
      add_members(const unsigned int i)
      {
        const auto           &below = joints[i - 1], &level = joints[i];
        const double          angle = plan.angle + p.column_angle * M_PI / 180;
        const Eigen::Vector3d column_axis(std::cos(angle), std::sin(angle), 0);
        const Eigen::Vector3d vertical(0, 0, 1);
        // (E, G, A, Iy, Iz, J, Avy, Avz, mass per length) of storey i
        const auto section = [i](const std::array<const std::vector<double> *, 9> &v) {
          std::array<double, 9> x;
          for (unsigned int k = 0; k < 9; ++k)
            x[k] = value_for(*v[k], i - 1);
          return Section3D{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8]};
        };
        const Section3D column = section(
          {{&p.column_youngs_modulus, &p.column_shear_modulus, &p.column_area,
            &p.column_second_moment, &p.column_second_moment_z, &p.column_torsion_constant,
            &p.column_shear_area_y, &p.column_shear_area_z, &p.column_mass_per_length}});
        const Section3D beam =
          section({{&p.beam_youngs_modulus, &p.beam_shear_modulus, &p.beam_area,
                    &p.beam_second_moment, &p.beam_second_moment_z, &p.beam_torsion_constant,
                    &p.beam_shear_area_y, &p.beam_shear_area_z, &p.beam_mass_per_length}});
        const std::string s = std::to_string(i) + ".";
        for (unsigned int jx = 0; jx < level.size(); ++jx)
          for (unsigned int jy = 0; jy < level[jx].size(); ++jy)
            {
              if (!level[jx][jy].present) // set back: no column, no beam from here
                continue;
              const std::string at = std::to_string(jx + 1) + "." + std::to_string(jy + 1);
              add_member({{&below[jx][jy], &level[jx][jy]}}, column_axis, column,
                         MemberKind::column, 2 * i - 1, "C" + s + at);
              if (jx + 1 < level.size() && level[jx + 1][jy].present)
                add_member({{&level[jx][jy], &level[jx + 1][jy]}}, vertical, beam, MemberKind::beam,
                           2 * i, "BX" + s + at);
              if (jy + 1 < level[jx].size() && level[jx][jy + 1].present)
                add_member({{&level[jx][jy], &level[jx][jy + 1]}}, vertical, beam, MemberKind::beam,
                           2 * i, "BY" + s + at);
            }
      }
    };
  } // namespace

  void
  build_frame_3d(Model &model, const BuildingParameters &p, const unsigned int b,
                 Building &building, const Point2 &centre)
  {
    FrameBuilder(model, p, b, building, centre).build();
  }
} // namespace poundfe
