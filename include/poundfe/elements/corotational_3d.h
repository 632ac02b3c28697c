// The corotational basic system of a member in space: Crisfield's
// formulation with nodal triads updated by the rotation increments, as
// OpenSees 3.8's CorotCrdTransf3d.
//
// Each end carries a triad R_I, R_J (unit quaternions, R_I = R_0 when the
// member is made: its local axes x, y, z as columns). An update takes the
// change of each end's rotation DOFs since the last update, d_theta, as a
// spatial spin: R <- exp(S(d_theta)) R (the DOFs themselves add up the
// increments, as OpenSees's nodes do). With the relative rotation
// R_J R_I^T as the tangent-scaled pseudo-vector w = 2 tan(phi/2) n, the
// mean triad is R_bar = R(w/2) R_I, R(w) = I + (S(w) + S(w)^2/2)/(1 +
// |w|^2/4), and its columns r_1, r_2, r_3 are turned onto the chord's
// direction e_1 = (X_J - X_I + u_J - u_I)/L_n by the mid-point rule
//   e_k = r_k - (e_1 + r_1)(r_k . e_1)/2   (k = 2, 3).
// The local deformations, with the triads' columns r_I1..r_I3, r_J1..r_J3,
//   t_Ix = asin((r_I2.e_3 - r_I3.e_2)/2),  t_Iz = asin((r_I1.e_2 - r_I2.e_1)/2),
//   t_Iy = asin((r_I1.e_3 - r_I3.e_1)/2)   (the same at J),
//   u = 2 (X_JI + d_JI/2) . d_JI / (L_n + L)   (the elongation, mid-point),
// give the basic ones of OpenSees's order
//   v = (u, t_Iz, t_Jz, -t_Iy, -t_Jy, t_Jx - t_Ix).
// Each asin(s) has the gradient ds/(2 cos t): d(a.e_k) = (a x e_k) . d_theta
// for the triad's vector a, plus, for e_1, A = (I - e_1 e_1^T)/L_n on the
// relative translation, and, for e_2 and e_3, L(r_k) of Crisfield's
// mid-point rule (12 x 3). The tangent is B^T k_b B plus the geometric
// terms K_sigma1..5 of Crisfield (vol. 2, §17.4) as CorotCrdTransf3d::
// getGlobalStiffMatrix writes them (its torsional terms on the moment at J,
// its terms of the mean triad through L(r_2), L(r_3)), so that Newton's
// iterates, which the triads' updates depend on, are OpenSees's.
// Sources: Crisfield, Non-linear Finite Element Analysis of Solids and
// Structures, vol. 2 (1997), ch. 17; Crisfield, "A consistent co-rotational
// formulation for non-linear, three-dimensional, beam-elements", CMAME 81
// (1990); de Souza (2000), ch. 3; OpenSees 3.8, SRC/coordTransformation/
// CorotCrdTransf3d.cpp (update, compTransfMatrixBasicGlobal,
// getGlobalStiffMatrix, getLMatrix, getKs2Matrix).
#ifndef poundfe_elements_corotational_3d_h
#define poundfe_elements_corotational_3d_h

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace poundfe
{
  class Corotational3d
  {
  public:
    using GlobalVector  = Eigen::Matrix<double, 12, 1>;
    using GlobalMatrix  = Eigen::Matrix<double, 12, 12>;
    using BasicVector   = Eigen::Matrix<double, 6, 1>;
    using Compatibility = Eigen::Matrix<double, 6, 12>;

    Corotational3d() = default;
    /// `axes`: the local x, y, z as rows; `chord`: J - I when made.
    Corotational3d(const Eigen::Matrix3d &axes, const Eigen::Vector3d &chord);

    /// The state at the end displacements u (from when made): the rotation
    /// DOFs' change since the last update turns the triads.
    void update(const GlobalVector &u);
    const BasicVector   &basic_deformation() const { return v; }
    const Compatibility &compatibility() const { return b; }
    /// The geometric part of the tangent at the basic forces q.
    GlobalMatrix geometric_tangent(const BasicVector &q) const;
    double       deformed_length() const { return length; }

    /// The triads as committed; back to them (the next update turns them
    /// by the change from the committed rotations); back to R_0.
    void commit() { committed = trial; }
    void revert() { trial = committed; }
    void reset();

  private:
    struct Triads
    {
      Eigen::Quaterniond i = Eigen::Quaterniond::Identity(), j = Eigen::Quaterniond::Identity();
      Eigen::Vector3d    rotation_i = Eigen::Vector3d::Zero(), rotation_j = Eigen::Vector3d::Zero();
    };
    using LocalVector = Eigen::Matrix<double, 7, 1>;
    using Gradients   = Eigen::Matrix<double, 7, 12>;
    using MidPoint    = Eigen::Matrix<double, 12, 3>;

    /// L(r) of the mid-point rule: d(a . e_k)/du through e_k's r_k = r.
    MidPoint mid_point_matrix(const Eigen::Vector3d &r) const;
    /// The gradient of a . e_k (k = 0, 1, 2) for the vector a of the triad of
    /// `end` (0: I, 1: J).
    GlobalVector dot_gradient(const Eigen::Vector3d &a, int end, int k) const;
    /// The rows of T: the local deformations' gradients.
    void set_gradients();
    /// Crisfield's K_sigma2 of (r, z).
    GlobalMatrix k_sigma2(const Eigen::Vector3d &r, const Eigen::Vector3d &z) const;
    /// K_sigma1, 3, 4 and 5 (m: the local moments over 2 cos t).
    GlobalMatrix k_sigma_1345(double axial, const Eigen::Matrix<double, 6, 1> &m) const;

    Eigen::Matrix3d axes0 = Eigen::Matrix3d::Identity(); // R_0's columns: x, y, z
    Eigen::Vector3d chord0 = Eigen::Vector3d::UnitX();
    double          length0 = 1, length = 1;
    Triads          trial, committed;
    // the geometry of the last update
    Eigen::Matrix3d r_i, r_j, r_bar, e, a;
    LocalVector     local = LocalVector::Zero();
    Gradients       t     = Gradients::Zero();
    MidPoint        l_2, l_3;
    BasicVector     v = BasicVector::Zero();
    Compatibility   b = Compatibility::Zero();
  };
} // namespace poundfe

#endif
