// prm -> Model for Model/Dimension = 3: torsionally coupled shear buildings
// placed in plan (model/torsional_shear_building.h, doc/theory.md §1.12) and
// the contacts between their slab outlines (doc/theory.md §1.13).
#ifndef poundfe_model_plan_builder_h
#define poundfe_model_plan_builder_h

#include <poundfe/base/input_file.h>
#include <poundfe/model/contact_parameters.h>
#include <poundfe/model/model.h>
#include <poundfe/model/parameters.h>
#include <poundfe/model/torsional_shear_building.h>

#include <vector>

namespace poundfe
{
  /// Entry i of a list given as one value for all or one value per item.
  template <typename T>
  T
  value_for(const std::vector<T> &values, const unsigned int i)
  {
    return values.size() == 1 ? values[0] : values[i];
  }

  /// A building placed on the site: its frame (plan centre, rotation), its
  /// floors (mass, polar moment, mass centre with the eccentricities; the
  /// resisting planes of a shear building) and its slab outline.
  struct SitePlan
  {
    Point2                 centre;
    double                 angle = 0; // rad, counter-clockwise
    TorsionalShearBuilding building;
    std::vector<Point2>    outline;

    /// A point of the building's frame on the site.
    Point2 place(const Point2 &x) const;
    /// A direction of the building's frame on the site.
    Point2 turn(const Point2 &d) const;
  };

  /// `building` (floors in the building's frame, slab sides
  /// `plan_dimensions` per floor) with the accidental eccentricity of p's
  /// Plan (Accidental eccentricity, ratio): unchanged for none.
  TorsionalShearBuilding with_plan_accidental_eccentricity(const PlanParameters &plan,
                                                           const TorsionalShearBuilding &building,
                                                           const std::vector<Point2> &plan_dimensions);

  /// Building p with its plan centre at `centre`.
  SitePlan site_plan(const BuildingParameters &p, const Point2 &centre);

  /// The slab outline of floor `storey` (1-based) of building p placed by
  /// `frame`, counter-clockwise: Plan/Plan dimensions, or a 3D frame's
  /// floor after its set-backs (model/set_backs.h).
  std::vector<Point2> slab_outline(const BuildingParameters &p, const SitePlan &frame,
                                   unsigned int storey);

  /// Half the extent along the site's x of building p's rotated slab.
  double plan_half_width(const BuildingParameters &p);

  /// Building b (0-based) with its plan centre at `centre` on the site: a
  /// fixed base node, a node (ux, uy, θz) per floor at its mass centre with
  /// its mass and polar moment, the resisting planes of every storey, the
  /// slab outlines. Throws InputError (a singular diaphragm: planes all
  /// parallel or through one point) naming `Building <b+1>/Plan/...`.
  void build_plan_building(Model &model, const BuildingParameters &p, unsigned int b,
                           Building &building, const Point2 &centre, const InputFile &input);

  /// Throws InputError when two buildings' slabs overlap at rest.
  void check_plans_apart(const Model &model, const ModelParameters &parameters,
                         const InputFile &input);

  /// One gap per end of the overlap of the facing edges of every pair of
  /// floors at the same level of two buildings whose slabs face each other.
  void add_plan_contacts(Model &model, const ContactParameters &contact);

  /// One gap per slab of a building and perimeter column of a 3D frame
  /// neighbour that faces the slab's edge, where the slab's level is
  /// strictly between the column's ends (model/column_contact_geometry.h;
  /// source/model/column_contact_builder.cc).
  void add_column_contacts(Model &model, const ContactParameters &contact);
} // namespace poundfe

#endif
