#include <poundfe/integration/newton_acceleration.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>

namespace poundfe
{
  const NameTable<NonlinearSolver> &
  nonlinear_solver_names()
  {
    static const NameTable<NonlinearSolver> table(
      {{NonlinearSolver::newton, "newton"},
       {NonlinearSolver::modified_newton, "modified-newton"},
       {NonlinearSolver::krylov_newton, "krylov-newton"},
       {NonlinearSolver::bfgs, "bfgs"},
       {NonlinearSolver::automatic, "auto"}});
    return table;
  }

  KrylovAcceleration::KrylovAcceleration(const unsigned int max_dimension)
    : max_dimension(max_dimension)
  {
    Assert(max_dimension >= 1, dealii::ExcMessage("the subspace needs one vector at least"));
  }

  void
  KrylovAcceleration::reset()
  {
    steps.clear();
    differences.clear();
    has_last = has_pending = false;
  }

  void
  KrylovAcceleration::record_step(const Vector &step)
  {
    pending_step = step;
    has_pending  = true;
  }

  void
  KrylovAcceleration::direction(const Vector &residual, const InverseOperator &h0,
                                Vector &correction)
  {
    Vector g;
    h0(residual, g);
    if (has_last && has_pending) // a_j = g_j - g_{j+1} ~ J v_j
      {
        if (steps.size() == max_dimension)
          {
            steps.pop_front();
            differences.pop_front();
          }
        steps.push_back(pending_step);
        differences.push_back(last_preconditioned - g);
      }
    has_pending         = false;
    last_preconditioned = g;
    has_last            = true;
    correction          = g;
    if (steps.empty())
      return;
    Eigen::MatrixXd A(g.size(), differences.size());
    for (unsigned int j = 0; j < differences.size(); ++j)
      A.col(j) = differences[j];
    // column pivoting: two nearly parallel steps give a nearly rank-deficient A
    const Eigen::VectorXd c = distribution ? distributed_least_squares(A, g) :
                                             Eigen::VectorXd(Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(A).solve(g));
    if (!c.allFinite())
      return;
    for (unsigned int j = 0; j < steps.size(); ++j)
      correction += c[j] * (steps[j] - differences[j]);
  }

  Eigen::VectorXd
  KrylovAcceleration::distributed_least_squares(const Eigen::MatrixXd &A, const Vector &g) const
  {
    // A and g are zero outside this rank's equations: A_r = Q_r R_r there,
    // and min |A c - g| = min |[R_1; ...; R_P] c - [Q_1^T g_1; ...]|.
    const auto [first, last] = distribution->owned_range();
    const unsigned int k = A.cols(), n_rows = last - first, n_ranks = distribution->n_ranks();
    Eigen::MatrixXd    local(k + 1, k); // R_r (upper k x k), then Q_r^T g_r as the last row
    local.setZero();
    if (n_rows > 0)
      {
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr(A.middleRows(first, n_rows));
        const unsigned int m = std::min(n_rows, k);
        local.topRows(m) = qr.matrixQR().topRows(m).triangularView<Eigen::Upper>();
        const Eigen::VectorXd qtg = qr.householderQ().transpose() * g.segment(first, n_rows);
        local.row(k).head(m) = qtg.head(m).transpose();
      }
    Eigen::MatrixXd all((k + 1) * k, n_ranks);
    distribution->all_gather(local.data(), (k + 1) * k, all.data());
    Eigen::MatrixXd stacked_r(n_ranks * k, k);
    Eigen::VectorXd stacked_g(n_ranks * k);
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        const Eigen::Map<const Eigen::MatrixXd> part(all.col(r).data(), k + 1, k);
        stacked_r.middleRows(r * k, k) = part.topRows(k);
        stacked_g.segment(r * k, k)    = part.row(k).transpose();
      }
    return Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(stacked_r).solve(stacked_g);
  }

  BfgsUpdate::BfgsUpdate(const unsigned int max_pairs)
    : max_pairs(max_pairs)
  {
    Assert(max_pairs >= 1, dealii::ExcMessage("BFGS needs one pair at least"));
  }

  void
  BfgsUpdate::reset()
  {
    pairs.clear();
    has_last = has_pending = false;
  }

  void
  BfgsUpdate::record_step(const Vector &step)
  {
    pending_step = step;
    has_pending  = true;
  }

  void
  BfgsUpdate::direction(const Vector &residual, const InverseOperator &h0, Vector &correction)
  {
    if (has_last && has_pending)
      {
        Vector       y  = last_residual - residual; // ~ K_t s
        const double ys = dot(y, pending_step);
        if (ys > 1e-12 * std::sqrt(dot(y, y) * dot(pending_step, pending_step)))
          {
            if (pairs.size() == max_pairs)
              pairs.pop_front();
            pairs.push_back({pending_step, std::move(y), 1 / ys});
          }
      }
    has_pending   = false;
    last_residual = residual;
    has_last      = true;
    // two-loop recursion: newest pair first, then H_0, then oldest first
    q = residual;
    alpha.assign(pairs.size(), 0.0);
    for (unsigned int j = pairs.size(); j-- > 0;)
      {
        alpha[j] = pairs[j].rho * dot(pairs[j].s, q);
        q -= alpha[j] * pairs[j].y;
      }
    h0(q, correction);
    for (unsigned int j = 0; j < pairs.size(); ++j)
      {
        const double beta = pairs[j].rho * dot(pairs[j].y, correction);
        correction += (alpha[j] - beta) * pairs[j].s;
      }
  }

  double
  line_search(const double g0, const double g1, const std::function<double(double)> &g,
              const LineSearchParameters &parameters)
  {
    const double target = parameters.tolerance * std::abs(g0);
    if (!(std::abs(g1) > target) || g0 == 0)
      return 1.0;
    double s_previous = 0, g_previous = g0, s = 1, g_s = g1;
    double best = 1, g_best = std::abs(g1);
    if (!std::isfinite(g1))
      g_best = std::numeric_limits<double>::infinity();
    for (unsigned int k = 0; k < parameters.max_iterations; ++k)
      {
        const double slope = g_s - g_previous;
        if (slope == 0 || !std::isfinite(g_s))
          break;
        double s_next = s - g_s * (s - s_previous) / slope;
        s_next        = std::min(std::max(s_next, parameters.min_step), parameters.max_step);
        if (s_next == s)
          break;
        const double g_next = g(s_next);
        if (!std::isfinite(g_next)) // the elements refused u + s d
          break;
        s_previous = s;
        g_previous = g_s;
        s          = s_next;
        g_s        = g_next;
        if (std::abs(g_s) < g_best)
          {
            best   = s;
            g_best = std::abs(g_s);
          }
        if (std::abs(g_s) <= target)
          return s;
      }
    return best;
  }
} // namespace poundfe
