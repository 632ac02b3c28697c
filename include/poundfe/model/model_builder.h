// prm -> Model: generated frames, frames from Gmsh meshes, shear buildings,
// placed left to right with the given clear separations.
#ifndef poundfe_model_model_builder_h
#define poundfe_model_model_builder_h

#include <poundfe/base/input_file.h>
#include <poundfe/model/contact_parameters.h>
#include <poundfe/model/friction_parameters.h>
#include <poundfe/model/model.h>
#include <poundfe/model/parameters.h>

namespace poundfe
{
  /// Build the model and number its equations; `input` names the file in
  /// messages and resolves mesh files. Throws InputError.
  Model build_model(const ModelParameters &parameters, const ContactParameters &contact,
                    const InputFile &input, const SpringParameters &springs = {},
                    const FrictionParameters &friction = {});

  /// Member model = fibre: the beam-column of the columns of storey
  /// `storey` (0-based) or the beams of its floor on their Sections entry
  /// (none for another member model). PDelta columns with
  /// Member transformation = PDelta, or auto and a gravity analysis.
  FibreMember fibre_member(const Model &model, const BuildingParameters &p,
                           unsigned int storey, bool column);

  /// The beam-column of a mesh's members of group `group` (its index in
  /// Group ids) on its Group sections entry (none for another member
  /// model); PDelta columns as fibre_member's.
  FibreMember group_fibre_member(const Model &model, const BuildingParameters &p,
                                 unsigned int group, MemberKind kind);

  /// Member::section and Member3D::section of every fibre member from its
  /// section law's initial tangent (E = 1, A = EA, I = EI; in space also
  /// G = 1, J = GJ): what reads a member elastically.
  void set_fibre_rigidities(Model &model);

  /// Member::weight_per_length and Member3D's of every member of a building
  /// with Member self-weight = distributed: Member unit weight times its
  /// area (a fibre member's: its section's fibres), or its mass per length
  /// times Gravity when the unit weight is 0. Before set_fibre_rigidities.
  void set_member_self_weights(Model &model, const ModelParameters &parameters);

  /// The building (0-based) that the field `token` of `entry` names: its
  /// number, 1-based (a field that is a whole number is always a number),
  /// or its Name (case-sensitive). Throws InputError naming `path`, the
  /// entry and the numbers and names that exist.
  unsigned int read_building(const InputFile &input, const Model &model, const std::string &token,
                             const std::string &path, const std::string &entry);
  /// The same, among buildings named `names` (in order).
  unsigned int read_building(const InputFile &input, const std::vector<std::string> &names,
                             const std::string &token, const std::string &path,
                             const std::string &entry);

  /// A node named 'building floor node' (counted from 1, 1 and 0; the
  /// building by number or name, read_building).
  struct FloorNode
  {
    unsigned int node     = 0; // in the model
    unsigned int building = 0;
    unsigned int floor    = 1; // as read
    unsigned int index    = 0; // on the floor, as read
    std::string  label;        // "A3 floor 2 node 0"
  };
  /// Read 'building floor node' from `fields`; `form` is the whole entry's
  /// expected form for the message. Throws InputError naming `path` and `entry`.
  FloorNode read_floor_node(const InputFile &input, const Model &model, std::istream &fields,
                            const std::string &path, const std::string &entry,
                            const std::string &form);

  /// The springs of the `Springs` section, at floor nodes of `model`
  /// (source/model/springs_and_friction.cc). Throws InputError.
  void add_springs(Model &model, const SpringParameters &springs, const InputFile &input);
  /// A storey of zero stiffness is allowed only where a spring holds the
  /// floor on top of it (the SD or Duffing oscillator); after add_springs.
  /// Throws InputError.
  void check_storeys_held(const Model &model, const InputFile &input);
  /// The friction elements of the `Friction` section; after add_springs
  /// (N may take an SD spring's reaction). Throws InputError.
  /// The links of the `Links` section between floor nodes of `model`, and
  /// the bumper of the `Bumpers` section in its gaps
  /// (source/model/building_links.cc). Throw InputError.
  void add_building_links(Model &model, const LinkParameters &links, const InputFile &input);
  void add_bumpers(Model &model, const BumperParameters &bumper, const InputFile &input);

  void add_friction_surfaces(Model &model, const FrictionParameters &friction,
                             const InputFile &input);
  /// The SD spring at `node` (the last listed there), or nullptr.
  const Spring *sd_spring_at(const Model &model, unsigned int node);
  /// N of a friction element takes the vertical reaction of the SD spring
  /// `sd` at its node (Friction/Normal force from SD spring): its K, L, H.
  void take_sd_reaction(NormalForce &normal, const SpringLawParameters &sd);
} // namespace poundfe

#endif
