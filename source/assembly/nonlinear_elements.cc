#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/elements/biaxial_element.h>
#include <poundfe/elements/column_contact_element.h>
#include <poundfe/elements/member_element.h>
#include <poundfe/elements/plan_contact_element.h>
#include <poundfe/elements/uniaxial_element.h>
#include <poundfe/laws/bouc_wen.h>
#include <poundfe/laws/bumper.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/laws/elastic_springs.h>
#include <poundfe/laws/friction.h>
#include <poundfe/laws/link_laws.h>

#include <algorithm>
#include <limits>

#include <deal.II/base/exceptions.h>

namespace poundfe
{
  namespace
  {
    /// Each part of each foundation (2D: sway, rocking; 3D: sway x, y,
    /// torsion, rocking x, y): a spring k (already in K, so the element adds
    /// only its dashpot's force c v to the residual) and a dashpot c in
    /// parallel (a Kelvin-Voigt law with alpha = 1), so that their forces and
    /// the dashpots' energy are reported and balanced.
    void
    add_foundation_elements(const Model &model, NonlinearElements &elements)
    {
      for (const Foundation &f : model.foundations)
        for (const FoundationPart &part : f.parts)
          {
            LinkLawParameters p;
            p.kind      = LinkKind::kelvin_voigt;
            p.stiffness = part.stiffness;
            p.damping   = part.damping;
            p.exponent  = 1;
            std::vector<int> equations;
            for (const unsigned int dof : part.dofs)
              equations.push_back(model.equation(dof));
            const std::string name = model.buildings[f.building].name + part.name;
            if (part.dofs.size() == 1)
              elements.emplace_back<UniaxialElement>(
                ElementKind::foundation, f.building, name,
                std::array<int, 2>{{equations[0], -1}}, make_link_law(p), part.stiffness);
            else
              elements.emplace_back<UniaxialElement>(ElementKind::foundation, f.building, name,
                                                     equations, part.coefficients,
                                                     make_link_law(p), part.stiffness);
          }
    }
  } // namespace

  namespace
  {
    /// A hysteretic resisting plane: a uniaxial Bouc-Wen on its drift, or,
    /// paired (Plan/Storey law = bidirectional Bouc-Wen), one bidirectional
    /// element on the drifts of the pair, made at the pair's first plane.
    void
    add_plane_element(const Model &model, const unsigned int l, NonlinearElements &elements)
    {
      const PlaneLink &link = model.plane_links[l];
      if (link.partner >= 0 && static_cast<unsigned int>(link.partner) < l)
        return; // made with its partner
      std::vector<unsigned int> dofs;
      std::vector<double>       weights;
      link.terms(dofs, weights);
      std::vector<int> equations;
      for (const unsigned int dof : dofs)
        equations.push_back(model.equation(dof));
      const std::string label = model.buildings[link.building].name + "_S" +
                                std::to_string(link.storey) + "P" + std::to_string(link.plane);
      if (link.partner < 0)
        {
          elements.emplace_back<UniaxialElement>(ElementKind::storey, link.building, label,
                                                 equations, weights,
                                                 std::make_unique<BoucWen>(link.hysteresis),
                                                 link.stiffness);
          return;
        }
      const PlaneLink          &other = model.plane_links[link.partner];
      std::vector<unsigned int> other_dofs;
      std::vector<double>       other_weights;
      other.terms(other_dofs, other_weights);
      Assert(other_dofs == dofs, dealii::ExcMessage("paired planes act on the same DOFs"));
      elements.emplace_back<BiaxialElement>(ElementKind::storey, link.building,
                                            label + "xP" + std::to_string(other.plane), equations,
                                            std::array<std::vector<double>, 2>{{weights,
                                                                                other_weights}},
                                            BidirectionalBoucWen(link.hysteresis,
                                                                 other.hysteresis));
    }

    /// The Bouc-Wen elements: frame hinges (2D and 3D), hysteretic storeys
    /// (with the sway-rocking term on a foundation) and resisting planes.
    void
    add_hysteretic_elements(const Model &model, NonlinearElements &elements)
    {
      for (const Member &member : model.members) // fibre frames' beam-columns
        if (member.fibre.fibre())
          elements.push_back(make_member_element(model, member));
      for (const Member3D &member : model.members_3d) // 3D fibre frames'
        if (member.fibre.fibre())
          elements.push_back(make_member_element(model, member));
      for (const Hinge &hinge : model.hinges)
        elements.emplace_back<UniaxialElement>(
          ElementKind::hinge, hinge.building, hinge.label,
          std::array<int, 2>{{model.equation(Model::dof(hinge.member_node, Component::rz)),
                              model.equation(Model::dof(hinge.joint_node, Component::rz))}},
          std::make_unique<BoucWen>(hinge.law), hinge.law.stiffness);
      for (unsigned int h = 0; h < model.hinges_3d.size(); ++h)
        {
          const Hinge3D &hinge = model.hinges_3d[h];
          const int      equation = model.equation(n_dofs_per_node * hinge.node + hinge.slot);
          if (!hinge.biaxial)
            elements.emplace_back<UniaxialElement>(
              ElementKind::hinge, hinge.building, hinge.label, std::array<int, 2>{{equation, -1}},
              std::make_unique<BoucWen>(hinge.law), hinge.law.stiffness);
          else if (hinge.slot == 0) // with the next hinge, about z at the same end
            {
              const Hinge3D &about_z = model.hinges_3d.at(h + 1);
              Assert(about_z.node == hinge.node && about_z.slot == 1,
                     dealii::ExcMessage("a biaxial hinge's two axes follow each other"));
              elements.emplace_back<BiaxialElement>(
                ElementKind::hinge, hinge.building, hinge.label.substr(0, hinge.label.size() - 2),
                std::vector<int>{equation, model.equation(n_dofs_per_node * hinge.node + 1)},
                std::array<std::vector<double>, 2>{{{1.0, 0.0}, {0.0, 1.0}}},
                BidirectionalBoucWen(hinge.law, about_z.law));
            }
        }
      std::vector<unsigned int> storey_of_building(model.buildings.size(), 0);
      for (const StoreyLink &link : model.links)
        {
          const unsigned int storey = ++storey_of_building[link.building];
          if (!link.hysteretic)
            continue;
          const std::string label =
            model.buildings[link.building].name + "_S" + std::to_string(storey);
          const int top    = model.equation(Model::dof(link.nodes[1], Component::ux));
          const int bottom = model.equation(Model::dof(link.nodes[0], Component::ux));
          if (link.rocking_node >= 0) // d = u_top - u_bottom - h θ (sway-rocking)
            elements.emplace_back<UniaxialElement>(
              ElementKind::storey, link.building, label,
              std::vector<int>{top, bottom,
                               model.equation(Model::dof(link.rocking_node, Component::rz))},
              std::vector<double>{1.0, -1.0, -link.rocking_arm},
              std::make_unique<BoucWen>(link.hysteresis), link.stiffness);
          else
            elements.emplace_back<UniaxialElement>(ElementKind::storey, link.building, label,
                                                   std::array<int, 2>{{top, bottom}},
                                                   std::make_unique<BoucWen>(link.hysteresis),
                                                   link.stiffness);
        }
      for (unsigned int l = 0; l < model.plane_links.size(); ++l)
        if (model.plane_links[l].hysteretic)
          add_plane_element(model, l, elements);
    }

