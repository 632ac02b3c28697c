// Bidirectional Bouc-Wen hysteresis (Park, Wen & Ang 1986) on two
// deformations u = (u_1, u_2) (a storey's drifts along two perpendicular
// resisting planes, or a 3D hinge's rotations about its two bending axes),
// each axis j with its own initial stiffness k_j and yield deformation u_yj:
//   F_j   = alpha k_j u_j + (1 - alpha) k_j u_yj z_j,
//   dz_i  = A dc_i - |z|^(n-2) z_i sum_j ( beta |dc_j z_j| + gamma dc_j z_j ),
//   dc_j  = du_j / u_yj,
// i.e. dz = G(z, s) dc with G_ij = A delta_ij - |z|^(n-2) z_i (beta s_j |z_j|
// + gamma z_j), s_j = sgn(dc_j). For n = 2 this is the published form (Park,
// Wen & Ang 1986, eq. 5; also 3D-BASIS, Nagarajaiah et al. 1991); for n != 2
// the factor |z|^(n-2) keeps Wen's uniaxial law (laws/bouc_wen.h) along each
// axis (n >= 2 here). Along one axis (dc_2 = 0, z_2 = 0) it IS the uniaxial
// law. Since z.dz = A dc.z - |z|^n (beta sum_j |dc_j z_j| + gamma dc.z), for
// A = beta + gamma z.dz = beta (dc.z - sum_j |dc_j z_j|) <= 0 on |z| = 1: the
// state stays in the unit disc, the yield surface is the circle |z| = 1, an
// ellipse (F_1/F_y1)^2 + (F_2/F_y2)^2 = 1 of the hysteretic forces
// F_yj = (1 - alpha) k_j u_yj.
// The rate-independent ODE is integrated over the step as the uniaxial law
// does (generalised midpoint rule, theta = 1/2 trapezoidal, 1 backward
// Euler), the sign s_j fixed by the step's increment:
//   z1 = z0 + (1 - theta) G(z0, s) dc + theta G(z1, s) dc,
// solved by a 2x2 Newton iteration from the committed z0 with backtracking,
// Jacobian J = I - theta d(G(z1, s) dc)/dz1 with
//   d(G dc)/dz = -( w dq/dz + q (dw/dz)^T ),  q = |z|^(n-2) z,
//   w = sum_j dc_j (beta s_j |z_j| + gamma z_j),
//   dq/dz = |z|^(n-2) I + (n - 2) |z|^(n-4) z z^T,
//   dw/dz_k = dc_k (beta s_k sgn(z_k) + gamma).
// The tangent is the exact derivative of the discrete map (implicit
// function theorem): dz1/dc = J^-1 ((1 - theta) G(z0, s) + theta G(z1, s)),
//   dF_i/du_j = alpha k_i delta_ij + (1 - alpha) k_i u_yi (dz1_i/dc_j) / u_yj,
// in general unsymmetric. Strength and stiffness degradation (Baber-Noori)
// are not part of the published bidirectional model: their parameters must
// be 0. State: trial -> force and tangent -> commit() or revert(), as the
// uniaxial laws (laws/uniaxial_law.h); revert() restores the committed
// state exactly.
// Sources: Y.J. Park, Y.K. Wen & A.H.-S. Ang, Earthquake Eng. Struct. Dyn.
// 14 (1986) 543-557; S. Nagarajaiah, A.M. Reinhorn & M.C. Constantinou,
// J. Struct. Eng. 117 (1991) 2035-2054; doc/theory.md §2.
#ifndef poundfe_laws_bidirectional_bouc_wen_h
#define poundfe_laws_bidirectional_bouc_wen_h

#include <poundfe/laws/bouc_wen.h>

#include <Eigen/Core>

#include <array>
#include <string>

namespace poundfe
{
  class BidirectionalBoucWen
  {
  public:
    /// One uniaxial parameter set per axis: the stiffness and the yield
    /// deformation are taken per axis, everything else (alpha, A, beta,
    /// gamma, n, theta, tolerance, iterations) from `axis_1`; the two must
    /// agree on these (Assert), and the degradation parameters must be 0.
    BidirectionalBoucWen(const BoucWenParameters &axis_1, const BoucWenParameters &axis_2);

    /// Evaluate the trial state at deformation u. Returns false when the
    /// local Newton iteration fails (failure() says why).
    bool set_trial(const Eigen::Vector2d &deformation);

    const Eigen::Vector2d &force() const { return trial_force; }
    /// dF/du at the trial state (unsymmetric).
    const Eigen::Matrix2d &tangent() const { return trial_tangent; }
    /// The hysteretic variables (z_1, z_2) of the trial state.
    const Eigen::Vector2d &history() const { return trial.z; }
    const Eigen::Vector2d &deformation() const { return trial.deformation; }
    /// Recoverable energy: alpha k |u|^2 / 2 + (1 - alpha) k u_y^2 |z|^2 / 2
    /// summed over the axes.
    double stored_energy() const;
    double initial_stiffness(unsigned int axis) const { return axes[axis].stiffness; }
    double yield_deformation(unsigned int axis) const { return axes[axis].yield_deformation; }

    void        commit();
    void        revert();
    void        reset();
    std::string failure() const { return failure_message; }

  private:
    struct State
    {
      Eigen::Vector2d deformation = Eigen::Vector2d::Zero();
      Eigen::Vector2d z           = Eigen::Vector2d::Zero();
      Eigen::Vector2d direction   = Eigen::Vector2d::Ones(); // sign of the last increment
    };
    /// G(z, s) of the header.
    Eigen::Matrix2d rate_matrix(const Eigen::Vector2d &z, const Eigen::Vector2d &s) const;
    /// d(G(z, s) dc)/dz.
    Eigen::Matrix2d rate_jacobian(const Eigen::Vector2d &z, const Eigen::Vector2d &s,
                                  const Eigen::Vector2d &dc) const;
    Eigen::Vector2d force_of(const Eigen::Vector2d &deformation, const Eigen::Vector2d &z) const;
    /// dF/du from dz/dc.
    Eigen::Matrix2d tangent_of(const Eigen::Matrix2d &dz_dc) const;

    /// The parameters the axes share (alpha, A, beta, gamma, n, theta, ...).
    const BoucWenParameters &shared() const { return axes[0]; }

    std::array<BoucWenParameters, 2> axes;
    State                            committed, trial;
    Eigen::Vector2d                  trial_force   = Eigen::Vector2d::Zero();
    Eigen::Matrix2d                  trial_tangent = Eigen::Matrix2d::Zero();
    std::string                      failure_message;
  };
} // namespace poundfe

#endif
