// 3D frame buildings with rigid floor diaphragms and hinges
// (include/poundfe/model/frame_building_3d.h; doc/theory.md §1.15).
#include <poundfe/model/frame_3d_assembler.h>
#include <poundfe/model/frame_building_3d.h>
#include <poundfe/model/model_builder.h>
#include <poundfe/model/plan_builder.h>
#include <poundfe/model/set_backs.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    /// The grid of a generated 3D frame on the parts of model/frame_3d_assembler.h.
    class FrameBuilder
    {
    public:
      FrameBuilder(Model &model, const BuildingParameters &p, const unsigned int b,
                   Building &building, const Point2 &centre)
          : model(model)
          , p(p)
          , building(building)
          , plan(site_plan(p, centre))
          , parts(model, p, b, building)
      {
      }

      void
      build()
      {
        building.left  = plan.centre.x - plan_half_width(p);
        building.right = plan.centre.x + plan_half_width(p);
        if (p.foundation.enabled())
          parts.add_foundation(plan.centre, 0.0, plan.angle);
        make_joints();
        for (unsigned int i = 1; i <= p.n_storeys; ++i)
          add_members(i);
      }

    private:
      const Model              &model;
      const BuildingParameters &p;
      Building                 &building;
      const SitePlan            plan;
      FrameAssembler3D          parts;
      // joints[level][line x][line y]
      std::vector<std::vector<std::vector<FrameJoint3D>>> joints;

      void
      make_floor(const unsigned int i, std::vector<std::vector<FrameJoint3D>> &level)
      {
        FrameSlab3D slab;
        slab.floor         = plan.building.floors[i - 1];
        slab.level         = level[0][0].position.z();
        slab.storey_height = value_for(p.storey_heights, i - 1);
        slab.outline       = slab_outline(p, plan, i);
        std::vector<FrameJoint3D *> present;
        for (auto &line : level)
          for (FrameJoint3D &j : line)
            if (j.present)
              present.push_back(&j);
        parts.make_floor(slab, present);
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
            std::vector<std::vector<FrameJoint3D>> level(xs.size(),
                                                         std::vector<FrameJoint3D>(ys.size()));
            const KeptGrid kept = kept_grid(p, std::max(i, 1u)); // the base: storey 1's
            for (unsigned int jx = 0; jx < xs.size(); ++jx)
              for (unsigned int jy = 0; jy < ys.size(); ++jy)
                {
                  const Point2 at        = plan.place({xs[jx], ys[jy]});
                  level[jx][jy].position = {at.x, at.y, z};
                  level[jx][jy].present  = kept.keeps(jx, jy);
                  if (i == 0)
                    parts.make_base(level[jx][jy]);
                }
            if (i > 0)
              make_floor(i, level);
            joints.push_back(level);
          }
      }

      /// The elastic sections of the columns of storey i and the beams of
      /// floor i; a fibre building's hold only their mass per length here
      /// (set_fibre_rigidities gives them their sections' rigidities).
      std::array<Section3D, 2>
      sections(const unsigned int i) const
      {
        if (p.fibre())
          {
            std::array<Section3D, 2> masses;
            masses[0].mass_per_length = value_for(p.column_mass_per_length, i - 1);
            masses[1].mass_per_length = value_for(p.beam_mass_per_length, i - 1);
            return masses;
          }
        // (E, G, A, Iy, Iz, J, Avy, Avz, mass per length) of storey i
        const auto section = [i](const std::array<const std::vector<double> *, 9> &v) {
          std::array<double, 9> x;
          for (unsigned int k = 0; k < 9; ++k)
            x[k] = value_for(*v[k], i - 1);
          return Section3D{x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8]};
        };
        return {{section({{&p.column_youngs_modulus, &p.column_shear_modulus, &p.column_area,
                           &p.column_second_moment, &p.column_second_moment_z,
                           &p.column_torsion_constant, &p.column_shear_area_y,
                           &p.column_shear_area_z, &p.column_mass_per_length}}),
                 section({{&p.beam_youngs_modulus, &p.beam_shear_modulus, &p.beam_area,
                           &p.beam_second_moment, &p.beam_second_moment_z,
                           &p.beam_torsion_constant, &p.beam_shear_area_y, &p.beam_shear_area_z,
                           &p.beam_mass_per_length}})}};
      }

      /// The columns of storey i and the beams of floor i (groups 2i-1, 2i).
      void
      add_members(const unsigned int i)
      {
        const auto           &below = joints[i - 1], &level = joints[i];
        const double          angle = plan.angle + p.column_angle * M_PI / 180;
        const Eigen::Vector3d column_axis(std::cos(angle), std::sin(angle), 0);
        const Eigen::Vector3d vertical(0, 0, 1);
        const auto [column, beam] = sections(i);
        const FibreMember column_fibre = fibre_member(model, p, i - 1, true);
        const FibreMember beam_fibre   = fibre_member(model, p, i - 1, false);
        // a fibre beam's section stands with its y axis (the depth of an RC
        // rectangle or I-shape, its top bars on +y) up: v = x × Z
        const auto beam_axis = [&](const FrameJoint3D &a, const FrameJoint3D &b) {
          return p.fibre() ? Eigen::Vector3d((b.position - a.position).cross(vertical).normalized()) :
                             vertical;
        };
        const std::string s = std::to_string(i) + ".";
        for (unsigned int jx = 0; jx < level.size(); ++jx)
          for (unsigned int jy = 0; jy < level[jx].size(); ++jy)
            {
              if (!level[jx][jy].present) // set back: no column, no beam from here
                continue;
              const std::string at = std::to_string(jx + 1) + "." + std::to_string(jy + 1);
              parts.add_member({{&below[jx][jy], &level[jx][jy]}}, column_axis, column,
                               MemberKind::column, 2 * i - 1, "C" + s + at, column_fibre);
              if (jx + 1 < level.size() && level[jx + 1][jy].present)
                parts.add_member({{&level[jx][jy], &level[jx + 1][jy]}},
                                 beam_axis(level[jx][jy], level[jx + 1][jy]), beam,
                                 MemberKind::beam, 2 * i, "BX" + s + at, beam_fibre);
              if (jy + 1 < level[jx].size() && level[jx][jy + 1].present)
                parts.add_member({{&level[jx][jy], &level[jx][jy + 1]}},
                                 beam_axis(level[jx][jy], level[jx][jy + 1]), beam,
                                 MemberKind::beam, 2 * i, "BY" + s + at, beam_fibre);
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
