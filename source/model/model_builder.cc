#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/mesh/line_mesh.h>
#include <poundfe/model/entry_scope.h>
#include <poundfe/model/floor_mass.h>
#include <poundfe/model/frame_foundation.h>
#include <poundfe/model/frame_building_3d.h>
#include <poundfe/model/mesh_building_3d.h>
#include <poundfe/model/model_builder.h>
#include <poundfe/model/plan_builder.h>
#include <poundfe/sections/fibre_section.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

namespace poundfe
{
  namespace
  {
    unsigned int
    add_node(Model &model, const Point2 &p, const unsigned int building)
    {
      Node node;
      node.position = p;
      node.building = building;
      model.nodes.push_back(node);
      return model.nodes.size() - 1;
    }

    /// A straight member from node a to node b split into n elements.
    void
    add_member(Model &model, const unsigned int a, const unsigned int b,
               const unsigned int n_elements, const Section &section,
               const unsigned int building, const unsigned int group, const MemberKind kind,
               const FibreMember &fibre = {})
    {
      const Point2 pa = model.nodes[a].position;
      const Point2 pb = model.nodes[b].position;
      unsigned int previous = a;
      for (unsigned int e = 1; e <= n_elements; ++e)
        {
          const double       s    = double(e) / n_elements;
          const unsigned int next = (e == n_elements) ?
                                      b :
                                      add_node(model,
                                               {pa.x + s * (pb.x - pa.x), pa.y + s * (pb.y - pa.y)},
                                               building);
          Member member;
          member.nodes    = {{previous, next}};
          member.section  = section;
          member.building = building;
          member.group    = group;
          member.kind     = kind;
          member.at_joint = {{e == 1, e == n_elements}};
          member.member_length = std::hypot(pb.x - pa.x, pb.y - pa.y);
          member.fibre         = fibre;
          model.members.push_back(member);
          previous = next;
        }
    }

    void
    fix_base(Model &model, const unsigned int node, const BaseFixity fixity)
    {
      model.nodes[node].fixed = {{true, true, fixity == BaseFixity::fixed}};
    }

    /// Lump a floor mass in equal shares at the floor's joints.
    void
    lump_floor_mass(Model &model, const Floor &floor, const double mass)
    {
      if (mass <= 0)
        return;
      for (const unsigned int n : floor.nodes)
        model.masses.push_back({n, mass / floor.nodes.size()});
    }

    /// 1-based rank of x among sorted distinct values (within tolerance).
    unsigned int
    rank_of(const std::vector<double> &sorted, const double x, const double tolerance)
    {
      unsigned int rank = 0;
      for (const double v : sorted)
        if (v < x - tolerance)
          ++rank;
      return rank + 1;
    }

    /// 1-based bay holding x: the number of column lines left of x. A piece
    /// of a beam split into several elements is placed by its midpoint, which
    /// lies inside its bay whichever piece it is; a beam left of every line
    /// counts as bay 1.
    unsigned int
    bay_of(const std::vector<double> &column_lines, const double x, const double tolerance)
    {
      return std::max(rank_of(column_lines, x, tolerance) - 1, 1u);
    }

    /// Label every member of a building by its place: C<storey>.<column line>
    /// for columns, B<floor>.<bay> for beams (lines and bays counted from the
    /// left, 1-based), M<n> for other members. The pieces of a member split
    /// into several elements share its label.
    void
    label_members(Model &model, const Building &building, const unsigned int first_member)
    {
      const unsigned int last_member = model.members.size();
      double             extent      = 0;
      std::vector<double> column_lines;
      for (unsigned int m = first_member; m < last_member; ++m)
        for (const unsigned int n : model.members[m].nodes)
          extent = std::max({extent, std::abs(model.nodes[n].position.x - building.left),
                             std::abs(model.nodes[n].position.y - building.base_level)});
      const double tolerance = 1e-6 * std::max(extent, 1.0);
      for (unsigned int m = first_member; m < last_member; ++m)
        if (model.members[m].kind == MemberKind::column)
          {
            const double x = model.nodes[model.members[m].nodes[0]].position.x;
            if (std::none_of(column_lines.begin(), column_lines.end(),
                             [&](double v) { return std::abs(v - x) <= tolerance; }))
              column_lines.push_back(x);
          }
      std::sort(column_lines.begin(), column_lines.end());
      auto floor_above = [&](const double y) { // 1-based storey containing level y
        unsigned int f = 0;
        while (f + 1 < building.floors.size() && building.floors[f].level < y - tolerance)
          ++f;
        return f + 1;
      };
      for (unsigned int m = first_member; m < last_member; ++m)
        {
          Member      &member = model.members[m];
          const Point2 p0     = model.nodes[member.nodes[0]].position;
          const Point2 p1     = model.nodes[member.nodes[1]].position;
          std::string  where;
          if (member.kind == MemberKind::column)
            where = "C" + std::to_string(floor_above(std::max(p0.y, p1.y))) + "." +
                    std::to_string(rank_of(column_lines, p0.x, tolerance));
          else if (member.kind == MemberKind::beam)
            where = "B" + std::to_string(floor_above(p0.y)) + "." +
                    std::to_string(bay_of(column_lines, 0.5 * (p0.x + p1.x), tolerance));
          else
            where = "M" + std::to_string(m - first_member + 1);
          member.label = building.name + "_" + where;
        }
    }

