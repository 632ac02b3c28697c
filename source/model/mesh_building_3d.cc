// 3D frame buildings drawn in Gmsh (include/poundfe/model/mesh_building_3d.h;
// doc/theory.md §1.15, "Frames drawn in Gmsh").
#include <poundfe/base/numbers.h>
#include <poundfe/mesh/line_mesh.h>
#include <poundfe/model/frame_3d_assembler.h>
#include <poundfe/model/mesh_building_3d.h>
#include <poundfe/model/model_builder.h>
#include <poundfe/model/plan_builder.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>

namespace poundfe
{
  std::vector<Point2>
  convex_hull(std::vector<Point2> points)
  {
    std::sort(points.begin(), points.end(), [](const Point2 &a, const Point2 &c) {
      return a.x < c.x || (a.x == c.x && a.y < c.y);
    });
    const auto cross = [](const Point2 &o, const Point2 &a, const Point2 &c) {
      return (a.x - o.x) * (c.y - o.y) - (a.y - o.y) * (c.x - o.x);
    };
    if (points.size() < 3)
      return points;
    std::vector<Point2> hull(2 * points.size());
    std::size_t         k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) // lower chain
      {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0)
          --k;
        hull[k++] = points[i];
      }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) // upper chain
      {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0)
          --k;
        hull[k++] = points[i];
      }
    hull.resize(k - 1);
    return hull;
  }

  PolygonProperties
  polygon_properties(const std::vector<Point2> &polygon)
  {
    // Green's theorem over the edges, about the mean vertex o for round-off
    Point2 o;
    for (const Point2 &v : polygon)
      o = {o.x + v.x / polygon.size(), o.y + v.y / polygon.size()};
    double a2 = 0, sx = 0, sy = 0, ixx = 0, iyy = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i)
      {
        const Point2 p{polygon[i].x - o.x, polygon[i].y - o.y};
        const Point2 q{polygon[(i + 1) % polygon.size()].x - o.x,
                       polygon[(i + 1) % polygon.size()].y - o.y};
        const double c = p.x * q.y - q.x * p.y;
        a2 += c;
        sx += (p.x + q.x) * c;
        sy += (p.y + q.y) * c;
        iyy += (p.x * p.x + p.x * q.x + q.x * q.x) * c;
        ixx += (p.y * p.y + p.y * q.y + q.y * q.y) * c;
      }
    PolygonProperties properties;
    properties.area = 0.5 * a2;
    if (!(properties.area > 0))
      return properties;
    const Point2 c{sx / (3 * a2), sy / (3 * a2)};
    properties.centroid     = {o.x + c.x, o.y + c.y};
    properties.polar_moment = (ixx + iyy) / 12 - properties.area * (c.x * c.x + c.y * c.y);
    return properties;
  }

  namespace
  {
    /// Builds one mesh building on the parts of model/frame_3d_assembler.h.
    class MeshFrameBuilder
    {
    public:
      MeshFrameBuilder(Model &model, const InputFile &input, const BuildingParameters &p,
                       const unsigned int b, Building &building)
          : model(model)
          , input(input)
          , p(p)
          , b(b)
          , building(building)
          , section("Building " + std::to_string(b + 1) + "/")
          , mesh(read_building_mesh(input, p, b, &read_line_mesh_3d))
          , file(input.resolve(p.mesh_file))
          , parts(model, p, b, building)
      {
      }

      void
      build(const double left)
      {
        measure();
        place(left);
        classify_members();
        find_levels();
        if (p.foundation.enabled())
          parts.add_foundation(plan.centre, base_level, plan.angle);
        for (FrameJoint3D &j : joints)
          if (j.present && j.position.z() <= base_level + tolerance)
            parts.make_base(j);
        make_floors();
        for (unsigned int v = 0; v < joints.size(); ++v)
          if (joints[v].present && level_of[v] < 0 &&
              joints[v].position.z() > base_level + tolerance)
            parts.make_free_joint(joints[v]);
        add_members();
      }

    private:
      const Model              &model; // its section laws (fibre members)
      const InputFile          &input;
      const BuildingParameters &p;
      const unsigned int        b;
      Building                 &building;
      const std::string         section;
      const LineMesh3D          mesh;
      const std::string         file;
      FrameAssembler3D          parts;
      SitePlan                  plan;
      double                    tolerance = 0, base_level = 0;
      Point2                    plan_origin; // the mesh's bounding box centre in plan
      Point2                    plan_dimensions; // ... and its sides
      std::vector<FrameJoint3D> joints;      // one per mesh vertex (present: used)
      std::vector<MemberKind>   kinds;       // per cell
      std::vector<double>       levels;      // of the floors, bottom to top
      std::vector<int>          level_of;    // per vertex: its floor (0-based), -1: none

      [[noreturn]] void
      fail(const std::string &entry, const std::string &problem) const
      {
        input.fail(section + entry, problem);
      }

      std::string
      at(const unsigned int v) const
      {
        const auto &x = mesh.vertices[v];
        return "(" + number_text(x[0]) + ", " + number_text(x[1]) + ", " + number_text(x[2]) +
               ")";
      }

      /// The extent of the used vertices, the tolerance, zero-length members
      /// and a mesh in one horizontal plane.
      void
      measure()
      {
        std::array<double, 3> low{{1e300, 1e300, 1e300}}, high{{-1e300, -1e300, -1e300}};
        joints.resize(mesh.vertices.size());
        for (FrameJoint3D &j : joints)
          j.present = false;
        for (const auto &cell : mesh.cells)
          for (const unsigned int v : cell)
            {
              joints[v].present = true;
              for (unsigned int c = 0; c < 3; ++c)
                {
                  low[c]  = std::min(low[c], mesh.vertices[v][c]);
                  high[c] = std::max(high[c], mesh.vertices[v][c]);
                }
            }
        tolerance =
          1e-6 * std::max({high[0] - low[0], high[1] - low[1], high[2] - low[2], 1e-300});
        base_level  = low[2];
        plan_origin = {0.5 * (low[0] + high[0]), 0.5 * (low[1] + high[1])};
        if (high[2] - low[2] <= tolerance)
          fail("Mesh file", file + " lies in the horizontal plane z = " + number_text(low[2]) +
                              ": with Model/Dimension = 3 a mesh is drawn in 3D with z up (a "
                              "2D frame's mesh, y up, is for Dimension = 2)");
        for (unsigned int c = 0; c < mesh.cells.size(); ++c)
          if (vertex_distance(mesh.cells[c][0], mesh.cells[c][1]) <= tolerance)
            fail("Mesh file", file + ": line element " + std::to_string(c + 1) +
                                " (physical id " + std::to_string(mesh.material_ids[c]) +
                                ") has zero length, at " + at(mesh.cells[c][0]));
        // the building's frame: the bounding box's plan centre at the origin
        building.base_level    = base_level;
        const double lx        = high[0] - low[0], ly = high[1] - low[1];
        plan_dimensions        = {lx, ly};
      }

      double
      vertex_distance(const unsigned int a, const unsigned int c) const
      {
        const auto &x = mesh.vertices[a], &y = mesh.vertices[c];
        return std::hypot(y[0] - x[0], y[1] - x[1], y[2] - x[2]);
      }

      /// The site frame (as a generated frame's: its plan centre at Position
      /// or next in the row, turned by Rotation) and the joints on the site.
      void
      place(const double left)
      {
        plan.angle        = p.plan.rotation * M_PI / 180;
        const double half = 0.5 * (std::abs(std::cos(plan.angle)) * plan_dimensions.x +
                                   std::abs(std::sin(plan.angle)) * plan_dimensions.y);
        plan.centre       = p.plan.position.empty() ?
                              Point2{left + half, 0.0} :
                              Point2{p.plan.position[0], p.plan.position[1]};
        building.left     = plan.centre.x - half;
        building.right    = plan.centre.x + half;
        for (unsigned int v = 0; v < joints.size(); ++v)
          {
            const Point2 at = plan.place(local(v));
            joints[v].position = {at.x, at.y, mesh.vertices[v][2]};
          }
      }

      /// Vertex v in plan in the building's frame.
      Point2
      local(const unsigned int v) const
      {
        return {mesh.vertices[v][0] - plan_origin.x, mesh.vertices[v][1] - plan_origin.y};
      }

      /// Columns (vertical), beams (horizontal, their levels) and braces;
      /// every physical id listed.
      void
      classify_members()
      {
        for (unsigned int c = 0; c < mesh.cells.size(); ++c)
          {
            group_index(c);
            const auto &a = mesh.vertices[mesh.cells[c][0]], &e = mesh.vertices[mesh.cells[c][1]];
            if (std::hypot(e[0] - a[0], e[1] - a[1]) <= tolerance)
              kinds.push_back(MemberKind::column);
            else if (std::abs(e[2] - a[2]) <= tolerance)
              {
                kinds.push_back(MemberKind::beam);
                if (a[2] > base_level + tolerance &&
                    std::none_of(levels.begin(), levels.end(),
                                 [&](double z) { return std::abs(z - a[2]) <= tolerance; }))
                  levels.push_back(a[2]);
              }
            else
              kinds.push_back(MemberKind::other);
          }
      }

      /// The index in Group ids of cell c's physical id.
      unsigned int
      group_index(const unsigned int c) const
      {
        const auto it = std::find(p.group_ids.begin(), p.group_ids.end(), mesh.material_ids[c]);
        if (it == p.group_ids.end())
          fail("Group ids", "the mesh " + file + " uses physical id " +
                              std::to_string(mesh.material_ids[c]) +
                              " (line element " + std::to_string(c + 1) +
                              "), which is not listed");
        return it - p.group_ids.begin();
      }

      /// The floors: the beams' levels above the base; each vertex's floor.
      void
      find_levels()
      {
        if (levels.empty())
          fail("Mesh file", file + " has no horizontal member above its lowest joints (z = " +
                              number_text(base_level) +
                              "): the floors of a 3D mesh building are found at its beams' "
                              "levels");
        std::sort(levels.begin(), levels.end());
        level_of.assign(joints.size(), -1);
        for (unsigned int v = 0; v < joints.size(); ++v)
          for (unsigned int i = 0; i < levels.size(); ++i)
            if (joints[v].present && std::abs(joints[v].position.z() - levels[i]) <= tolerance)
              level_of[v] = i;
        const unsigned int n = levels.size();
        if (p.floor_masses.size() != 1 && p.floor_masses.size() != n)
          fail("Floor masses", "needs 1 value or " + std::to_string(n) + " (the mesh " + file +
                                 " has that many floors), got " +
                                 std::to_string(p.floor_masses.size()));
        if (!p.plan.polar_moments.empty() && p.plan.polar_moments.size() != n)
          fail("Plan/Polar moments", "needs " + std::to_string(n) + " values (the mesh " +
                                       file + " has that many floors), got " +
                                       std::to_string(p.plan.polar_moments.size()));
      }

      /// Each floor's slab: the convex hull of its joints in the building's
      /// frame; its mass centre, polar moment and outline on the site.
      void
      make_floors()
      {
        TorsionalShearBuilding             local_floors;
        std::vector<Point2>                dimensions;
        std::vector<std::vector<Point2>>   hulls;
        for (unsigned int i = 0; i < levels.size(); ++i)
          {
            std::vector<Point2> points;
            for (unsigned int v = 0; v < joints.size(); ++v)
              if (level_of[v] == int(i))
                points.push_back(local(v));
            hulls.push_back(convex_hull(points));
            const PolygonProperties slab = polygon_properties(hulls.back());
            const bool              flat = !(slab.area > tolerance * tolerance);
            if (flat && p.diaphragm == "rigid")
              fail("Mesh file", file + ": the joints of floor " + std::to_string(i + 1) +
                                  " (z = " + number_text(levels[i]) +
                                  ") lie on one line: a rigid diaphragm on them is singular "
                                  "(nothing holds its twist); add joints off the line, or "
                                  "Diaphragm = none");
            TorsionalFloor floor;
            floor.mass         = value_for(p.floor_masses, i);
            floor.polar_moment = !p.plan.polar_moments.empty() ?
                                   p.plan.polar_moments[i] :
                                   flat ? 0.0 : floor.mass * slab.polar_moment / slab.area;
            floor.mass_centre  = flat ? hulls.back().front() : slab.centroid;
            floor.mass_centre.x += p.plan.mass_eccentricity[0];
            floor.mass_centre.y += p.plan.mass_eccentricity[1];
            local_floors.floors.push_back(floor);
            double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
            for (const Point2 &q : hulls.back())
              {
                x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
                y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
              }
            dimensions.push_back({x1 - x0, y1 - y0});
          }
        local_floors = with_plan_accidental_eccentricity(p.plan, local_floors, dimensions);
        for (unsigned int i = 0; i < levels.size(); ++i)
          {
            FrameSlab3D slab;
            slab.floor             = local_floors.floors[i];
            slab.floor.mass_centre = plan.place(slab.floor.mass_centre);
            slab.level             = levels[i];
            slab.storey_height     = levels[i] - (i > 0 ? levels[i - 1] : base_level);
            for (const Point2 &q : hulls[i])
              slab.outline.push_back(plan.place(q));
            std::vector<FrameJoint3D *> on_floor;
            for (unsigned int v = 0; v < joints.size(); ++v)
              if (level_of[v] == int(i))
                on_floor.push_back(&joints[v]);
            parts.make_floor(slab, on_floor);
          }
      }

      /// The storey (1-based) whose floor is at or first above level z.
      unsigned int
      storey_of(const double z) const
      {
        unsigned int i = 0;
        while (i + 1 < levels.size() && levels[i] < z - tolerance)
          ++i;
        return i + 1;
      }

      void
      add_members()
      {
        std::map<std::string, unsigned int> counts; // per label prefix
        for (unsigned int c = 0; c < mesh.cells.size(); ++c)
          {
            const unsigned int g    = group_index(c);
            const MemberKind   kind = kinds[c];
            unsigned int       v0 = mesh.cells[c][0], v1 = mesh.cells[c][1];
            if (kind == MemberKind::column && joints[v1].position.z() < joints[v0].position.z())
              std::swap(v0, v1); // columns bottom to top, as a generated frame's
            const Eigen::Vector3d a = joints[v0].position, e = joints[v1].position;
            const Eigen::Vector3d v = orientation(g, kind);
            // a fibre member's section stands with its y axis up unless told
            // (v = x × Z), as a generated frame's fibre beams
            const Eigen::Vector3d site_v =
              p.fibre() && kind != MemberKind::column && !given_orientation(g) ?
                Eigen::Vector3d((e - a).cross(Eigen::Vector3d::UnitZ()).normalized()) :
                plan_turned(v);
            if (site_v.cross((e - a).normalized()).norm() <= 1e-9 * v.norm())
              fail("Group orientation",
                   "group " + std::to_string(p.group_ids[g]) + ": the vector (" +
                     number_text(v[0]) + ", " + number_text(v[1]) + ", " + number_text(v[2]) +
                     ") is along line element " + std::to_string(c + 1) + " from " + at(v0) +
                     " to " + at(v1) + ": it cannot fix the member's local axes");
            const Section3D   section = group_section(g);
            const std::string prefix =
              kind == MemberKind::column ? "C" + std::to_string(storey_of(e.z())) + "." :
              kind == MemberKind::beam   ? "B" + std::to_string(storey_of(a.z())) + "." :
                                           "M";
            parts.add_member({{&joints[v0], &joints[v1]}}, site_v, section, kind,
                             p.group_ids[g], prefix + std::to_string(++counts[prefix]),
                             group_fibre_member(model, p, g, kind));
          }
      }

      /// Group g's elastic section; a fibre member's mass alone (its
      /// rigidities come from its section law: set_fibre_rigidities).
      Section3D
      group_section(const unsigned int g) const
      {
        Section3D section;
        section.mass_per_length = value_for(p.group_mass_per_length, g);
        if (p.fibre())
          return section;
        section.youngs_modulus   = value_for(p.group_youngs_modulus, g);
        section.shear_modulus    = value_for(p.group_shear_modulus, g);
        section.area             = value_for(p.group_area, g);
        section.second_moment_y  = value_for(p.group_second_moment, g);
        section.second_moment_z  = value_for(p.group_second_moment_z, g);
        section.torsion_constant = value_for(p.group_torsion_constant, g);
        return section;
      }

      /// Whether Group orientation gives group g's vector.
      bool
      given_orientation(const unsigned int g) const
      {
        const std::array<double, 3> given =
          g < p.group_orientations.size() ? p.group_orientations[g] : std::array<double, 3>{};
        return given[0] != 0 || given[1] != 0 || given[2] != 0;
      }

      /// Group g's vector v (building frame): given, or the default.
      Eigen::Vector3d
      orientation(const unsigned int g, const MemberKind kind) const
      {
        if (given_orientation(g))
          {
            const std::array<double, 3> &given = p.group_orientations[g];
            return {given[0], given[1], given[2]};
          }
        return kind == MemberKind::column ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, 1);
      }

      /// A vector of the building's frame on the site.
      Eigen::Vector3d
      plan_turned(const Eigen::Vector3d &v) const
      {
        const Point2 d = plan.turn({v.x(), v.y()});
        return {d.x, d.y, v.z()};
      }
    };
  } // namespace

  void
  build_mesh_frame_3d(Model &model, const InputFile &input, const BuildingParameters &p,
                      const unsigned int b, Building &building, const double left)
  {
    MeshFrameBuilder(model, input, p, b, building).build(left);
  }
} // namespace poundfe
