// The floor-to-column contacts of a 3D model (model/plan_builder.h's
// add_column_contacts; geometry in model/column_contact_geometry.h,
// doc/theory.md §1.13): a slab at a level where a 3D frame neighbour has no
// floor touches the neighbour's perimeter columns that face its edge.
#include <poundfe/model/column_contact_geometry.h>
#include <poundfe/model/floor_mass.h>
#include <poundfe/model/plan_builder.h>
#include <poundfe/model/plan_contact_geometry.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace
  {
    double column_dot(const Point2 &a, const Point2 &b) { return a.x * b.x + a.y * b.y; }
    Point2 column_minus(const Point2 &a, const Point2 &b) { return {a.x - b.x, a.y - b.y}; }

    /// The outward normals of the edges of `outline` that the point x lies
    /// on (two at a corner; none inside).
    std::vector<Point2>
    normals_of_edges_through(const std::vector<Point2> &outline, const Point2 &x)
    {
      std::vector<Point2> normals;
      for (unsigned int i = 0; i < outline.size(); ++i)
        {
          const Point2 &a = outline[i], &b = outline[(i + 1) % outline.size()];
          const Point2  t = column_minus(b, a);
          const double  length2 = column_dot(t, t), along = column_dot(column_minus(x, a), t) / length2;
          const Point2  n       = outward_normal(a, b);
          if (along >= -1e-9 && along <= 1 + 1e-9 &&
              std::abs(column_dot(column_minus(x, a), n)) <= 1e-9 * std::sqrt(length2))
            normals.push_back(n);
        }
      return normals;
    }

    /// The floor of building b at `level`, or nullptr.
    const Floor *
    frame_floor_at(const Building &b, const double level)
    {
      for (const Floor &f : b.floors)
        if (std::abs(f.level - level) <= 1e-9 * std::max(1.0, level))
          return &f;
      return nullptr;
    }

    /// The slab edge of `outline` nearest to the column point P that faces
    /// the column's own edge (outward normal `column_normal`) with P in
    /// front of it and between its ends; false when there is none.
    bool
    facing_slab_edge(const std::vector<Point2> &outline, const Point2 &column_point,
                     const Point2 &column_normal, std::array<Point2, 2> &edge)
    {
      double nearest = 1e300;
      for (unsigned int i = 0; i < outline.size(); ++i)
        {
          const Point2 &a = outline[i], &b = outline[(i + 1) % outline.size()];
          const Point2  n = outward_normal(a, b), t = column_minus(b, a);
          const double  gap = column_dot(column_minus(column_point, a), n);
          const double  along = column_dot(column_minus(column_point, a), t) / column_dot(t, t);
          if (column_dot(n, column_normal) < -0.5 && gap >= 0 && along >= 0 && along <= 1 &&
              gap < nearest)
            {
              nearest = gap;
              edge    = {{a, b}};
            }
        }
      return nearest < 1e300;
    }

    /// The contacts of the slabs of building a with the columns of building b.
    void
    add_slab_to_columns(Model &model, const ContactParameters &contact, const unsigned int a,
                        const unsigned int b)
    {
      const Building &slabs = model.buildings[a], &frame = model.buildings[b];
      for (const Member3D &column : model.members_3d)
        {
          if (column.building != b || column.kind != MemberKind::column)
            continue;
          const double  z0 = column.ends[0][2], z1 = column.ends[1][2];
          const Floor  *top = frame_floor_at(frame, z1);
          if (top == nullptr)
            continue;
          const Point2 point{column.ends[0][0], column.ends[0][1]};
          const std::vector<Point2> column_normals =
            normals_of_edges_through(frame.plan[top - frame.floors.data()].outline, point);
          // none: an inner column, which the slab reaches after the perimeter
          for (unsigned int i = 0; i < slabs.floors.size(); ++i)
            {
              const double level = slabs.floors[i].level;
              const double tolerance = 1e-6 * std::max(1.0, level);
              if (!(level > z0 + tolerance && level < z1 - tolerance))
                continue;
              Gap gap;
              if (std::none_of(column_normals.begin(), column_normals.end(),
                               [&](const Point2 &normal) {
                                 return facing_slab_edge(slabs.plan[i].outline, point, normal,
                                                         gap.column.edge);
                               }))
                continue;
              gap.nodes        = {{int(top->nodes[0]), int(slabs.floors[i].nodes[0])}};
              gap.buildings    = {{b, a}};
              gap.level        = level;
              gap.on_column    = true;
              gap.column.slab_centre  = slabs.plan[i].mass_centre;
              gap.column.column_point = point;
              gap.column.column_dofs  = column.dofs;
              gap.column.weights      = column_weights(column, level);
              gap.column.column       = column.label;
              gap.initial_gap = column_contact_state(gap.column, Vector5::Zero()).gap;
              gap.effective_mass = contact.effective_mass > 0 ? contact.effective_mass :
                                                                 floor_effective_mass(model, gap);
              std::ostringstream label;
              label << slabs.name << "@" << level << "-" << column.label;
              gap.label = label.str();
              model.gaps.push_back(gap);
            }
        }
    }
  } // namespace

  void
  add_column_contacts(Model &model, const ContactParameters &contact)
  {
    for (unsigned int a = 0; a < model.buildings.size(); ++a)
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        if (a != b && !model.buildings[a].plan.empty() && !model.buildings[b].plan.empty())
          add_slab_to_columns(model, contact, a, b);
  }
} // namespace poundfe