    /// Put Bouc-Wen rotational hinges at the selected member ends of building
    /// b: the member end moves to a new node that shares the joint's
    /// translations, and a rotational spring joins the two rotations. The
    /// hinge is labelled by its member and end (A3_C1.2_bottom, A3_B1.1_left).
    /// The label's suffix of a hinge at the end `here` of `member` (its
    /// other end `there`), or nothing where Hinges/Locations puts none.
    std::optional<std::string>
    hinge_suffix(const BuildingParameters &p, const Member &member, const Point2 &here,
                 const Point2 &there, const bool supported)
    {
      auto wants = [&](const char *location) {
        return std::find(p.hinge_locations.begin(), p.hinge_locations.end(), location) !=
               p.hinge_locations.end();
      };
      if (member.kind == MemberKind::column)
        {
          const bool bottom = here.y < there.y;
          if (!((wants("column ends")) || (wants("column tops") && !bottom) ||
                (wants("column bases") && bottom && supported)))
            return std::nullopt;
          return bottom ? "_bottom" : "_top";
        }
      if (member.kind == MemberKind::beam && wants("beam ends"))
        return here.x < there.x ? "_left" : "_right";
      return std::nullopt;
    }

    /// The Bouc-Wen law of a hinge of `member` in hinge group `group_index`:
    /// k given, or Stiffness factor x 6 E I / L; u_y = M_y / k, or given.
    BoucWenParameters
    hinge_law(const BuildingParameters &p, const Member &member, const unsigned int group_index)
    {
      const double k_given = value_for(p.hinge_stiffnesses, group_index);
      const double stiffness =
        k_given > 0 ? k_given :
                      p.hinge_stiffness_factor * 6 * member.section.youngs_modulus *
                        member.section.second_moment / member.member_length;
      const double      yield_moment = value_for(p.hinge_yield_moments, group_index);
      BoucWenParameters law          = p.hysteresis;
      law.stiffness                  = stiffness;
      law.yield_deformation          = yield_moment > 0 ?
                                         yield_moment / stiffness :
                                         value_for(p.hinge_yield_rotations, group_index);
      return law;
    }

    void
    insert_hinges(Model &model, const BuildingParameters &p, const unsigned int b,
                  const unsigned int first_member)
    {
      if (p.hinge_locations.empty())
        return;
      const unsigned int last_member = model.members.size();
      for (unsigned int m = first_member; m < last_member; ++m)
        {
          const Member member = model.members[m];
          unsigned int group_index = 0;
          if (!p.hinge_groups.empty())
            {
              const auto it = std::find(p.hinge_groups.begin(), p.hinge_groups.end(), member.group);
              if (it == p.hinge_groups.end())
                continue;
              group_index = it - p.hinge_groups.begin();
            }
          const Point2 p0 = model.nodes[member.nodes[0]].position;
          const Point2 p1 = model.nodes[member.nodes[1]].position;
          for (unsigned int k = 0; k < 2; ++k)
            {
              if (!member.at_joint[k])
                continue;
              const unsigned int joint = member.nodes[k];
              const Node        &jn    = model.nodes[joint];
              const bool supported     = jn.fixed[0] || jn.fixed[1];
              if (supported && !jn.fixed[2])
                continue; // a pinned support already releases the rotation
              const Point2 here  = k == 0 ? p0 : p1;
              const std::optional<std::string> where =
                hinge_suffix(p, member, here, k == 0 ? p1 : p0, supported);
              if (!where)
                continue;
              Hinge hinge;
              hinge.joint_node  = joint;
              hinge.member_node = add_node(model, here, b);
              hinge.member      = m;
              hinge.building    = b;
              hinge.label       = member.label + *where;
              hinge.law         = hinge_law(p, member, group_index);
              model.nodes[hinge.member_node].tied_to = joint;
              model.nodes[hinge.member_node].fixed   = {{jn.fixed[0], jn.fixed[1], false}};
              model.members[m].nodes[k]              = hinge.member_node;
              model.hinges.push_back(hinge);
            }
        }
    }

    /// The fibre section of each `Sections` entry a fibre building names
    /// (model.section_laws): plane in 2D, in space in 3D.
    void
    add_section_laws(Model &model, const ModelParameters &parameters, const InputFile &input)
    {
      model.section_laws.assign(parameters.sections.sections.size(), nullptr);
      for (const BuildingParameters &p : parameters.buildings)
        for (const auto *indices :
             {&p.column_section_index, &p.beam_section_index, &p.group_section_index})
          for (const unsigned int k : *indices)
            if (!model.section_laws[k])
              model.section_laws[k] =
                std::make_shared<const FibreSection>(
                  parameters.sections.section(input, k, model.section_resultants()));
    }

