// The entries of a 3D frame building (Model/Dimension = 3, Type = frame):
// the bays along y, the second bending axis and the twist of the sections,
// the columns' local axes and the floor diaphragm (model/frame_building_3d.h,
// doc/theory.md §1.15), and the set-backs (model/set_backs.h).
#include <poundfe/base/numbers.h>
#include <poundfe/model/member_rigidities.h>
#include <poundfe/model/parameters.h>
#include <poundfe/model/plan_builder.h>
#include <poundfe/model/section_shorthands.h>
#include <poundfe/model/set_backs.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <sstream>

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
    declare_poisson_ratio(prm);
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
    prm.add_parameter("Set-backs", set_backs_text,
                      "[3D frame] Set-backs, separated by ';', each 'storey: n_-x n_+x n_-y "
                      "n_+y': from that storey (2 or above) up to the next entry, the "
                      "storeys keep the grid less n bays on each side (-x, +x, -y, +y, "
                      "counted on the whole grid; no storey wider than the one below). "
                      "The floors' slab outline, mass centre and polar moment follow the "
                      "reduced plan, e.g. '4: 0 1 0 0; 6: 1 1 0 0'. Unit: count.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
    prm.add_parameter("Diaphragm", diaphragm,
                      "[3D frame, mesh] rigid: each floor a rigid diaphragm, its joints slaved "
                      "exactly to (ux, uy, rz) at the mass centre (which carries the floor "
                      "mass and polar moment; the joints carry the vertical mass: Vertical floor mass); none: "
                      "every joint free, the floor mass in equal shares at the joints (no "
                      "contact in plan). Unit: -.",
                      Patterns::Selection("rigid|none"));
    prm.add_parameter("Vertical floor mass", vertical_floor_mass,
                      "[3D frame, mesh] joints: each joint's vertical DOF carries an equal "
                      "share of its floor's mass (the floor's vertical and rocking inertia: "
                      "its vertical modes, and the joints' vertical motion in sway); none: "
                      "the floor mass moves along x and y and turns (polar moment) at the "
                      "diaphragm's master only (with Diaphragm = none: at the joints along x "
                      "and y only), the joints' vertical DOFs carry no floor mass, as the "
                      "storeys of a shear building. Either way the floor's weight loads its "
                      "joints in the gravity analysis. Unit: -.",
                      Patterns::Selection("joints|none"));
  }

  void
  BuildingParameters::finalize_frame_3d(const InputFile &input, const std::string &s)
  {
    const unsigned int n        = n_storeys;
    // a fibre building's rigidities are its sections' (its entries refused)
    const auto         required = [&](const std::string &entry, const std::vector<double> &values,
                              const char *what) {
      if (!fibre())
        require_positive_list(input, s + entry, values, n, "a 3D frame needs the " +
                                                             std::string(what), "one per storey");
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
    if (!fibre())
      {
        check_member_rigidities(input, s, "Column", column_youngs_modulus, column_area,
                                column_second_moment);
        check_member_rigidities(input, s, "Beam", beam_youngs_modulus, beam_area,
                                beam_second_moment);
      }
    for (const auto &[entry, values] :
         {std::pair<const char *, const std::vector<double> *>{"Column Avz", &column_shear_area_z},
          {"Column Avy", &column_shear_area_y},
          {"Beam Avz", &beam_shear_area_z},
          {"Beam Avy", &beam_shear_area_y}})
      input.list(s + entry, *values, n, true, "one per storey");
    if (n_bays_y > 0)
      input.list(s + "Bay widths y", bay_widths_y, n_bays_y, false, "one per bay");
    for (const double w : bay_widths_y)
      input.at_most(s + "Bay widths y", w, largest_building_length, "m",
                    "10 km is beyond any building");
    if (n_bays_y == 0 && diaphragm == "rigid")
      input.fail(s + "Number of bays y",
                 "all columns stand on one line along x: a rigid diaphragm on them is "
                 "singular (no frame across the line holds its sway along y and its "
                 "twist); give bays along y, or Diaphragm = none");
    check_one_element_no_planes(input, s);
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
    parse_set_backs(*this, input, s);
  }

  void
  BuildingParameters::check_one_element_no_planes(const InputFile &input,
                                                  const std::string &s) const
  {
    if (elements_per_member != 1)
      input.fail(s + "Elements per member", "3D frames take one element per member");
    if (!plan.planes_text.empty())
      input.fail(s + "Plan/Resisting planes",
                 "a frame resists with its columns: resisting planes are for "
                 "shear buildings");
  }

  void
  require_positive_list(const InputFile &input, const std::string &path,
                        const std::vector<double> &values, const std::size_t n,
                        const std::string &need, const std::string &per)
  {
    if (values.empty())
      input.fail(path, need + " (one value or " + per + ")");
    input.list(path, values, n, false, per);
    for (const double v : values)
      input.positive(path, v);
  }

  // Set-backs (include/poundfe/model/set_backs.h).
  std::vector<double>
  grid_lines(const std::vector<double> &widths, const unsigned int n_bays)
  {
    std::vector<double> x(n_bays + 1, 0);
    for (unsigned int j = 0; j < n_bays; ++j)
      x[j + 1] = x[j] + value_for(widths, j);
    for (double &v : x)
      v -= 0.5 * x.back();
    return x;
  }

  KeptGrid
  kept_grid(const BuildingParameters &p, const unsigned int storey)
  {
    std::array<unsigned int, 4> removed{{0, 0, 0, 0}};
    for (const BuildingParameters::SetBack &s : p.set_backs) // by increasing storey
      if (s.storey <= storey)
        removed = s.removed;
    KeptGrid kept;
    kept.x = {{removed[0], p.n_bays - removed[1]}};
    kept.y = {{removed[2], p.n_bays_y - removed[3]}};
    return kept;
  }

  FloorRectangle
  floor_rectangle(const BuildingParameters &p, const unsigned int storey)
  {
    FloorRectangle rectangle;
    rectangle.dimensions = {p.plan.dimensions[0], p.plan.dimensions[1]};
    if (p.set_backs.empty() || storey < p.set_backs.front().storey)
      return rectangle; // the whole plan: exactly as without set-backs
    const KeptGrid            kept = kept_grid(p, storey);
    const std::vector<double> xs   = grid_lines(p.bay_widths, p.n_bays);
    rectangle.centre.x             = 0.5 * (xs[kept.x[0]] + xs[kept.x[1]]);
    rectangle.dimensions.x         = xs[kept.x[1]] - xs[kept.x[0]];
    if (p.n_bays_y > 0) // a line of columns keeps its thin slab
      {
        const std::vector<double> ys = grid_lines(p.bay_widths_y, p.n_bays_y);
        rectangle.centre.y           = 0.5 * (ys[kept.y[0]] + ys[kept.y[1]]);
        rectangle.dimensions.y       = ys[kept.y[1]] - ys[kept.y[0]];
      }
    return rectangle;
  }

  namespace
  {
    /// One 'storey: n_-x n_+x n_-y n_+y' entry.
    BuildingParameters::SetBack
    parse_set_back(const BuildingParameters &p, const InputFile &input, const std::string &path,
                   const std::string &entry)
    {
      BuildingParameters::SetBack s;
      std::istringstream          fields(entry);
      std::string                 storey, rest;
      const auto                  bad = [&](const std::string &why) {
        input.fail(path, "'" + entry + "': " + why);
      };
      if (!std::getline(fields, storey, ':'))
        bad("expected 'storey: bays removed on the -x +x -y +y sides'");
      const std::optional<unsigned long> n = parse_count(trimmed(storey), 1u << 20);
      if (!n || fields.eof())
        bad("expected 'storey: bays removed on the -x +x -y +y sides'");
      s.storey = *n;
      for (unsigned int &r : s.removed)
        if (!read_number(fields, r))
          bad("expected four whole numbers of bays after the storey (-x +x -y +y)");
      if (fields >> rest)
        bad("expected four whole numbers of bays after the storey (-x +x -y +y), got more");
      if (s.storey < 2 || s.storey > p.n_storeys)
        bad("storey " + std::to_string(s.storey) + " does not exist or is the first: a "
            "set-back applies to storeys 2 to " + std::to_string(p.n_storeys) +
            " (storey 1 stands on the whole grid)");
      if (s.removed[0] + s.removed[1] >= p.n_bays)
        bad("removes " + std::to_string(s.removed[0] + s.removed[1]) + " of the " +
            std::to_string(p.n_bays) + " bays along x: a storey keeps at least one bay");
      if (s.removed[2] + s.removed[3] > 0 && s.removed[2] + s.removed[3] >= p.n_bays_y)
        bad("removes " + std::to_string(s.removed[2] + s.removed[3]) + " of the " +
            std::to_string(p.n_bays_y) + " bays along y: a storey keeps at least one bay");
      return s;
    }
  } // namespace

  void
  parse_set_backs(BuildingParameters &p, const InputFile &input, const std::string &section)
  {
    const std::string path = section + "Set-backs";
    p.set_backs.clear();
    for (const std::string &text : p.set_backs_text)
      {
        const std::string entry = trimmed(text);
        if (!entry.empty())
          p.set_backs.push_back(parse_set_back(p, input, path, entry));
      }
    std::sort(p.set_backs.begin(), p.set_backs.end(),
              [](const auto &a, const auto &b) { return a.storey < b.storey; });
    std::array<unsigned int, 4> below{{0, 0, 0, 0}}; // storey 1: the whole grid
    unsigned int                below_storey = 1;
    for (const BuildingParameters::SetBack &s : p.set_backs)
      {
        if (s.storey == below_storey)
          input.fail(path, "storey " + std::to_string(s.storey) + " is given twice");
        for (unsigned int side = 0; side < 4; ++side)
          if (s.removed[side] < below[side])
            input.fail(path, "storey " + std::to_string(s.storey) + " is wider than storey " +
                               std::to_string(s.storey - 1) + " on its " +
                               std::array<const char *, 4>{{"-x", "+x", "-y", "+y"}}[side] +
                               " side (" + std::to_string(s.removed[side]) + " bays removed, " +
                               std::to_string(below[side]) + " below): its columns would "
                               "stand on no joint");
        below        = s.removed;
        below_storey = s.storey;
      }
  }
} // namespace poundfe
