// The 2D frames of a poundfe model in an OpenSees 3.8 script (report/
// opensees_export.h). A member is poundfe's Euler-Bernoulli frame element
// (elements/frame_element.h: the exact stiffness of a prismatic member loaded
// at its ends, k = E I / L [12/L^2, 6/L, 4, 2] in bending, E A / L axially),
// which is OpenSees's elasticBeamColumn on geomTransf Linear
// (ElasticBeam2d.cpp); its mass is in M, which the nodes carry. Rayleigh's
// a1 K is `rayleigh 0 0 a1 0`: betaKinit, the initial stiffness of the
// elements that take Rayleigh damping (the members and hinges; zeroLength
// does not by default, ZeroLength.cpp), as poundfe's C = a0 M + a1 K, K
// without the gaps (assembly/linear_system.cc, assemble_damping); frames of
// different a1 each get theirs by `region tag -eleOnly ... -rayleigh 0 0 a1
// 0` over their members and hinges (OpenSees's MeshRegion sets the
// elements' factors; the nodes' alphaM stays 0: a0 M is the dashpots'). The gravity analysis
// is OpenSees's usual one (Plain pattern on a Linear series, LoadControl
// 1/n over n steps, loadConst -time 0) with the loads poundfe applies
// (assembly/linear_system.h, total_gravity_loads).
#include <poundfe/base/exceptions.h>

#include <algorithm>
#include <cmath>

#include "opensees_export_parts.h"

namespace poundfe::opensees_export
{
  namespace
  {
    /// The script's DOF (1-based) of slot c of model node n: a 3D joint's
    /// (uz, rx, ry) are 3, 4, 5, a 3D floor's (ux, uy, θz) 1, 2, 6.
    unsigned int
    script_dof(const Model &model, const unsigned int n, const unsigned int c,
               const OpenSeesExport &out)
    {
      if (out.ndm != 3)
        return c + 1;
      return model.nodes[n].generalized ? 3 + c : c == 2 ? 6 : c + 1;
    }

    /// The loads of node n's DOFs among `loads` (by equation), each
    /// equation's once: `seen` marks those given.
    std::string
    node_loads(const Model &model, const unsigned int n, const Vector &loads,
               const OpenSeesExport &out, std::vector<char> &seen)
    {
      std::vector<double> values(out.ndf, 0.0);
      for (unsigned int c = 0; c < n_dofs_per_node; ++c)
        if (const int eq = model.equation(Model::dof(n, Component(c))); eq >= 0 && !seen[eq])
          {
            seen[eq]                                  = 1;
            values[script_dof(model, n, c, out) - 1] = loads[eq];
          }
      std::string text;
      for (const double value : values)
        text += " " + exact_text(value);
      return std::any_of(values.begin(), values.end(), [](double v) { return v != 0; }) ?
               "  load " + std::to_string(n + 1) + text :
               std::string();
    }

    std::string
    elastic_member_command(const Member &member, Tags &tags)
    {
      const Section &s = member.section;
      return "element elasticBeamColumn " + std::to_string(tags.element++) + " " +
             std::to_string(member.nodes[0] + 1) + " " + std::to_string(member.nodes[1] + 1) +
             " " + exact_text(s.area) + " " + exact_text(s.youngs_modulus) + " " +
             exact_text(s.second_moment) + " 1";
    }
  } // namespace

  void
  frames_stiffness_damping(const Analysis &analysis, const Tags &tags, OpenSeesExport &out)
  {
    if (tags.damped.empty())
      return;
    const auto a1_of = [&](const unsigned int b) { return analysis.system.rayleigh.at(b)[1]; };
    const double a1  = a1_of(tags.damped.begin()->first);
    if (std::all_of(tags.damped.begin(), tags.damped.end(),
                    [&](const auto &building) { return a1_of(building.first) == a1; }))
      {
        out.member_stiffness_damping = a1;
        return;
      }
    for (const auto &[b, elements] : tags.damped)
      if (a1_of(b) != 0)
        out.damping_regions.push_back(
          {b + 1, analysis.model.buildings[b].name, a1_of(b), elements});
  }

  bool
  in_plane(const Model &model)
  {
    for (const Building &building : model.buildings)
      if (building.type != BuildingType::shear)
        return true;
    return false;
  }

  std::string
  bouc_wen_comment()
  {
    return "BoucWen alpha k n gamma beta A dA dnu deta tol maxIter with z = u_y z_poundfe: "
           "gamma and beta over u_y^n, the degradations over (1 - alpha) k u_y^2; OpenSees's "
           "BoucWen integrates z by backward Euler, poundfe's by the trapezoidal rule, so the "
           "two agree as the time step shrinks (to first order), not at one step";
  }

