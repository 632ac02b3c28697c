#include <poundfe/elements/frame_element_3d.h>
#include <poundfe/elements/member_element.h>
#include <poundfe/output/storey_forces.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    std::array<int, 6>
    element_equations(const Model &model, const Member &member)
    {
      std::array<int, 6> equations;
      for (unsigned int k = 0; k < 6; ++k)
        equations[k] = model.equation(n_dofs_per_node * member.nodes[k / 3] + k % 3);
      return equations;
    }

    /// The member's six end displacements, through the constraints (a
    /// column base on a rigid foundation: its vertical is v_0 + (x - x_O) θ).
    Vector6
    member_end_displacements(const Model &model, const Member &member, const Vector &u)
    {
      Vector6                             ue = Vector6::Zero();
      std::vector<std::pair<int, double>> terms;
      for (unsigned int k = 0; k < 6; ++k)
        {
          model.equation_terms(n_dofs_per_node * member.nodes[k / 3] + k % 3, terms);
          for (const auto &[equation, coefficient] : terms)
            ue[k] += coefficient * u[equation];
        }
      return ue;
    }
  } // namespace

  StoreyForces::StoreyForces(const Model &model_, const NonlinearElements &elements)
    : model(model_)
    , nonlinear(elements)
  {
    for (const Building &building : model.buildings)
      {
        first.push_back(storeys.size());
        storeys.resize(storeys.size() + building.floors.size());
      }
    // fibre members' elements come first (assembly/nonlinear_elements.h)
    int next_member = 0;
    for (const Member &member : model.members)
      member_elements.push_back(member.fibre.fibre() ? next_member++ : -1);
    // Frame elements crossing each storey's mid-height cut.
    for (const Member &member : model.members)
      {
        const Building &building = model.buildings[member.building];
        const double    y0       = model.nodes[member.nodes[0]].position.y;
        const double    y1       = model.nodes[member.nodes[1]].position.y;
        for (unsigned int s = 0; s < building.floors.size(); ++s)
          {
            const double below = s == 0 ? building.base_level : building.floors[s - 1].level;
            const double cut   = 0.5 * (below + building.floors[s].level);
            if (std::min(y0, y1) < cut && cut < std::max(y0, y1))
              {
                const FrameElement element(model.nodes[member.nodes[0]].position,
                                           model.nodes[member.nodes[1]].position,
                                           member.section);
                storeys[index(member.building, s)].elements.push_back(
                  {element_equations(model, member), element.stiffness(), y0 < y1 ? 0u : 1u,
                   member_elements[&member - model.members.data()]});
              }
          }
      }
    // Shear-building storeys: the k-th link of a building is its storey k;
    // Bouc-Wen storeys are the nonlinear elements of kind storey, in link order.
    std::vector<unsigned int> storey_of_building(model.buildings.size(), 0);
    std::vector<int>          storey_elements;
    for (unsigned int h = 0; h < elements.size(); ++h)
      if (elements[h].kind == ElementKind::storey)
        storey_elements.push_back(h);
    unsigned int next_hysteretic = 0;
    for (unsigned int l = 0; l < model.links.size(); ++l)
      {
        const StoreyLink &link = model.links[l];
        Storey &storey = storeys[index(link.building, storey_of_building[link.building]++)];
        storey.link    = l;
        if (link.hysteretic)
          storey.hysteretic = storey_elements.at(next_hysteretic++);
      }
    if (model.dimension != 3)
      return;
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      for (unsigned int s = 0; s < model.buildings[b].floors.size(); ++s)
        if (s < model.buildings[b].plan.size())
          storeys[index(b, s)].centre = model.buildings[b].plan[s].mass_centre;
    add_members_3d();
    add_planes();
  }

  void
  StoreyForces::add_members_3d()
  {
    using RowMajor = Eigen::Matrix<double, 12, Eigen::Dynamic, Eigen::RowMajor>;
    using Point3   = Eigen::Map<const Eigen::Vector3d>;
    // the 3D fibre members' elements follow the plane ones
    int next_member = std::count_if(member_elements.begin(), member_elements.end(),
                                    [](const int e) { return e >= 0; });
    for (const Member3D &member : model.members_3d)
      {
        const int element_index = member.fibre.fibre() ? next_member++ : -1;
        if (element_index >= 0)
          member_elements_3d++;
        member_3d_elements.push_back(element_index);
        const Building    &building = model.buildings[member.building];
        const double       z0 = member.ends[0][2], z1 = member.ends[1][2];
        const unsigned int lower = z0 < z1 ? 0 : 1;
        for (unsigned int s = 0; s < building.floors.size(); ++s)
          {
            const double below = s == 0 ? building.base_level : building.floors[s - 1].level;
            const double cut   = 0.5 * (below + building.floors[s].level);
            if (!(std::min(z0, z1) < cut && cut < std::max(z0, z1)))
              continue;
            const FrameElement3D element(Point3(member.ends[0].data()),
                                         Point3(member.ends[1].data()),
                                         Point3(member.orientation.data()), member.section);
            const Eigen::Map<const RowMajor> t(member.map.data(), 12, member.dofs.size());
            CutMember3D cut_member;
            for (const unsigned int dof : member.dofs)
              cut_member.equations.push_back(model.equation(dof));
            cut_member.forces = (element.stiffness() * t).middleRows<6>(6 * lower);
            cut_member.at     = {member.ends[lower][0], member.ends[lower][1]};
            cut_member.lower          = lower;
            cut_member.member_element = element_index;
            storeys[index(member.building, s)].members_3d.push_back(std::move(cut_member));
          }
      }
  }

  void
  StoreyForces::add_planes()
  {
    // the hysteretic planes' elements follow the hinges and the storey links;
    // a pair of planes shares one bidirectional element, made at its first
    // (and the fibre members', first of all)
    int next = member_elements_3d + std::count_if(member_elements.begin(), member_elements.end(),
                                                  [](const int e) { return e >= 0; });
    next += model.hinges.size() + std::count_if(model.links.begin(), model.links.end(),
                                                   [](const StoreyLink &l) { return l.hysteretic; });
    std::vector<int> element_of(model.plane_links.size(), -1);
    for (unsigned int l = 0; l < model.plane_links.size(); ++l)
      {
        const PlaneLink &link   = model.plane_links[l];
        const bool       second = link.partner >= 0 && link.partner < static_cast<int>(l);
        if (link.hysteretic)
          element_of[l] = second ? element_of[link.partner] : next++;
        storeys[index(link.building, link.storey - 1)].planes.push_back(
          {{static_cast<int>(l), element_of[l], second ? 1 : 0}});
      }
  }

  std::array<double, 3>
  StoreyForces::plan_forces(const unsigned int i, const Vector &u) const
  {
    const Storey         &storey = storeys[i];
    std::array<double, 3> V{{0, 0, 0}};
    for (const CutMember3D &m : storey.members_3d)
      {
        Eigen::VectorXd q(m.equations.size());
        for (unsigned int k = 0; k < m.equations.size(); ++k)
          q[k] = m.equations[k] >= 0 ? u[m.equations[k]] : 0.0;
        const Eigen::Matrix<double, 6, 1> f =
          m.member_element >= 0 ? Eigen::Matrix<double, 6, 1>(
                                    fibre_member_forces_3d(m.member_element).segment<6>(6 * m.lower)) :
                                  Eigen::Matrix<double, 6, 1>(m.forces * q);
        V[0] -= f[0];
        V[1] -= f[1];
        V[2] -= (m.at.x - storey.centre.x) * f[1] - (m.at.y - storey.centre.y) * f[0] + f[5];
      }
    for (const auto &[l, element, component] : storey.planes)
      {
        const PlaneLink &link = model.plane_links[l];
        double           F    = 0; // k δ, or the Bouc-Wen force
        if (element >= 0)
          F = nonlinear[element].force_component(component);
        else
          {
            std::vector<unsigned int> dofs;
            std::vector<double>       weights; // with the foundation's rocking, if any
            link.terms(dofs, weights);
            for (unsigned int k = 0; k < dofs.size(); ++k)
              {
                const int e = model.equation(dofs[k]);
                F += e >= 0 ? link.stiffness * weights[k] * u[e] : 0.0;
              }
          }
        // the top floor's coefficients are (d_x, d_y, (p - C) × d)
        for (unsigned int c = 0; c < 3; ++c)
          V[c] += F * link.coefficients[3 + c];
      }
    return V;
  }

  Vector6
  StoreyForces::end_displacements(const std::array<int, 6> &equations, const Vector &u) const
  {
    Vector6 ue;
    for (unsigned int k = 0; k < 6; ++k)
      ue[k] = equations[k] >= 0 ? u[equations[k]] : 0.0;
    return ue;
  }

  void
  StoreyForces::storey_shears(const Vector &u, const Vector &v, std::vector<double> &shear) const
  {
    shear.resize(storeys.size());
    for (unsigned int i = 0; i < storeys.size(); ++i)
      shear[i] = storey_shear(i, u, v);
  }

  double
  StoreyForces::storey_shear(const unsigned int index, const Vector &u, const Vector &v) const
  {
    const Storey &storey = storeys[index];
    double        V      = model.dimension == 3 ? plan_forces(index, u)[0] : 0.0;
    for (const CutElement &e : storey.elements)
      V -= e.member_element >= 0 ? fibre_member_forces(e.member_element)[3 * e.lower] :
                                   e.stiffness.row(3 * e.lower).dot(end_displacements(e.equations, u));
    if (storey.link >= 0)
      {
        const StoreyLink &link = model.links[storey.link];
        auto drift = [&](const Vector &x) {
          const int top    = model.equation(Model::dof(link.nodes[1], Component::ux));
          const int bottom = model.equation(Model::dof(link.nodes[0], Component::ux));
          const double rocking = // the base rotation's share (sway-rocking)
            link.rocking_node < 0 ?
              0.0 :
              link.rocking_arm * x[model.equation(Model::dof(link.rocking_node, Component::rz))];
          return (top >= 0 ? x[top] : 0.0) - (bottom >= 0 ? x[bottom] : 0.0) - rocking;
        };
        V += storey.hysteretic >= 0 ? nonlinear[storey.hysteretic].force() :
                                      link.stiffness * drift(u);
        V += link.damping * drift(v);
      }
    return V;
  }

  bool
  StoreyForces::has_member(const std::string &label) const
  {
    return std::any_of(model.members.begin(), model.members.end(),
                       [&](const Member &m) { return m.label == label; }) ||
           std::any_of(model.members_3d.begin(), model.members_3d.end(),
                       [&](const Member3D &m) { return m.label == label; });
  }

  Eigen::Matrix<double, 12, 1>
  StoreyForces::member_end_forces_3d(const std::string &label, const Vector &u) const
  {
    using Point = Eigen::Map<const Eigen::Vector3d>;
    for (unsigned int k = 0; k < model.members_3d.size(); ++k)
      if (const Member3D &member = model.members_3d[k]; member.label == label)
        {
          const FrameElement3D element(Point(member.ends[0].data()), Point(member.ends[1].data()),
                                       Point(member.orientation.data()), member.section);
          if (member_3d_elements[k] >= 0)
            return element.rotation() * fibre_member_forces_3d(member_3d_elements[k]);
          // K_e u_e plus the fixed-end forces of its self-weight
          return element.local_end_forces(member_3d_end_displacements(model, member, u)) +
                 element.rotation() * self_weight_end_forces(member);
        }
    return Vector12::Zero();
  }

  Eigen::Matrix<double, 12, 1>
  member_3d_end_displacements(const Model &model, const Member3D &member, const Vector &u)
  {
    const unsigned int           n  = member.dofs.size();
    Eigen::Matrix<double, 12, 1> ue = Eigen::Matrix<double, 12, 1>::Zero();
    for (unsigned int i = 0; i < 12; ++i)
      for (unsigned int j = 0; j < n; ++j)
        if (const int q = model.equation(member.dofs[j]); q >= 0)
          ue[i] += member.map[i * n + j] * u[q];
    return ue;
  }

  Vector6
  StoreyForces::member_end_forces(const std::string &label, const Vector &u) const
  {
    Vector6 forces = Vector6::Zero();
    for (const Member &member : model.members)
      if (member.label == label && (member.at_joint[0] || member.at_joint[1]))
        {
          const FrameElement element(model.nodes[member.nodes[0]].position,
                                     model.nodes[member.nodes[1]].position, member.section);
          const int     e = member_elements[&member - model.members.data()];
          const Vector6 f =
            e < 0 ? Vector6(element.local_end_forces(member_end_displacements(model, member, u)) +
                            element.rotation() * self_weight_end_forces(model, member)) :
                    Vector6(element.rotation() * fibre_member_forces(e));
          for (unsigned int end = 0; end < 2; ++end)
            if (member.at_joint[end])
              forces.segment<3>(3 * end) = f.segment<3>(3 * end);
        }
    return forces;
  }

  Vector6
  StoreyForces::fibre_member_forces(const int e) const
  {
    const auto *member = dynamic_cast<const MemberElement<2> *>(&nonlinear[e]);
    Assert(member, dealii::ExcMessage("a fibre member's element is a MemberElement"));
    return member->member().resisting_force();
  }

  Eigen::Matrix<double, 12, 1>
  StoreyForces::fibre_member_forces_3d(const int e) const
  {
    const auto *member = dynamic_cast<const MemberElement<3> *>(&nonlinear[e]);
    Assert(member, dealii::ExcMessage("a fibre member's element is a MemberElement"));
    return member->member().resisting_force();
  }
} // namespace poundfe

