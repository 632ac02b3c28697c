// A beam-column as a NonlinearElement, and a member's mass (see the header).
#include <poundfe/base/lean_assert.h>
#include <poundfe/elements/frame_element.h>
#include <poundfe/elements/member_element.h>

namespace poundfe
{
  template <int dim>
  MemberElement<dim>::MemberElement(const unsigned int building, std::string label,
                                    std::vector<int> equations,
                                    std::unique_ptr<BeamColumn<dim>> member,
                                    const ReferenceStiffness reference_stiffness,
                                    const ElementKind        kind)
    : NonlinearElement(kind, building, std::move(label), std::move(equations))
    , beam(std::move(member))
  {
    AssertDimension(n_dofs(), static_cast<unsigned int>(BeamColumn<dim>::n_dofs));
    beam->reset();
    reference       = beam->initial_tangent();
    reference_basic = beam->basic_tangent();
    if (reference_stiffness == ReferenceStiffness::none)
      {
        reference.setZero();
        reference_basic.setZero();
      }
    committed_force.setZero();
    committed_u.setZero();
  }

  template <int dim>
  MemberElement<dim>::MemberElement(const unsigned int building, std::string label,
                                    std::vector<int> equations, Eigen::MatrixXd t,
                                    std::unique_ptr<BeamColumn<dim>> member)
    : NonlinearElement(ElementKind::member, building, std::move(label), std::move(equations))
    , beam(std::move(member))
    , map(std::move(t))
  {
    AssertDimension(map.rows(), static_cast<int>(BeamColumn<dim>::n_dofs));
    AssertDimension(map.cols(), static_cast<int>(n_dofs()));
    beam->reset();
    reference       = beam->initial_tangent();
    reference_basic = beam->basic_tangent();
    committed_force.setZero();
    committed_u.setZero();
  }

  template <int dim>
  typename MemberElement<dim>::GlobalVector
  MemberElement<dim>::end_displacements(const Eigen::Ref<const Eigen::VectorXd> &u) const
  {
    if (map.size() == 0)
      return GlobalVector(u);
    return GlobalVector(map * u);
  }

  template <int dim>
  unsigned int
  MemberElement<dim>::rank() const
  {
    return linear() ? BeamColumn<dim>::n_basic : BeamColumn<dim>::n_dofs;
  }

  template <int dim>
  Eigen::MatrixXd
  MemberElement<dim>::tangent_basis() const
  {
    const Eigen::MatrixXd basis =
      linear() ? Eigen::MatrixXd(beam->transformation().compatibility().transpose()) :
                 Eigen::MatrixXd::Identity(BeamColumn<dim>::n_dofs, BeamColumn<dim>::n_dofs);
    return map.size() == 0 ? basis : Eigen::MatrixXd(map.transpose() * basis);
  }

  template <int dim>
  bool
  MemberElement<dim>::has_symmetric_tangent() const
  {
    return beam->transformation().has_symmetric_tangent();
  }

  template <int dim>
  bool
  MemberElement<dim>::set_trial(const LocalVector &u, const LocalVector & /*v*/)
  {
    return beam->set_trial(end_displacements(u));
  }

  template <int dim>
  void
  MemberElement<dim>::force_correction(LocalVectorOut f) const
  {
    const GlobalVector f_e = beam->resisting_force() - reference * beam->trial_displacement();
    if (map.size() == 0)
      f = f_e;
    else
      f = map.transpose() * f_e;
  }

  template <int dim>
  void
  MemberElement<dim>::tangent_change(const double /*damping_factor*/, LocalMatrixOut d) const
  {
    if (linear())
      d = beam->basic_tangent() - reference_basic;
    else
      d = beam->tangent() - reference;
  }

  template <int dim>
  double
  MemberElement<dim>::work_increment() const
  {
    return 0.5 * (committed_force + beam->resisting_force())
                   .dot(beam->trial_displacement() - committed_u) +
           held_load_work_increment();
  }

  template <int dim>
  double
  MemberElement<dim>::held_load_work_increment() const
  {
    return beam->held_load_work() - committed_held_work;
  }

  template <int dim>
  double
  MemberElement<dim>::reference_energy() const
  {
    const GlobalVector &u = beam->trial_displacement();
    return 0.5 * u.dot(reference * u);
  }

  template <int dim>
  void
  MemberElement<dim>::commit()
  {
    beam->commit();
    committed_force     = beam->resisting_force();
    committed_u         = beam->trial_displacement();
    committed_held_work = beam->held_load_work();
  }

  template <int dim>
  void
  MemberElement<dim>::revert()
  {
    beam->revert();
  }

  template <int dim>
  void
  MemberElement<dim>::reset()
  {
    beam->reset();
    committed_force.setZero();
    committed_u.setZero();
    committed_held_work = 0;
  }

  template <int dim>
  double
  MemberElement<dim>::deformation(const Eigen::VectorXd &u) const
  {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(n_dofs());
    for (unsigned int i = 0; i < n_dofs(); ++i)
      if (equations()[i] >= 0)
        q[i] = u[equations()[i]];
    CrdTransformation<dim> transformation = beam->transformation();
    transformation.update(end_displacements(q));
    return transformation.basic_deformation()[1];
  }

  namespace
  {
    /// The member's transformation between its nodes: PDelta or Linear.
    CrdTransformation<2>
    transformation_of(const Model &model, const Member &member, const Transformation kind)
    {
      const Point2 a = model.nodes[member.nodes[0]].position;
      const Point2 b = model.nodes[member.nodes[1]].position;
      return CrdTransformation<2>(kind, Eigen::Vector2d(a.x, a.y), Eigen::Vector2d(b.x, b.y));
    }

