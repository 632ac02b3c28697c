// The 3D frames of a poundfe model in an OpenSees 3.8 script (report/
// opensees_export.h; model/frame_building_3d.h). poundfe reduces a rigid
// floor exactly to its mass centre's (ux, uy, θz) (ux = ux_C - (y - C_y)
// θz, uy = uy_C + (x - C_x) θz, rz = θz), each joint keeping its uz, rx,
// ry; OpenSees's rigidDiaphragm 3 under constraints Transformation is the
// same reduction (RigidDiaphragm.cpp). So: a node at each floor's mass
// centre (its mass and polar moment on 1, 2 and 6; 3, 4, 5 fixed), a node
// at each joint (its uz mass; 1, 2 and 6 the diaphragm's), the base joints
// fixed, and each member an elasticBeamColumn A E G J Iy Iz on geomTransf
// Linear with poundfe's v_xz (the same local axes: y = v_xz x x, z = x x
// y, Iy the bending in the local x-z plane; LinearCrdTransf3d.cpp).
#include <poundfe/base/exceptions.h>

#include "opensees_export_parts.h"

#include <algorithm>
#include <map>

namespace poundfe::opensees_export
{
  namespace
  {
    /// The model DOF (and coefficient) of row `row` of a member's map when
    /// it has exactly one term; -1 when it has none; -2 when more.
    std::pair<int, double>
    single_term(const Member3D &member, const unsigned int row)
    {
      std::pair<int, double> term{-1, 0.0};
      const unsigned int     n = member.dofs.size();
      for (unsigned int i = 0; i < n; ++i)
        if (const double c = member.map[row * n + i]; c != 0)
          term = term.first == -1 ? std::make_pair(int(member.dofs[i]), c) :
                                    std::make_pair(-2, 0.0);
      return term;
    }

    /// The node whose ux enters row `row` (a ux row) with coefficient 1: the
    /// floor's master; -1 if none.
    int
    master_of(const Member3D &member, const unsigned int row)
    {
      const unsigned int n = member.dofs.size();
      for (unsigned int i = 0; i < n; ++i)
        if (member.map[row * n + i] == 1 && member.dofs[i] % n_dofs_per_node == 0)
          return member.dofs[i] / n_dofs_per_node;
      return -1;
    }

    std::string
    point_text(const std::array<double, 3> &p)
    {
      return exact_text(p[0]) + " " + exact_text(p[1]) + " " + exact_text(p[2]);
    }

    /// What the script's nodes of the members' ends are.
    struct Joints3D
    {
      std::map<unsigned int, std::array<double, 3>> joints; // joint node -> (x, y, z)
      std::map<unsigned int, std::vector<unsigned int>> floors; // master -> its joints
      std::map<std::string, int> ground;                         // position -> tag
      std::vector<std::array<int, 2>> ends;                      // each member's tags
    };

    /// The joints of every member end from the members' maps: a joint node
    /// (uz, rx, ry on its slots 0, 1, 2) under a floor's master, or the
    /// ground; anything else InputError (the refusals come first).
    Joints3D
    find_joints(const Model &model, const InputFile &input, Tags &tags)
    {
      Joints3D j;
      for (const Member3D &member : model.members_3d)
        {
          std::array<int, 2> tags_of_ends{};
          for (unsigned int k = 0; k < 2; ++k)
            {
              const auto vertical = single_term(member, 6 * k + 2);
              const int  master   = master_of(member, 6 * k);
              if (vertical.first == -1 && single_term(member, 6 * k).first == -1) // clamped
                {
                  auto [at, fresh] = j.ground.emplace(point_text(member.ends[k]), 0);
                  if (fresh)
                    at->second = ++tags.node;
                  tags_of_ends[k] = at->second;
                  continue;
                }
              if (vertical.first < 0 || vertical.second != 1 || master < 0)
                input.fail(building_entry(member.building, "Diaphragm"),
                           "export-opensees writes 3D frames of rigid floors on clamped bases "
                           "only (member " + member.label + ")");
              const unsigned int joint = vertical.first / n_dofs_per_node;
              if (j.joints.emplace(joint, member.ends[k]).second)
                j.floors[master].push_back(joint);
              tags_of_ends[k] = joint + 1;
            }
          j.ends.push_back(tags_of_ends);
        }
      return j;
    }

    /// "-mass m1 ... m6" of `masses` (empty when all 0).
    std::string
    mass_text(const std::array<double, 6> &masses)
    {
      std::string text;
      for (const double m : masses)
        text += " " + exact_text(m);
      return std::any_of(masses.begin(), masses.end(), [](double m) { return m != 0; }) ?
               " -mass" + text :
               std::string();
    }