    void
    build_frame(Model &model, const BuildingParameters &p, const unsigned int b,
                Building &building)
    {
      const unsigned int n_storeys = p.n_storeys;
      const unsigned int n_lines   = p.n_bays + 1;
      std::vector<double> x(n_lines, building.left);
      for (unsigned int j = 1; j < n_lines; ++j)
        x[j] = x[j - 1] + value_for(p.bay_widths, j - 1);
      building.right = x.back();

      std::vector<std::vector<unsigned int>> joint(n_storeys + 1,
                                                   std::vector<unsigned int>(n_lines));
      double level = 0;
      for (unsigned int i = 0; i <= n_storeys; ++i)
        {
          if (i > 0)
            level += value_for(p.storey_heights, i - 1);
          for (unsigned int j = 0; j < n_lines; ++j)
            joint[i][j] = add_node(model, {x[j], level}, b);
        }
      for (unsigned int j = 0; j < n_lines; ++j)
        fix_base(model, joint[0][j], p.base_fixity);

      for (unsigned int i = 1; i <= n_storeys; ++i)
        {
          const Section column{value_for(p.column_youngs_modulus, i - 1),
                         value_for(p.column_area, i - 1),
                         value_for(p.column_second_moment, i - 1),
                         value_for(p.column_mass_per_length, i - 1)};
          const Section beam{value_for(p.beam_youngs_modulus, i - 1), value_for(p.beam_area, i - 1),
                       value_for(p.beam_second_moment, i - 1),
                       value_for(p.beam_mass_per_length, i - 1)};
          const FibreMember column_fibre = fibre_member(model, p, i - 1, true);
          const FibreMember beam_fibre   = fibre_member(model, p, i - 1, false);
          for (unsigned int j = 0; j < n_lines; ++j)
            add_member(model, joint[i - 1][j], joint[i][j], p.elements_per_member, column, b,
                       2 * i - 1, MemberKind::column, column_fibre);
          for (unsigned int j = 0; j + 1 < n_lines; ++j)
            add_member(model, joint[i][j], joint[i][j + 1], p.elements_per_member, beam, b,
                       2 * i, MemberKind::beam, beam_fibre);

          Floor floor;
          floor.level         = model.nodes[joint[i][0]].position.y;
          floor.storey_height = value_for(p.storey_heights, i - 1);
          floor.nodes         = joint[i];
          building.floors.push_back(floor);
          lump_floor_mass(model, floor, value_for(p.floor_masses, i - 1));
        }
    }

    void
    build_shear(Model &model, const BuildingParameters &p, const unsigned int b,
                Building &building)
    {
      building.right     = building.left + p.drawing_width;
      const double x     = building.left + 0.5 * p.drawing_width;
      unsigned int below = add_node(model, {x, 0.0}, b);
      model.nodes[below].fixed = {{true, true, true}};
      const unsigned int base = below;
      if (p.foundation.enabled())
        add_planar_foundation(model, p.foundation, b, base, false);
      double level = 0;
      for (unsigned int i = 1; i <= p.n_storeys; ++i)
        {
          level += value_for(p.storey_heights, i - 1);
          const unsigned int node = add_node(model, {x, level}, b);
          model.nodes[node].fixed = {{false, true, true}};
          StoreyLink link;
          link.nodes     = {{below, node}};
          link.stiffness = value_for(p.storey_stiffnesses, i - 1);
          link.damping   = value_for(p.storey_damping, i - 1);
          link.building  = b;
          if (p.foundation.enabled())
            {
              link.rocking_node = base;
              link.rocking_arm  = value_for(p.storey_heights, i - 1);
            }
          const double yield_drift =
            p.storey_yield_drifts.empty() ? 0.0 : value_for(p.storey_yield_drifts, i - 1);
          if (yield_drift > 0)
            {
              link.hysteretic                   = true;
              link.hysteresis                   = p.hysteresis;
              link.hysteresis.stiffness         = link.stiffness;
              link.hysteresis.yield_deformation = yield_drift;
            }
          model.links.push_back(link);

          Floor floor;
          floor.level         = level;
          floor.storey_height = value_for(p.storey_heights, i - 1);
          floor.nodes         = {node};
          building.floors.push_back(floor);
          model.masses.push_back({node, value_for(p.floor_masses, i - 1)});
          below = node;
        }
    }

    /// The floors of a mesh building: one at each distinct beam level above
    /// the base (within `tolerance`), holding the column joints at that
    /// level, left to right.
    void
    add_mesh_floors(const Model &model, std::vector<double> beam_levels,
                    const std::map<double, std::vector<unsigned int>> &joints_at_level,
                    const double base_level, const double tolerance, Building &building)
    {
      std::sort(beam_levels.begin(), beam_levels.end());
      double previous = base_level;
      for (const double level : beam_levels)
        {
          if (level <= previous + tolerance)
            continue;
          Floor floor;
          floor.level         = level;
          floor.storey_height = level - previous;
          for (const auto &[y, nodes] : joints_at_level)
            if (std::abs(y - level) <= tolerance)
              for (const unsigned int n : nodes)
                if (std::find(floor.nodes.begin(), floor.nodes.end(), n) == floor.nodes.end())
                  floor.nodes.push_back(n);
          std::sort(floor.nodes.begin(), floor.nodes.end(), [&](unsigned int a, unsigned int c) {
            return model.nodes[a].position.x < model.nodes[c].position.x;
          });
          if (!floor.nodes.empty())
            building.floors.push_back(floor);
          previous = level;
        }
    }

