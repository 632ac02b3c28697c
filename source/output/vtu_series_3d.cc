// The ParaView drawing of a 3D model (Model/Dimension = 3; doc/theory.md
// §10, "3D models"), in VTK's XML unstructured grid (Kitware, "VTK File
// Formats", VTK User's Guide 11th ed., ch. 19), site axes, z up:
//   - each 3D frame member a line between its end joints, each joint one
//     point shared by its members; point data: the joint's six motions
//     (displacement ux, uy, uz and rotation rx, ry, rz), read through the
//     member's map u_e = T_e q (doc/theory.md §1.15) without the hinges'
//     relative rotations α (those belong to the member end, not the joint);
//   - each rigid floor its slab outline as a polygon whose corners move with
//     the diaphragm, u = u_C + θ e_z × (X - C) (small rotations, §1.12), a
//     frame's corners being its corner joints, and its mass centre (the
//     master node) as a vertex;
//   - each storey of a torsionally coupled shear building a line between
//     the mass centres of its floors (the first from the ground below C_1);
//   - each gap in plan a line between the two floors' mass centres, with its
//     contact force and state, and a vertex at its point of contact: at rest
//     where it lies then (the corner of the overlap's end, or the column's
//     axis), in a time frame displaced to the element's contact point in the
//     deformed configuration (x_c(t) - x_c(0), so that Warp By Vector puts it
//     there), carrying the contact force on the gap's first building,
//     F ∂g/∂u_1 = F n (model/plan_contact_geometry.h), on a point lifted
//     above the contact point by `contact_arrow_lift` of the model's size
//     and joined to it by a line (the stem): a Glyph of `contact_force`
//     draws each hit as an arrow along the contact normal just above where
//     it happens, clear of the two slabs, which lie in the contact point's
//     plane and would hide an arrow drawn in it.
// Point data: displacement, rotation, node (the model node of a mass centre
// or of a joint's (uz, rx, ry); else -1), and in a time frame contact_force
// (N; zero but at the contact arrows' points);
//   - each integration point of a member on fibre sections a vertex on its
//     member's line at the rule's place (a Gauss-Lobatto end point is the
//     member's end point), moving as the straight line drawn between the
//     member's ends, u = (1 - ξ) u_1 + ξ u_2.
// Cell data: kind (0 member, 1
// storey, 2 gap, 4 slab, 5 mass centre, 6 contact point, 7 integration
// point, 8 contact arrow's stem), building and member ids
// (1-based; a slab's and a mass centre's floor number, a gap's number; an
// integration point's its member's), integration_point (1-based along its
// member), and in a time frame the member end forces in local axes (N, Vy,
// Vz, T, My, Mz) at each end (a fibre member's from its element's resisting
// forces: the elastic K u is wrong once it cracks), the gap force and
// contact (on its line, its vertex and its stem), and at the integration
// points the section states of output/section_states.h (section_N,
// section_Mz, axial_strain, curvature_z, the extreme fibre strains,
// section_My, curvature_y).
#include <poundfe/elements/frame_element_3d.h>
#include <poundfe/elements/member_element.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/model/plan_contact_geometry.h>
#include <poundfe/output/section_states.h>
#include <poundfe/output/storey_forces.h>
#include <poundfe/output/vtu_series.h>

