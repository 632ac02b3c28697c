// The member model of a generated frame, 2D or 3D (Building <i>/Member model):
// elastic frame elements with Bouc-Wen hinges at their ends (the default),
// or beam-columns on fibre sections (elements/beam_column.h: force-based on
// Gauss-Lobatto points, Spacone, Filippou & Taucer 1996; or displacement-
// based on Gauss-Legendre points), one section of the `Sections` input per
// storey for its columns and per floor for its beams, or, in a Gmsh mesh,
// per physical group (Group sections, in the order of Group ids). A fibre building's
// members yield in their fibres: the entries of the elastic-hinges model
// (hinges, Column/Beam E, A, I) are refused there rather than ignored.
// The members' self-weight in the gravity analysis, of either model: at
// their nodes from their mass (nodal), or a uniform load along each
// (distributed: elements/beam_column.h's element loads).
#include <poundfe/base/numbers.h>
#include <poundfe/model/parameters.h>

#include <deal.II/base/parameter_handler.h>

namespace poundfe
{
  void
  BuildingParameters::declare_member_model(dealii::ParameterHandler &prm)
  {
    namespace Patterns = dealii::Patterns;
    prm.add_parameter("Member model", member_model,
                      "[frame, mesh] elastic-hinges: elastic frame elements with the Bouc-Wen "
                      "hinges of Hinges; fibre: beam-columns on the fibre sections of `Sections` "
                      "named by Column sections and Beam sections (generated frames) or by "
                      "Group sections (meshes), 2D and 3D. Unit: -.",
                      Patterns::Selection("elastic-hinges|fibre"));
    prm.add_parameter("Member element", member_element,
                      "[frame, mesh, fibre] force: force-based beam-column (Gauss-Lobatto points, "
                      "exact for an elastic member); displacement: displacement-based "
                      "(Gauss-Legendre points, cubic displacements). Unit: -.",
                      Patterns::Selection("force|displacement"));
    prm.add_parameter("Integration points", integration_points,
                      "[frame, mesh, fibre] Sections along each element: 2..10 (force), 1..10 "
                      "(displacement). Unit: count.",
                      Patterns::Integer(1, 10));
    prm.add_parameter("Member transformation", member_transformation,
                      "[frame, mesh, fibre] The columns' coordinate transformation: Linear, PDelta "
                      "(the shear of the axial force on the drifted chord), or auto: PDelta "
                      "when Model/Gravity analysis/Type = static, else Linear. Beams are "
                      "always Linear. Unit: -.",
                      Patterns::Selection("auto|Linear|PDelta"));
    prm.add_parameter("Column sections", column_sections,
                      "[frame, fibre] The Name of a section of `Sections` for the columns, "
                      "one for all or one per storey, bottom up, separated by commas. Unit: -.");
    prm.add_parameter("Beam sections", beam_sections,
                      "[frame, fibre] The same for the beams, one for all or one per floor. "
                      "Unit: -.");
    prm.add_parameter("Group sections", group_sections,
                      "[mesh, fibre] The Name of a section of `Sections` for the members of "
                      "each physical group of the mesh, in the order of Group ids, separated by "
                      "commas (one name: every group). Unit: -.");
    prm.add_parameter("Member self-weight", member_self_weight,
                      "[frame, mesh] The members' weight in the gravity analysis (Model/"
                      "Gravity analysis/Type = static): nodal: their mass per length times "
                      "Gravity, at their nodes as the mass matrix puts it; distributed: a "
                      "uniform load along each member (element loads: a fibre member's "
                      "sections carry it, an elastic member takes its consistent nodal loads "
                      "and its end forces the fixed-end forces), Member unit weight times the "
                      "member's area, or its mass per length times Gravity when the unit "
                      "weight is 0; its mass's weight then does not load its nodes. Unit: -.",
                      Patterns::Selection("nodal|distributed"));
    prm.add_parameter("Member unit weight", member_unit_weight,
                      "[frame, mesh] Weight per volume of the members with Member self-weight "
                      "= distributed (e.g. 25e3 for reinforced concrete): the weight per "
                      "length is this times the area (Column A, Beam A, Group A; a fibre "
                      "member's: the sum of its section's fibre areas, bars included); 0: the "
                      "mass per length times Gravity. Unit: N/m^3.",
                      Patterns::Double(0));
  }

  namespace
  {
    /// The Sections index of each name of `names` (one or `n`), at `path`.
    std::vector<unsigned int>
    section_indices(const InputFile &input, const std::string &path,
                    const std::vector<std::string> &names, const unsigned int n,
                    const SectionsParameters &sections, const std::string &per)
    {
      if (names.empty())
        input.fail(path, "Member model = fibre needs the name of a section of `Sections` (one "
                         "for all or " + per + ")");
      if (names.size() != 1 && names.size() != n)
        input.fail(path, "has " + std::to_string(names.size()) + " names: give one for all or " +
                           per + " (" + std::to_string(n) + ")");
      std::vector<unsigned int> indices;
      for (const std::string &name : names)
        indices.push_back(sections.find(input, path, trimmed(name)));
      return indices;
    }