    /// The extent min x, max x, min y, max y of the vertices a line mesh's
    /// cells use (a mesh file may hold points no cell uses).
    std::array<double, 4>
    used_vertex_extent(const LineMesh &mesh)
    {
      double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300;
      for (const auto &cell : mesh.cells)
        for (const unsigned int v : cell)
          {
            min_x = std::min(min_x, mesh.vertices[v].x);
            max_x = std::max(max_x, mesh.vertices[v].x);
            min_y = std::min(min_y, mesh.vertices[v].y);
            max_y = std::max(max_y, mesh.vertices[v].y);
          }
      return {{min_x, max_x, min_y, max_y}};
    }

    /// The group of Building <b + 1>'s parameters that a mesh cell's
    /// physical id `id` names; an id not listed is bad input.
    unsigned int
    mesh_group_of(const InputFile &input, const BuildingParameters &p, const unsigned int b,
                  const std::string &mesh_file, const unsigned int id)
    {
      const auto it = std::find(p.group_ids.begin(), p.group_ids.end(), id);
      if (it == p.group_ids.end())
      {
        const std::string parameter = "Building " + std::to_string(b + 1) + "/Group ids";
        throw InputError(input.file, input.line_of(parameter), parameter,
                         "the mesh " + mesh_file + " uses physical id " + std::to_string(id) +
                           ", which is not listed");
      }
      return it - p.group_ids.begin();
    }

    /// Building <b + 1>/Floor masses lumped on a mesh's floors (one for all
    /// or one per floor: the floors are known only once the mesh is read).
    void
    lump_mesh_floor_masses(Model &model, const InputFile &input, const BuildingParameters &p,
                           const unsigned int b, Building &building)
    {
      const std::string masses = "Building " + std::to_string(b + 1) + "/Floor masses";
      if (p.floor_masses.size() != 1 && p.floor_masses.size() != building.floors.size())
        throw InputError(input.file, input.line_of(masses), masses,
                         "needs 1 value or " + std::to_string(building.floors.size()) +
                           " (the mesh has that many floors), got " +
                           std::to_string(p.floor_masses.size()));
      for (unsigned int i = 0; i < building.floors.size(); ++i)
        lump_floor_mass(model, building.floors[i], value_for(p.floor_masses, i));
    }

    void
    build_from_mesh(Model &model, const InputFile &input, const BuildingParameters &p,
                    const unsigned int b, Building &building)
    {
      const std::string file = input.resolve(p.mesh_file);
      const LineMesh    mesh = read_building_mesh(input, p, b, &read_line_mesh);

      // Keep only vertices that cells use, in their order of first use.
      std::vector<int> node_of_vertex(mesh.vertices.size(), -1);
      const auto [min_x, max_x, min_y, max_y] = used_vertex_extent(mesh);
      const double shift = building.left - min_x;
      building.right     = max_x + shift;
      building.base_level = min_y;
      const double tolerance = 1e-6 * std::max(max_y - min_y, max_x - min_x);
      for (const auto &cell : mesh.cells)
        for (const unsigned int v : cell)
          if (node_of_vertex[v] < 0)
            node_of_vertex[v] =
              add_node(model, {mesh.vertices[v].x + shift, mesh.vertices[v].y}, b);

      std::map<double, std::vector<unsigned int>> joints_at_level; // nodes touching columns
      std::vector<double>                         beam_levels;
      for (unsigned int c = 0; c < mesh.cells.size(); ++c)
        {
          const unsigned int g = mesh_group_of(input, p, b, file, mesh.material_ids[c]);
          const Section section{value_for(p.group_youngs_modulus, g), value_for(p.group_area, g),
                                value_for(p.group_second_moment, g),
                                value_for(p.group_mass_per_length, g)};
          const unsigned int n0 = node_of_vertex[mesh.cells[c][0]];
          const unsigned int n1 = node_of_vertex[mesh.cells[c][1]];
          const Point2       p0 = model.nodes[n0].position, p1 = model.nodes[n1].position;
          MemberKind         kind = MemberKind::other;
          if (std::abs(p1.x - p0.x) <= tolerance)
            kind = MemberKind::column;
          else if (std::abs(p1.y - p0.y) <= tolerance)
            {
              kind = MemberKind::beam;
              beam_levels.push_back(p0.y);
            }
          add_member(model, n0, n1, 1, section, b, mesh.material_ids[c], kind,
                     group_fibre_member(model, p, g, kind));
          if (kind == MemberKind::column)
            for (const unsigned int n : {n0, n1})
              joints_at_level[model.nodes[n].position.y].push_back(n);
        }
      for (unsigned int n = building.first_node; n < model.n_nodes(); ++n)
        if (model.nodes[n].position.y <= min_y + tolerance)
          fix_base(model, n, p.base_fixity);

      add_mesh_floors(model, beam_levels, joints_at_level, min_y, tolerance, building);
      lump_mesh_floor_masses(model, input, p, b, building);
    }

