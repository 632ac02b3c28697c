// Distributed-plasticity beam-columns on the basic system of a coordinate
// transformation (elements/crd_transformation.h), with a section law at
// each integration point (elements/beam_integration.h), in the plane and in
// space, as OpenSees's ForceBeamColumn2d/3d and DispBeamColumn2d/3d.
//
// Displacement-based (Hughes 1987 §1.15; OpenSees's DispBeamColumn): the
// section deformations follow the basic deformations by the cubic
// (Hermite) transverse and linear axial displacement fields,
//   e(x) = a(x) v,  eps0 = v0/L,  kappa_z = ((6 xi - 4) vI + (6 xi - 2) vJ)/L
//   (the same for kappa_y on vIy, vJy; theta = twist/L),
//   q = L sum_i w_i a_i^T s_i,   k_b = L sum_i w_i a_i^T k_s,i a_i,
// with Gauss-Legendre by default. Its curvature is linear along the member:
// exact for an elastic prismatic member under end loads (the Hermite cubics
// solve it), not once a section yields (the curvature then concentrates
// where the moment exceeds the yield moment): a cantilever pushed past
// yield needs several elements, its tip deflection converging with them.
//
// Force-based (Spacone, Filippou & Taucer 1996, "Fibre beam-column model
// for non-linear analysis of R/C frames", EESD 25; Neuenhofer & Filippou
// 1997, "Evaluation of nonlinear frame finite-element models", J. Struct.
// Eng. 123(7); OpenSees's ForceBeamColumn): the section forces follow the
// basic forces by equilibrium, exactly, with no element loads:
//   s(x) = b(x) q,  N = q0,  Mz = (xi - 1) qI + xi qJ  (My likewise on
//   qIy, qJy; T = q_T),
// and the element is compatible when v = L sum_i w_i b_i^T e_i. The state
// determination iterates on q with the element's flexibility
//   F = L sum_i w_i b_i^T f_s,i b_i,  f_s = k_s^-1,
// from the state of the last trial (OpenSees: "vin"): predictor
// q += F^-1 dv; then, for each iteration, at each section
//   e_i += f_s,i (b_i q - s_i),  s_i, k_s,i from the section law at e_i,
// the residual deformation r = v - L sum_i w_i b_i^T (e_i + f_s,i (b_i q - s_i))
// and q += F^-1 r, until the work r . F^-1 r is below 1e-20 of the
// element's energy scale, v . F^-1 v + dv . F^-1 dv plus the sections' own
// work L sum_i w_i |e_i . s_i| (a member back near v = 0 after cracking
// keeps residual section forces that set the round-off of the sum), or
// stalls at round-off below 1e-12 of it (OpenSees stops at an absolute
// 1e-12). When the iterations do not
// converge within 20, the increment is divided by 10 (up to 4 times) and
// applied in pieces, each from the last converged one (OpenSees's
// subdivision). The consistent tangent is k_b = F^-1 at convergence. For
// an elastic prismatic member b^T f_s b is quadratic in x, so Lobatto with
// 3 points or more integrates F exactly: one element gives the closed-form
// stiffness and the exact response to end loads. A section tangent whose
// diagonal falls below 1e-8 of the initial one (a perfectly plastic
// section) is raised to it in f_s: the flexibility stays finite; the
// converged forces are those of the section laws (the iteration ends when
// compatibility holds), only the tangent differs, by 1e-8 relative.
//
// Element loads (a uniform load w per unit length in the local axes, w_x
// along the chord, w_y, w_z across it, times a load factor lambda; OpenSees's
// eleLoad -beamUniform): the basic system's reactions p0 = -(w_x L, w_y L/2,
// w_y L/2[, w_z L/2, w_z L/2]) (end I axial, end I and J transverse) are added
// to the local end forces, and
//   displacement-based (DispBeamColumn2d/3d::addLoad): the fixed-end basic
//     forces q0 = (-w_x L/2, -w_y L^2/12, w_y L^2/12[, w_z L^2/12,
//     -w_z L^2/12, 0]) are added to q: the consistent nodal loads of the
//     cubic and linear fields; the sections do not see the load;
//   force-based (Spacone et al. 1996 eq. 9; ForceBeamColumn2d/3d::
//     computeSectionForces): the sections carry the simply supported
//     member's forces under the load, s(x) = b(x) q + s_p(x),
//       N_p = w_x (L - x),  Mz_p = w_y x (x - L)/2,  My_p = w_z x (L - x)/2,
//     and q follows by compatibility, exactly as without the load (for an
//     elastic fixed-fixed member q then holds the end moments w L^2/12 and
//     the mid-span section w L^2/24). A change of lambda is stepped as a
//     change of v is, in the same pieces.
// The elastic frame elements take the same q0 and p0 (fixed_end_forces: the
// global end forces of the member held fixed at both ends).
//
// State: set_trial(u) -> resisting_force(), tangent() -> commit() or
// revert(); revert() restores the committed state bit for bit (the
// forces and tangent are stored, the sections revert); reset() goes back
// to the virgin state. Fixed-size Eigen throughout: set_trial allocates
// nothing.
#ifndef poundfe_elements_beam_column_h
#define poundfe_elements_beam_column_h

