// The entries of a 3D frame building (Model/Dimension = 3, Type = frame):
// the bays along y, the second bending axis and the twist of the sections,
// the columns' local axes and the floor diaphragm (model/frame_building_3d.h,
// doc/theory.md §1.15).
#include <poundfe/base/numbers.h>
#include <poundfe/model/parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <numeric>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  void
  BuildingParameters::declare_frame_3d_entries(dealii::ParameterHandler &prm)
  {
    prm.add_parameter("Number of bays y", n_bays_y,
                      "[3D frame] Bays along y (Number of bays: along x). Unit: count.",
                      Patterns::Integer(0));
    prm.add_parameter("Bay widths y", bay_widths_y,
                      "[3D frame] Bay widths along y, one value for all or one per bay. "
                      "Unit: m.");
    prm.add_parameter("Column G", column_shear_modulus,
                      "[3D frame] Column shear modulus, one or per storey (required). Unit: "
                      "Pa.");
    prm.add_parameter("Column Iz", column_second_moment_z,
                      "[3D frame] Column second moment about the local z axis (bending in "
                      "the local x-y plane: sway along y with Column angle 0; Column I is "
                      "sway along x), one or per storey (required). Unit: m^4.");
    prm.add_parameter("Column J", column_torsion_constant,
                      "[3D frame] Column torsion constant, one or per storey (required). "
                      "Unit: m^4.");
    prm.add_parameter("Column angle", column_angle,
                      "[3D frame] Rotation of the columns' local axes about the vertical, "
                      "counter-clockwise from the building's x axis (0: Column I resists "
                      "sway along x). Unit: degrees.");
    prm.add_parameter("Beam G", beam_shear_modulus,
                      "[3D frame] Beam shear modulus, one or per floor (required). Unit: Pa.");
    prm.add_parameter("Beam Iz", beam_second_moment_z,
                      "[3D frame] Beam second moment about the vertical (bending in plan; "
                      "Beam I: in the vertical plane), one or per floor (required). Unit: "
                      "m^4.");
    prm.add_parameter("Beam J", beam_torsion_constant,
                      "[3D frame] Beam torsion constant, one or per floor (required). Unit: "
                      "m^4.");
    prm.add_parameter("Column Avz", column_shear_area_z,
                      "[3D frame] Column shear area along the local z axis, which goes "
                      "with Column I (sway along x with Column angle 0): Timoshenko "
                      "shear deformation, Phi = 12 E I/(G Avz h^2); e.g. 5/6 A for a "
                      "rectangle, the web for an I section. 0: none (Euler-Bernoulli). "
                      "One or per storey. Unit: m^2.");
    prm.add_parameter("Column Avy", column_shear_area_y,
                      "[3D frame] Column shear area along the local y axis, which goes "
                      "with Column Iz (sway along y with Column angle 0). 0: no shear "
                      "deformation. One or per storey. Unit: m^2.");
    prm.add_parameter("Beam Avz", beam_shear_area_z,
                      "[3D frame] Beam shear area for vertical shear (with Beam I). 0: no "
                      "shear deformation. One or per floor. Unit: m^2.");
    prm.add_parameter("Beam Avy", beam_shear_area_y,
                      "[3D frame] Beam shear area for horizontal shear (with Beam Iz). 0: "
                      "no shear deformation. One or per floor. Unit: m^2.");
    prm.add_parameter("Diaphragm", diaphragm,
                      "[3D frame] rigid: each floor a rigid diaphragm, its joints slaved "
                      "exactly to (ux, uy, rz) at the mass centre (which carries the floor "
                      "mass and polar moment; the joints carry the vertical mass); none: "
                      "every joint free, the floor mass in equal shares at the joints (no "
                      "contact in plan). Unit: -.",
                      Patterns::Selection("rigid|none"));
  }

  void
  BuildingParameters::finalize_frame_3d(const InputFile &input, const std::string &s)
  {
    const unsigned int n        = n_storeys;
    const auto         required = [&](const std::string &entry, const std::vector<double> &values,
                              const char *what) {
      if (values.empty())
        input.fail(s + entry,
                           "a 3D frame needs the " + std::string(what) + " (one value or one per storey)");
      input.list(s + entry, values, n, false, "one per storey");
      for (const double v : values)
        input.positive(s + entry, v);
    };
    required("Column G", column_shear_modulus, "columns' shear modulus G");
    required("Column Iz", column_second_moment_z, "columns' second moment Iz");
    required("Column J", column_torsion_constant, "columns' torsion constant J");
    required("Beam G", beam_shear_modulus, "beams' shear modulus G");
    required("Beam Iz", beam_second_moment_z, "beams' second moment Iz");
    required("Beam J", beam_torsion_constant, "beams' torsion constant J");
    required("Column E", column_youngs_modulus, "columns' Young's modulus E");
    required("Column A", column_area, "columns' area A");
    required("Column I", column_second_moment, "columns' second moment I");
    required("Beam E", beam_youngs_modulus, "beams' Young's modulus E");
    required("Beam A", beam_area, "beams' area A");
    required("Beam I", beam_second_moment, "beams' second moment I");
    for (const auto &[entry, values] :
         {std::pair<const char *, const std::vector<double> *>{"Column Avz", &column_shear_area_z},
          {"Column Avy", &column_shear_area_y},
          {"Beam Avz", &beam_shear_area_z},
          {"Beam Avy", &beam_shear_area_y}})
      input.list(s + entry, *values, n, true, "one per storey");
    if (n_bays_y > 0)
      input.list(s + "Bay widths y", bay_widths_y, n_bays_y, false, "one per bay");
    if (n_bays_y == 0 && diaphragm == "rigid")
      input.fail(s + "Number of bays y",
                 "all columns stand on one line along x: a rigid diaphragm on them is "
                 "singular (no frame across the line holds its sway along y and its "
                 "twist); give bays along y, or Diaphragm = none");
    if (elements_per_member != 1)
      input.fail(s + "Elements per member", "3D frames take one element per member");
    if (!plan.planes_text.empty())
      input.fail(s + "Plan/Resisting planes",
                 "a frame resists with its columns: resisting planes are for "
                 "shear buildings");
    const auto total = [](const std::vector<double> &widths, const unsigned int n_bays) {
      double sum = 0;
      for (unsigned int i = 0; i < n_bays; ++i)
        sum += widths.size() == 1 ? widths[0] : widths[i];
      return sum;
    };
    // The slab is the column grid (a line of columns: a slab 1e-3 of its
    // length wide, for contact and the default polar moment).
    const double lx = total(bay_widths, n_bays);
    const double ly = n_bays_y > 0 ? total(bay_widths_y, n_bays_y) : 1e-3 * lx;
    plan.dimensions = {lx, ly};
  }
} // namespace poundfe
