#include <poundfe/base/numbers.h>
#include <poundfe/model/plan_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  void
  PlanParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Plan");
    prm.add_parameter("Plan dimensions", dimensions,
                      "[3D shear] Slab rectangle L_x, L_y in the building's frame (the slab "
                      "outline for contact, and the polar moments by default); 3D frames: "
                      "the column grid. Unit: m.");
    prm.add_parameter("Position", position,
                      "[3D] Plan centre x, y on the site; empty: in a row along x, "
                      "Model/Separations apart, centred on y = 0. Unit: m.");
    prm.add_parameter("Rotation", rotation,
                      "[3D] Rotation of the building's frame on the site, counter-"
                      "clockwise. Unit: degrees.");
    prm.add_parameter("Polar moments", polar_moments,
                      "[3D] Polar moment of inertia of each floor about its mass "
                      "centre, one or one per floor; empty: m (L_x^2 + L_y^2) / 12 (a "
                      "uniform slab). Unit: kg m^2.");
    prm.add_parameter("Mass eccentricity", mass_eccentricity,
                      "[3D] Mass centre e_x, e_y from the plan centre, building frame. "
                      "Unit: m.");
    prm.add_parameter("Accidental eccentricity", accidental,
                      "[3D] The codes' accidental eccentricity (EN 1998-1 4.3.2, ASCE "
                      "7-16 12.8.4.2): the mass centre moved by the ratio times the plan "
                      "dimension normal to the action: +x or -x (action along y, shift "
                      "along x), +y or -y (action along x, shift along y), or none. Unit: -.",
                      Patterns::Selection("none|+x|-x|+y|-y"));
    prm.add_parameter("Accidental eccentricity ratio", accidental_ratio,
                      "[3D] The ratio of the accidental eccentricity. Unit: "
                      "dimensionless.");
    prm.add_parameter("Resisting planes", planes_text,
                      "[3D shear] Lateral-resisting planes of every storey, separated by ';', "
                      "each 'x y angle k [u_y]': a point of the plane from the plan centre "
                      "(building frame, m), its direction from x (degrees), its storey "
                      "stiffness (N/m) and a Bouc-Wen yield drift (m; absent or 0: elastic). "
                      "Empty: four planes on the slab's edges sharing each Storey stiffness "
                      "(and Storey yield drift) equally per direction. Unit: -.");
    prm.add_parameter("Storey law", storey_law,
                      "[3D shear] planes: each hysteretic plane its own uniaxial Bouc-Wen; "
                      "bidirectional Bouc-Wen: each hysteretic plane paired with the next "
                      "hysteretic plane of the storey perpendicular to it, the pair one "
                      "Park-Wen-Ang bidirectional Bouc-Wen element on the drift of their "
                      "crossing point (circular yield surface; Bouc-Wen n >= 2, no "
                      "degradation). Unit: -.",
                      Patterns::Selection("planes|bidirectional Bouc-Wen"));
    prm.leave_subsection();
  }

  namespace
  {
    std::vector<PlaneEntry>
    parse_planes(const InputFile &input, const std::string &path, const std::string &text)
    {
      std::vector<PlaneEntry> planes;
      std::istringstream      entries(text);
      std::string             entry;
      while (std::getline(entries, entry, ';'))
        {
          if (trimmed(entry).empty())
            continue;
          std::istringstream fields(entry);
          PlaneEntry         plane;
          double             degrees = 0;
          std::string        rest;
          if (!(fields >> plane.position.x >> plane.position.y >> degrees >> plane.stiffness))
            input.fail(path, "'" + trimmed(entry) + "': expected 'x y angle k [u_y]'");
          if (!(fields >> plane.yield_drift))
            plane.yield_drift = 0;
          fields.clear();
          if (fields >> rest)
            input.fail(path, "'" + trimmed(entry) + "': unexpected '" + rest + "'");
          if (!(plane.stiffness > 0) || !std::isfinite(plane.stiffness))
            input.fail(path, "'" + trimmed(entry) + "': the stiffness must be positive");
          if (!(plane.yield_drift >= 0))
            input.fail(path, "'" + trimmed(entry) + "': the yield drift must be >= 0");
          plane.angle = degrees * M_PI / 180;
          planes.push_back(plane);
        }
      return planes;
    }
  } // namespace

  void
  PlanParameters::finalize(const InputFile &input, const std::string &section,
                           const unsigned int n_floors)
  {
    const std::string s = section + "Plan/";
    if (dimensions.size() != 2)
      input.fail(s + "Plan dimensions", "needs two values, L_x and L_y");
    const std::string building = "10 km is beyond any building";
    for (const double length : dimensions)
      {
        input.positive(s + "Plan dimensions", length);
        input.at_most(s + "Plan dimensions", length, largest_building_length, "m", building);
      }
    if (!position.empty() && position.size() != 2)
      input.fail(s + "Position", "needs two values, x and y, or none");
    for (const double x : position)
      input.at_most(s + "Position", x, largest_site_coordinate, "m",
                    "site coordinates, e.g. UTM, stay below it: place the origin near the "
                    "buildings");
    // cos and sin of a huge angle in radians keep none of its digits
    input.at_most(s + "Rotation", rotation, 360, "degrees", "one turn");
    if (mass_eccentricity.size() != 2)
      input.fail(s + "Mass eccentricity", "needs two values, e_x and e_y");
    if (!polar_moments.empty())
      input.list(s + "Polar moments", polar_moments, n_floors, false, "one per floor");
    if (!(accidental_ratio >= 0 && accidental_ratio < 0.5))
      input.fail(s + "Accidental eccentricity ratio",
                 "must lie in [0, 0.5), got " + number_text(accidental_ratio));
    planes = parse_planes(input, s + "Resisting planes", planes_text);
  }

  void
  PlanParameters::check_mass_on_slab(const InputFile &input, const std::string &section) const
  {
    // the mass centre of a floor lies on its slab: beyond the edge the
    // floor would be a lever, not a diaphragm with its mass
    for (unsigned int i = 0; i < 2; ++i)
      if (!(std::abs(mass_eccentricity[i]) <= 0.5 * dimensions[i]))
        input.fail(section + "Plan/Mass eccentricity",
                   std::string(i == 0 ? "e_x = " : "e_y = ") + number_text(mass_eccentricity[i]) +
                     " m puts the mass centre outside the slab (|e| <= L/2 = " +
                     number_text(0.5 * dimensions[i]) + " m, Plan dimensions " +
                     number_text(dimensions[0]) + " x " + number_text(dimensions[1]) + " m)");
  }
} // namespace poundfe
