// Torsionally coupled shear buildings in plan and the contacts between their
// slab outlines (include/poundfe/model/plan_builder.h; doc/theory.md §1.12,
// §1.13).
#include <poundfe/base/exceptions.h>
#include <poundfe/model/plan_builder.h>
#include <poundfe/model/plan_contact_geometry.h>
#include <poundfe/model/plan_foundation.h>
#include <poundfe/model/set_backs.h>
#include <poundfe/model/torsional_shear_building.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// The planes of storey i (building frame): as given, or four on the
    /// slab's edges sharing the storey stiffness equally per direction.
    std::vector<PlaneEntry>
    storey_planes(const BuildingParameters &p, const unsigned int i)
    {
      if (!p.plan.planes.empty())
        return p.plan.planes;
      const double k  = 0.5 * value_for(p.storey_stiffnesses, i);
      const double uy = p.storey_yield_drifts.empty() ? 0 : value_for(p.storey_yield_drifts, i);
      const double hx = 0.5 * p.plan.dimensions[0], hy = 0.5 * p.plan.dimensions[1];
      return {{{0, -hy}, 0, k, uy}, {{0, hy}, 0, k, uy},
              {{-hx, 0}, 0.5 * M_PI, k, uy}, {{hx, 0}, 0.5 * M_PI, k, uy}};
    }

    /// The building in its own frame, accidental eccentricity applied.
    TorsionalShearBuilding
    local_building(const BuildingParameters &p)
    {
      const PlanParameters  &plan = p.plan;
      TorsionalShearBuilding building;
      std::vector<Point2>    dimensions; // of each floor's slab (set-backs: model/set_backs.h)
      for (unsigned int i = 0; i < p.n_storeys; ++i)
        {
          const FloorRectangle slab = floor_rectangle(p, i + 1);
          const double         lx = slab.dimensions.x, ly = slab.dimensions.y;
          dimensions.push_back(slab.dimensions);
          TorsionalFloor floor;
          floor.mass         = value_for(p.floor_masses, i);
          floor.polar_moment = plan.polar_moments.empty() ?
                                 floor.mass * (lx * lx + ly * ly) / 12 :
                                 value_for(plan.polar_moments, i);
          floor.mass_centre  = {slab.centre.x + plan.mass_eccentricity[0],
                                slab.centre.y + plan.mass_eccentricity[1]};
          for (const PlaneEntry &e : storey_planes(p, i))
            floor.planes.push_back(
              {{std::cos(e.angle), std::sin(e.angle)}, e.position, e.stiffness});
          building.floors.push_back(floor);
        }
      return with_plan_accidental_eccentricity(plan, building, dimensions);
    }

    /// The same building on the site.
    TorsionalShearBuilding
    placed(TorsionalShearBuilding building, const SitePlan &frame)
    {
      for (TorsionalFloor &floor : building.floors)
        {
          floor.mass_centre = frame.place(floor.mass_centre);
          for (ResistingPlane &plane : floor.planes)
            {
              plane.position  = frame.place(plane.position);
              plane.direction = frame.turn(plane.direction);
            }
        }
      return building;
    }

  } // namespace

  TorsionalShearBuilding
  with_plan_accidental_eccentricity(const PlanParameters &plan,
                                    const TorsionalShearBuilding &building,
                                    const std::vector<Point2> &plan_dimensions)
  {
    if (plan.accidental == "none")
      return building;
    const bool shift_x = plan.accidental[1] == 'x';
    return with_accidental_eccentricity(building, plan_dimensions,
                                        shift_x ? PlanDirection::y : PlanDirection::x,
                                        plan.accidental[0] == '-' ? -1 : 1, plan.accidental_ratio);
  }

  std::vector<Point2>
  slab_outline(const BuildingParameters &p, const SitePlan &frame, const unsigned int storey)
  {
    const FloorRectangle slab = floor_rectangle(p, storey);
    const double         hx = 0.5 * slab.dimensions.x, hy = 0.5 * slab.dimensions.y;
    const Point2         c  = slab.centre;
    return {frame.place({c.x - hx, c.y - hy}), frame.place({c.x + hx, c.y - hy}),
            frame.place({c.x + hx, c.y + hy}), frame.place({c.x - hx, c.y + hy})};
  }

  namespace
  {

    /// The storeys' planes; on a compliant foundation (`rocking_node` >= 0)
    /// the base node moves about `base_point` and the planes take the
    /// rocking (model/plan_foundation.h).
    void
    add_plane_links(Model &model, const BuildingParameters &p, const TorsionalShearBuilding &site,
                    const unsigned int b, const std::vector<unsigned int> &nodes,
                    const Point2 &base_point, const int rocking_node)
    {
      for (unsigned int i = 0; i < site.n_floors(); ++i)
        {
          const std::vector<PlaneEntry> entries = storey_planes(p, i);
          const Point2 below = i > 0            ? site.floors[i - 1].mass_centre :
                               rocking_node >= 0 ? base_point :
                                                   site.floors[0].mass_centre;
          const double height = value_for(p.storey_heights, i);
          for (unsigned int j = 0; j < entries.size(); ++j)
            {
              const ResistingPlane &plane = site.floors[i].planes[j];
              const Eigen::Vector3d bottom = -plane_row(plane, below);
              const Eigen::Vector3d top    = plane_row(plane, site.floors[i].mass_centre);
              PlaneLink link;
              link.nodes        = {{nodes[i], nodes[i + 1]}};
              link.coefficients = {{bottom[0], bottom[1], bottom[2], top[0], top[1], top[2]}};
              link.stiffness    = plane.stiffness;
              link.building     = b;
              link.storey       = i + 1;
              link.plane        = j + 1;
              if (rocking_node >= 0)
                {
                  link.rocking_node         = rocking_node;
                  link.rocking_coefficients = {{height * top[1], -height * top[0]}};
                }
              if (entries[j].yield_drift > 0)
                {
                  link.hysteretic                   = true;
                  link.hysteresis                   = p.hysteresis;
                  link.hysteresis.stiffness         = plane.stiffness;
                  link.hysteresis.yield_deformation = entries[j].yield_drift;
                }
              model.plane_links.push_back(link);
            }
        }
    }

    /// Plan/Storey law = bidirectional Bouc-Wen: each hysteretic plane of a
    /// storey (links from `first` on) shares one bidirectional element with
    /// the next unpaired hysteretic plane of the storey perpendicular to it:
    /// the pair's drifts are the drift of their crossing point along them, as
    /// the bearings of 3D-BASIS (Nagarajaiah, Reinhorn & Constantinou 1991).
    void
    pair_planes(Model &model, const TorsionalShearBuilding &site, const unsigned int first,
                const std::string &path, const InputFile &input)
    {
      auto direction = [&](const PlaneLink &link) {
        const Point2 d = site.floors[link.storey - 1].planes[link.plane - 1].direction;
        return Eigen::Vector2d(d.x, d.y).normalized();
      };
      for (unsigned int l = first; l < model.plane_links.size(); ++l)
        {
          PlaneLink &link = model.plane_links[l];
          if (!link.hysteretic || link.partner >= 0)
            continue;
          for (unsigned int m = l + 1; m < model.plane_links.size() && link.partner < 0; ++m)
            {
              PlaneLink &other = model.plane_links[m];
              if (other.storey == link.storey && other.hysteretic && other.partner < 0 &&
                  std::abs(direction(link).dot(direction(other))) <= 1e-9)
                {
                  link.partner  = m;
                  other.partner = l;
                }
            }
          if (link.partner < 0)
            throw InputError(input.file, input.line_of(path), path,
                             "plane " + std::to_string(link.plane) + " of storey " +
                               std::to_string(link.storey) +
                               " has no hysteretic plane perpendicular to it to share a "
                               "bidirectional Bouc-Wen element with");
        }
    }

    /// Separating-axis test of two convex polygons (touching is apart).
    bool
    convex_polygons_overlap(const std::vector<Point2> &a, const std::vector<Point2> &b)
    {
      for (const auto *polygon : {&a, &b})
        for (unsigned int i = 0; i < polygon->size(); ++i)
          {
            const Point2 n = outward_normal((*polygon)[i], (*polygon)[(i + 1) % polygon->size()]);
            auto range = [&](const std::vector<Point2> &p) {
              double lo = 1e300, hi = -1e300;
              for (const Point2 &x : p)
                {
                  lo = std::min(lo, x.x * n.x + x.y * n.y);
                  hi = std::max(hi, x.x * n.x + x.y * n.y);
                }
              return std::array<double, 2>{{lo, hi}};
            };
            const auto ra = range(a), rb = range(b);
            const double tolerance = 1e-9 * (std::abs(ra[1]) + std::abs(rb[1]) + 1);
            if (ra[1] <= rb[0] + tolerance || rb[1] <= ra[0] + tolerance)
              return false;
          }
      return true;
    }

    double
    node_mass(const Model &model, const unsigned int node)
    {
      double m = 0;
      for (const NodalMass &mass : model.masses)
        if (mass.node == node)
          m += mass.mass;
      return m;
    }

    /// The facing edges of two floors' outlines: antiparallel, overlapping
    /// along them, open at both ends of the overlap; the nearest such pair.
    /// Returns false when the outlines do not face each other.
    bool
    facing_edges(const std::array<const PlanFloor *, 2> &floors, PlanContactGeometry &best)
    {
      const std::vector<Point2> &a = floors[0]->outline, &b = floors[1]->outline;
      double nearest = 1e300;
      for (unsigned int i = 0; i < a.size(); ++i)
        for (unsigned int j = 0; j < b.size(); ++j)
          {
            PlanContactGeometry g;
            g.edges   = {{{{a[i], a[(i + 1) % a.size()]}}, {{b[j], b[(j + 1) % b.size()]}}}};
            g.centres = {{floors[0]->mass_centre, floors[1]->mass_centre}};
            const Point2 na = outward_normal(g.edges[0][0], g.edges[0][1]);
            const Point2 nb = outward_normal(g.edges[1][0], g.edges[1][1]);
            if (na.x * nb.x + na.y * nb.y > -0.5) // not facing (more than 60° apart)
              continue;
            double gap = 1e300;
            for (const unsigned int end : {0u, 1u})
              {
                g.end = end;
                const PlanContactState s = plan_contact_state(g, Vector6::Zero());
                gap = s.defined ? std::min(gap, s.gap) : -1.0;
              }
            if (gap >= 0 && gap < nearest)
              {
                nearest = gap;
                best    = g;
              }
          }
      return nearest < 1e300;
    }

    void
    add_floor_contacts(Model &model, const ContactParameters &contact,
                       const std::array<unsigned int, 2> &buildings,
                       const std::array<unsigned int, 2> &floors)
    {
      const std::array<const Building *, 2> b{
        {&model.buildings[buildings[0]], &model.buildings[buildings[1]]}};
      PlanContactGeometry geometry;
      if (!facing_edges({{&b[0]->plan[floors[0]], &b[1]->plan[floors[1]]}}, geometry))
        return;
      const std::array<unsigned int, 2> nodes{
        {b[0]->floors[floors[0]].nodes[0], b[1]->floors[floors[1]].nodes[0]}};
      const double m1 = node_mass(model, nodes[0]), m2 = node_mass(model, nodes[1]);
      for (const unsigned int end : {0u, 1u})
        {
          Gap gap;
          gap.nodes          = {{int(nodes[0]), int(nodes[1])}};
          gap.buildings      = buildings;
          gap.level          = b[0]->floors[floors[0]].level;
          gap.effective_mass = contact.effective_mass > 0 ? contact.effective_mass :
                                                             m1 * m2 / (m1 + m2);
          gap.in_plan        = true;
          gap.plan           = geometry;
          gap.plan.end       = end;
          gap.initial_gap    = plan_contact_state(gap.plan, Vector6::Zero()).gap;
          std::ostringstream label;
          label << b[0]->name << "-" << b[1]->name << "@" << gap.level << "/" << end + 1;
          gap.label = label.str();
          model.gaps.push_back(gap);
        }
    }
  } // namespace

  void
  add_plan_contacts(Model &model, const ContactParameters &contact)
  {
    for (unsigned int a = 0; a < model.buildings.size(); ++a)
      for (unsigned int b = a + 1; b < model.buildings.size(); ++b)
        {
          const std::vector<Floor> &fa = model.buildings[a].floors, &fb = model.buildings[b].floors;
          for (unsigned int i = 0; i < fa.size(); ++i)
            for (unsigned int j = 0; j < fb.size(); ++j)
              if (std::abs(fa[i].level - fb[j].level) <=
                  1e-6 * std::max(fa[i].level, fb[j].level))
                add_floor_contacts(model, contact, {{a, b}}, {{i, j}});
        }
  }

  Point2
  SitePlan::place(const Point2 &x) const
  {
    const double c = std::cos(angle), s = std::sin(angle);
    return {centre.x + c * x.x - s * x.y, centre.y + s * x.x + c * x.y};
  }

  Point2
  SitePlan::turn(const Point2 &d) const
  {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * d.x - s * d.y, s * d.x + c * d.y};
  }

  SitePlan
  site_plan(const BuildingParameters &p, const Point2 &centre)
  {
    SitePlan plan;
    plan.centre   = centre;
    plan.angle    = p.plan.rotation * M_PI / 180;
    plan.building = placed(local_building(p), plan);
    plan.outline  = slab_outline(p, plan, 1);
    return plan;
  }

  double
  plan_half_width(const BuildingParameters &p)
  {
    const double angle = p.plan.rotation * M_PI / 180;
    return 0.5 * (std::abs(std::cos(angle)) * p.plan.dimensions[0] +
                  std::abs(std::sin(angle)) * p.plan.dimensions[1]);
  }

  void
  build_plan_building(Model &model, const BuildingParameters &p, const unsigned int b,
                      Building &building, const Point2 &centre, const InputFile &input)
  {
    const SitePlan               plan = site_plan(p, centre);
    const TorsionalShearBuilding &site = plan.building;
    const std::string planes_path = "Building " + std::to_string(b + 1) + "/Plan/Resisting planes";
    try
      {
        check_building(site);
      }
    catch (const InputError &e)
      {
        throw InputError(input.file, input.line_of(planes_path), planes_path,
                         e.parameter() + ": " + e.problem());
      }
    building.left  = centre.x - plan_half_width(p);
    building.right = centre.x + plan_half_width(p);
    std::vector<unsigned int> nodes;
    auto add_node = [&](const Point2 &position) {
      Node node;
      node.position = position;
      node.building = b;
      model.nodes.push_back(node);
      nodes.push_back(model.nodes.size() - 1);
      return nodes.back();
    };
    model.nodes[add_node({centre.x, 0.0})].fixed = {{true, true, true}};
    const std::vector<Point2> &outline = plan.outline;
    double level = 0;
    for (unsigned int i = 0; i < site.n_floors(); ++i)
      {
        const TorsionalFloor &f = site.floors[i];
        level += value_for(p.storey_heights, i);
        const unsigned int node = add_node({f.mass_centre.x, level});
        model.masses.push_back({node, f.mass, f.polar_moment});
        Floor floor;
        floor.level         = level;
        floor.storey_height = value_for(p.storey_heights, i);
        floor.nodes         = {node};
        building.floors.push_back(floor);
        building.plan.push_back({f.mass_centre, outline});
      }
    const int rocking_node =
      p.foundation.enabled() ?
        int(add_plan_foundation(model, p.foundation, b, nodes.front(), plan.angle)) :
        -1;
    const unsigned int first_link = model.plane_links.size();
    add_plane_links(model, p, site, b, nodes, centre, rocking_node);
    if (p.plan.storey_law == "bidirectional Bouc-Wen")
      pair_planes(model, site, first_link, "Building " + std::to_string(b + 1) + "/Plan/Storey law",
                  input);
  }

  void
  check_plans_apart(const Model &model, const ModelParameters &parameters, const InputFile &input)
  {
    for (unsigned int a = 0; a < model.buildings.size(); ++a)
      for (unsigned int b = a + 1; b < model.buildings.size(); ++b)
        if (convex_polygons_overlap(model.buildings[a].plan.front().outline,
                                    model.buildings[b].plan.front().outline))
          {
            const std::string path = "Building " + std::to_string(b + 1) + "/Plan/" +
                                     (parameters.buildings[b].plan.position.empty() ?
                                        "Rotation" : "Position");
            throw InputError(input.file, input.line_of(path), path,
                             "the slabs of " + model.buildings[a].name + " and " +
                               model.buildings[b].name + " overlap at rest");
          }
  }
} // namespace poundfe