    /// Building <b + 1>/Floor loads on its floors (one for all or one per
    /// floor; a mesh's floors are known only now).
    void
    set_floor_loads(const InputFile &input, const BuildingParameters &p, const unsigned int b,
                    Building &building)
    {
      if (p.floor_loads.empty())
        return;
      const std::string path = "Building " + std::to_string(b + 1) + "/Floor loads";
      if (p.floor_loads.size() != 1 && p.floor_loads.size() != building.floors.size())
        throw InputError(input.file, input.line_of(path), path,
                         "needs 1 value or " + std::to_string(building.floors.size()) +
                           " (one per floor), got " + std::to_string(p.floor_loads.size()));
      for (unsigned int i = 0; i < building.floors.size(); ++i)
        building.floors[i].gravity_load = value_for(p.floor_loads, i);
    }

    /// The joint of a floor that faces the neighbour: rightmost or leftmost.
    unsigned int
    facing_node(const Model &model, const Floor &floor, const bool right_side)
    {
      unsigned int best = floor.nodes.front();
      for (const unsigned int n : floor.nodes)
        if (right_side ? model.nodes[n].position.x > model.nodes[best].position.x :
                         model.nodes[n].position.x < model.nodes[best].position.x)
          best = n;
      return best;
    }

    /// A node of building b's facing column line at `level`, splitting the
    /// column element that spans it; -1 if there is none.
    int
    node_on_facing_column(Model &model, const unsigned int b, const bool right_side,
                          const double level, const double tolerance)
    {
      const Building &building = model.buildings[b];
      const double    x        = right_side ? building.right : building.left;
      for (unsigned int n = 0; n < model.n_nodes(); ++n)
        if (model.nodes[n].building == b && model.nodes[n].tied_to < 0 &&
            std::abs(model.nodes[n].position.x - x) <= tolerance &&
            std::abs(model.nodes[n].position.y - level) <= tolerance)
          return n;
      for (unsigned int m = 0; m < model.members.size(); ++m)
        {
          const Member member = model.members[m];
          if (member.building != b || member.kind != MemberKind::column)
            continue;
          const Point2 p0 = model.nodes[member.nodes[0]].position;
          const Point2 p1 = model.nodes[member.nodes[1]].position;
          if (std::abs(p0.x - x) > tolerance || std::abs(p1.x - x) > tolerance)
            continue;
          if (!(std::min(p0.y, p1.y) < level - tolerance && std::max(p0.y, p1.y) > level + tolerance))
            continue;
          const unsigned int node = add_node(model, {x, level}, b);
          Member             upper = member;
          upper.nodes[0]           = node;
          upper.at_joint[0]        = false;
          model.members[m].nodes[1]    = node;
          model.members[m].at_joint[1] = false;
          model.members.push_back(upper);
          // a hinge at the far end now belongs to the new element
          for (Hinge &h : model.hinges)
            if (h.member == m && h.member_node == upper.nodes[1])
              h.member = model.members.size() - 1;
          return node;
        }
      return -1;
    }

    void
    add_gaps_between(Model &model, const ContactParameters &contact, const unsigned int left,
                     const unsigned int right, const double separation,
                     const MassesByNode &masses)
    {
      const Building &L = model.buildings[left], &R = model.buildings[right];
      if (L.floors.empty() || R.floors.empty())
        return;
      const double tolerance = 1e-6 * std::max(L.floors.back().level, R.floors.back().level);
      // every level of either building up to the lower roof
      std::vector<double> levels;
      const double        top = std::min(L.floors.back().level, R.floors.back().level);
      for (const Building *b : {&L, &R})
        for (const Floor &f : b->floors)
          if (f.level <= top + tolerance &&
              std::none_of(levels.begin(), levels.end(),
                           [&](double y) { return std::abs(y - f.level) <= tolerance; }))
            levels.push_back(f.level);
      std::sort(levels.begin(), levels.end());
      for (const double level : levels)
        {
          auto floor_at = [&](const Building &b) -> const Floor * {
            for (const Floor &f : b.floors)
              if (std::abs(f.level - level) <= tolerance)
                return &f;
            return nullptr;
          };
          const Floor *fl = floor_at(L), *fr = floor_at(R);
          if ((!fl || !fr) && !contact.floor_to_column)
            continue;
          const int nl = fl ? int(facing_node(model, *fl, true)) :
                              (L.type == BuildingType::shear ?
                                 -1 :
                                 node_on_facing_column(model, left, true, level, tolerance));
          const int nr = fr ? int(facing_node(model, *fr, false)) :
                              (R.type == BuildingType::shear ?
                                 -1 :
                                 node_on_facing_column(model, right, false, level, tolerance));
          if (nl < 0 || nr < 0)
            continue;
          Gap gap;
          gap.nodes       = {{nl, nr}};
          gap.buildings   = {{left, right}};
          gap.level       = level;
          gap.initial_gap = separation;
          // colliding masses: the floors at this level, or the nearest floor
          gap.effective_mass = contact.effective_mass > 0 ? contact.effective_mass :
                                                             floor_effective_mass(model, gap, &masses);
          std::ostringstream label;
          label << model.buildings[left].name << "-" << model.buildings[right].name << "@"
                << level << (fl && fr ? "" : "c");
          gap.label = label.str();
          model.gaps.push_back(gap);
        }
    }

