// Undamped modes: K phi = omega^2 M phi on the free DOFs. Lumped masses leave
// rotations massless (M singular), so we solve the equivalent M phi = mu K phi
// with K positive definite, mu = 1/omega^2, and drop the massless mu = 0 modes.
// Participation: Gamma_n = phi_n^T M r (phi mass-normalised), effective modal
// mass Gamma_n^2, ratio Gamma_n^2 / (r^T M r) (Chopra, §13.2).
#ifndef poundfe_analysis_modal_h
#define poundfe_analysis_modal_h

#include <poundfe/assembly/linear_system.h>

#include <Eigen/Core>

#include <vector>

namespace poundfe
{
  struct Modes
  {
    std::vector<double> omega;                   // rad/s, ascending
    Eigen::MatrixXd     shapes;                  // mass-normalised, one per column
    std::vector<double> participating_mass_ratio; // horizontal (x) direction

    unsigned int n_modes() const { return omega.size(); }
    double frequency(unsigned int i) const;      // Hz
    double period(unsigned int i) const;         // s
  };

  /// The n lowest modes (all if n exceeds the count). Dense: meant for the
  /// model sizes of building pairs (up to a few thousand DOFs).
  /// Throws NumericalError if K is singular (a mechanism).
  Modes compute_modes(const SparseMatrix &mass, const SparseMatrix &stiffness,
                      const Vector &influence, unsigned int n);
} // namespace poundfe

#endif
