// The section parameters of frame buildings (model/parameter_registry.h):
//   Building b/Column E|A|I|mass per length[i]
//                                      section of the columns of storey i of a
//                                      generated frame (K; M, K_G for the mass;
//                                      E, I: the k = f 6 E I / L of their hinges)
//   Building b/Beam ...[i]             the same for the beams of floor i
//   Building b/Column E|G|A|I|Iz|J|Avy|Avz|mass per length[i], Building b/Beam ...[i]
//                                      the same for a 3D frame (Model/Dimension = 3;
//                                      I is Iy; k = f 6 E I_y|z / L of its hinges; a
//                                      3D member's rotary inertias are rho I with
//                                      rho = m / A, so A, I, Iz enter M too)
//   Building b/Group E|A|I|mass per length[i]
//                                      group i (Group ids order) of a 2D mesh building
//   Building b/Group E|G|A|I|Iz|J|mass per length[i]
//                                      the same of a 3D mesh building (I is Iy)
// A hinge whose k is f 6 E I / L of its member keeps its f when E or I is set.
//   Sections/Section k/Concrete strength|Yield stress|Elastic modulus|Cover|Bar diameter
//                                      the engineering data of Section k (an RC
//                                      rectangle or circle, or a steel I: its
//                                      steel alone) that fibre members use: the
//                                      section is built again from its entries with
//                                      the value (its fibres and materials, Mander's
//                                      core), each member clones it when the
//                                      realization makes its elements (K: the
//                                      members' virgin tangent changes); Concrete
//                                      strength and Yield stress at most 5e10 Pa,
//                                      Elastic modulus at most 1e13 Pa, as typed ones
//                                      (sections/material_bounds.h)
#include <poundfe/base/exceptions.h>
#include <poundfe/model/model_builder.h>
#include <poundfe/model/parameter_registry.h>
#include <poundfe/sections/fibre_section.h>
#include <poundfe/sections/material_bounds.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>

namespace poundfe::section_registration
{
  namespace
  {
    /// A section entry: its name after "Column ", "Beam " or "Group ", the
    /// field of a planar (nullptr: none) and of a 3D section.
    struct SectionField
    {
      const char *name;
      double Section::*planar;
      double Section3D::*spatial;
    };

    const std::vector<SectionField> section_fields = {
      {"E", &Section::youngs_modulus, &Section3D::youngs_modulus},
      {"G", nullptr, &Section3D::shear_modulus},
      {"A", &Section::area, &Section3D::area},
      {"I", &Section::second_moment, &Section3D::second_moment_y},
      {"Iz", nullptr, &Section3D::second_moment_z},
      {"J", nullptr, &Section3D::torsion_constant},
      {"Avy", nullptr, &Section3D::shear_area_y},
      {"Avz", nullptr, &Section3D::shear_area_z},
      {"mass per length", &Section::mass_per_length, &Section3D::mass_per_length}};

    /// What a field enters: K; M too for the mass, and in 3D for A, I, Iz.
    unsigned int
    section_touches(const SectionField &f, const bool three_d)
    {
      if (f.planar == &Section::mass_per_length)
        return ModelParameter::mass;
      const bool rotary = f.spatial == &Section3D::area ||
                          f.spatial == &Section3D::second_moment_y ||
                          f.spatial == &Section3D::second_moment_z;
      return ModelParameter::stiffness | (three_d && rotary ? ModelParameter::mass : 0u);
    }

    /// Whether `member` (a Member or a Member3D) is one `p` names: a column
    /// of storey i (group 2i - 1) or a beam of floor i (group 2i) of its
    /// generated frame, or a member of a mesh's group `p.group` (`kind`
    /// other); without [i], all of them.
    template <typename MemberType>
    bool
    named_member(const ModelParameter &p, const MemberKind kind, const MemberType &member)
    {
      if (member.building != p.building)
        return false;
      if (kind == MemberKind::other) // a mesh's group (all without [i])
        return p.entry < 0 || int(member.group) == p.group;
      const int group = 2 * p.entry + (kind == MemberKind::column ? 1 : 2);
      return member.kind == kind && (p.entry < 0 || int(member.group) == group);
    }

