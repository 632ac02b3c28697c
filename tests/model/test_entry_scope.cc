// Entries without effect (model/entry_scope.h; doc/verification.md,
// "Entries without effect"): the tags of the Building entries' help texts
// are read as scopes; every tagged entry, written for a building of every
// Type, dimension and member model, is refused exactly where its scope
// excludes that building, naming the file, the line and the entry; the
// entries the issue named (Column E, Diaphragm, Vertical floor mass on a 3D
// shear building) are among them; untagged and unwritten entries pass.
#include <poundfe/base/exceptions.h>
#include <poundfe/model/entry_scope.h>
#include <poundfe/model/parameters.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <string>

using namespace poundfe;

namespace
{
  /// One building of `type` in a model of `dimension`, with `entry` of
  /// Building 1 written on line 7.
  struct OneEntry
  {
    InputFile       input;
    ModelParameters model;

    OneEntry(const BuildingType type, const unsigned int dimension, const bool fibre,
             const std::string &entry)
    {
      input.file = "scope.prm";
      input.lines["Building 1/" + entry] = 7;
      model.dimension = dimension;
      model.buildings.resize(1);
      model.buildings[0].type         = type;
      model.buildings[0].member_model = fibre ? "fibre" : "elastic-hinges";
    }

    /// The problem refuse_entries_without_effect states, "" if none.
    std::string
    refusal() const
    {
      try
        {
          refuse_entries_without_effect(input, model);
        }
      catch (const InputError &e)
        {
          BOOST_TEST(e.file() == "scope.prm");
          BOOST_TEST(e.line() == 7);
          return e.parameter() + ": " + e.problem();
        }
      return "";
    }
  };

  const BuildingType all_types[] = {BuildingType::frame, BuildingType::mesh, BuildingType::shear};
} // namespace

BOOST_AUTO_TEST_CASE(tags_read_as_scopes)
{
  BOOST_TEST(!parse_entry_scope("Label used in reports. Unit: -."));
  BOOST_TEST(!parse_entry_scope("Of the hinges [frame, mesh] and storeys [shear]: ratio."));
  const EntryScope frame = *parse_entry_scope("[frame] Column Young's modulus.");
  BOOST_TEST((frame.types == std::vector<BuildingType>{BuildingType::frame}));
  BOOST_TEST(!frame.only_3d);
  const EntryScope any_3d = *parse_entry_scope("[3D] Plan centre.");
  BOOST_TEST(any_3d.only_3d);
  BOOST_TEST(any_3d.types.empty());
  const EntryScope frame_mesh_3d = *parse_entry_scope("[3D frame, mesh] rigid: ...");
  BOOST_TEST(frame_mesh_3d.only_3d);
  BOOST_TEST((frame_mesh_3d.types ==
              std::vector<BuildingType>{BuildingType::frame, BuildingType::mesh}));
  const EntryScope fibre = *parse_entry_scope("[frame, fibre] force: ...");
  BOOST_TEST(fibre.only_fibre);
  BOOST_TEST(fibre.tag == "frame, fibre");
  BOOST_CHECK_THROW(parse_entry_scope("[frames] a typo in a tag"), std::exception);
}

// The table is read from the declarations: the entries named in the help's
// tags, in their subsections, and none untagged.
BOOST_AUTO_TEST_CASE(scopes_come_from_the_declarations)
{
  const std::map<std::string, EntryScope> &scopes = building_entry_scopes();
  BOOST_TEST(scopes.size() >= 60u);
  for (const char *entry : {"Column E", "Diaphragm", "Vertical floor mass", "Plan/Position",
                            "Foundation/Vertical stiffness", "Hinges/Locations",
                            "Column section", "Poisson ratio", "Member element"})
    BOOST_TEST(scopes.count(entry) == 1u, entry);
  for (const char *entry : {"Name", "Type", "Floor masses", "Bouc-Wen/alpha", "Damping/Type"})
    BOOST_TEST(scopes.count(entry) == 0u, entry);
  BOOST_TEST(scopes.at("Hinges/Biaxial interaction").tag == "3D frame, mesh");
}

// Every tagged entry x every Type x dimension 2 and 3 x member model: refused
// exactly where its scope excludes the building, with the message naming it.
BOOST_AUTO_TEST_CASE(every_tagged_entry_on_every_building)
{
  unsigned int refused = 0, accepted = 0;
  for (const auto &[entry, scope] : building_entry_scopes())
    for (const BuildingType type : all_types)
      for (const unsigned int dimension : {2u, 3u})
        for (const bool fibre : {false, true})
          {
            const OneEntry    one(type, dimension, fibre, entry);
            const std::string why = one.refusal();
            const bool        fits =
              (scope.types.empty() ||
               std::find(scope.types.begin(), scope.types.end(), type) != scope.types.end()) &&
              (!scope.only_3d || dimension == 3) && (!scope.only_fibre || fibre);
            BOOST_TEST(why.empty() == fits, entry << " on a " << dimension << "D "
                                                  << building_type_names().name(type)
                                                  << (fibre ? " (fibre)" : "") << ": " << why);
            if (!fits)
              BOOST_TEST(why.find("Building 1/" + entry + ": has no effect on a " +
                                  std::to_string(dimension) + "D " +
                                  building_type_names().name(type) + " building") == 0u,
                         why);
            (fits ? accepted : refused) += 1;
          }
  BOOST_TEST(refused > 300u);
  BOOST_TEST(accepted > 100u);
}

BOOST_AUTO_TEST_CASE(the_entries_of_the_issue)
{
  for (const char *entry : {"Column E", "Diaphragm", "Vertical floor mass"})
    BOOST_TEST(OneEntry(BuildingType::shear, 3, false, entry).refusal().find(
                 "has no effect on a 3D shear building") != std::string::npos,
               entry);
  BOOST_TEST(OneEntry(BuildingType::mesh, 3, false, "Diaphragm").refusal().empty());
  BOOST_TEST(OneEntry(BuildingType::mesh, 3, false, "Hinges/Biaxial interaction").refusal().empty());
  BOOST_TEST(OneEntry(BuildingType::frame, 2, false, "Plan/Rotation").refusal() ==
             "Building 1/Plan/Rotation: has no effect on a 2D frame building: it is a [3D] "
             "entry (every Type, Model/Dimension = 3); remove it, or set Model/Dimension = 3");
  BOOST_TEST(OneEntry(BuildingType::frame, 2, false, "Member element").refusal() ==
             "Building 1/Member element: has no effect on a 2D frame building with Member "
             "model = elastic-hinges: it is a [frame, mesh, fibre] entry (Type = frame or mesh, "
             "Member model = fibre); remove it, or set Member model = fibre");
  // an entry not written is never refused, whatever its default
  OneEntry nothing_written(BuildingType::shear, 3, false, "Name");
  BOOST_TEST(nothing_written.refusal().empty());
}
