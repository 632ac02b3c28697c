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

  namespace
  {
    /// The springs, dashpots and inertias of a 3D building's foundation alone.
    void
    declare_3d_entries(dealii::ParameterHandler &prm, FoundationParameters &p)
    {
      prm.add_parameter("Horizontal stiffness y", p.given_3d.sway_stiffness[1],
                        "[3D] Sway spring along the foundation's local y (given; "
                        "Horizontal stiffness: along x). Unit: N/m.");
      prm.add_parameter("Horizontal damping y", p.given_3d.sway_damping[1],
                        "[3D] Sway dashpot along local y (given). Unit: N s/m.");
      prm.add_parameter("Rocking stiffness x", p.given_3d.rocking_stiffness[0],
                        "[3D] Rocking spring about local x (given; Rocking stiffness: "
                        "about y). Unit: N m/rad.");
      prm.add_parameter("Rocking damping x", p.given_3d.rocking_damping[0],
                        "[3D] Rocking dashpot about local x (given). Unit: N m s/rad.");
      prm.add_parameter("Torsional stiffness", p.given_3d.torsional_stiffness,
                        "[3D] Torsion spring about the vertical (given). Unit: N m/rad.");
      prm.add_parameter("Torsional damping", p.given_3d.torsional_damping,
                        "[3D] Torsion dashpot about the vertical (given). Unit: "
                        "N m s/rad.");
      prm.add_parameter("Rotary inertia x", p.rotary_inertia_x,
                        "[3D] Mass moment of inertia of the foundation about its local x "
                        "axis through its base (Rotary inertia: about y; cone: Wolf's trapped "
                        "soil is added). Unit: kg m^2.");
      prm.add_parameter("Polar inertia", p.polar_inertia,
                        "[3D] Mass moment of inertia of the foundation about the vertical "
                        "through its centre. Unit: kg m^2.");
    }
  } // namespace

  void
  FoundationParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Foundation");
    add_choice(prm, "Type", type,
               "none: fixed base. gazetas: sway and rocking springs and dashpots "
               "of a rectangular foundation by Gazetas (1991), surface or embedded; cone: "
               "Wolf's cones (1994), surface; given: the springs and dashpots typed below "
               "(shear buildings, 2D and 3D: the sway-rocking model, floors moving with "
               "the base rotation; frames, 2D and 3D: a rigid foundation under the column "
               "bases, also on a vertical spring). Unit: -.",
               foundation_type_names());
    prm.add_parameter("Shear-wave velocity", soil.shear_wave_velocity,
                      "V_s of the soil (gazetas, cone). Unit: m/s.");
    prm.add_parameter("Soil density", soil.density,
                      "Mass density of the soil (gazetas, cone). Unit: kg/m^3.");
    prm.add_parameter("Poisson ratio", soil.poisson_ratio,
                      "Poisson ratio of the soil, in (0, 0.5) (gazetas, cone). "
                      "Unit: -.");
    prm.add_parameter("Length", geometry.length,
                      "Side of the foundation in the plane of the model (3D: along "
                      "the building's local x) (gazetas, cone). Unit: m.");
    prm.add_parameter("Width", geometry.width,
                      "Side of the foundation normal to the plane (3D: along local "
                      "y) (gazetas, cone). Unit: m.");
    prm.add_parameter("Embedment", geometry.embedment,
                      "Depth of the foundation's base below the surface, sidewalls "
                      "in contact over it (gazetas; at most the smaller side). Unit: m.");
    prm.add_parameter("Horizontal stiffness", given.horizontal_stiffness,
                      "Sway spring (given). Unit: N/m.");
    prm.add_parameter("Rocking stiffness", given.rocking_stiffness,
                      "Rocking spring (given). Unit: N m/rad.");
    prm.add_parameter("Horizontal damping", given.horizontal_damping,
                      "Sway dashpot (given). Unit: N s/m.");
    prm.add_parameter("Rocking damping", given.rocking_damping,
                      "Rocking dashpot (given). Unit: N m s/rad.");
    prm.add_parameter("Vertical stiffness", given.vertical_stiffness,
                      "[frame, mesh] Vertical spring (given; frames and meshes only). Unit: N/m.");
    prm.add_parameter("Vertical damping", given.vertical_damping,
                      "[frame, mesh] Vertical dashpot (given; frames and meshes only). Unit: N s/m.");
    declare_3d_entries(prm, *this);
    prm.add_parameter("Mass", mass,
                      "Mass of the foundation (moves with the sway). Unit: kg.");
    prm.add_parameter("Rotary inertia", rotary_inertia,
                      "Mass moment of inertia of the foundation about the horizontal "
                      "axis through its base (3D: local y) (cone: Wolf's trapped soil is "
                      "added). Unit: kg m^2.");
    prm.leave_subsection();
  }

  void
  FoundationParameters::finalize(const InputFile &input, const std::string &section,
                                 const BuildingType building_type)
  {
    if (!enabled())
      return;
    const std::string s = section + "Foundation/";
    input.positive(s + "Mass", mass);
    input.positive(s + "Rotary inertia", rotary_inertia);
    if (type == FoundationType::given)
      {
        input.positive(s + "Horizontal stiffness", given.horizontal_stiffness);
        input.positive(s + "Rocking stiffness", given.rocking_stiffness);
        input.non_negative(s + "Horizontal damping", given.horizontal_damping);
        input.non_negative(s + "Rocking damping", given.rocking_damping);
        if (building_type != BuildingType::shear) // frames and meshes: a vertical part
          {
            input.positive(s + "Vertical stiffness", given.vertical_stiffness);
            input.non_negative(s + "Vertical damping", given.vertical_damping);
          }
        compute_planar_impedance();
        return;
      }
    if (!(soil.shear_wave_velocity >= smallest_shear_wave_velocity &&
          soil.shear_wave_velocity <= largest_shear_wave_velocity))
      input.fail(s + "Shear-wave velocity",
                 "must lie in [" + number_text(smallest_shear_wave_velocity) + ", " +
                   number_text(largest_shear_wave_velocity) + "] m/s (the softest peats have "
                   "about 30 m/s, hard rock below 4000 m/s), got " +
                   number_text(soil.shear_wave_velocity));
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
    compute_planar_impedance();
  }

  void
  FoundationParameters::compute_planar_impedance()
  {
    if (type == FoundationType::given)
      {
        impedance = given;
        return;
      }
    impedance = type == FoundationType::gazetas ? gazetas_impedance(soil, geometry) :
                                                  cone_impedance(soil, geometry);
    rotary_inertia += impedance.added_rotary_inertia;
  }

  void
  FoundationParameters::finalize_3d(const InputFile &input, const std::string &section)
  {
    if (!enabled())
      return;
    const std::string s = section + "Foundation/";
    input.positive(s + "Rotary inertia x", rotary_inertia_x);
    input.positive(s + "Polar inertia", polar_inertia);
    if (type == FoundationType::given)
      {
        input.positive(s + "Horizontal stiffness y", given_3d.sway_stiffness[1]);
        input.positive(s + "Rocking stiffness x", given_3d.rocking_stiffness[0]);
        input.positive(s + "Torsional stiffness", given_3d.torsional_stiffness);
        input.non_negative(s + "Horizontal damping y", given_3d.sway_damping[1]);
        input.non_negative(s + "Rocking damping x", given_3d.rocking_damping[0]);
        input.non_negative(s + "Torsional damping", given_3d.torsional_damping);
        compute_impedance_3d();
        return;
      }
    // finalize checked the soil and the geometry
    compute_impedance_3d();
  }

  void
  FoundationParameters::compute_impedance_3d()
  {
    if (type == FoundationType::given)
      {
        impedance_3d                      = given_3d;
        impedance_3d.sway_stiffness[0]    = given.horizontal_stiffness;
        impedance_3d.sway_damping[0]      = given.horizontal_damping;
        impedance_3d.rocking_stiffness[1] = given.rocking_stiffness;
        impedance_3d.rocking_damping[1]   = given.rocking_damping;
        impedance_3d.vertical_stiffness   = given.vertical_stiffness;
        impedance_3d.vertical_damping     = given.vertical_damping;
        return;
      }
    impedance_3d = type == FoundationType::gazetas ? gazetas_impedance_3d(soil, geometry) :
                                                     cone_impedance_3d(soil, geometry);
    // about y: compute_planar_impedance added the plane x-z's already (the same value)
    rotary_inertia_x += impedance_3d.added_rotary_inertia[0];
  }

  FoundationParameters
  FoundationParameters::as_typed(const bool three_d) const
  {
    FoundationParameters typed = *this;
    typed.rotary_inertia -= impedance.added_rotary_inertia;
    if (three_d)
      typed.rotary_inertia_x -= impedance_3d.added_rotary_inertia[0];
    return typed;
  }

  void
  FoundationParameters::recompute_impedance(const bool three_d)
  {
    compute_planar_impedance();
    if (three_d)
      compute_impedance_3d();
  }
} // namespace poundfe
