#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/laws/bouc_wen.h>
#include <poundfe/laws/contact_law.h>

namespace poundfe
{
  UniaxialElements
  make_nonlinear_elements(const Model &model)
  {
    UniaxialElements elements;
    for (const Hinge &hinge : model.hinges)
      {
        UniaxialElement e;
        e.kind      = ElementKind::hinge;
        e.building  = hinge.building;
        e.label     = hinge.label;
        e.equations = {{model.equation(Model::dof(hinge.member_node, Component::rz)),
                        model.equation(Model::dof(hinge.joint_node, Component::rz))}};
        e.reference_stiffness = hinge.law.stiffness;
        e.law                 = std::make_unique<BoucWen>(hinge.law);
        elements.push_back(std::move(e));
      }
    std::vector<unsigned int> storey_of_building(model.buildings.size(), 0);
    for (const StoreyLink &link : model.links)
      {
        const unsigned int storey = ++storey_of_building[link.building];
        if (!link.hysteretic)
          continue;
        UniaxialElement e;
        e.kind      = ElementKind::storey;
        e.building  = link.building;
        e.label     = model.buildings[link.building].name + "_S" + std::to_string(storey);
        e.equations = {{model.equation(Model::dof(link.nodes[1], Component::ux)),
                        model.equation(Model::dof(link.nodes[0], Component::ux))}};
        e.reference_stiffness = link.stiffness;
        e.law                 = std::make_unique<BoucWen>(link.hysteresis);
        elements.push_back(std::move(e));
      }
    for (const Gap &gap : model.gaps)
      {
        UniaxialElement e;
        e.kind     = ElementKind::gap;
        e.building = gap.buildings[0];
        e.label    = gap.label;
        for (unsigned int i = 0; i < 2; ++i)
          e.equations[i] =
            gap.nodes[i] < 0 ? -1 : model.equation(Model::dof(gap.nodes[i], Component::ux));
        ContactLawParameters law = model.contact;
        law.initial_gap          = gap.initial_gap;
        law.effective_mass       = gap.effective_mass;
        e.law                    = make_contact_law(law);
        elements.push_back(std::move(e));
      }
    return elements;
  }
} // namespace poundfe