    /// A floor's master at its mass centre, its joints and rigidDiaphragm.
    void
    describe_floor(const Analysis &analysis, const InputFile &input, const unsigned int master,
                   const std::array<double, 3> &centre, const Joints3D &j, Tags &tags,
                   OpenSeesExport &out)
    {
      std::array<double, 6> masses{};
      std::vector<std::pair<unsigned int, double>> dashpots;
      for (const auto &[c, dof] : {std::pair{0u, 1u}, std::pair{1u, 2u}, std::pair{2u, 6u}})
        {
          masses[dof - 1] = node_mass(analysis, master, Component(c), input);
          dashpots.emplace_back(dof, masses[dof - 1]);
        }
      out.model.push_back("node " + std::to_string(master + 1) + " " + point_text(centre) +
                          mass_text(masses));
      out.model.push_back("fix " + std::to_string(master + 1) + " 0 0 1 1 1 0");
      describe_mass_dashpots(analysis, master, dashpots, point_text(centre), tags, out);
      std::string slaves;
      for (const unsigned int joint : j.floors.at(master))
        {
          std::array<double, 6> joint_masses{};
          std::string           fixity;
          dashpots.clear();
          for (unsigned int c = 0; c < 3; ++c)
            {
              joint_masses[2 + c] = node_mass(analysis, joint, Component(c), input);
              dashpots.emplace_back(3 + c, joint_masses[2 + c]);
              fixity += analysis.model.equation(Model::dof(joint, Component(c))) < 0 ? " 1" : " 0";
            }
          const std::string position = point_text(j.joints.at(joint));
          out.model.push_back("node " + std::to_string(joint + 1) + " " + position +
                              mass_text(joint_masses));
          if (fixity.find('1') != std::string::npos)
            out.model.push_back("fix " + std::to_string(joint + 1) + " 0 0" + fixity + " 0");
          describe_mass_dashpots(analysis, joint, dashpots, position, tags, out);
          slaves += " " + std::to_string(joint + 1);
        }
      out.model.push_back("rigidDiaphragm 3 " + std::to_string(master + 1) + slaves);
    }
  } // namespace

  void
  refuse_3d_parts(const Analysis &analysis, const InputFile &input)
  {
    const Model &model = analysis.model;
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      if (model.buildings[b].type != BuildingType::frame)
        input.fail(building_entry(b, "Type"), "export-opensees writes 3D frames only");
    for (const Hinge3D &hinge : model.hinges_3d)
      input.fail(building_entry(hinge.building, "Hinges/Locations"),
                 "export-opensees writes 3D frames without hinges");
    for (const Member3D &member : model.members_3d)
      {
        const Section3D &s = member.section;
        if (s.shear_area_y != 0 || s.shear_area_z != 0)
          input.fail(building_entry(member.building, member.kind == MemberKind::beam ?
                                                       "Beam Avy" : "Column Avy"),
                     "export-opensees writes 3D members without shear deformation "
                     "(OpenSees's elasticBeamColumn)");
        if (s.mass_per_length != 0)
          input.fail(building_entry(member.building, member.kind == MemberKind::beam ?
                                                       "Beam mass per length" :
                                                       "Column mass per length"),
                     "export-opensees writes 3D members without mass: the script's check, "
                     "`poundfe opensees`, takes no mass on a node under rigidDiaphragm");
      }
    if (!model.gaps.empty())
      input.fail("Contact/Law", "export-opensees writes no contact in plan (3D)");
  }

  void
  describe_frames_3d(const Analysis &analysis, const InputFile &input, Tags &tags,
                     OpenSeesExport &out)
  {
    const Model   &model = analysis.model;
    const Joints3D j     = find_joints(model, input, tags);
    out.tied             = true;
    out.model.push_back("# floors: a master node at the mass centre (ux, uy, rz), the joints "
                        "(uz, rx, ry their own) under rigidDiaphragm 3; the bases fixed");
    for (const auto &[position, tag] : j.ground)
      add_fixed_node(tag, position, "", out);
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const Building &building = model.buildings[b];
        for (unsigned int f = 0; f < building.floors.size(); ++f)
          {
            const unsigned int master = building.floors[f].nodes.front();
            const Point2      &c      = building.plan[f].mass_centre;
            describe_floor(analysis, input, master, {{c.x, c.y, building.floors[f].level}}, j,
                           tags, out);
            const std::string name = building.name + "_floor" + std::to_string(f + 1);
            out.floor_nodes.push_back(master + 1);
            for (const char *what : {"_disp_x_m", "_disp_y_m", "_rot_z_rad"})
              out.floor_names.push_back(name + what);
          }
      }
    out.floor_dofs = "1 2 6";
    out.model.push_back("# members: elasticBeamColumn A E G J Iy Iz, or fibre beam-columns, on "
                        "geomTransf with poundfe's v_xz");
    std::map<std::string, int> transformations; // (type, v_xz) -> tag
    for (unsigned int m = 0; m < model.members_3d.size(); ++m)
      {
        const Member3D   &member = model.members_3d[m];
        const std::string kind =
          member.fibre.fibre() && member.fibre.p_delta ? "PDelta " : "Linear ";
        const std::string v = point_text(member.orientation);
        auto [at, fresh]    = transformations.emplace(kind + v, transformations.size() + 1);
        if (fresh)
          out.model.push_back("geomTransf " + kind + std::to_string(at->second) + " " + v);
        const Section3D &s = member.section;
        tags.damped[member.building].push_back(tags.element);
        out.model.push_back(
          (member.fibre.fibre() ?
             fibre_element_command(model, member.fibre, j.ends[m], at->second, input, tags, out) :
             "element elasticBeamColumn " + std::to_string(tags.element++) + " " +
               std::to_string(j.ends[m][0]) + " " + std::to_string(j.ends[m][1]) + " " +
               exact_text(s.area) + " " + exact_text(s.youngs_modulus) + " " +
               exact_text(s.shear_modulus) + " " + exact_text(s.torsion_constant) + " " +
               exact_text(s.second_moment_y) + " " + exact_text(s.second_moment_z) + " " +
               std::to_string(at->second)) +
          " ;# " + comment_word(member.label));
      }
  }
} // namespace poundfe::opensees_export