#include <poundfe/elements/beam_integration.h>
#include <poundfe/elements/crd_transformation.h>
#include <poundfe/sections/section_law.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  /// One section per integration point, each a virgin clone of `section`.
  std::vector<std::unique_ptr<SectionLaw>> sections_along(const BeamIntegration &integration,
                                                          const SectionLaw      &section);
  /// HingeRadau's six sections: two of end I, two of the interior, two of
  /// end J (beam_integration.h).
  std::vector<std::unique_ptr<SectionLaw>>
  hinge_sections(const SectionLaw &end_i, const SectionLaw &interior, const SectionLaw &end_j);

  /// A uniform load along a member per unit length, in its local axes:
  /// 2D (w_x, w_y), 3D (w_x, w_y, w_z); x along the chord.
  template <int dim>
  using MemberLoad = Eigen::Matrix<double, MemberSize<dim>::space, 1>;

  /// The fixed-end basic forces q0 and the basic system's reactions p0
  /// (2D: axial at I, transverse at I and J; 3D: then along z at I and J)
  /// of a uniform load on a member of length L (see above; OpenSees's
  /// ElasticBeam2d/3d and DispBeamColumn2d/3d::addLoad).
  template <int dim>
  struct UniformLoadForces
  {
    typename CrdTransformation<dim>::BasicVector q0;
    Eigen::Matrix<double, 2 * dim - 1, 1>      p0;
  };
  template <int dim>
  UniformLoadForces<dim> uniform_load_forces(double length, const MemberLoad<dim> &w);
  /// The basic reactions p0 as global end forces of the member of
  /// `transformation` (local components at its ends, carried to the nodes
  /// by the rigid offsets).
  template <int dim>
  typename CrdTransformation<dim>::GlobalVector
  basic_reactions(const CrdTransformation<dim> &transformation,
                  const Eigen::Matrix<double, 2 * dim - 1, 1> &p0);
  /// The global end forces that hold an elastic member fixed at both ends
  /// under the uniform load w (local axes): B^T q0 + p0 at u = 0. Their
  /// negative is the load's consistent nodal loads.
  template <int dim>
  typename CrdTransformation<dim>::GlobalVector
  fixed_end_forces(const CrdTransformation<dim> &transformation, const MemberLoad<dim> &w);

  template <int dim>
  class BeamColumn
  {
  public:
    static constexpr int n_dofs = MemberSize<dim>::dofs, n_basic = MemberSize<dim>::basic,
                         n_resultants = MemberSize<dim>::resultants;
    using GlobalVector     = typename CrdTransformation<dim>::GlobalVector;
    using GlobalMatrix     = typename CrdTransformation<dim>::GlobalMatrix;
    using BasicVector      = typename CrdTransformation<dim>::BasicVector;
    using BasicMatrix      = typename CrdTransformation<dim>::BasicMatrix;
    using ResultantVector  = Eigen::Matrix<double, n_resultants, 1>;
    using ResultantMatrix  = Eigen::Matrix<double, n_resultants, n_resultants>;
    using Interpolation    = Eigen::Matrix<double, n_resultants, n_basic>;

    /// One section per point of `integration` (n_resultants() each: 2 in
    /// the plane, 4 in space); Assert otherwise.
    BeamColumn(const CrdTransformation<dim> &transformation, BeamIntegration integration,
               std::vector<std::unique_ptr<SectionLaw>> sections);
    virtual ~BeamColumn() = default;

    /// The state at the global end displacements u (the nodes' totals:
    /// the transformation's displacements_when_made are subtracted); false when a section
    /// refuses its deformation or the element's iteration fails (failure()
    /// says which): the trial state must then not be used.
    bool set_trial(const GlobalVector &u);
    const GlobalVector &resisting_force() const { return trial.force; }
    const GlobalMatrix &tangent() const { return trial.stiffness; }
    const BasicVector  &basic_force() const { return trial.basic_force; }
    const BasicMatrix  &basic_tangent() const { return trial.basic_stiffness; }
    const BasicVector  &basic_deformation() const { return transf.basic_deformation(); }
    /// The global tangent at the virgin state, u = 0.
    const GlobalMatrix &initial_tangent() const { return virgin_stiffness; }
    /// u of the last set_trial, measured from when the member was made.
    const GlobalVector &trial_displacement() const { return trial_u; }

    /// A uniform load along the member (local axes, per unit length, at load
    /// factor 1; see above). Not on a corotational member.
    void set_uniform_load(const MemberLoad<dim> &w);
    const MemberLoad<dim> &uniform_load() const { return load; }
    bool                   loaded() const { return has_load; }
    /// The factor of the uniform load from the next set_trial on; reset()
    /// and the constructor leave it at 0.
    void   set_load_factor(const double lambda) { load_factor = lambda; }
    double current_load_factor() const { return load_factor; }

    void commit();
    void revert();
    void reset();
    std::string failure() const { return why; }

    const CrdTransformation<dim> &transformation() const { return transf; }
    const BeamIntegration        &integration() const { return rule; }
    unsigned int                  n_points() const { return rule.size(); }
    /// The section law at point i (resultants, deformations: recorders).
    const SectionLaw &section(unsigned int i) const { return *sections[i]; }
    double            length() const { return transf.initial_length(); }
    /// sum_i w_i L s_i^T k_s0,i^-1 s_i / 2: the energy unloading at the
    /// sections' initial stiffness recovers.
    double stored_energy() const;
    /// The work the uniform load, held at its current factor lambda, does
    /// from the undeformed member to the trial state: with p0 the basic
    /// reactions (global, load_reactions) and u the end displacements,
    ///   displacement-based: -lambda (q0 . v + p0 . u) (the consistent loads
    ///     on the cubic and linear fields),
    ///   force-based: lambda (L sum_i w_i s_p,i . e_i - p0 . u) (the load
    ///     on the field of the sections' deformations, by virtual work on
    ///     the simply supported member, plus its rigid motion).
    /// Linear in the state: its change at a constant factor is the load's
    /// work, which the resisting force's work then lacks (0 without a load).
    double held_load_work() const;

  protected:
    /// q and k_b at the basic deformations v (from the last trial state).
    virtual bool basic_state(const BasicVector &v, BasicVector &q, BasicMatrix &k) = 0;
    virtual void commit_basic() {}
    virtual void revert_basic() {}
    virtual void reset_basic() {}
    /// After reset's evaluation at v = 0: forget what it left in the basic
    /// state, as the sections forget it (default: nothing to forget).
    virtual void forget_reset_evaluation() {}
    /// Whether the sections carry the uniform load (force-based: s_p), or
    /// the fixed-end forces q0 are added to q (displacement-based).
    virtual bool sections_carry_load() const { return false; }
    /// The sections' forces s_p at point i of the uniform load at factor 1.
    ResultantVector particular_forces(unsigned int i) const;

    struct State
    {
      GlobalVector force;
      GlobalMatrix stiffness;
      BasicVector  basic_force;
      BasicMatrix  basic_stiffness;
    };

    CrdTransformation<dim>                   transf;
    BeamIntegration                          rule;
    std::vector<std::unique_ptr<SectionLaw>> sections;
    std::string                              why;
    MemberLoad<dim>                          load = MemberLoad<dim>::Zero();
    bool                                     has_load    = false;
    double                                   load_factor = 0;

  private:
    UniformLoadForces<dim> load_forces{};   // at factor 1
    GlobalVector           load_reactions; // p0 in global components, at factor 1
    State        trial, committed;
    GlobalVector trial_u, committed_u;
    GlobalMatrix virgin_stiffness;
  };

  /// Displacement-based: e_i = a_i v (see above).
  template <int dim>
  class DispBeamColumn : public BeamColumn<dim>
  {
  public:
    using typename BeamColumn<dim>::BasicVector;
    using typename BeamColumn<dim>::BasicMatrix;
    using typename BeamColumn<dim>::Interpolation;
    /// Gauss-Legendre with `n_points` points, one clone of `section` each.
    DispBeamColumn(const CrdTransformation<dim> &transformation, const SectionLaw &section,
                   unsigned int n_points = 5);
    DispBeamColumn(const CrdTransformation<dim> &transformation, BeamIntegration integration,
                   std::vector<std::unique_ptr<SectionLaw>> sections);

    /// a(xi) with e = a v.
    static Interpolation deformation_interpolation(double xi, double length);

  protected:
    bool basic_state(const BasicVector &v, BasicVector &q, BasicMatrix &k) override;
  };

  /// OpenSees's own element iteration (ForceBeamColumn2d/3d::update in
  /// OpenSees 3.8), for scripts that must give OpenSees's numbers: from the
  /// last trial state, q += k_v dv; then up to max_iterations iterations of
  /// the section updates above, converged when |dW| = |r . F^-1 r| <
  /// tolerance (absolute, in the model's units of work); when they do not
  /// converge, the same from the last converged state with the sections'
  /// deformation increments by their initial flexibility (10 max_iterations),
  /// then with the initial flexibility in the first iteration only; then
  /// the increment divided by subdivide_factor, up to max_subdivisions
  /// times (a converged piece resets the count). An increment below
  /// DBL_EPSILON leaves the state as it is, except in the first update
  /// after a reset or a revert, which also keeps the sections' deformations
  /// (OpenSees's initialFlag 0). Defaults: OpenSees's (-iter 10 1e-12,
  /// -subdivide 4 10).
  struct OpenSeesIteration
  {
    unsigned int max_iterations   = 10;
    double       tolerance        = 1e-12;
    unsigned int max_subdivisions = 4;
    double       subdivide_factor = 10;
  };

  /// Force-based: s_i = b_i q, iterated to compatibility (see above).
  template <int dim>
  class ForceBeamColumn : public BeamColumn<dim>
  {
  public:
    using typename BeamColumn<dim>::BasicVector;
    using typename BeamColumn<dim>::BasicMatrix;
    using typename BeamColumn<dim>::Interpolation;
    using typename BeamColumn<dim>::ResultantVector;
    using typename BeamColumn<dim>::ResultantMatrix;
    /// Gauss-Lobatto with `n_points` points, one clone of `section` each.
    ForceBeamColumn(const CrdTransformation<dim> &transformation, const SectionLaw &section,
                    unsigned int n_points = 5);
    ForceBeamColumn(const CrdTransformation<dim> &transformation, BeamIntegration integration,
                    std::vector<std::unique_ptr<SectionLaw>> sections);

    /// b(xi) with s = b q.
    static Interpolation force_interpolation(double xi);

    /// The element iterations of the last set_trial (all pieces), and the
    /// number of pieces its increment took (1: no subdivision).
    unsigned int last_iterations() const { return iterations; }
    unsigned int last_pieces() const { return pieces; }

    /// Iterate as OpenSees does (OpenSeesIteration) from now on.
    void use_opensees_iteration(const OpenSeesIteration &controls);

  protected:
    bool basic_state(const BasicVector &v, BasicVector &q, BasicMatrix &k) override;
    void commit_basic() override { committed = current; }
    void revert_basic() override
    {
      current     = committed;
      initialised = false;
    }
    void reset_basic() override;
    /// OpenSees's revertToStart leaves initialFlag = 0: the next update (the
    /// domain's, at the nodes' zero displacements) is then the linear first
    /// one, q = F_0^-1 v with the sections at zero, whatever v is (it is not
    /// 0 for a member made on nodes that had moved).
    void forget_reset_evaluation() override
    {
      if (opensees)
        revert_basic();
    }
    bool sections_carry_load() const override { return true; }

  private:
    /// The element's state between trials: the compatible v, q, F^-1, and
    /// at each point e_i, s_i, f_s,i; the load factor it is compatible at.
    struct IterationState
    {
      BasicVector                  v, q;
      double                       factor = 0;
      BasicMatrix                  kv;
      std::vector<ResultantVector> e, s;
      std::vector<ResultantMatrix> fs;
    };
    /// Iterate from `current` to compatibility with `target` at the load
    /// factor `target_factor`; false (and `current` spoiled) when it does
    /// not converge. `initial`: the sections' deformations corrected by
    /// their initial flexibility (ten times the iterations), OpenSees's
    /// fallback.
    bool iterate(const BasicVector &target, double target_factor, bool initial);
    /// b_i q + lambda s_p,i: the forces section i must carry.
    ResultantVector section_forces(unsigned int i, const BasicVector &q, double factor) const;
    /// lambda^2 sum_i w_i L |s_p,i . f_s,i s_p,i|: the load's share of the
    /// tolerance's energy scale (0 without a load).
    double load_energy(double factor) const;
    /// f_s from the section's tangent, its small diagonal raised.
    ResultantMatrix flexibility(unsigned int i) const;
    /// OpenSeesIteration's state determination.
    bool opensees_state(const BasicVector &v);
    /// One of its three passes (0: tangent flexibility, 1: initial, 2:
    /// initial in the first iteration) over the increment dv from `vin`,
    /// from `current` into `start`: 1 converged, 0 not, -1 a section failed.
    int opensees_pass(unsigned int pass, const BasicVector &vin, const BasicVector &dv);

    IterationState              current, committed, start;
    std::vector<ResultantMatrix> initial_section_stiffness;
    unsigned int                iterations = 0, pieces = 0;
    bool                        opensees     = false;
    OpenSeesIteration           opensees_controls;
    bool                        initialised = false; // OpenSees's initialFlag != 0
  };
} // namespace poundfe

#endif
