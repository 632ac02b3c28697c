// Newton on the static equations K u + f(u) = p and load control
// (integration/static_analysis.h).
#include <poundfe/integration/static_analysis.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace poundfe
{
  StaticSolver::StaticSolver(const SparseMatrix &stiffness_, NonlinearElements *elements_)
    : stiffness(stiffness_)
    , elements(elements_)
  {
    dof_start.push_back(0);
    if (elements)
      for (const NonlinearElement &e : *elements)
        dof_start.push_back(dof_start.back() + e.n_dofs());
    local_u    = Vector::Zero(dof_start.back());
    local_v    = Vector::Zero(dof_start.back());
    correction = Vector::Zero(dof_start.back());
  }

  void
  StaticSolver::gather(const Vector &u)
  {
    if (!elements)
      return;
    for (unsigned int h = 0; h < elements->size(); ++h)
      {
        const std::vector<int> &equations = (*elements)[h].equations();
        for (unsigned int i = 0; i < equations.size(); ++i)
          local_u[dof_start[h] + i] = equations[i] >= 0 ? u[equations[i]] : 0.0;
      }
  }

  bool
  StaticSolver::residual(const Vector &load, const Vector &u, Vector &r)
  {
    r = load - stiffness * u;
    if (!elements)
      return r.allFinite();
    gather(u);
    for (unsigned int h = 0; h < elements->size(); ++h)
      {
        NonlinearElement  &e = (*elements)[h];
        const unsigned int s = dof_start[h], k = e.n_dofs();
        e.set_trial_time(0);
        if (!e.set_trial(local_u.segment(s, k), local_v.segment(s, k)))
          {
            why = e.label + ": " + e.failure();
            return false;
          }
        e.force_correction(correction.segment(s, k));
        const std::vector<int> &equations = e.equations();
        for (unsigned int i = 0; i < k; ++i)
          if (equations[i] >= 0)
            r[equations[i]] -= correction[s + i];
      }
    if (!r.allFinite())
      {
        why = "the residual is not finite";
        return false;
      }
    return true;
  }

  Vector
  StaticSolver::resisting_force(const Vector &u) const
  {
    Vector f = stiffness * u;
    if (elements)
      for (unsigned int h = 0; h < elements->size(); ++h)
        {
          const NonlinearElement &e = (*elements)[h];
          Vector                  local(e.n_dofs());
          e.force_correction(local);
          for (unsigned int i = 0; i < e.n_dofs(); ++i)
            if (e.equations()[i] >= 0)
              f[e.equations()[i]] += local[i];
        }
    return f;
  }

  SparseMatrix
  StaticSolver::tangent() const
  {
    std::vector<Eigen::Triplet<double>> triplets;
    for (int k = 0; k < stiffness.outerSize(); ++k)
      for (SparseMatrix::InnerIterator entry(stiffness, k); entry; ++entry)
        triplets.emplace_back(entry.row(), entry.col(), entry.value());
    if (elements)
      for (const NonlinearElement &e : *elements)
        {
          const Eigen::MatrixXd basis = e.tangent_basis();
          Eigen::MatrixXd       d(e.rank(), e.rank());
          e.tangent_change(0.0, d);
          const Eigen::MatrixXd change = basis * d * basis.transpose();
          const std::vector<int> &equations = e.equations();
          for (unsigned int i = 0; i < e.n_dofs(); ++i)
            for (unsigned int j = 0; j < e.n_dofs(); ++j)
              if (equations[i] >= 0 && equations[j] >= 0 && change(i, j) != 0)
                triplets.emplace_back(equations[i], equations[j], change(i, j));
        }
    SparseMatrix t(stiffness.rows(), stiffness.cols());
    t.setFromTriplets(triplets.begin(), triplets.end());
    return t;
  }

  bool
  StaticSolver::newton(const Vector &load, Vector &u, const double tolerance, const double scale,
                       const unsigned int max_iterations)
  {
    const double target = tolerance * std::max(load.norm(), scale);
    Vector       r;
    Eigen::SparseLU<SparseMatrix> lu;
    for (last_iterations = 0; last_iterations <= max_iterations; ++last_iterations)
      {
        if (!residual(load, u, r))
          return false;
        // an overflowed norm would pass (or never pass) the test below unnoticed
        if (!std::isfinite(r.norm()) || !std::isfinite(target))
          {
            why = "the load or residual norm is not finite (" + number_text(r.norm()) +
                  ", load " + number_text(load.norm()) + ")";
            return false;
          }
        if (r.norm() <= target)
          return true;
        if (last_iterations == max_iterations)
          break;
        lu.compute(tangent());
        if (lu.info() != Eigen::Success)
          {
            why = "the tangent stiffness is singular (a mechanism)";
            return false;
          }
        u += lu.solve(r);
      }
    why = "no convergence in " + std::to_string(max_iterations) +
          " iterations (residual norm " + number_text(r.norm()) + ", tolerance " +
          number_text(target) + ")";
    return false;
  }

  void
  StaticSolver::commit()
  {
    if (elements)
      for (NonlinearElement &e : *elements)
        e.commit();
  }

  void
  StaticSolver::revert()
  {
    if (elements)
      for (NonlinearElement &e : *elements)
        e.revert();
  }

  std::string
  StaticSolver::most_strained_element(const Vector &u) const
  {
    if (!elements || elements->empty())
      return "";
    double      largest = -1;
    std::string label;
    for (const NonlinearElement &e : *elements)
      {
        const double yield = e.yield_deformation();
        const double ratio = std::abs(e.deformation(u)) / (yield > 0 ? yield : 1.0);
        if (ratio > largest)
          {
            largest = ratio;
            label   = e.label + " (deformation " + number_text(e.deformation(u)) +
                    (yield > 0 ? ", " + number_text(ratio) + " times its yield deformation)" :
                                 ")");
          }
      }
    return label;
  }

  bool
  StaticSolver::set_state(const Vector &u)
  {
    gather(u);
    if (elements)
      for (unsigned int h = 0; h < elements->size(); ++h)
        {
          NonlinearElement  &e = (*elements)[h];
          const unsigned int s = dof_start[h], k = e.n_dofs();
          e.set_trial_time(0);
          if (!e.set_trial(local_u.segment(s, k), local_v.segment(s, k)))
            {
              why = e.label + ": " + e.failure();
              return false;
            }
        }
    return true;
  }

  void
  StaticSolver::set_load_factor(const double lambda)
  {
    if (elements)
      for (NonlinearElement &e : *elements)
        e.set_load_factor(lambda);
  }

  namespace
  {
    /// The NumericalError of a load step that failed at its smallest size.
    [[noreturn]] void
    throw_static_failure(const StaticSolver &solver, const std::string &what, const double lambda,
                         const double step, const unsigned int cuts, const Vector &u)
    {
      std::ostringstream s;
      s << what << ": no equilibrium beyond load factor " << lambda << " (step " << std::abs(step)
        << " after " << cuts << " cuts): " << solver.failure();
      const std::string element = solver.most_strained_element(u);
      if (!element.empty())
        s << "; most strained element " << element;
      throw NumericalError(s.str());
    }
  } // namespace

  void
  load_control(StaticSolver &solver, const Vector &p_ref, const double lambda0,
               const double lambda1, const LoadControlSettings &settings,
               const std::string &what, StaticState &state)
  {
    if (state.displacement.size() != p_ref.size())
      state.displacement = Vector::Zero(p_ref.size());
    const double scale     = std::max(std::abs(lambda0), std::abs(lambda1)) * p_ref.norm();
    const double full_step = (lambda1 - lambda0) / settings.n_steps;
    double       step      = full_step;
    double       lambda    = lambda0;
    unsigned int level     = 0; // cuts of the current step size
    if (lambda0 == lambda1) // one solve at the same load (re-equilibrate)
      {
        Vector u = state.displacement;
        solver.set_load_factor(lambda1);
        if (!solver.newton(lambda1 * p_ref, u, settings.tolerance, scale, settings.max_iterations))
          {
            solver.revert();
            throw_static_failure(solver, what, lambda, 0, 0, u);
          }
        solver.commit();
        state.displacement = u;
        state.path.push_back(u);
        state.load_factors.push_back(lambda1);
        ++state.steps;
        state.iterations += solver.iterations();
        return;
      }
    while (lambda != lambda1)
      {
        // the last step lands on lambda1 exactly (no drift of the sum)
        const double remaining = lambda1 - lambda;
        const double next =
          std::abs(remaining) <= std::abs(step) * (1 + 1e-9) ? lambda1 : lambda + step;
        Vector u = state.displacement;
        solver.set_load_factor(next);
        if (solver.newton(next * p_ref, u, settings.tolerance, scale, settings.max_iterations))
          {
            solver.commit();
            state.displacement = u;
            state.path.push_back(u);
            state.load_factors.push_back(next);
            ++state.steps;
            state.iterations += solver.iterations();
            lambda = next;
            if (level > 0) // grow back towards the given step
              {
                step *= 2;
                --level;
              }
            continue;
          }
        solver.revert();
        if (level == settings.max_step_cuts)
          throw_static_failure(solver, what, lambda, step, level, u);
        step /= 2;
        ++level;
        ++state.cuts;
      }
  }

  PathFollower::PathFollower(StaticSolver &solver_, const Vector &constant_load_,
                             const Vector &reference_load_, const PathSettings &settings_)
    : solver(solver_)
    , constant_load(constant_load_)
    , reference_load(reference_load_)
    , settings(settings_)
  {}

  bool
  PathFollower::residual_at(const Vector &u, const double lambda, Vector &r, double &target)
  {
    const Vector load = constant_load + lambda * reference_load;
    if (!solver.residual(load, u, r))
      {
        why = solver.failure();
        return false;
      }
    // relative to the load, or to the internal forces while the load is
    // still nearly zero (the first step of a push without gravity)
    target = settings.tolerance *
             std::max({load.norm(), (solver.stiffness_matrix() * u).norm(),
                       std::numeric_limits<double>::min()});
    return true;
  }

  bool
  PathFollower::solve_both(const Vector &r, Vector &du_reference, Vector &du_residual)
  {
    Eigen::SparseLU<SparseMatrix> lu(solver.tangent());
    if (lu.info() != Eigen::Success)
      {
        why = "the tangent stiffness is singular (a mechanism)";
        return false;
      }
    du_reference = lu.solve(reference_load);
    du_residual  = lu.solve(r);
    return du_reference.allFinite() && du_residual.allFinite();
  }

  void
  PathFollower::accept(const Vector &u, const double lambda, PathPoint &point)
  {
    solver.commit();
    point.increment        = u - point.u;
    point.lambda_increment = lambda - point.lambda;
    point.u                = u;
    point.lambda           = lambda;
  }

  bool
  PathFollower::displacement_step(const unsigned int control, const double increment,
                                  PathPoint &point)
  {
    Vector       u      = point.u, r, du_reference, du_residual;
    double       lambda = point.lambda, target = 0;
    const double goal   = point.u[control] + increment;
    for (last_iterations = 0; last_iterations <= settings.max_iterations; ++last_iterations)
      {
        if (!residual_at(u, lambda, r, target))
          break;
        if (last_iterations > 0 && r.norm() <= target)
          {
            accept(u, lambda, point);
            return true;
          }
        if (last_iterations == settings.max_iterations)
          {
            why = "no convergence in " + std::to_string(settings.max_iterations) +
                  " iterations (residual " + number_text(r.norm()) + ", tolerance " +
                  number_text(target) + ")";
            break;
          }
        if (!solve_both(r, du_reference, du_residual) || du_reference[control] == 0)
          break;
        const double d_lambda = (goal - u[control] - du_residual[control]) / du_reference[control];
        u += du_residual + d_lambda * du_reference;
        lambda += d_lambda;
      }
    solver.revert();
    return false;
  }

  namespace
  {
    /// The root delta lambda of ||a + delta lambda b||^2 = length^2 whose
    /// increment a + delta lambda b lies nearest `previous`, the step's
    /// increment before this correction (Crisfield 1981, the angle
    /// criterion); false when there is no real root.
    bool
    arc_length_root(const Vector &a, const Vector &b, const double length, const Vector &previous,
                    double &root)
    {
      const double qa = b.squaredNorm(), qb = 2 * b.dot(a), qc = a.squaredNorm() - length * length;
      const double discriminant = qb * qb - 4 * qa * qc;
      if (!(qa > 0) || discriminant < 0)
        return false;
      const double r1 = (-qb + std::sqrt(discriminant)) / (2 * qa);
      const double r2 = (-qb - std::sqrt(discriminant)) / (2 * qa);
      root = (a + r1 * b).dot(previous) >= (a + r2 * b).dot(previous) ? r1 : r2;
      return true;
    }
  } // namespace

  bool
  PathFollower::arc_length_step(const double length, const unsigned int control,
                                const double direction, PathPoint &point)
  {
    Vector r, du_reference, du_residual;
    double target = 0;
    // predictor along the tangent, in the direction of the last increment
    if (!residual_at(point.u, point.lambda, r, target) ||
        !solve_both(Vector::Zero(r.size()), du_reference, du_residual))
      {
        solver.revert();
        return false;
      }
    const bool first = point.increment.size() == 0;
    const double sense =
      first ? (du_reference[control] * direction >= 0 ? 1.0 : -1.0) :
              (du_reference.dot(point.increment) >= 0 ? 1.0 : -1.0);
    double d_lambda = sense * length / du_reference.norm();
    Vector step     = d_lambda * du_reference;
    for (last_iterations = 1; last_iterations <= settings.max_iterations; ++last_iterations)
      {
        if (!residual_at(point.u + step, point.lambda + d_lambda, r, target))
          break;
        if (r.norm() <= target)
          {
            accept(point.u + step, point.lambda + d_lambda, point);
            return true;
          }
        double delta = 0;
        if (!solve_both(r, du_reference, du_residual))
          break;
        if (!arc_length_root(step + du_residual, du_reference, length, step, delta))
          {
            why = "the arc-length constraint has no real root";
            break;
          }
        step += du_residual + delta * du_reference;
        d_lambda += delta;
      }
    if (last_iterations > settings.max_iterations)
      why = "no arc-length convergence in " + std::to_string(settings.max_iterations) +
            " iterations";
    solver.revert();
    return false;
  }

  void
  restore_static_state(const std::vector<Vector> &path, const std::vector<double> &load_factors,
                       NonlinearElements &elements)
  {
    AssertDimension(path.size(), load_factors.size());
    const SparseMatrix none;
    StaticSolver       solver(none, &elements);
    for (unsigned int step = 0; step < path.size(); ++step)
      {
        solver.set_load_factor(load_factors[step]);
        // an element's iteration from its committed state may fail where
        // the Newton iteration's trials converged: a numerical failure,
        // the element named
        if (!solver.set_state(path[step]))
          throw NumericalError("restoring the gravity state, load step " +
                               std::to_string(step + 1) + " of " + std::to_string(path.size()) +
                               ": " + solver.failure());
        solver.commit();
      }
  }
} // namespace poundfe