namespace poundfe
{
  void
  BaseShearPeaks::initialize(const ResponseView &state)
  {
    forces.emplace(state.model, state.elements);
    const unsigned int n_buildings = state.model.buildings.size();
    const unsigned int n_plan      = state.model.dimension == 3 ? n_buildings : 0;
    along_x.value.assign(n_buildings, 0.0);
    along_x.time.assign(n_buildings, state.time());
    for (Peaks *p : {&along_y, &resultant})
      {
        p->value.assign(n_plan, 0.0);
        p->time.assign(n_plan, state.time());
      }
    observe_step(state);
  }

  void
  BaseShearPeaks::Peaks::keep(const unsigned int b, const double v, const double t)
  {
    if (std::abs(v) > value[b])
      {
        value[b] = std::abs(v);
        time[b]  = t;
      }
  }

  void
  BaseShearPeaks::observe_step(const ResponseView &state)
  {
    for (unsigned int b = 0; b < along_x.value.size(); ++b)
      {
        if (!state.observes_building(b))
          continue;
        const unsigned int base = forces->index(b, 0);
        const double V_x = forces->storey_shear(base, state.displacement(), state.velocity());
        along_x.keep(b, V_x, state.time());
        if (b < along_y.value.size()) // dimension 3
          {
            const double V_y = forces->plan_forces(base, state.displacement())[1];
            along_y.keep(b, V_y, state.time());
            resultant.keep(b, std::hypot(V_x, V_y), state.time());
          }
      }
  }
} // namespace poundfe