    /// The section value of the named members; a hinge whose k is f 6 E I / L
    /// of its member keeps its f = k / (6 E I / L) of before.
    void
    write_planar(const ModelParameter &p, const MemberKind kind, double Section::*field,
                 const double value, Model &model)
    {
      const bool bending = field == &Section::youngs_modulus || field == &Section::second_moment;
      const auto origin  = [&](const Hinge &hinge) -> const HingeOrigin & {
        Assert(p.hinges && p.hinges->size() == model.hinges.size() + model.hinges_3d.size(),
               dealii::ExcMessage("a section parameter needs the hinges' origins"));
        return (*p.hinges)[&hinge - model.hinges.data()];
      };
      std::vector<Hinge *> following;
      std::vector<double>  factors;
      for (Hinge &hinge : model.hinges)
        if (bending && named_member(p, kind, model.members[hinge.member]) &&
            origin(hinge).stiffness_from_section)
          {
            following.push_back(&hinge);
            factors.push_back(hinge.law.stiffness / section_stiffness(model, hinge));
          }
      for (Member &member : model.members)
        if (named_member(p, kind, member))
          member.section.*field = value;
      for (std::size_t h = 0; h < following.size(); ++h)
        set_hinge_stiffness(following[h]->law, origin(*following[h]),
                            factors[h] * section_stiffness(model, *following[h]));
    }

    /// The same for 3D members.
    void
    write_spatial(const ModelParameter &p, const MemberKind kind, double Section3D::*field,
                  const double value, Model &model)
    {
      const bool bending = field == &Section3D::youngs_modulus ||
                           field == &Section3D::second_moment_y ||
                           field == &Section3D::second_moment_z;
      Assert(p.hinges && p.hinges->size() == model.hinges.size() + model.hinges_3d.size(),
             dealii::ExcMessage("a section parameter needs the hinges' origins"));
      const auto origin = [&](const Hinge3D &hinge) -> const HingeOrigin & {
        return (*p.hinges)[model.hinges.size() + (&hinge - model.hinges_3d.data())];
      };
      std::vector<Hinge3D *> following;
      std::vector<double>    factors;
      for (Hinge3D &hinge : model.hinges_3d)
        if (bending && named_member(p, kind, model.members_3d[hinge.member]) &&
            origin(hinge).stiffness_from_section)
          {
            following.push_back(&hinge);
            factors.push_back(hinge.law.stiffness / section_stiffness_3d(model, hinge));
          }
      for (Member3D &member : model.members_3d)
        if (named_member(p, kind, member))
          member.section.*field = value;
      for (std::size_t h = 0; h < following.size(); ++h)
        set_hinge_stiffness(following[h]->law, origin(*following[h]),
                            factors[h] * section_stiffness_3d(model, *following[h]));
    }

    /// A 3D section needs the hinges' origins (its hinges' k follows E and
    /// I as the builder set it).
    void
    require_hinge_origins(const ModelParameter &p, const Model &model)
    {
      if (!p.hinges || p.hinges->size() != model.hinges.size() + model.hinges_3d.size())
        refuse_parameter(p, ": a 3D section needs the hinges' origins (hinge_origins)");
    }

    /// "Column F[i]" or "Beam F[i]": a generated frame's (variant 1: 3D).
    void
    check_frame(ModelParameter &p, const Model &model, const SectionField &f, const bool column)
    {
      const Building &building = model.buildings[p.building];
      const auto      check_entry = [&] {
        if (p.entry >= int(building.floors.size()))
          refuse_parameter(p, ": building '" + building.name + "' has " +
                                (column ? "storeys" : "floors") + " 1.." +
                                std::to_string(building.floors.size()));
      };
      const auto of_building = [&](const auto &m) {
        return m.building == p.building && m.fibre.fibre();
      };
      const bool fibre =
        std::any_of(model.members.begin(), model.members.end(), of_building) ||
        std::any_of(model.members_3d.begin(), model.members_3d.end(), of_building);
      p.variant = building.type == BuildingType::frame && model.dimension == 3 ? 1 : 0;
      if (p.variant == 1)
        {
          check_entry();
          require_hinge_origins(p, model);
        }
      else
        {
          if (!f.planar)
            refuse_unknown_parameter(p);
          if (building.type != BuildingType::frame)
            refuse_parameter(p, ": building '" + building.name +
                                  "' is not a generated frame (Type = frame)");
          check_entry();
        }
      if (fibre && (p.variant == 1 ? f.spatial != &Section3D::mass_per_length :
                                     f.planar != &Section::mass_per_length))
        refuse_parameter(p, ": building '" + building.name + "' is made of fibre members, "
                              "whose rigidities come from their sections (Sections/Section "
                              "k/Concrete strength, ...)");
      p.touches = section_touches(f, p.variant == 1);
    }

