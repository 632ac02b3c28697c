// Where an entry of `Building <i>` acts, and the refusal of an entry the user
// wrote where it has no effect. The scope of an entry is the tag that opens
// its help text ("[frame]", "[frame, shear]", "[3D]", "[3D frame, mesh]",
// "[frame, fibre]"), read from the declarations themselves: the help a user
// reads and the check cannot disagree, and a new tagged entry is checked
// without a list to keep. Grammar of a tag: an optional leading "3D"
// (Model/Dimension = 3), then comma-separated words, each a building Type
// (frame, mesh, shear: any of them) or "fibre" (and Member model = fibre);
// no Type: every Type. An untagged entry acts on every building.
//
// An entry can also lose its effect through another entry's value, which a
// tag cannot say: the Bouc-Wen shape of a building with no hysteretic
// hinge or storey, a Damping entry of another Damping/Type, a Foundation
// entry under Type = none, the Storey stiffnesses (and yield drifts) beside
// typed Plan/Resisting planes. The run still makes sense (random-structure
// and sweep inputs write such entries on purpose), so these are warned
// about (terminal and summary.json), not refused: one table of conditions,
// warn_entries_without_effect.
#ifndef poundfe_model_entry_scope_h
#define poundfe_model_entry_scope_h

#include <poundfe/base/input_file.h>
#include <poundfe/model/model.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace poundfe
{
  struct BuildingParameters;
  struct ModelParameters;

  struct EntryScope
  {
    std::string               tag;                // as written, without the brackets
    bool                      only_3d    = false; // Model/Dimension = 3
    bool                      only_fibre = false; // Member model = fibre
    std::vector<BuildingType> types;              // empty: every Type
  };

  /// The scope a help text opens with, or none for an untagged entry. A
  /// word of the tag that is neither a Type, "3D" nor "fibre" is a
  /// programming error (an exception, so that a test finds it).
  std::optional<EntryScope> parse_entry_scope(const std::string &help);

  /// Every tagged entry of a `Building <i>` section, by its path below it
  /// ("Column E", "Plan/Position", "Foundation/Vertical stiffness"), read
  /// from BuildingParameters::declare's help texts.
  const std::map<std::string, EntryScope> &building_entry_scopes();

  /// Empty when an entry of `scope` acts on `building` in a model of
  /// `dimension`; otherwise the problem an InputError states ("has no
  /// effect on a 3D shear building ...").
  std::string entry_without_effect(const EntryScope &scope, const BuildingParameters &building,
                                   unsigned int dimension);

  /// Refuse (InputError naming file, line and entry) an entry of a building
  /// that the user wrote (a .prm line, a JSON key, a --set override: the
  /// keys of input.lines) and that has no effect on that building; the
  /// earliest such line first. Defaults are never refused.
  void refuse_entries_without_effect(const InputFile &input, const ModelParameters &model);

  /// A warning (InputFile::warning: file, line, entry, "has no effect: ...")
  /// for every entry of a building that the user wrote and that another
  /// entry's value leaves without effect, earliest line first. Defaults are
  /// never warned about.
  std::vector<std::string> warn_entries_without_effect(const InputFile       &input,
                                                       const ModelParameters &model);
} // namespace poundfe

#endif
