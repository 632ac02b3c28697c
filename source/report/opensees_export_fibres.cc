// The fibre members of a 2D frame in an OpenSees 3.8 script (report/
// opensees_export.h). poundfe's beam-columns on fibre sections are
// OpenSees's (elements/beam_column.h: ForceBeamColumn2d and
// DispBeamColumn2d; sections/fibre_section.h: FiberSection2d, the strains
// a_i = (1, -y_i) . (eps0, kappa) about the fibres' area centroid), so a
// member is written as its parts are: each fibre of its section one
// `fiber y z A mat` (the fibres as poundfe placed them, not the patches
// they came from), each material uniaxialMaterial NAME with the registry's
// parameters, which are OpenSees's in OpenSees's order (laws/
// material_registry.h; a default that stands for another value written as
// that value, ElasticPP's epsyN 0 as -epsyP), the points beamIntegration
// Lobatto (force-based) or Legendre (displacement-based), and a PDelta
// column geomTransf PDelta;
// in space (FiberSection3d, ForceBeamColumn3d) the section's -GJ.
// A material's strain limits (Sections/Materials) only mark a fibre failed
// in poundfe's reports: they are not written.
#include <poundfe/base/exceptions.h>
#include <poundfe/sections/fibre_section.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <map>

#include "opensees_export_parts.h"

namespace poundfe::opensees_export
{
  namespace
  {
    /// The law's parameters, each given or its registry default, with the
    /// defaults that stand for another value resolved: OpenSees reads a
    /// written value literally (ElasticPP's epsyN = 0 as no compressive
    /// strength, Elastic's Eneg = inf as an infinite modulus).
    std::map<std::string, double>
    resolved_values(const MaterialParameters &law)
    {
      std::map<std::string, double> v;
      for (const MaterialParameter &p : material_type(law.material).parameters)
        {
          const auto given = law.values.find(p.name);
          v[p.name]        = given != law.values.end() ? given->second : p.default_value;
        }
      if (law.material == "ElasticPP" && v.at("epsyN") == 0) // poundfe's law: symmetric
        v["epsyN"] = -v.at("epsyP");
      if (law.material == "Elastic" && std::isinf(v.at("Eneg"))) // poundfe's law: E
        v["Eneg"] = v.at("E");
      return v;
    }

    /// uniaxialMaterial NAME tag and the parameters in the registry's order
    /// (ElasticPPGap's damage as OpenSees's word).
    std::string
    material_command(const MaterialParameters &law, const int tag)
    {
      std::string command = "uniaxialMaterial " + law.material + " " + std::to_string(tag);
      const std::map<std::string, double> values = resolved_values(law);
      for (const MaterialParameter &p : material_type(law.material).parameters)
        if (law.material == "ElasticPPGap" && p.name == "damage")
          command += values.at("damage") != 0 ? " damage" : "";
        else
          command += " " + exact_text(values.at(p.name));
      return command;
    }

    /// Section k as section Fiber, with its materials first; its tag.
    int
    describe_section(const Model &model, const int k, const InputFile &input, Tags &tags,
                     OpenSeesExport &out)
    {
      const auto *section = dynamic_cast<const FibreSection *>(model.section_laws.at(k).get());
      Assert(section != nullptr, dealii::ExcMessage("a member's section is not a fibre section"));
      const FibreGeometry &g = section->geometry();
      std::vector<int>     material_tags;
      for (const SectionMaterial &m : g.materials)
        {
          // the registry's materials whose Tcl arguments are a fixed list
          if (m.law.material == "Hysteretic")
            input.fail("Sections/Materials",
                       "export-opensees writes no Hysteretic fibre material (material '" +
                         m.name + "', used by Section " + std::to_string(k + 1) + ")");
          material_tags.push_back(tags.material);
          out.model.push_back(material_command(m.law, tags.material++) + " ;# " +
                              comment_word(m.name));
        }
      const int tag = tags.section++;
      // in space the torque is elastic, GJ the initial tangent's last term
      const std::string torsion =
        model.dimension == 3 ? " -GJ " + exact_text(section->initial_tangent()(3, 3)) : "";
      out.model.push_back("section Fiber " + std::to_string(tag) + torsion + " {");
      for (const Fibre &f : g.fibres)
        out.model.push_back("  fiber " + exact_text(f.y) + " " + exact_text(f.z) + " " +
                            exact_text(f.area) + " " +
                            std::to_string(material_tags[f.material]));
      out.model.push_back("}");
      return tag;
    }

    /// The beamIntegration of the member's section and points; its tag.
    int
    integration_tag(const Model &model, const FibreMember &fibre, const InputFile &input,
                    Tags &tags, OpenSeesExport &out)
    {
      const std::array<int, 3> key{{fibre.section, fibre.force_based ? 1 : 0,
                                    int(fibre.n_points)}};
      if (const auto known = tags.integrations.find(key); known != tags.integrations.end())
        return known->second;
      if (tags.sections.count(fibre.section) == 0)
        tags.sections[fibre.section] = describe_section(model, fibre.section, input, tags, out);
      const int tag = tags.integration++;
      out.model.push_back("beamIntegration " +
                          std::string(fibre.force_based ? "Lobatto " : "Legendre ") +
                          std::to_string(tag) + " " +
                          std::to_string(tags.sections[fibre.section]) + " " +
                          std::to_string(fibre.n_points));
      tags.integrations[key] = tag;
      return tag;
    }
  } // namespace

  std::string
  fibre_element_command(const Model &model, const FibreMember &fibre,
                        const std::array<int, 2> &nodes, const int transformation,
                        const InputFile &input, Tags &tags, OpenSeesExport &out)
  {
    const int integration = integration_tag(model, fibre, input, tags, out);
    out.nonlinear         = true;
    return std::string("element ") + (fibre.force_based ? "forceBeamColumn " : "dispBeamColumn ") +
           std::to_string(tags.element++) + " " + std::to_string(nodes[0]) + " " +
           std::to_string(nodes[1]) + " " + std::to_string(transformation) + " " +
           std::to_string(integration);
  }

  std::string
  fibre_member_command(const Model &model, const Member &member, const InputFile &input,
                       Tags &tags, OpenSeesExport &out)
  {
    return fibre_element_command(model, member.fibre,
                                 {{int(member.nodes[0]) + 1, int(member.nodes[1]) + 1}},
                                 member.fibre.p_delta ? 2 : 1, input, tags, out);
  }
} // namespace poundfe::opensees_export
