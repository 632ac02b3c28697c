// The parts of `poundfe export-opensees`'s description shared by its two
// files (report/opensees_export.cc: shear buildings, gaps, the excitation;
// report/opensees_export_frames.cc: frames and the gravity analysis). Private
// to source/report/.
#ifndef poundfe_report_opensees_export_parts_h
#define poundfe_report_opensees_export_parts_h

#include <poundfe/base/input_file.h>
#include <poundfe/report/opensees_export.h>

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace poundfe::opensees_export
{
  /// A number as OpenSees reads it back to the last bit.
  std::string exact_text(double value);

  /// "Building <b + 1>/entry".
  std::string building_entry(unsigned int b, const std::string &entry);

  /// Numbers of the script being written: the next free tags.
  struct Tags
  {
    int node = 0, material = 1, element = 1, section = 1, integration = 1;
    /// The sections written (Model::section_laws index -> tag) and the
    /// beamIntegrations ((section, force-based, points) -> tag).
    std::map<int, int>                sections;
    std::map<std::array<int, 3>, int> integrations;
    /// The Rayleigh-damped elements (members, hinges) of each building.
    std::map<unsigned int, std::vector<int>> damped;
  };

  /// The lumped mass on the node's DOF `c` (0 when fixed); InputError when
  /// M couples it to another equation.
  double node_mass(const Analysis &analysis, unsigned int node, Component c,
                   const InputFile &input);

  /// A node at `position` ("x [y [z]]") fixed in every DOF (a dashpot's
  /// ground, a barrier), with `what` as its comment.
  void add_fixed_node(int tag, const std::string &position, const std::string &what,
                      OpenSeesExport &out);

  /// The a0 M term of node n (the building's a0) with `masses` on the
  /// zeroLength directions given: a zeroLength of dashpots Elastic 0 a0 m to
  /// a fixed node at `position`.
  void describe_mass_dashpots(const Analysis &analysis, unsigned int n,
                              const std::vector<std::pair<unsigned int, double>> &masses,
                              const std::string &position, Tags &tags, OpenSeesExport &out);

  /// Whether the model is written in the plane (model basic -ndm 2 -ndf 3):
  /// some building is not a shear building.
  bool in_plane(const Model &model);

  /// The parts of a 2D frame OpenSees cannot be given the same way:
  /// InputError naming the first one's entry.
  void refuse_frame_parts(const Analysis &analysis, const InputFile &input);

  /// Every node in the plane (-ndm 2 -ndf 3) with its masses and fixities,
  /// and each building's a0 M as dashpots to fixed nodes of their own.
  void describe_plane_nodes(const Analysis &analysis, const InputFile &input, Tags &tags,
                            OpenSeesExport &out);

  /// The frames' members (elasticBeamColumn, or fibre beam-columns) and
  /// their a1 K (rayleigh).
  void describe_members(const Analysis &analysis, const InputFile &input, Tags &tags,
                        OpenSeesExport &out);

  /// The element command of a fibre member (report/opensees_export_fibres.cc),
  /// its section, materials and beamIntegration written first when new;
  /// geomTransf 1 is Linear, 2 PDelta.
  std::string fibre_member_command(const Model &model, const Member &member,
                                   const InputFile &input, Tags &tags, OpenSeesExport &out);
  /// The same for a member of `fibre` between the script's `nodes` on the
  /// geomTransf `transformation` (2D or 3D).
  std::string fibre_element_command(const Model &model, const FibreMember &fibre,
                                    const std::array<int, 2> &nodes, int transformation,
                                    const InputFile &input, Tags &tags, OpenSeesExport &out);

  /// uniaxialMaterial BoucWen of poundfe's Bouc-Wen law `p` (z scaled by
  /// its yield deformation) with a comment naming `label`, and the comment
  /// that says what the parameters are.
  std::string bouc_wen_material(const BoucWenParameters &p, int tag, const std::string &label);
  std::string bouc_wen_comment();

  /// The frames' Bouc-Wen hinges: zeroLength rotational springs on BoucWen.
  void describe_hinges(const Analysis &analysis, Tags &tags, OpenSeesExport &out);

  /// The parts of a 3D frame OpenSees cannot be given the same way
  /// (report/opensees_export_3d.cc): InputError naming the first one's entry.
  void refuse_3d_parts(const Analysis &analysis, const InputFile &input);

  /// 3D frames (-ndm 3 -ndf 6): the floors' masters, the joints under
  /// rigidDiaphragm, the fixed bases, the members, and the floors to record.
  void describe_frames_3d(const Analysis &analysis, const InputFile &input, Tags &tags,
                          OpenSeesExport &out);

  /// The stiffness-proportional Rayleigh a1 of the buildings of the
  /// model's members (2D and 3D): one `rayleigh` for all when they share it
  /// (out.member_stiffness_damping), else a `region` of each building's
  /// damped elements (out.damping_regions).
  void frames_stiffness_damping(const Analysis &analysis, const Tags &tags,
                                OpenSeesExport &out);

  /// Model/Gravity analysis: the loads and the static analysis.
  void describe_gravity(const Analysis &analysis, OpenSeesExport &out);
} // namespace poundfe::opensees_export

#endif