    void
    add_barrier(Model &model, const InputFile &input, const ContactParameters &contact,
                const std::string &entry, const MassesByNode &masses)
    {
      const std::string path = "Contact/Barriers";
      std::istringstream in(entry);
      unsigned int       f = 0;
      std::string        building_field, side, rest;
      double             gap = 0;
      if (!read_number(in >> building_field, f) || !(in >> side) || !read_number(in, gap) ||
          (in >> rest) || (side != "left" && side != "right") || !(gap >= 0))
        throw InputError(input.file, input.line_of(path), path,
                         "'" + entry + "': expected 'building floor left|right gap' (a "
                         "building number or name, a whole number, a side, a gap in m >= 0, "
                         "nothing after it)");
      const unsigned int b = read_building(input, model, building_field, path, entry) + 1;
      const Building    &building = model.buildings[b - 1];
      if (f < 1 || f > building.floors.size())
        throw InputError(input.file, input.line_of(path), path,
                         "'" + entry + "': floor must be 1.." +
                           std::to_string(building.floors.size()));
      const Floor &floor = building.floors[f - 1];
      const int    node  = facing_node(model, floor, side == "right");
      Gap          g;
      g.nodes          = side == "right" ? std::array<int, 2>{{node, -1}} : std::array<int, 2>{{-1, node}};
      g.buildings      = {{b - 1, b - 1}};
      g.level          = floor.level;
      g.initial_gap    = gap;
      g.effective_mass = contact.effective_mass > 0 ? contact.effective_mass :
                                                       floor_effective_mass(model, g, &masses);
      g.label          = building.name + "@" + std::to_string(f) + "-barrier-" + side;
      model.gaps.push_back(g);
    }

    void
    add_contact(Model &model, const ModelParameters &parameters, const ContactParameters &contact,
                const InputFile &input)
    {
      if (contact.law == "none")
        return;
      if (model.dimension == 3 && !contact.barriers.empty())
        input.fail("Contact/Barriers", "barriers are not available with Dimension = 3");
      if (contact.floor_to_column_in_plan && model.dimension != 3)
        input.fail("Contact/Floor to column in plan",
                   "is for Model/Dimension = 3 (in 2D, Floor to column places the contact)");
      if (contact.between_buildings && model.dimension == 3)
        {
          for (unsigned int b = 0; b < parameters.buildings.size(); ++b)
            if (parameters.buildings[b].type != BuildingType::shear &&
                parameters.buildings[b].diaphragm == "none")
              input.fail("Building " + std::to_string(b + 1) + "/Diaphragm",
                         "contact in plan acts between slabs: it needs Diaphragm = rigid");
          add_plan_contacts(model, contact);
          if (contact.floor_to_column_in_plan)
            add_column_contacts(model, contact);
        }
      // the floors' masses of every gap from one index (a scan of every
      // mass per gap is quadratic in a row of many buildings)
      const MassesByNode masses = masses_by_node(model);
      if (contact.between_buildings && model.dimension != 3) // 3D: in plan, above
        for (unsigned int b = 0; b + 1 < model.buildings.size(); ++b)
          add_gaps_between(model, contact, b, b + 1, value_for(parameters.separations, b), masses);
      for (const std::string &entry : contact.barriers)
        add_barrier(model, input, contact, entry, masses);

      ContactLawParameters &law = model.contact;
      law.law                   = contact.law;
      law.stiffness             = contact.stiffness;
      law.effective_mass = model.gaps.empty() ? 1.0 : model.gaps.front().effective_mass;
      law.damping               = contact_law_damping(contact, law);
    }

    /// Dimension 3: the plan centre given, or the next in the row along x.
    Point2
    plan_centre(const BuildingParameters &p, const double left)
    {
      if (!p.plan.position.empty())
        return {p.plan.position[0], p.plan.position[1]};
      return {left + plan_half_width(p), 0.0};
    }

    /// The largest coordinate in size of the points a gap is measured from.
    double
    gap_coordinate_scale(const Model &model, const Gap &gap)
    {
      double scale = 0;
      const auto take = [&scale](const Point2 &p) {
        scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
      };
      for (const int node : gap.nodes)
        if (node >= 0)
          take(model.nodes[node].position);
      if (gap.in_plan)
        for (const auto &edge : gap.plan.edges)
          for (const Point2 &p : edge)
            take(p);
      return scale;
    }