    /// "Group F[i]" of a mesh building: the members of its i-th group id
    /// (3D: Group G, Iz and J too; its members have no shear areas,
    /// Euler-Bernoulli).
    void
    check_mesh(ModelParameter &p, const Model &model, const SectionField &f)
    {
      const Building &building = model.buildings[p.building];
      p.variant                = model.dimension == 3 ? 1 : 0;
      if (p.variant == 0 && !f.planar)
        refuse_unknown_parameter(p);
      if (building.type != BuildingType::mesh)
        refuse_parameter(p, ": building '" + building.name + "' is not a mesh building (Type "
                              "= mesh)");
      if (f.spatial == &Section3D::shear_area_y || f.spatial == &Section3D::shear_area_z)
        refuse_parameter(p, ": the members of a 3D mesh building have no shear areas "
                            "(Euler-Bernoulli; Group " + std::string(f.name) + " is no entry)");
      if (!p.inputs)
        refuse_parameter(p, ": a mesh group needs the input the model was built from (its "
                            "Group ids)");
      const std::vector<unsigned int> &ids = p.inputs->model.buildings[p.building].group_ids;
      if (p.entry >= int(ids.size()))
        refuse_parameter(p, ": building '" + building.name + "' has groups 1.." +
                              std::to_string(ids.size()));
      p.group = p.entry < 0 ? -1 : int(ids[p.entry]);
      if (p.variant == 1)
        require_hinge_origins(p, model);
      p.touches = section_touches(f, p.variant == 1);
    }

    /// An entry of a `Sections` section and the builders that read it.
    struct MaterialField
    {
      const char *name;
      double (*get)(const SectionEntry &);
      void (*set)(SectionEntry &, double);
      bool steel_i; // also read by the steel I builder
      /// the builders' bound (sections/material_bounds.h), held to by a
      /// sampled or swept value as by a typed one
      double largest = std::numeric_limits<double>::infinity();
    };

    const std::vector<MaterialField> material_fields = {
      {"Concrete strength", [](const SectionEntry &s) { return s.concrete.fc; },
       [](SectionEntry &s, const double v) { s.concrete.fc = v; }, false,
       largest_section_strength},
      {"Yield stress", [](const SectionEntry &s) { return s.steel.fy; },
       [](SectionEntry &s, const double v) { s.steel.fy = v; }, true, largest_section_strength},
      {"Elastic modulus", [](const SectionEntry &s) { return s.steel.E; },
       [](SectionEntry &s, const double v) { s.steel.E = v; }, true, largest_section_modulus},
      {"Cover", [](const SectionEntry &s) { return s.cover; },
       [](SectionEntry &s, const double v) { s.cover = v; }, false},
      {"Bar diameter", [](const SectionEntry &s) { return s.bar_diameter; },
       [](SectionEntry &s, const double v) { s.bar_diameter = v; }, false}};