    /// One gap: a slab against a column or a slab in plan (the element
    /// measures the gap itself), else a uniaxial contact, behind a bumper
    /// when the model has one.
    void
    add_gap_element(const Model &model, const Gap &gap, NonlinearElements &elements)
    {
      std::array<int, 2> equations{{-1, -1}};
      for (unsigned int i = 0; i < 2; ++i)
        if (gap.nodes[i] >= 0)
          equations[i] = model.equation(Model::dof(gap.nodes[i], Component::ux));
      ContactLawParameters law = model.contact;
      law.initial_gap          = gap.initial_gap;
      law.effective_mass       = gap.effective_mass;
      if (gap.on_column)
        {
          law.initial_gap = 0; // the element measures the gap itself
          std::vector<int> equations;
          for (const unsigned int dof : gap.column.column_dofs)
            equations.push_back(model.equation(dof));
          for (const Component c : {Component::ux, Component::uy, Component::rz})
            equations.push_back(model.equation(Model::dof(gap.nodes[1], c)));
          elements.emplace_back<ColumnContactElement>(gap.buildings[1], gap.label, equations,
                                                      gap.column, make_contact_law(law));
          return;
        }
      if (gap.in_plan)
        {
          law.initial_gap = 0; // the element measures the gap itself
          std::vector<int> equations;
          for (const int node : gap.nodes)
            for (const Component c : {Component::ux, Component::uy, Component::rz})
              equations.push_back(model.equation(Model::dof(node, c)));
          elements.emplace_back<PlanContactElement>(gap.buildings[0], gap.label, equations,
                                                    gap.plan, make_contact_law(law));
          return;
        }
      std::unique_ptr<UniaxialLaw> contact = make_contact_law(law);
      if (model.bumper.law != BumperLaw::none)
        contact = make_bumpered_contact(make_contact_law(law), model.bumper);
      elements.emplace_back<UniaxialElement>(ElementKind::gap, gap.buildings[0], gap.label,
                                             equations, std::move(contact));
    }
  } // namespace

  NonlinearElements
  make_nonlinear_elements(const Model &model)
  {
    return make_nonlinear_elements(model, {{0, std::numeric_limits<unsigned int>::max()}});
  }

  NonlinearElements
  make_nonlinear_elements(const Model &model, const std::array<unsigned int, 2> kept)
  {
    NonlinearElements elements;
    if (kept[0] > 0 || kept[1] < model.n_equations())
      elements.keep_only([kept](const NonlinearElement &e) {
        return std::any_of(e.equations().begin(), e.equations().end(), [kept](const int i) {
          return i >= 0 && unsigned(i) >= kept[0] && unsigned(i) < kept[1];
        });
      });
    add_hysteretic_elements(model, elements);
    for (const Gap &gap : model.gaps)
      add_gap_element(model, gap, elements);
    for (const Spring &spring : model.springs)
      elements.emplace_back<UniaxialElement>(
        ElementKind::spring, spring.building, spring.label,
        std::array<int, 2>{{model.equation(Model::dof(spring.node, Component::ux)), -1}},
        std::make_unique<ElasticSpring>(spring.law), spring.law.stiffness);
    for (const FrictionSurface &surface : model.friction_surfaces)
      {
        const int equation = model.equation(Model::dof(surface.node, Component::ux));
        elements.emplace_back<UniaxialElement>(ElementKind::friction, surface.building,
                                               surface.label, std::array<int, 2>{{equation, -1}},
                                               std::make_unique<Friction>(surface.law));
      }
    // links last: outputs count hysteretic elements, then gaps, from the start
    for (const BuildingLink &link : model.building_links)
      elements.emplace_back<UniaxialElement>(
        ElementKind::link, link.buildings[0], link.label,
        std::array<int, 2>{{model.equation(Model::dof(link.nodes[0], link.component)),
                            model.equation(Model::dof(link.nodes[1], link.component))}},
        make_link_law(link.law));
    add_foundation_elements(model, elements);
    elements.keep_only({});
    return elements;
  }
} // namespace poundfe
