#include <poundfe/base/numbers.h>
#include <poundfe/model/foundation_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  const NameTable<FoundationType> &
  foundation_type_names()
  {
    static const NameTable<FoundationType> table({{FoundationType::none, "none"},
                                                  {FoundationType::gazetas, "gazetas"},
                                                  {FoundationType::cone, "cone"},
                                                  {FoundationType::given, "given"}});
    return table;
  }

  void
  FoundationParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Foundation");
    add_choice(prm, "Type", type,
               "[shear] none: fixed base. gazetas: sway and rocking springs and dashpots "
               "of a rectangular foundation by Gazetas (1991), surface or embedded; cone: "
               "Wolf's cones (1994), surface; given: the springs and dashpots typed below "
               "(2D shear buildings: the sway-rocking model, floors moving with the base "
               "rotation). Unit: -.",
               foundation_type_names());
    prm.add_parameter("Shear-wave velocity", soil.shear_wave_velocity,
                      "[shear] V_s of the soil (gazetas, cone). Unit: m/s.");
    prm.add_parameter("Soil density", soil.density,
                      "[shear] Mass density of the soil (gazetas, cone). Unit: kg/m^3.");
    prm.add_parameter("Poisson ratio", soil.poisson_ratio,
                      "[shear] Poisson ratio of the soil, in (0, 0.5) (gazetas, cone). "
                      "Unit: -.");
    prm.add_parameter("Length", geometry.length,
                      "[shear] Side of the foundation in the plane of the model (gazetas, "
                      "cone). Unit: m.");
    prm.add_parameter("Width", geometry.width,
                      "[shear] Side of the foundation normal to the plane (gazetas, cone). "
                      "Unit: m.");
    prm.add_parameter("Embedment", geometry.embedment,
                      "[shear] Depth of the foundation's base below the surface, sidewalls "
                      "in contact over it (gazetas; at most the smaller side). Unit: m.");
    prm.add_parameter("Horizontal stiffness", given.horizontal_stiffness,
                      "[shear] Sway spring (given). Unit: N/m.");
    prm.add_parameter("Rocking stiffness", given.rocking_stiffness,
                      "[shear] Rocking spring (given). Unit: N m/rad.");
    prm.add_parameter("Horizontal damping", given.horizontal_damping,
                      "[shear] Sway dashpot (given). Unit: N s/m.");
    prm.add_parameter("Rocking damping", given.rocking_damping,
                      "[shear] Rocking dashpot (given). Unit: N m s/rad.");
    prm.add_parameter("Mass", mass,
                      "[shear] Mass of the foundation (moves with the sway). Unit: kg.");
    prm.add_parameter("Rotary inertia", rotary_inertia,
                      "[shear] Mass moment of inertia of the foundation about the horizontal "
                      "axis through its base (cone: Wolf's trapped soil is added). Unit: "
                      "kg m^2.");
    prm.leave_subsection();
  }

  void
  FoundationParameters::finalize(const InputFile &input, const std::string &section,
                                 const bool shear)
  {
    if (!enabled())
      return;
    const std::string s = section + "Foundation/";
    if (!shear)
      input.fail(s + "Type", "compliant foundations are for shear buildings (frames and "
                             "meshes: not yet)");
    input.positive(s + "Mass", mass);
    input.positive(s + "Rotary inertia", rotary_inertia);
    if (type == FoundationType::given)
      {
        input.positive(s + "Horizontal stiffness", given.horizontal_stiffness);
        input.positive(s + "Rocking stiffness", given.rocking_stiffness);
        input.non_negative(s + "Horizontal damping", given.horizontal_damping);
        input.non_negative(s + "Rocking damping", given.rocking_damping);
        impedance = given;
        return;
      }
    input.positive(s + "Shear-wave velocity", soil.shear_wave_velocity);
    input.positive(s + "Soil density", soil.density);
    if (!(soil.poisson_ratio > 0 && soil.poisson_ratio < 0.5))
      input.fail(s + "Poisson ratio",
                 "must lie in (0, 0.5), got " + number_text(soil.poisson_ratio));
    input.positive(s + "Length", geometry.length);
    input.positive(s + "Width", geometry.width);
    input.non_negative(s + "Embedment", geometry.embedment);
    const double smaller_side = std::min(geometry.length, geometry.width);
    if (type == FoundationType::cone && geometry.embedment > 0)
      input.fail(s + "Embedment", "the cones here are for surface foundations (Embedment = "
                                  "0); use Type = gazetas for an embedded one");
    if (geometry.embedment > smaller_side)
      input.fail(s + "Embedment",
                 "deeper (" + number_text(geometry.embedment) +
                   " m) than the foundation's smaller side (" + number_text(smaller_side) +
                   " m): beyond the range of Gazetas' embedment formulas (D/B <= 2)");
    impedance = type == FoundationType::gazetas ? gazetas_impedance(soil, geometry) :
                                                  cone_impedance(soil, geometry);
    rotary_inertia += impedance.added_rotary_inertia;
  }
} // namespace poundfe