    /// A gap narrower than a million steps of a double at the coordinates
    /// it is measured from is lost in their rounding: the contact would see
    /// closures that are not there (phantom impacts of meganewtons).
    void
    check_gaps_resolved(const Model &model, const ModelParameters &parameters,
                        const InputFile &input)
    {
      for (const Gap &gap : model.gaps)
        {
          const double scale = gap_coordinate_scale(model, gap);
          const double step  = std::nextafter(scale, 2 * scale + 1) - scale;
          if (!(gap.initial_gap > 0 && gap.initial_gap < fewest_gap_ulps * step))
            continue;
          const unsigned int b    = gap.buildings[1];
          const std::string  path = model.dimension == 3 && !parameters.buildings[b].plan.position.empty() ?
                                      "Building " + std::to_string(b + 1) + "/Plan/Position" :
                                      "Model/Separations";
          input.fail(path, "the gap " + gap.label + " of " + number_text(gap.initial_gap) +
                             " m, at coordinates up to " + number_text(scale) +
                             " m, is below a million steps of a double there (" +
                             number_text(fewest_gap_ulps * step) +
                             " m): rounding would open or close it; place the site's "
                             "origin near the buildings");
        }
    }
    /// Model/Separations places a building after the one before it: in 3D
    /// a building with Plan/Position is placed by it instead. Given beside
    /// a Position for every building it would place, or with one building,
    /// it has no effect: a warning (the Positions place the buildings).
    void
    check_separations_used(const ModelParameters &parameters, const InputFile &input,
                           std::vector<std::string> &warnings)
    {
      if (input.line_of("Model/Separations") == 0)
        return; // not given (or a JSON file: no line index)
      const std::size_t n = parameters.buildings.size();
      if (n < 2)
        {
          warnings.push_back(input.warning("Model/Separations",
                                           "has no effect: the model has one building"));
          return;
        }
      if (parameters.dimension != 3)
        return;
      for (std::size_t b = 1; b < n; ++b)
        if (parameters.buildings[b].plan.position.empty())
          return; // placed by its separation
      warnings.push_back(input.warning(
        "Model/Separations",
        "has no effect: every building after the first has Plan/Position, which places it "
        "(e.g. Building 2/Plan/Position, line " +
          std::to_string(input.line_of("Building 2/Plan/Position")) +
          "); remove Separations or the Positions"));
    }
  } // namespace

  namespace
  {
    /// A fibre building's member on Sections entry `section`; PDelta when a
    /// column with Member transformation = PDelta, or auto and a gravity
    /// analysis.
    FibreMember
    fibre_member_on_section(const Model &model, const BuildingParameters &p, const int section,
                            const bool column)
    {
      FibreMember fibre;
      fibre.section     = section;
      fibre.force_based = p.member_element == "force";
      fibre.n_points    = p.integration_points;
      fibre.p_delta     = column && (p.member_transformation == "PDelta" ||
                                 (p.member_transformation == "auto" &&
                                  model.gravity_analysis.enabled));
      return fibre;
    }
  } // namespace

  FibreMember
  fibre_member(const Model &model, const BuildingParameters &p, const unsigned int storey,
               const bool column)
  {
    if (!p.fibre())
      return {};
    return fibre_member_on_section(
      model, p, int(value_for(column ? p.column_section_index : p.beam_section_index, storey)),
      column);
  }

  FibreMember
  group_fibre_member(const Model &model, const BuildingParameters &p, const unsigned int group,
                     const MemberKind kind)
  {
    if (!p.fibre())
      return {};
    return fibre_member_on_section(model, p, int(value_for(p.group_section_index, group)),
                                   kind == MemberKind::column);
  }

  void
  set_fibre_rigidities(Model &model)
  {
    for (Member &member : model.members)
      if (member.fibre.fibre())
        {
          const auto k0                 = model.section_laws[member.fibre.section]->initial_tangent();
          member.section.youngs_modulus = 1;
          member.section.area           = k0(0, 0);
          member.section.second_moment  = k0(1, 1);
        }
    // (N, Mz, My, T): the mass's twist inertia m (Iy + Iz) / A keeps its
    // ratio when E scales A and both I alike
    for (Member3D &member : model.members_3d)
      if (member.fibre.fibre())
        {
          const auto k0 = model.section_laws[member.fibre.section]->initial_tangent();
          Section3D &s  = member.section;
          s.youngs_modulus = s.shear_modulus = 1;
          s.area                             = k0(0, 0);
          s.second_moment_z                  = k0(1, 1);
          s.second_moment_y                  = k0(2, 2);
          s.torsion_constant                 = k0(3, 3);
          s.shear_area_y = s.shear_area_z = 0;
        }
  }

  namespace
  {
    /// A member's area for its unit weight: a fibre member's section's
    /// fibres (bars included), an elastic member's A.
    double
    weighed_area(const Model &model, const FibreMember &fibre, const double elastic_area)
    {
      if (!fibre.fibre())
        return elastic_area;
      const auto *section = dynamic_cast<const FibreSection *>(
        model.section_laws[fibre.section].get());
      Assert(section, dealii::ExcMessage("a fibre member's section is a fibre section"));
      return section->geometry().area();
    }
  } // namespace

