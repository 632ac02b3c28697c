// The entries of a 3D frame drawn in Gmsh (Model/Dimension = 3, Type =
// mesh; model/mesh_building_3d.h, doc/theory.md §1.15, "Frames drawn in
// Gmsh"): per member group the shear modulus, the second moment about the
// local z axis, the torsion constant and the vector v that fixes the local
// axes (OpenSees's vecxz: y = v × x), as Column G/Iz/J and Column angle do
// for a generated 3D frame.
#include <poundfe/base/numbers.h>
#include <poundfe/model/parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  void
  BuildingParameters::declare_mesh_3d_entries(dealii::ParameterHandler &prm)
  {
    prm.add_parameter("Group G", group_shear_modulus,
                      "[3D mesh] Shear modulus per group (required). Unit: Pa.");
    prm.add_parameter("Group Iz", group_second_moment_z,
                      "[3D mesh] Second moment about the local z axis per group (bending in "
                      "the local x-y plane; Group I: about the local y axis) (required). "
                      "Unit: m^4.");
    prm.add_parameter("Group J", group_torsion_constant,
                      "[3D mesh] Torsion constant per group (required). Unit: m^4.");
    prm.add_parameter("Group orientation", group_orientation_text,
                      "[3D mesh] Per group, separated by ';', a vector 'vx vy vz' in the "
                      "local x-z plane of its members (local y = v x local x; not along "
                      "a member), or empty: vertical members global X, the others global "
                      "Z (the generated 3D frame's columns with Column angle 0 and its "
                      "beams). E.g. '1 0 0; ; 0 1 0'. Unit: -.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
  }

  void
  BuildingParameters::finalize_mesh_3d(const InputFile &input, const std::string &s)
  {
    const std::size_t g        = group_ids.size();
    const auto        required = [&](const std::string &entry, const std::vector<double> &values,
                              const char *what) {
      require_positive_list(input, s + entry, values, g,
                            "a 3D mesh building needs the " + std::string(what),
                            "one per group id");
    };
    if (!fibre()) // a fibre mesh's members take their rigidities from their sections
      {
        required("Group G", group_shear_modulus, "groups' shear modulus G");
        required("Group Iz", group_second_moment_z, "groups' second moment Iz");
        required("Group J", group_torsion_constant, "groups' torsion constant J");
      }
    for (const auto &[entry, values] :
         {std::pair<const char *, const std::vector<double> *>{"Group E", &group_youngs_modulus},
          {"Group A", &group_area},
          {"Group I", &group_second_moment}})
      for (const double v : *values)
        input.positive(s + entry, v);
    check_one_element_no_planes(input, s);

    const std::string path = s + "Group orientation";
    group_orientations.assign(g, {{0, 0, 0}});
    const bool blank = group_orientation_text.size() == 1 && trimmed(group_orientation_text[0]).empty();
    if (group_orientation_text.empty() || blank)
      return;
    if (group_orientation_text.size() != g)
      input.fail(path, "needs one entry per group id (" + std::to_string(g) + ", ';' between; "
                       "an empty entry: the default), got " +
                         std::to_string(group_orientation_text.size()));
    for (std::size_t i = 0; i < g; ++i)
      {
        const std::string entry = trimmed(group_orientation_text[i]);
        if (entry.empty())
          continue;
        std::istringstream    fields(entry);
        std::array<double, 3> v{{0, 0, 0}};
        std::string           rest;
        for (double &c : v)
          if (!read_number(fields, c))
            input.fail(path, "'" + entry + "': expected three numbers 'vx vy vz'");
        if (fields >> rest)
          input.fail(path, "'" + entry + "': expected three numbers 'vx vy vz', got more");
        if (!(std::hypot(v[0], v[1], v[2]) > 0))
          input.fail(path, "'" + entry + "': the vector is zero");
        group_orientations[i] = v;
      }
  }
} // namespace poundfe