    /// An entry of the elastic-hinges model given in a fibre building.
    void
    refuse_unused(const InputFile &input, const std::string &path, const std::string &why)
    {
      if (input.line_of(path) > 0)
        input.fail(path, "a fibre building (Member model = fibre) " + why);
    }
    /// A member in space twists: its section needs its GJ (a rigid floor
    /// turns the columns, the beams twist with the joints).
    void
    require_torsional_rigidities(const InputFile &input, const BuildingParameters &p,
                                 const SectionsParameters &sections)
    {
      for (const auto *indices :
           {&p.column_section_index, &p.beam_section_index, &p.group_section_index})
        for (const unsigned int k : *indices)
          if (!(sections.sections[k].torsional_rigidity > 0))
            input.fail("Sections/Section " + std::to_string(k + 1) + "/Torsional rigidity",
                       "section '" + trimmed(sections.sections[k].name) +
                         "' is a member of a 3D frame (Model/Dimension = 3), which twists: "
                         "give its GJ (> 0)");
    }
  } // namespace

  void
  BuildingParameters::finalize_member_model(const InputFile &input, const std::string &s,
                                            const ModelParameters &model)
  {
    column_section_index.clear();
    beam_section_index.clear();
    group_section_index.clear();
    if (!fibre())
      return;
    const std::string path = s + "Member model";
    if (type != BuildingType::frame && type != BuildingType::mesh)
      input.fail(path, "fibre members are for frames (Type = frame or mesh)");
    if (!hinge_locations.empty())
      input.fail(s + "Hinges/Locations", "a fibre building's members yield in their fibres: "
                                         "hinges are for Member model = elastic-hinges");
    if (model.geometric_nonlinearity != GeometricNonlinearity::none)
      input.fail("Model/Geometric nonlinearity",
                 "fibre members carry P-Delta in their own transformation (Building <i>/"
                 "Member transformation = PDelta): set none");
    if (foundation.enabled())
      input.fail(s + "Foundation/Type", "a fibre building stands on a fixed or pinned base");
    // the rules' ranges (elements/beam_integration.h; at most 10: OpenSees's)
    const unsigned int lowest = member_element == "force" ? 2 : 1;
    if (integration_points < lowest || integration_points > 10)
      input.fail(s + "Integration points", "must lie in " + std::to_string(lowest) + ".." +
                                             std::to_string(10) +
                                             " for Member element = " + member_element);
    for (const char *entry : {"Column E", "Column A", "Column I", "Beam E", "Beam A", "Beam I",
                              "Column G", "Column Iz", "Column J", "Column Avy", "Column Avz",
                              "Beam G", "Beam Iz", "Beam J", "Beam Avy", "Beam Avz", "Group E",
                              "Group A", "Group I", "Group G", "Group Iz", "Group J"})
      refuse_unused(input, s + entry, "takes its rigidities from its sections");
    if (type == BuildingType::mesh)
      group_section_index = section_indices(input, s + "Group sections", group_sections,
                                            group_ids.size(), model.sections,
                                            "one per entry of Group ids");
    else
      {
        column_section_index = section_indices(input, s + "Column sections", column_sections,
                                               n_storeys, model.sections, "one per storey");
        beam_section_index   = section_indices(input, s + "Beam sections", beam_sections,
                                               n_storeys, model.sections, "one per floor");
      }
    if (model.dimension == 3)
      require_torsional_rigidities(input, *this, model.sections);
  }

  void
  BuildingParameters::finalize_self_weight(const InputFile &input, const std::string &s,
                                           const ModelParameters &model) const
  {
    if (member_self_weight != "distributed")
      {
        if (input.line_of(s + "Member unit weight") > 0)
          input.fail(s + "Member unit weight",
                     "has effect only with Member self-weight = distributed");
        return;
      }
    if (!model.gravity_analysis.enabled)
      input.fail(s + "Member self-weight",
                 "a distributed self-weight is a load of the gravity analysis: set "
                 "Model/Gravity analysis/Type = static");
    input.non_negative(s + "Member unit weight", member_unit_weight);
    // the bound of masses and stiffnesses (dynamics/analysis.cc): beyond it the
    // gravity analysis' residual norm overflows
    input.at_most(s + "Member unit weight", member_unit_weight, largest_model_value, "N/m^3",
                  "beyond any material");
  }
} // namespace poundfe
