// Undamped modes: K phi = omega^2 M phi on the free DOFs. Lumped masses leave
// rotations massless (M singular), so both solvers work with K, the positive
// definite matrix, and never invert M:
//  - dense (Eigen): M phi = mu K phi, mu = 1/omega^2, all n modes, and the
//    massless mu = 0 ones dropped; O(n^3), for small models;
//  - sparse (ARPACK's implicitly restarted Lanczos through deal.II's
//    ArpackSolver): shift-invert with shift 0, the operator K^-1 M (fine
//    with M semidefinite: its massless directions have eigenvalue 0, the
//    far end of the spectrum), a sparse Cholesky factor of K, the few
//    lowest modes; then one subspace-iteration step and a Rayleigh-Ritz
//    projection (source/dynamics/modal_sparse.cc).
// Participation: Gamma_n = phi_n^T M r (phi mass-normalised), effective modal
// mass Gamma_n^2, ratio Gamma_n^2 / (r^T M r) (Chopra, §13.2).
// Sources: Bathe, Finite Element Procedures (1996), §11.6
// (subspace iteration, Rayleigh-Ritz); Ericsson & Ruhe, Math. Comp. 35
// (1980) 1251-1268 (spectral transformation Lanczos, singular M); Lehoucq,
// Sorensen & Yang, ARPACK Users' Guide (SIAM 1998) (mode 3, shift-invert).
#ifndef poundfe_dynamics_modal_h
#define poundfe_dynamics_modal_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/dynamics/modal_parameters.h>

#include <Eigen/Core>

#include <vector>

namespace poundfe
{
  struct Modes
  {
    std::vector<double> omega;                   // rad/s, ascending
    Eigen::MatrixXd     shapes;                  // mass-normalised, one per column
    std::vector<double> participating_mass_ratio; // horizontal (x) direction
    /// Dimension 3 (empty in 2D): along y, and about z (θz of every floor
    /// about its mass centre: Gamma^2 / sum of the polar moments).
    std::vector<double> participating_mass_ratio_y, participating_mass_ratio_rz;

    unsigned int n_modes() const { return omega.size(); }
    double frequency(unsigned int i) const;      // Hz
    double period(unsigned int i) const;         // s
  };

  /// The most modes the sparse solver can return: one per DOF that carries
  /// mass (the rank of K^-1 M; the other eigenvalues are infinite).
  unsigned int max_sparse_modes(const SparseMatrix &mass);

  /// The most modes ARPACK's Lanczos iteration can find: its basis needs
  /// more than 2n + 1 vectors, all within the DOFs that carry mass. Beyond
  /// it (small models) the sparse solver projects on every massive DOF.
  unsigned int lanczos_mode_limit(const SparseMatrix &mass);

  /// The solver `automatic` stands for with this model and n modes wanted
  /// (dense or sparse); others are returned as they are.
  Eigensolver choose_eigensolver(Eigensolver requested, const SparseMatrix &mass,
                                 unsigned int n);

  /// The n lowest modes (all if n exceeds the count). Throws NumericalError if K is
  /// singular or not positive definite (a mechanism), or if the sparse
  /// solver does not converge.
  Modes compute_modes(const SparseMatrix &mass, const SparseMatrix &stiffness,
                      const Vector &influence, unsigned int n,
                      Eigensolver solver = Eigensolver::automatic);

  Modes compute_modes_dense(const SparseMatrix &mass, const SparseMatrix &stiffness,
                            const Vector &influence, unsigned int n);
  Modes compute_modes_sparse(const SparseMatrix &mass, const SparseMatrix &stiffness,
                             const Vector &influence, unsigned int n);

  /// Mass-normalise `phi`, give it the sign convention (its largest
  /// component positive) and append it with omega and its participation.
  /// Both solvers finish their modes here.
  void append_mode(Modes &modes, Eigen::VectorXd phi, double omega, const SparseMatrix &mass,
                   const Vector &influence);

  /// Gamma^2 / (r^T M r), Gamma = phi^T M r, of a mass-normalised phi.
  double participating_mass_ratio(const Eigen::VectorXd &phi, const SparseMatrix &mass,
                                  const Vector &influence);

  /// Dimension 3: the ratios along y and about z of every mode.
  void add_plan_participation(Modes &modes, const SparseMatrix &mass, const Vector &influence_y,
                              const Vector &influence_rz);

  /// What compute_modes throws when K has no Cholesky factor.
  extern const char *const stiffness_not_positive_definite;
} // namespace poundfe

#endif