  void
  set_member_self_weights(Model &model, const ModelParameters &parameters)
  {
    const auto weight = [&](const unsigned int b, const FibreMember &fibre, const double area,
                            const double mass_per_length) {
      const BuildingParameters &p = parameters.buildings[b];
      if (p.member_self_weight != "distributed")
        return 0.0;
      return p.member_unit_weight > 0 ?
               p.member_unit_weight * weighed_area(model, fibre, area) :
               mass_per_length * model.gravity;
    };
    for (Member &m : model.members)
      m.weight_per_length =
        weight(m.building, m.fibre, m.section.area, m.section.mass_per_length);
    for (Member3D &m : model.members_3d)
      m.weight_per_length =
        weight(m.building, m.fibre, m.section.area, m.section.mass_per_length);
  }

  namespace
  {
    /// A building's damping as its entries give it (the modes' ratios and
    /// coefficients are found once the modes are known).
    RayleighDamping
    building_damping(const BuildingParameters &p)
    {
      RayleighDamping d;
      d.damping_ratio = p.damping_ratio;
      d.a0            = p.rayleigh_a0;
      d.a1            = p.rayleigh_a1;
      d.kind          = p.damping_type;
      if (p.damping_type == RayleighDamping::Kind::modes)
        {
          d.first_mode  = p.damping_modes[0];
          d.second_mode = p.damping_modes[1];
        }
      d.modal_ratios = p.modal_damping_ratios;
      d.bands        = p.damping_bands;
      d.damped_modes = p.damped_modes;
      return d;
    }

    /// Building b's nodes, members, hinges, foundation and floor loads,
    /// added to `model`, its left edge at `left`.
    Building
    build_building(Model &model, const ModelParameters &parameters, const unsigned int b,
                   const double left, const InputFile &input)
    {
      const BuildingParameters &p = parameters.buildings[b];
      Building                  building;
      building.name       = p.name;
      building.left       = left;
      building.first_node = model.n_nodes();
      building.type       = p.type;
      const unsigned int first_member = model.members.size();
      switch (p.type)
        {
          case BuildingType::frame:
            if (parameters.dimension == 3)
              build_frame_3d(model, p, b, building, plan_centre(p, left));
            else
              build_frame(model, p, b, building);
            break;
          case BuildingType::shear:
            if (parameters.dimension == 3)
              build_plan_building(model, p, b, building, plan_centre(p, left), input);
            else
              build_shear(model, p, b, building);
            break;
          case BuildingType::mesh:
            if (parameters.dimension == 3)
              build_mesh_frame_3d(model, input, p, b, building, left);
            else
              build_from_mesh(model, input, p, b, building);
            break;
        }
      label_members(model, building, first_member);
      insert_hinges(model, p, b, first_member);
      // a mesh's supports are its column bases as a generated frame's
      if (p.type != BuildingType::shear && parameters.dimension == 2 && p.foundation.enabled())
        add_frame_foundation(model, p.foundation, b, building);
      building.n_nodes = model.n_nodes() - building.first_node;
      set_floor_loads(input, p, b, building);
      building.damping = building_damping(p);
      return building;
    }
  } // namespace

  Model
  build_model(const ModelParameters &parameters, const ContactParameters &contact,
              const InputFile &input, const SpringParameters &springs,
              const FrictionParameters &friction)
  {
    Model model;
    model.mass_matrix            = parameters.mass_matrix;
    model.geometric_nonlinearity = parameters.geometric_nonlinearity;
    model.gravity                = parameters.gravity;
    model.gravity_analysis       = parameters.gravity_analysis;
    model.dimension              = parameters.dimension;
    add_section_laws(model, parameters, input);
    double left = 0;
    for (unsigned int b = 0; b < parameters.buildings.size(); ++b)
      {
        Building building = build_building(model, parameters, b, left, input);
        if (b + 1 < parameters.buildings.size())
          left = building.right + value_for(parameters.separations, b);
        model.buildings.push_back(std::move(building));
      }
    set_member_self_weights(model, parameters); // before the rigidities replace A
    set_fibre_rigidities(model);
    if (model.dimension == 3)
      check_plans_apart(model, parameters, input);
    model.warnings = warn_entries_without_effect(input, parameters);
    for (std::string &warning : contact.entries_without_effect(input))
      model.warnings.push_back(std::move(warning));
    check_separations_used(parameters, input, model.warnings);
    add_contact(model, parameters, contact, input);
    if (contact.law != "none" && model.gaps.empty()) // nothing the law could act on
      model.warnings.push_back(input.warning(
        "Contact/Law", "has no effect: no gap element was made (no slabs of two buildings face "
                       "each other at a common level, and no barrier is given): the run has no "
                       "contact"));
    check_gaps_resolved(model, parameters, input);
    model.number_equations();
    add_springs(model, springs, input);
    check_storeys_held(model, input);
    add_friction_surfaces(model, friction, input);
    add_building_links(model, contact.links, input);
    add_bumpers(model, contact.bumpers.bumper, input);
    return model;
  }
} // namespace poundfe
