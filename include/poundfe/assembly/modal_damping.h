// Modal (per-mode) damping of a building (Chopra, Dynamics of Structures,
// 4th ed., §11.4; Wilson & Penzien, Int. J. Numer. Meth. Eng. 4 (1972) 5):
//   C = M Phi diag(2 zeta_i omega_i) Phi^T M = U D U^T,  U = M Phi,
// over the building's first m modes (Phi mass-normalised, Phi^T M Phi = I),
// so that Phi^T C Phi = diag(2 zeta_i omega_i): mode i decays with its own
// ratio zeta_i and the modes beyond m are undamped. C is dense (every DOF
// of the building couples to every other) but of rank m: it is never
// formed. Its product is C v = U (D (U^T v)), O(n m), and the effective
// matrix A + s U D U^T of a Newmark step (s = gamma/(beta dt)) is solved by
// the Woodbury identity on A's sparse factorisation (Hager, SIAM Review 31
// (1989) 221; assembly/low_rank_update.h): m solves with A each time A is
// factorised, then per solve one solve with A and an m x m system.
#ifndef poundfe_assembly_modal_damping_h
#define poundfe_assembly_modal_damping_h

#include <poundfe/assembly/linear_solver.h>
#include <poundfe/assembly/linear_system.h>

#include <array>
#include <memory>
#include <vector>

namespace poundfe
{
  /// Appends the modes of one building to `damping`: the building has the
  /// equations [range[0], range[1]) of an n-equation system, `mass` its
  /// block of M, `shapes` its mass-normalised modes (one per column, at
  /// least as many as `ratios`) with circular frequencies `omega`; mode i
  /// gets ratios[i] (a zero ratio adds nothing).
  void add_modal_damping(LowRankDamping &damping, unsigned int n,
                         std::array<unsigned int, 2> range, const SparseMatrix &mass,
                         const Eigen::MatrixXd &shapes, const std::vector<double> &omega,
                         const std::vector<double> &ratios);

  /// out += U diag(weights) U^T v (nothing when `damping` is empty).
  void add_low_rank_damping_product(const LowRankDamping &damping, const Vector &v,
                                    Vector &out);

  /// C v, the sparse part and the modal part.
  Vector damping_product(const LinearSystem &system, const Vector &v);

  /// A solver of A + scale U D U^T for every A it factorises: `base`
  /// factorises A, and each solve applies the Woodbury identity. `damping`
  /// must outlive the solver. An empty `damping` returns `base` itself.
  std::unique_ptr<LinearSolver> with_low_rank_damping(std::unique_ptr<LinearSolver> base,
                                                      const LowRankDamping &damping,
                                                      double scale);
} // namespace poundfe

#endif