#include "vtu_arrays.h"

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace vtu
  {
    VtuGeometry3D::VtuGeometry3D(const Model &model)
      : model(model)
      , master_point(model.n_nodes(), -1)
    {
      add_members();
      add_floors();
      add_gaps();
      std::array<double, 3> low{}, high{};
      for (unsigned int p = 0; p < points.size(); ++p)
        for (unsigned int c = 0; c < 3; ++c)
          {
            low[c]  = p == 0 ? points[p][c] : std::min(low[c], points[p][c]);
            high[c] = p == 0 ? points[p][c] : std::max(high[c], points[p][c]);
          }
      for (unsigned int c = 0; c < 3; ++c)
        model_size = std::max(model_size, high[c] - low[c]);
      add_contact_arrows(contact_arrow_lift * model_size);
      add_section_points();
    }

    void
    VtuGeometry3D::add_section_points()
    {
      section_points.first_cell = cells.types.size();
      for (unsigned int e = 0; e < model.members_3d.size(); ++e)
        {
          const Member3D &member = model.members_3d[e];
          if (!member.fibre.fibre() ||
              !dynamic_cast<const FibreSection *>(model.section_laws.at(member.fibre.section).get()))
            continue; // its element has no section states (ElementFrameStates::evaluate)
          section_members.push_back(e);
          const std::vector<double> xi = fibre_member_integration(member.fibre).points;
          for (unsigned int i = 0; i < xi.size(); ++i)
            {
              long point = xi[i] < 1e-12 ? member_ends[e][0] :
                           xi[i] > 1 - 1e-12 ? member_ends[e][1] : -1;
              if (point < 0) // on the member's line, moving with it
                {
                  Point3 at;
                  Motion motion;
                  for (unsigned int c = 0; c < 3; ++c)
                    at[c] = (1 - xi[i]) * member.ends[0][c] + xi[i] * member.ends[1][c];
                  for (unsigned int end = 0; end < 2; ++end)
                    for (unsigned int c = 0; c < 6; ++c)
                      for (const auto &[dof, a] : motions[member_ends[e][end]][c])
                        motion[c].emplace_back(dof, (end == 0 ? 1 - xi[i] : xi[i]) * a);
                  point = new_point(at, motion, -1);
                }
              cells.add({point}, vtk_vertex, section_point, member.building,
                        cells.members[e]);
              section_points.numbers.push_back(i + 1);
            }
        }
    }

    void
    VtuGeometry3D::add_contact_arrows(const double lift)
    {
      gap_arrow.assign(gap_point.size(), -1);
      gap_stem.assign(gap_point.size(), -1);
      for (unsigned int g = 0; g < gap_point.size(); ++g)
        if (const int p = gap_point[g]; p >= 0)
          {
            const Point3 at = points[p];
            gap_arrow[g]    = new_point({{at[0], at[1], at[2] + lift}}, {}, -1);
            gap_stem[g]     = cells.types.size();
            cells.add({p, gap_arrow[g]}, vtk_line, contact_arrow, model.gaps[g].buildings[0], g + 1);
          }
    }

    unsigned int
    VtuGeometry3D::new_point(const Point3 &at, const Motion &motion, const int node)
    {
      points.push_back(at);
      motions.push_back(motion);
      point_node.push_back(node);
      return points.size() - 1;
    }

    unsigned int
    VtuGeometry3D::point_at(const unsigned int b, const Point3 &at, const Motion &motion,
                            const int node)
    {
      // to the micrometre: a joint and a slab corner computed apart are one point
      const std::array<long long, 4> key{{b, std::llround(at[0] * 1e6), std::llround(at[1] * 1e6),
                                          std::llround(at[2] * 1e6)}};
      const auto [it, added] = point_index.emplace(key, points.size());
      if (added)
        new_point(at, motion, node);
      return it->second;
    }

    void
    VtuGeometry3D::add_members()
    {
      std::vector<unsigned int> hinge_dofs; // the α of the hinges: the member's, not the joint's
      for (const Hinge3D &h : model.hinges_3d)
        hinge_dofs.push_back(n_dofs_per_node * h.node + h.slot);
      std::vector<int> n_members(model.buildings.size(), 0);
      for (const Member3D &member : model.members_3d)
        {
          const unsigned int  n = member.dofs.size();
          std::array<long, 2> ends{};
          for (unsigned int k = 0; k < 2; ++k)
            {
              Motion motion;
              int    node = -1; // the joint's generalized node: its uz is that node's first DOF
              for (unsigned int c = 0; c < 6; ++c)
                for (unsigned int j = 0; j < n; ++j)
                  if (const double a = member.map[(6 * k + c) * n + j];
                      a != 0 && std::find(hinge_dofs.begin(), hinge_dofs.end(), member.dofs[j]) ==
                                  hinge_dofs.end())
                    {
                      motion[c].emplace_back(member.dofs[j], a);
                      if (c == 2)
                        node = member.dofs[j] / n_dofs_per_node;
                    }
              ends[k] = point_at(member.building, member.ends[k], motion, node);
            }
          member_ends.push_back(ends);
          cells.add({ends[0], ends[1]}, vtk_line, frame_element, member.building,
                    ++n_members[member.building]);
        }
    }

    void
    VtuGeometry3D::add_floors()
    {
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        {
          const Building &building = model.buildings[b];
          long            below    = -1; // the mass centre under the storey
          for (unsigned int i = 0; i < building.floors.size() && i < building.plan.size(); ++i)
            {
              if (building.floors[i].nodes.size() != 1)
                continue; // no diaphragm: the joints are the floor
              const unsigned int master = building.floors[i].nodes.front();
              const Point2      &C      = building.plan[i].mass_centre;
              const double       z      = building.floors[i].level;
              const auto         rigid  = [&](const Point2 &x) {
                const unsigned int theta = Model::dof(master, Component::rz);
                Motion             m;
                m[0] = {{Model::dof(master, Component::ux), 1.0}, {theta, -(x.y - C.y)}};
                m[1] = {{Model::dof(master, Component::uy), 1.0}, {theta, x.x - C.x}};
                m[5] = {{theta, 1.0}};
                return m;
              };
              const unsigned int centre = new_point({{C.x, C.y, z}}, rigid(C), master);
              master_point[master]      = centre;
              cells.add({centre}, vtk_vertex, mass_centre, b, i + 1);
              std::vector<long> corners;
              for (const Point2 &x : building.plan[i].outline)
                corners.push_back(point_at(b, {{x.x, x.y, z}}, rigid(x), -1));
              cells.add(corners, vtk_polygon, slab, b, i + 1);
              if (building.type != BuildingType::shear)
                continue;
              if (below < 0) // the ground under the first floor's mass centre
                below = new_point({{C.x, C.y, building.base_level}}, {}, -1);
              cells.add({below, centre}, vtk_line, storey, b, i + 1);
              below = centre;
            }
        }
    }

    void
    VtuGeometry3D::add_gaps()
    {
      for (unsigned int g = 0; g < model.gaps.size(); ++g)
        {
          const std::array<int, 2> &ends = model.gaps[g].nodes;
          add_contact_point(g);
          gap_cell.push_back(-1);
          if (ends[0] < 0 || ends[1] < 0 || master_point[ends[0]] < 0 || master_point[ends[1]] < 0)
            continue; // a barrier or a floor without a diaphragm: not drawn
          gap_cell.back() = cells.types.size();
          cells.add({master_point[ends[0]], master_point[ends[1]]}, vtk_line, gap,
                    model.gaps[g].buildings[0], g + 1);
        }
    }

    void
    VtuGeometry3D::add_contact_point(const unsigned int g)
    {
      const Gap &gap = model.gaps[g];
      gap_point.push_back(-1);
      gap_vertex.push_back(-1);
      if (!gap.in_plan && !gap.on_column)
        return;
      Point2 rest = gap.column.column_point;
      if (gap.in_plan)
        {
          const PlanContactState state = plan_contact_state(gap.plan, Vector6::Zero());
          // out of reach at rest (edges that do not overlap yet): the end of
          // the first floor's edge stands in until a frame has the point
          rest = state.defined ? state.point : gap.plan.edges[0][gap.plan.end];
        }
      gap_point.back()  = new_point({{rest.x, rest.y, gap.level}}, {}, -1);
      gap_vertex.back() = cells.types.size();
      cells.add({gap_point.back()}, vtk_vertex, contact_point, gap.buildings[0], g + 1);
    }

    std::vector<std::array<double, 3>>
    VtuGeometry3D::contact_points(const ElementFrameStates &states, const double scale,
                                  std::vector<std::array<double, 6>> &d) const
    {
      using State = ElementFrameStates;
      std::vector<std::array<double, 3>> force(points.size(), std::array<double, 3>{});
      unsigned int                       g = 0;
      for (unsigned int h = 0; h < states.kinds.size(); ++h)
        if (states.kinds[h] == ElementKind::gap)
          if (const int p = gap_point.at(g++); p >= 0)
            {
              if (states(h, State::in_reach) == 0)
                continue; // the rest point, no force
              const std::array<double, 2> x{{states(h, State::point_x), states(h, State::point_y)}};
              const std::array<double, 2> f{{states(h, State::force_x), states(h, State::force_y)}};
              const int                   arrow = gap_arrow.at(g - 1); // moves with its point
              for (unsigned int c = 0; c < 2; ++c)
                {
                  d[p][c]         = scale * (x[c] - points[p][c]);
                  d[arrow][c]     = d[p][c];
                  force[arrow][c] = f[c];
                }
            }
      return force;
    }

    double
    VtuGeometry3D::value(const Combination &combination, const Vector &u) const
    {
      double sum = 0;
      for (const auto &[dof, coefficient] : combination)
        if (const int e = model.equation(dof); e >= 0)
          sum += coefficient * u[e];
      return sum;
    }

    double
    VtuGeometry3D::largest_translation(const Vector &u) const
    {
      double largest = 0;
      for (const Motion &m : motions)
        largest = std::max(largest, std::hypot(value(m[0], u), value(m[1], u), value(m[2], u)));
      return largest;
    }

    void
    VtuGeometry3D::time_arrays(const Vector &u, const ElementFrameStates &states,
                               FieldFrame &frame) const
    {
      const unsigned int n_cells = cells.types.size();
      FieldArray         start{"end_forces_start", 6, false, false, {}};
      FieldArray         end{"end_forces_end", 6, false, false, {}};
      start.values.assign(6 * n_cells, 0.0);
      end.values.assign(6 * n_cells, 0.0);
      for (unsigned int e = 0; e < model.members_3d.size(); ++e) // the first cells
        {
          const Member3D &member = model.members_3d[e];
          using Point            = Eigen::Map<const Eigen::Vector3d>;
          const FrameElement3D element(Point(member.ends[0].data()), Point(member.ends[1].data()),
                                       Point(member.orientation.data()), member.section);
          const Vector12 f =
            element.local_end_forces(member_3d_end_displacements(model, member, u)) +
            element.rotation() * self_weight_end_forces(member);
          for (unsigned int k = 0; k < 6; ++k)
            {
              start.values[6 * e + k] = f[k];
              end.values[6 * e + k]   = f[6 + k];
            }
        }
      set_fibre_end_forces(states, start, end);
      FieldArray   force{"force", 1, false, false, std::vector<double>(n_cells, 0.0)};
      FieldArray   contact{"contact", 1, true, false, std::vector<double>(n_cells, 0.0)};
      unsigned int g = 0;
      for (unsigned int h = 0; h < states.kinds.size(); ++h)
        if (states.kinds[h] == ElementKind::gap)
          {
            for (const int cell : {gap_cell.at(g), gap_vertex.at(g), gap_stem.at(g)})
              if (cell >= 0)
                {
                  force.values[cell]   = states(h, ElementFrameStates::force);
                  contact.values[cell] = states(h, ElementFrameStates::active) != 0;
                }
            ++g;
          }
      for (FieldArray *array : {&start, &end, &force, &contact})
        frame.cell.push_back(std::move(*array));
      add_section_arrays(states, frame);
    }

    std::size_t
    VtuGeometry3D::first_member_force(const ElementFrameStates &states) const
    {
      constexpr unsigned int n_values = n_section_state_entries + 2; // in space
      const std::size_t      first    = ElementFrameStates::n_entries * states.kinds.size() +
                                 n_values * section_points.numbers.size();
      AssertThrow(states.values.size() == first + 12 * section_members.size(),
                  dealii::ExcMessage(
                    "the fibre members' integration points and their drawing differ"));
      return first;
    }

    void
    VtuGeometry3D::set_fibre_end_forces(const ElementFrameStates &states, FieldArray &start,
                                        FieldArray &end) const
    {
      const std::size_t first = first_member_force(states);
      using Point             = Eigen::Map<const Eigen::Vector3d>;
      for (std::size_t k = 0; k < section_members.size(); ++k)
        {
          const unsigned int   e      = section_members[k];
          const Member3D      &member = model.members_3d[e];
          const FrameElement3D element(Point(member.ends[0].data()), Point(member.ends[1].data()),
                                       Point(member.orientation.data()), member.section);
          const Vector12 f =
            element.rotation() * Eigen::Map<const Vector12>(&states.values[first + 12 * k]);
          for (unsigned int c = 0; c < 6; ++c)
            {
              start.values[6 * e + c] = f[c];
              end.values[6 * e + c]   = f[6 + c];
            }
        }
    }

    void
    VtuGeometry3D::add_section_arrays(const ElementFrameStates &states, FieldFrame &frame) const
    {
      if (section_points.numbers.empty())
        return;
      first_member_force(states); // checks the sizes
      // section_state_values' order in space
      section_points.add_arrays({"section_N", "section_Mz", "axial_strain", "curvature_z",
                                 "concrete_strain", "steel_strain_max", "steel_strain_min",
                                 "section_My", "curvature_y"},
                                states.values, ElementFrameStates::n_entries * states.kinds.size(),
                                cells.types.size(), frame);
    }

    FieldFrame
    VtuGeometry3D::frame(const Vector &u, const double scale,
                         const ElementFrameStates *states) const
    {
      std::vector<std::array<double, 6>> d(points.size());
      for (unsigned int p = 0; p < points.size(); ++p)
        for (unsigned int c = 0; c < 6; ++c)
          d[p][c] = scale * value(motions[p][c], u);
      const std::vector<std::array<double, 3>> contact_force =
        states ? contact_points(*states, scale, d) : std::vector<std::array<double, 3>>{};
      FieldFrame frame;
      for (const unsigned int first : {0u, 3u})
        {
          FieldArray motion{first == 0 ? "displacement" : "rotation", 3, false, false, {}};
          motion.values.reserve(3 * d.size());
          for (const auto &m : d)
            motion.values.insert(motion.values.end(), m.begin() + first, m.begin() + first + 3);
          frame.point.push_back(std::move(motion));
        }
      frame.point.push_back(
        {"node", 1, true, true, std::vector<double>(point_node.begin(), point_node.end())});
      if (states != nullptr)
        {
          FieldArray force{"contact_force", 3, false, false, {}};
          for (const auto &f : contact_force)
            force.values.insert(force.values.end(), f.begin(), f.end());
          frame.point.push_back(std::move(force));
        }
      frame.cell = cell_id_arrays(cells);
      if (!section_points.numbers.empty())
        frame.cell.push_back(section_points.number_array(cells.types.size()));
      if (states != nullptr)
        time_arrays(u, *states, frame);
      return frame;
    }
  } // namespace vtu
} // namespace poundfe
