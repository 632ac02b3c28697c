// Corrections of a Newton iteration on R(u) = 0 that reuse one factorised
// tangent K_0 (H_0 = K_0^{-1}) instead of refactorising K_t(u_i) at every
// iterate (doc/theory.md §3.4b).
//
// Krylov–Newton (Carlson & Miller 1998, SIAM J. Sci. Comput. 19(3):728–765;
// OpenSees's KrylovNewton): with g_i = H_0 R(u_i), the preconditioned
// residual, whose Jacobian is -J = -K_0^{-1} K_t, every step v_j taken so
// far gave a_j = g_j - g_{j+1} ~ J v_j. The new correction is
//   c = argmin || g_i - A c ||_2 ,  du = V c + (g_i - A c),
// J^{-1} resolved on span(A) and taken as the identity (modified Newton) on
// the rest. V, A: the last m steps of the step (a sliding window).
//
// BFGS (Matthies & Strang 1979, IJNME 14:1613–1626; Nocedal 1980 for the
// two-loop form): with s_j = u_{j+1} - u_j, y_j = R(u_j) - R(u_{j+1})
// (~ K_t s_j), rho_j = 1 / y_j.s_j, the inverse update
//   H_{j+1} = (I - rho_j s_j y_j^T) H_j (I - rho_j y_j s_j^T) + rho_j s_j s_j^T
// applied to R_i by the two-loop recursion from H_0 = K_0^{-1}; a pair with
// y.s <= 1e-12 |y| |s| (no positive curvature) is not kept.
//
// Line search (Crisfield 1991, Non-linear FE Analysis of Solids and
// Structures, vol. 1, §9.3; OpenSees's SecantLineSearch): along a direction
// d, s with |G(s)| <= eta |G(0)|, G(s) = d . R(u + s d), by secant steps
//   s_{k+1} = s_k - G(s_k) (s_k - s_{k-1}) / (G(s_k) - G(s_{k-1})),
// s_0 = 0, s_1 = 1, kept in [s_min, s_max], at most n iterations; tried
// only when the full step misses, |G(1)| > eta |G(0)|.
#ifndef poundfe_integration_newton_acceleration_h
#define poundfe_integration_newton_acceleration_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/base/choices.h>
#include <poundfe/assembly/rank_ownership.h>

#include <deque>
#include <functional>

namespace poundfe
{
  /// How a Newton iteration gets its correction.
  enum class NonlinearSolver
  {
    newton,          // the tangent at every iterate, factorised anew (quadratic)
    modified_newton, // one factorised tangent reused (linear)
    krylov_newton,   // modified Newton with Carlson–Miller subspace acceleration
    bfgs,            // modified Newton with the BFGS inverse update
    automatic        // newton when no sparse refactorisation is needed, else krylov-newton
  };

  const NameTable<NonlinearSolver> &nonlinear_solver_names();

  /// x = H_0 b: a solve with the reused factorisation.
  using InverseOperator = std::function<void(const Vector &b, Vector &x)>;

  /// Carlson–Miller acceleration of the modified-Newton correction.
  class KrylovAcceleration
  {
  public:
    /// At most `max_dimension` (>= 1) earlier steps span the subspace.
    explicit KrylovAcceleration(unsigned int max_dimension);
    /// Forget the steps (a new time step, or a new K_0).
    void reset();
    /// The correction at residual R (one solve with H_0).
    void direction(const Vector &residual, const InverseOperator &h0, Vector &correction);
    /// The step actually taken after the last direction() (the correction,
    /// or a line search's multiple of it).
    void record_step(const Vector &step);
    unsigned int dimension() const { return steps.size(); }
    /// Vectors spread over ranks (assembly/rank_ownership.h): the least
    /// squares of the subspace by a QR of each rank's rows and one of the
    /// stacked R factors (TSQR; Demmel et al., SIAM J. Sci. Comput. 34
    /// (2012) A206). Null: one process.
    void set_distribution(const RankOwnership *d) { distribution = d; }

  private:
    /// The coefficients c of min |A c - g| over all ranks' rows.
    Eigen::VectorXd distributed_least_squares(const Eigen::MatrixXd &A, const Vector &g) const;

    const RankOwnership *distribution = nullptr;
    unsigned int       max_dimension;
    std::deque<Vector> steps, differences; // V and A
    Vector             last_preconditioned, pending_step;
    bool               has_last = false, has_pending = false;
  };

  /// The limited-memory BFGS inverse update on H_0 = K_0^{-1}.
  class BfgsUpdate
  {
  public:
    /// At most `max_pairs` (>= 1) pairs (s, y) kept.
    explicit BfgsUpdate(unsigned int max_pairs);
    void reset();
    /// The correction H_i R (one solve with H_0); adds the pair of the step
    /// recorded since the last call.
    void direction(const Vector &residual, const InverseOperator &h0, Vector &correction);
    void record_step(const Vector &step);
    unsigned int n_pairs() const { return pairs.size(); }
    /// Inner products over the ranks' own equations; null: one process.
    void set_distribution(const RankOwnership *d) { distribution = d; }

  private:
    double dot(const Vector &a, const Vector &b) const
    {
      return distribution ? distribution->dot(a, b) : a.dot(b);
    }

    const RankOwnership *distribution = nullptr;
    struct Pair
    {
      Vector s, y;
      double rho;
    };
    unsigned int     max_pairs;
    std::deque<Pair> pairs;
    Vector           last_residual, pending_step, q;
    std::vector<double> alpha;
    bool             has_last = false, has_pending = false;
  };

  struct LineSearchParameters
  {
    double       tolerance      = 0.8; // eta
    unsigned int max_iterations = 10;
    double       min_step       = 0.1;
    double       max_step       = 10.0;
  };

  /// The step length s along a direction: `g(s)` = d . R(u + s d), which
  /// returns NaN when the elements refuse u + s d. g0 = g(0), g1 = g(1)
  /// (already evaluated). Returns 1 when the full step is good enough, else
  /// the first s that meets the tolerance, or the one with the smallest
  /// |g| seen.
  double line_search(double g0, double g1, const std::function<double(double)> &g,
                     const LineSearchParameters &parameters);
} // namespace poundfe

#endif
