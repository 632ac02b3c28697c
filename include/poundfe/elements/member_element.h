// A beam-column (elements/beam_column.h) as a NonlinearElement, so that the
// assembly and the Newmark-Newton integrator use it as they use hinges:
//   K_ref,e = the member's tangent at the virgin state, u = 0 (assembled
//     once into the linear K by whoever builds the model),
//   force correction  p(u) - K_ref,e u,
//   tangent change    K_t - K_ref,e = B_e D_e B_e^T with
//     linear transformation:  B_e = B^T (n_dofs x n_basic, constant: the
//       basic system's compatibility), D_e = k_b - k_b,0: rank 3 in the
//       plane, 6 in space, so the Woodbury path keeps n_basic columns;
//     PDelta, corotational: B changes with u, so B_e = I over the member's
//       DOFs and D_e = K_t - K_ref,e (rank 6 or 12), the only constant
//       basis the interface allows.
// A member of a 3D frame moves with its joints' DOFs through u_e = T q (the
// rigid diaphragm's master-slave map, model/frame_3d_assembler.h): over
// the model DOFs q its force is T^T p, its basis T^T B_e, D_e unchanged.
// The member has no rate dependence (C_t = 0): damping is the model's
// Rayleigh or modal C. Its work is trapezoidal, its stored energy what
// unloading the sections at their initial stiffness recovers, so the
// energy balance books its dissipation as hysteretic (as a hinge's).
// A member's self-weight (Member::weight_per_length) is a uniform load along
// it (elements/beam_column.h), its factor that of the gravity analysis.
// The mass (member_mass) is the elastic frame elements' consistent or
// lumped mass over the flexible length, carried to the nodes by the rigid
// offsets.
#ifndef poundfe_elements_member_element_h
#define poundfe_elements_member_element_h

#include <poundfe/elements/beam_column.h>
#include <poundfe/elements/frame_element_3d.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/model/model.h>

#include <memory>

namespace poundfe
{
  /// Whether the linear K holds the member's virgin tangent (K_ref,e, the
  /// way a model builder assembles its members) or nothing of it (K_ref,e =
  /// 0: the whole force goes through the correction, for an element added
  /// to a model whose K does not know it).
  enum class ReferenceStiffness
  {
    initial,
    none
  };

  template <int dim>
  class MemberElement : public NonlinearElement
  {
  public:
    using GlobalVector = typename BeamColumn<dim>::GlobalVector;
    using GlobalMatrix = typename BeamColumn<dim>::GlobalMatrix;

    /// `equations`: the equation of each of the member's global DOFs
    /// (n_dofs, -1 for the ground).
    MemberElement(unsigned int building, std::string label, std::vector<int> equations,
                  std::unique_ptr<BeamColumn<dim>> member,
                  ReferenceStiffness reference_stiffness = ReferenceStiffness::initial,
                  ElementKind        kind                = ElementKind::hinge);
    /// On model DOFs q with u_e = `map` q (n_dofs x equations.size()).
    MemberElement(unsigned int building, std::string label, std::vector<int> equations,
                  Eigen::MatrixXd map, std::unique_ptr<BeamColumn<dim>> member);

    /// K_ref,e: what the linear K must hold for this member (over its end
    /// DOFs u_e).
    const GlobalMatrix &reference_stiffness() const { return reference; }
    const BeamColumn<dim> &member() const { return *beam; }

    unsigned int    rank() const override;
    Eigen::MatrixXd tangent_basis() const override;
    bool            has_symmetric_tangent() const override;

    void   set_load_factor(const double lambda) override { beam->set_load_factor(lambda); }
    bool   set_trial(const LocalVector &u, const LocalVector &v) override;
    void   force_correction(LocalVectorOut f) const override;
    void   tangent_change(double damping_factor, LocalMatrixOut d) const override;
    /// The end forces' work plus the member's own load's
    /// (held_load_work_increment): the work its sections take.
    double work_increment() const override;
    double held_load_work_increment() const override;
    double reference_energy() const override;
    void   commit() override;
    void   revert() override;
    void   reset() override;
    std::string failure() const override { return beam->failure(); }

    /// The moment at end I (basic force 1); force_component(a): basic force a.
    double force() const override { return beam->basic_force()[1]; }
    double force_component(unsigned int a) const override { return beam->basic_force()[a]; }
    /// The rotation of end I relative to the chord at global displacements u.
    double deformation(const Eigen::VectorXd &u) const override;
    double stored_energy() const override { return beam->stored_energy(); }
    double initial_stiffness() const override { return beam->initial_tangent().norm(); }

  private:
    bool linear() const { return beam->transformation().kind() == Transformation::linear; }
    /// u_e of the element's DOFs q.
    GlobalVector end_displacements(const Eigen::Ref<const Eigen::VectorXd> &u) const;

    std::unique_ptr<BeamColumn<dim>> beam;
    GlobalMatrix                     reference;
    typename BeamColumn<dim>::BasicMatrix reference_basic;
    GlobalVector                     committed_force, committed_u;
    double                           committed_held_work = 0; // BeamColumn::held_load_work
    Eigen::MatrixXd                  map; // T; empty: u_e = q
  };

  /// The beam-column of a fibre member of a 2D frame (Member::fibre):
  /// force- or displacement-based on clones of its section, between its
  /// nodes, Linear or PDelta.
  std::unique_ptr<BeamColumn<2>> make_beam_column(const Model &model, const Member &member);
  /// Its element on the equations of its nodes' (ux, uy, rz), kind member.
  std::unique_ptr<MemberElement<2>> make_member_element(const Model &model, const Member &member);
  /// The beam-column of a fibre member of a 3D frame (Member3D::fibre),
  /// its local axes by the member's orientation.
  std::unique_ptr<BeamColumn<3>> make_beam_column(const Model &model, const Member3D &member);
  /// Its element on the model DOFs it moves with (Member3D::dofs, map).
  std::unique_ptr<MemberElement<3>> make_member_element(const Model &model,
                                                        const Member3D &member);

  /// A member's self-weight (Member::weight_per_length, downwards: -y in
  /// the plane, -z in space) in its local axes, per unit length.
  MemberLoad<2> self_weight_load(const CrdTransformation<2> &transformation, double weight);
  MemberLoad<3> self_weight_load(const CrdTransformation<3> &transformation, double weight);
  /// The global end forces that hold an elastic member fixed at both ends
  /// under its self-weight (fixed_end_forces; 0 without one): the
  /// consistent nodal loads are their negative, its end forces K_e u_e plus
  /// them.
  Eigen::Matrix<double, 6, 1>  self_weight_end_forces(const Model &model, const Member &member);
  Eigen::Matrix<double, 12, 1> self_weight_end_forces(const Member3D &member);

  /// The plane member's mass: mass per length m, the frame element's matrix.
  Eigen::Matrix<double, 6, 6> member_mass(const CrdTransformation<2> &transformation,
                                          double mass_per_length, MassMatrixType type);
  /// The space member's mass from its elastic section's mass data (m, A,
  /// Iy, Iz: the twist's inertia), FrameElement3D's matrix.
  Eigen::Matrix<double, 12, 12> member_mass(const CrdTransformation<3> &transformation,
                                            const Section3D &section, MassMatrixType type,
                                            RotaryInertia rotary = RotaryInertia::excluded);
} // namespace poundfe

#endif