    /// The 3D member's, its local axes by its orientation.
    CrdTransformation<3>
    transformation_of(const Member3D &member, const Transformation kind)
    {
      using Point = Eigen::Map<const Eigen::Vector3d>;
      return CrdTransformation<3>(kind, Point(member.ends[0].data()), Point(member.ends[1].data()),
                                  Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                  Point(member.orientation.data()));
    }

    /// A fibre member's beam-column on its section, with its self-weight.
    template <int dim>
    std::unique_ptr<BeamColumn<dim>>
    make_fibre_beam_column(const Model &model, const FibreMember &fibre,
                           const CrdTransformation<dim> &transformation, const double weight)
    {
      Assert(fibre.fibre() && model.section_laws.at(fibre.section),
             dealii::ExcMessage("a fibre member needs its section"));
      const SectionLaw &section = *model.section_laws[fibre.section];
      std::unique_ptr<BeamColumn<dim>> beam;
      if (fibre.force_based)
        beam = std::make_unique<ForceBeamColumn<dim>>(transformation, section, fibre.n_points);
      else
        beam = std::make_unique<DispBeamColumn<dim>>(transformation, section, fibre.n_points);
      if (weight != 0)
        beam->set_uniform_load(self_weight_load(transformation, weight));
      return beam;
    }
  } // namespace

  MemberLoad<2>
  self_weight_load(const CrdTransformation<2> &transformation, const double weight)
  {
    return transformation.local_axes() * Eigen::Vector2d(0, -weight);
  }

  MemberLoad<3>
  self_weight_load(const CrdTransformation<3> &transformation, const double weight)
  {
    return transformation.local_axes() * Eigen::Vector3d(0, 0, -weight);
  }

  Eigen::Matrix<double, 6, 1>
  self_weight_end_forces(const Model &model, const Member &member)
  {
    if (member.weight_per_length == 0)
      return Eigen::Matrix<double, 6, 1>::Zero();
    const CrdTransformation<2> t = transformation_of(model, member, Transformation::linear);
    return fixed_end_forces(t, self_weight_load(t, member.weight_per_length));
  }

  Eigen::Matrix<double, 12, 1>
  self_weight_end_forces(const Member3D &member)
  {
    if (member.weight_per_length == 0)
      return Eigen::Matrix<double, 12, 1>::Zero();
    const CrdTransformation<3> t = transformation_of(member, Transformation::linear);
    return fixed_end_forces(t, self_weight_load(t, member.weight_per_length));
  }

  std::unique_ptr<BeamColumn<2>>
  make_beam_column(const Model &model, const Member &member)
  {
    return make_fibre_beam_column<2>(
      model, member.fibre,
      transformation_of(model, member,
                        member.fibre.p_delta ? Transformation::pdelta : Transformation::linear),
      member.weight_per_length);
  }

  std::unique_ptr<MemberElement<2>>
  make_member_element(const Model &model, const Member &member)
  {
    std::vector<int> equations;
    for (const unsigned int node : member.nodes)
      for (const Component c : {Component::ux, Component::uy, Component::rz})
        equations.push_back(model.equation(Model::dof(node, c)));
    return std::make_unique<MemberElement<2>>(member.building, member.label, equations,
                                              make_beam_column(model, member),
                                              ReferenceStiffness::initial, ElementKind::member);
  }

  std::unique_ptr<BeamColumn<3>>
  make_beam_column(const Model &model, const Member3D &member)
  {
    return make_fibre_beam_column<3>(
      model, member.fibre,
      transformation_of(member,
                        member.fibre.p_delta ? Transformation::pdelta : Transformation::linear),
      member.weight_per_length);
  }

  std::unique_ptr<MemberElement<3>>
  make_member_element(const Model &model, const Member3D &member)
  {
    std::vector<int> equations;
    for (const unsigned int dof : member.dofs)
      equations.push_back(model.equation(dof));
    const Eigen::MatrixXd map = Eigen::Map<const Eigen::Matrix<double, 12, Eigen::Dynamic,
                                                               Eigen::RowMajor>>(
      member.map.data(), 12, member.dofs.size());
    return std::make_unique<MemberElement<3>>(member.building, member.label, equations, map,
                                              make_beam_column(model, member));
  }

  Eigen::Matrix<double, 6, 6>
  member_mass(const CrdTransformation<2> &transformation, const double mass_per_length,
              const MassMatrixType type)
  {
    const Eigen::Vector2d chord = transformation.chord();
    Section               section;
    section.mass_per_length = mass_per_length;
    const FrameElement element(Point2{0, 0}, Point2{chord[0], chord[1]}, section);
    const auto        &t = transformation.offset_matrix();
    return t.transpose() * element.mass(type) * t;
  }

  Eigen::Matrix<double, 12, 12>
  member_mass(const CrdTransformation<3> &transformation, const Section3D &section,
              const MassMatrixType type, const RotaryInertia rotary)
  {
    const FrameElement3D element(Eigen::Vector3d::Zero(), transformation.chord(),
                                 transformation.local_axes().row(2).transpose(), section);
    const auto &t = transformation.offset_matrix();
    return t.transpose() * element.mass(type, rotary) * t;
  }

  template class MemberElement<2>;
  template class MemberElement<3>;
} // namespace poundfe