    /// Section p.group of the input exists, is built from engineering data
    /// that `f` is part of, and fibre members use it.
    void
    check_material(const ModelParameter &p, const Model &model, const MaterialField &f)
    {
      if (!p.inputs)
        refuse_parameter(p, ": a section needs the input the model was built from");
      const auto &sections = p.inputs->model.sections.sections;
      if (p.group < 0 || p.group >= int(sections.size()))
        refuse_parameter(p, ": the input has sections 1.." + std::to_string(sections.size()));
      const SectionEntry &s = sections[p.group];
      if (s.type == "fibres" || (s.type == "steel I" && !f.steel_i))
        refuse_parameter(p, ": section '" + s.name + "' (Type = " + s.type + ") has no " +
                              f.name);
      if (p.group >= int(model.section_laws.size()) || !model.section_laws[p.group])
        refuse_parameter(p, ": no fibre member uses section '" + s.name +
                              "' (Building <i>/Column sections, Beam sections)");
    }

    /// Section k built again from the working input with the value, and the
    /// members' rigidities that follow it.
    void
    write_material(const ModelParameter &p, const MaterialField &f, const double value,
                   Model &model, ModelInputs &inputs)
    {
      SectionsParameters &sections = inputs.model.sections;
      f.set(sections.sections[p.group], value);
      try
        {
          model.section_laws[p.group] =
            std::make_shared<const FibreSection>(
              sections.section(InputFile(), p.group, model.section_resultants()));
        }
      catch (const InputError &e)
        {
          refuse_parameter(p, " = " + std::to_string(value) + ": " + e.problem());
        }
      set_fibre_rigidities(model);
    }

    void
    section_materials(ParameterRegistry &registry)
    {
      for (const MaterialField &f : material_fields)
        {
          ParameterRegistration r;
          r.name    = std::string("Sections/Section k/") + f.name;
          r.family  = "Sections/Section k";
          r.label   = f.name;
          r.range   = {0, false, f.largest};
          r.touches = ModelParameter::stiffness;
          r.resolve = [f](ModelParameter &p, const Model &model) { check_material(p, model, f); };
          r.get     = [f](const ModelParameter &p, const Model &) {
            return f.get(p.inputs->model.sections.sections[p.group]);
          };
          r.set = [f](const ModelParameter &p, const double value, Model &model,
                      ModelInputs &inputs) { write_material(p, f, value, model, inputs); };
          registry.add(r);
        }
    }

    void
    sections(ParameterRegistry &registry)
    {
      for (const MemberKind kind : {MemberKind::column, MemberKind::beam, MemberKind::other})
        for (const SectionField &f : section_fields)
          {
            const std::string family = kind == MemberKind::column ? "Column" :
                                       kind == MemberKind::beam   ? "Beam" :
                                                                    "Group";
            ParameterRegistration r;
            r.name        = family + " " + f.name;
            r.of_building = true;
            r.takes_index = true;
            r.family      = family;
            r.label       = f.name;
            // a mesh's members have no shear areas: Group Avy, Avz only say so
            r.listed = kind != MemberKind::other || (f.spatial != &Section3D::shear_area_y &&
                                                     f.spatial != &Section3D::shear_area_z);
            r.range   = {0, f.planar == &Section::mass_per_length,
                       std::numeric_limits<double>::infinity()};
            r.touches = section_touches(f, false);
            r.resolve = [kind, f](ModelParameter &p, const Model &model) {
              if (kind == MemberKind::other)
                check_mesh(p, model, f);
              else
                check_frame(p, model, f, kind == MemberKind::column);
            };
            r.get = [kind, f](const ModelParameter &p, const Model &model) {
              if (p.variant == 1)
                {
                  for (const Member3D &member : model.members_3d)
                    if (named_member(p, kind, member))
                      return member.section.*f.spatial;
                }
              else
                for (const Member &member : model.members)
                  if (named_member(p, kind, member))
                    return member.section.*f.planar;
              return 0.0;
            };
            r.set = [kind, f](const ModelParameter &p, const double value, Model &model,
                              ModelInputs &) {
              if (p.variant == 1)
                write_spatial(p, kind, f.spatial, value, model);
              else
                write_planar(p, kind, f.planar, value, model);
            };
            registry.add(r);
          }
    }
  } // namespace
} // namespace poundfe::section_registration

namespace poundfe
{
  void
  register_section_parameters(ParameterRegistry &registry)
  {
    section_registration::sections(registry);
    section_registration::section_materials(registry);
  }
} // namespace poundfe
