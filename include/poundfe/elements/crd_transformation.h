// The coordinate transformations of a beam-column between its global end
// displacements u (2D: ux, uy, rz per end; 3D: ux, uy, uz, rx, ry, rz per
// end) and OpenSees's basic system, the deformations v free of rigid-body
// motion and their work-conjugate basic forces q:
//   2D: v = (axial deformation, thetaI, thetaJ), q = (N, MI, MJ);
//   3D: v = (axial, thetaIz, thetaJz, thetaIy, thetaJy, twist),
//       q = (N, MzI, MzJ, MyI, MyJ, T);
// the end rotations are relative to the chord. The element's global
// resisting force and tangent are then
//   p = B(u)^T q + p_g,   K = B^T k_b B + K_g,
// with B = dv/du and K_g the geometric part of the transformation.
//   Linear (OpenSees's LinearCrdTransf2d/3d): v = B u, B constant, K_g = 0:
//     2D, with (c, s) the chord's direction, L its length,
//       v0 = c dux + s duy,  vI = rzI - (c duy - s dux)/L,  vJ = rzJ - (...)/L
//     (d = end J minus end I); 3D the same per plane in the local axes of
//     elements/frame_element_3d.h, vIy = ryI + dw/L, twist = rxJ - rxI.
//   PDelta (OpenSees's PDeltaCrdTransf2d/3d): v as Linear, and the chord's
//     transverse relative displacements delta (2D one, 3D two) carry
//     p_g = N delta/L g (g = d delta/du): the shear of an axial force on a
//     drifted chord. Its consistent tangent K_g = N/L g g^T + (delta/L) g
//     (dN/du)^T keeps the second term, which OpenSees drops (it vanishes on
//     the undeformed member, so buckling loads agree) and which makes K
//     nonsymmetric; Newton's iteration then converges quadratically. An
//     OpenSees script's members drop it as OpenSees does
//     (use_opensees_tangent).
//   Corotational 2D (Crisfield 1991, vol. 1, §7.3; de Souza 2000, ch. 3;
//     OpenSees's CorotCrdTransf2d): the chord's current length Ln and angle
//     beta, its rotation alpha = beta - beta0 from the initial chord,
//       v0 = (Ln^2 - L0^2)/(Ln + L0),  vI = rzI - alpha,  vJ = rzJ - alpha,
//     B = [r; e3 - w/Ln; e6 - w/Ln], r = (-c, -s, 0, c, s, 0),
//     w = (s, -c, 0, -s, c, 0), and
//       K_g = N/Ln w w^T + (MI + MJ)/Ln^2 (r w^T + w r^T)   (symmetric).
//     alpha is taken within pi of the mean end rotation (rzI + rzJ)/2, so a
//     member may turn through any number of turns (a circle).
//   Corotational 3D (Crisfield 1990, 1997; OpenSees's CorotCrdTransf3d):
//     the nodal triads turned by the rotation increments between updates,
//     elements/corotational_3d.h; commit, revert and reset keep, restore
//     and restart the triads. No rigid end offsets (OpenSees 3.8 drops
//     them with a warning).
//   A member made on nodes that have moved (OpenSees's LinearCrdTransf2d/3d,
//     PDeltaCrdTransf2d/3d, CorotCrdTransf2d/3d::initialize: nodeIInitialDisp,
//     nodeJInitialDisp): its chord joins the ends displaced by the nodes'
//     translations u_0 then, X_J + o_J + u_0J - (X_I + o_I + u_0I), and it
//     is measured from then: update takes u - u_0 (BeamColumn::set_trial).
//   Rigid end offsets (OpenSees's -jntOffset, global components o_I, o_J
//     from each node to the member's flexible end) as OpenSees: by the
//     linearised rigid link u_end = u_node + r x o, a constant matrix T_o:
//     p = T_o^T p', K = T_o^T K' T_o, the chord joining the offset ends.
// Sources: McGuire, Gallagher & Ziemian (2000) ch. 4, 9; Crisfield,
// Non-linear Finite Element Analysis of Solids and Structures, vol. 1 (1991)
// §7.3; de Souza, Force-based finite element for large displacement
// inelastic analysis of frames, PhD thesis, UC Berkeley (2000); OpenSees's
// CrdTransf classes for the basic system and its signs.
#ifndef poundfe_elements_crd_transformation_h
#define poundfe_elements_crd_transformation_h

#include <poundfe/elements/corotational_3d.h>

#include <Eigen/Core>

namespace poundfe
{
  /// Sizes of a member in dim dimensions: global DOFs, basic deformations,
  /// section resultants.
  template <int dim>
  struct MemberSize;
  template <>
  struct MemberSize<2>
  {
    static constexpr int dofs = 6, basic = 3, resultants = 2, space = 2;
  };
  template <>
  struct MemberSize<3>
  {
    static constexpr int dofs = 12, basic = 6, resultants = 4, space = 3;
  };

  enum class Transformation
  {
    linear,
    pdelta,
    corotational
  };