  void
  refuse_frame_parts(const Analysis &analysis, const InputFile &input)
  {
    const auto self_weight = [&](const unsigned int building) {
      input.fail(building_entry(building, "Member self-weight"),
                 "export-opensees writes no element loads: a distributed self-weight would be "
                 "eleLoad -beamUniform on every member, which the export does not write yet "
                 "(use Member self-weight = nodal)");
    };
    for (const Member &member : analysis.model.members)
      if (member.weight_per_length != 0)
        self_weight(member.building);
    for (const Member3D &member : analysis.model.members_3d)
      if (member.weight_per_length != 0)
        self_weight(member.building);
    for (const Hinge &hinge : analysis.model.hinges)
      if (hinge.law.A != 1)
        input.fail(building_entry(hinge.building, "Bouc-Wen/A"),
                   "export-opensees writes hinges of A = 1 only: OpenSees's rayleigh damps a "
                   "zeroLength by its initial tangent alpha k + (1 - alpha) k A, poundfe's C "
                   "by the hinge's k");
    for (const StoreyLink &link : analysis.model.links)
      if (link.hysteretic && link.hysteresis.A != 1)
        input.fail(building_entry(link.building, "Bouc-Wen/A"),
                   "export-opensees writes Bouc-Wen storeys of A = 1 only: their initial "
                   "stiffness alpha k + (1 - alpha) k A would differ from the k in poundfe's K");
  }

  std::string
  bouc_wen_material(const BoucWenParameters &p, const int tag, const std::string &label)
  {
    const double u_y    = p.yield_deformation;
    const double u_y_n  = std::pow(u_y, p.n);
    const double energy = (1 - p.alpha) * p.stiffness * u_y * u_y;
    // alpha = 1: F = k u whatever z, and OpenSees's energy (1 - alpha) k int z du
    // stays 0, so any rate degrades nothing there: written as 0
    const auto per_energy = [energy](const double delta) {
      return exact_text(energy == 0 ? 0.0 : delta / energy);
    };
    return "uniaxialMaterial BoucWen " + std::to_string(tag) + " " + exact_text(p.alpha) + " " +
           exact_text(p.stiffness) + " " + exact_text(p.n) + " " + exact_text(p.gamma / u_y_n) +
           " " + exact_text(p.beta / u_y_n) + " " + exact_text(p.A) + " " +
           per_energy(p.delta_A) + " " + per_energy(p.delta_nu) + " " + per_energy(p.delta_eta) +
           " " + exact_text(1e-12 * u_y) + " 50 ;# " + label;
  }

  void
  describe_hinges(const Analysis &analysis, Tags &tags, OpenSeesExport &out)
  {
    const Model &model = analysis.model;
    if (model.hinges.empty())
      return;
    out.model.push_back("# hinges: zeroLength rz (joint, member end; -dir 6, the rotation about z) "
                        "on " + bouc_wen_comment());
    for (const Hinge &hinge : model.hinges)
      {
        tags.damped[hinge.building].push_back(tags.element);
        out.model.push_back(bouc_wen_material(hinge.law, tags.material, comment_word(hinge.label)));
        out.model.push_back("element zeroLength " + std::to_string(tags.element++) + " " +
                            std::to_string(hinge.joint_node + 1) + " " +
                            std::to_string(hinge.member_node + 1) + " -mat " +
                            std::to_string(tags.material++) + " -dir 6 -doRayleigh 1");
      }
    out.nonlinear = true;
  }

  void
  describe_members(const Analysis &analysis, const InputFile &input, Tags &tags,
                   OpenSeesExport &out)
  {
    const Model &model = analysis.model;
    if (model.members.empty())
      return;
    out.model.push_back("# members: elasticBeamColumn A E Iz (poundfe's Euler-Bernoulli frame "
                        "element) or fibre beam-columns; their mass is on the nodes");
    out.model.push_back("geomTransf Linear 1");
    if (std::any_of(model.members.begin(), model.members.end(),
                    [](const Member &m) { return m.fibre.fibre() && m.fibre.p_delta; }))
      out.model.push_back("geomTransf PDelta 2 ;# the columns of Member transformation PDelta");
    for (const Member &member : model.members)
      {
        tags.damped[member.building].push_back(tags.element);
        out.model.push_back(
          (member.fibre.fibre() ? fibre_member_command(model, member, input, tags, out) :
                                  elastic_member_command(member, tags)) +
          " ;# " + comment_word(member.label));
      }
  }

  void
  describe_gravity(const Analysis &analysis, OpenSeesExport &out)
  {
    const Model &model = analysis.model;
    if (!model.gravity_analysis.enabled)
      return;
    const unsigned int n_steps = model.gravity_analysis.n_steps;
    std::vector<std::string> &lines = out.gravity;
    lines.push_back("# Model/Gravity analysis: the weights of M's masses and the floor loads "
                    "(Fx Fy Mz), in " + std::to_string(n_steps) +
                    " load steps, then held through the record");
    lines.push_back("pattern Plain 2 Linear {");
    std::vector<char> seen(model.n_equations(), 0); // an equation's load once
    for (unsigned int n = 0; n < model.n_nodes(); ++n)
      if (const std::string load = node_loads(model, n, analysis.gravity.applied, out, seen);
          !load.empty())
        lines.push_back(load);
    lines.push_back("}");
    for (const std::string &line :
         {"constraints " + out.constraints(), std::string("numberer Plain"),
          std::string("system BandGeneral"),
          "test NormDispIncr 1.0e-12 " + std::to_string(model.gravity_analysis.max_iterations),
          std::string("algorithm Newton"),
          "integrator LoadControl " + exact_text(1.0 / n_steps), std::string("analysis Static"),
          "set status [analyze " + std::to_string(n_steps) + "]",
          std::string("puts \"gravity status $status\""), std::string("loadConst -time 0.0"),
          std::string("wipeAnalysis")})
      lines.push_back(line);
  }
} // namespace poundfe::opensees_export