  template <int dim>
  class CrdTransformation
  {
  public:
    static constexpr int n_dofs = MemberSize<dim>::dofs, n_basic = MemberSize<dim>::basic;
    using Point       = Eigen::Matrix<double, dim, 1>;
    using GlobalVector = Eigen::Matrix<double, n_dofs, 1>;
    using GlobalMatrix = Eigen::Matrix<double, n_dofs, n_dofs>;
    using BasicVector  = Eigen::Matrix<double, n_basic, 1>;
    using BasicMatrix  = Eigen::Matrix<double, n_basic, n_basic>;
    using Compatibility = Eigen::Matrix<double, n_basic, n_dofs>;

    /// The member from node I to node J; `orientation` (3D only): the
    /// vector in the local x-z plane (elements/frame_element_3d.h);
    /// offsets from each node to the flexible end; `u_made`: the nodes'
    /// displacements when the member is made (OpenSees's initial
    /// displacements: a member added on nodes that have moved). InputError
    /// for a member of zero length, an orientation parallel to it, or a
    /// corotational member in space with offsets.
    CrdTransformation(Transformation kind, const Point &node_i, const Point &node_j,
                      const Point &offset_i = Point::Zero(), const Point &offset_j = Point::Zero(),
                      const Eigen::Vector3d &orientation = Eigen::Vector3d::UnitZ(),
                      const GlobalVector &u_made = GlobalVector::Zero());

    Transformation kind() const { return type; }
    /// The flexible length between the offset ends, undeformed.
    double initial_length() const { return length0; }
    /// Rows: local x, y(, z) in global components (2D: 2 x 2).
    const Eigen::Matrix<double, dim, dim> &local_axes() const { return axes; }

    /// The nodes' displacements when the member was made: u of update is
    /// measured from them.
    const GlobalVector &displacements_when_made() const { return u_made; }

    /// Evaluate v and B at the global end displacements u (from u_made).
    /// Corotational in space, the rotations' change since the last update
    /// turns the nodal triads: updates follow the path of the trials.
    void update(const GlobalVector &u);
    /// Corotational in space: keep the nodal triads, go back to the kept
    /// ones (the next update turns them from the committed rotations), or
    /// to the initial ones; nothing for the others.
    void commit();
    void revert();
    void reset();
    const BasicVector  &basic_deformation() const { return v; }
    /// B = dv/du at the last update (constant for linear and PDelta).
    const Compatibility &compatibility() const { return b; }
    /// p = B^T q + p_g at the last update.
    GlobalVector global_force(const BasicVector &q) const;
    /// K = B^T k_b B + K_g at the last update, for the basic forces q and
    /// the basic tangent k_b = dq/dv.
    GlobalMatrix global_tangent(const BasicVector &q, const BasicMatrix &k_b) const;
    /// T_o: the flexible ends' displacements u' = T_o u (identity without
    /// offsets).
    const GlobalMatrix &offset_matrix() const { return offsets; }
    /// J - I between the flexible ends, undeformed.
    const Point &chord() const { return chord0; }
    /// PDelta: K_g = N/L g g^T alone, without (delta/L) g (dN/du)^T, as
    /// OpenSees's PDeltaCrdTransf2d/3d::getGlobalStiffMatrix. The converged
    /// states are the same; the tangent itself differs wherever N varies
    /// on a drifted chord, and an OpenSees script's Rayleigh damping on the
    /// current or committed stiffness (C = beta K_t) takes it as it is.
    void use_opensees_tangent() { opensees_tangent = true; }
    /// Whether K is symmetric whenever k_b is (PDelta's consistent one is not).
    bool has_symmetric_tangent() const
    {
      if (type == Transformation::corotational)
        return dim == 2;
      return type != Transformation::pdelta || opensees_tangent;
    }

  private:
    /// Local x, y(, z) rows from the chord and the orientation.
    void set_axes(const Eigen::Vector3d &orientation);
    /// The flexible ends' displacements u' = T_o u.
    GlobalVector offset_displacements(const GlobalVector &u) const;
    void         update_corotational(const GlobalVector &u_flexible);
    /// The transverse relative displacements' gradients g (PDelta), in
    /// flexible-end components, and delta.
    void transverse(const GlobalVector &u_flexible, Eigen::Matrix<double, n_dofs, dim - 1> &g,
                    Eigen::Matrix<double, dim - 1, 1> &delta) const;

    Transformation                  type;
    GlobalVector                    u_made; // see displacements_when_made
    Point                           chord0; // J - I between the flexible ends
    double                          length0;
    Eigen::Matrix<double, dim, dim> axes;
    GlobalMatrix                    offsets; // T_o
    bool                            has_offsets;
    bool                            opensees_tangent = false; // see use_opensees_tangent
    Compatibility                   b_linear, b; // B' (flexible ends) and B = B' T_o
    BasicVector                     v;
    GlobalVector                    u_end; // u' of the last update
    double                          length = 0;      // corotational: Ln
    Eigen::Matrix<double, 2, 1>     direction;       // corotational: (c, s)
    Corotational3d                  triads;          // corotational in space
  };
} // namespace poundfe

#endif
