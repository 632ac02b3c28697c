// The state at t = 0 of the massless equations of a run given initial
// conditions (NewmarkIntegrator::equilibrate_massless_start).
//   A massless equation (index 0; the massive ones m) carries no inertia, so
//   at every time r_0 = (p - C v - K u - f(u, v))_0 = 0: it has no state of
//   its own. Given u_m and v_m, u_0 solves r_0 = 0 by Newton at fixed v
//   (K_t,00 du_0 = r_0, K_t = K + sum_e B_e D_e B_e^T the static tangent),
//   v_0 is the rate of that equilibrium, K_t,00 v_0 = -K_t,0m v_m, and u_0 is
//   brought to r_0 = 0 again at the new v_0 (a damping force on the massless
//   equations is then balanced by their elastic force).
// Why: the average-acceleration Newmark step's energy identity,
//   dt/2 (v_n + v_n+1)^T M (a_n + a_n+1)/2 = E_K,n+1 - E_K,n,
// takes M a = r at both ends. A massless equation with r_0 != 0 at t = 0
// (where M a_0 = 0) makes the first step do -du_0^T r_0 / 2 of work that no
// energy term holds (a frame's rotations at the floors' given sway: 12 % of
// the initial energy). Sources: N.M. Newmark (1959), J. Eng. Mech. Div. ASCE
// 85(3) 67; T.J.R. Hughes, The Finite Element Method (1987) §9.3 (the
// energy identity). Theory: doc/theory.md §3.8a.
#include <poundfe/base/exceptions.h>
#include <poundfe/integration/newmark.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    /// Newton iterations on the massless equations: they are few and
    /// nearly linear (a frame's joint rotations), so more than this means
    /// the start is not reachable.
    constexpr unsigned int max_massless_iterations = 50;
    /// r_0 small enough for the energy balance: its work is du_0 r_0 / 2,
    /// below 1e-12 of the forces' size.
    constexpr double massless_tolerance = 1e-13;

    Vector
    restricted(const Vector &x, const std::vector<int> &indices)
    {
      Vector part(indices.size());
      for (unsigned int k = 0; k < indices.size(); ++k)
        part[k] = x[indices[k]];
      return part;
    }

    Vector
    solve_massless(const SparseMatrix &tangent, const Vector &b)
    {
      Eigen::SparseLU<SparseMatrix> lu(tangent);
      if (lu.info() != Eigen::Success)
        throw NumericalError("the state at t = 0: the tangent of the massless equations "
                             "(those without mass, e.g. a frame's joint rotations) is singular");
      return lu.solve(b);
    }
  } // namespace

  void
  NewmarkIntegrator::equilibrate_massless_dofs(const Vector &load)
  {
    AssertThrow(!distribution, dealii::ExcMessage("initial conditions are not distributed"));
    unsigned int           n_massive = 0;
    const std::vector<int> reduced   = massive_numbering(n_massive);
    std::vector<int>       massless;
    for (unsigned int i = 0; i < reduced.size(); ++i)
      if (reduced[i] < 0)
        massless.push_back(i);
    if (massless.empty())
      return;
    relax_massless_displacements(load, massless);
    SparseMatrix square, rows;
    massless_tangent(massless, square, rows);
    Vector v_massive = v;
    for (const int i : massless)
      v_massive[i] = 0;
    const Vector v_massless = solve_massless(square, -(rows * v_massive));
    for (unsigned int k = 0; k < massless.size(); ++k)
      v[massless[k]] = v_massless[k];
    relax_massless_displacements(load, massless);
  }

  void
  NewmarkIntegrator::relax_massless_displacements(const Vector             &load,
                                                  const std::vector<int> &massless)
  {
    Vector       r;
    SparseMatrix square, rows;
    for (unsigned int it = 0;; ++it)
      {
        evaluate_start(load, r, false);
        stiffness_product_is_current = false;
        const double scale = std::max({load.lpNorm<Eigen::Infinity>(),
                                       (system.stiffness * u).lpNorm<Eigen::Infinity>(),
                                       r.lpNorm<Eigen::Infinity>()});
        const Vector r_massless = restricted(r, massless);
        const double relative = scale > 0 ? r_massless.lpNorm<Eigen::Infinity>() / scale : 0;
        if (!std::isfinite(relative))
          throw NumericalError("the state at t = 0: the massless equations' residual is not "
                               "finite");
        // past the iterations, the residual left shows in the energy
        // balance's error, which the run reports
        if (relative <= massless_tolerance || it == max_massless_iterations)
          return;
        massless_tangent(massless, square, rows);
        const Vector du = solve_massless(square, r_massless);
        for (unsigned int k = 0; k < massless.size(); ++k)
          u[massless[k]] += du[k];
      }
  }

  void
  NewmarkIntegrator::massless_tangent(const std::vector<int> &massless, SparseMatrix &square,
                                      SparseMatrix &rows) const
  {
    const unsigned int n = system.n_equations();
    std::vector<int>   row_of(n, -1);
    for (unsigned int k = 0; k < massless.size(); ++k)
      row_of[massless[k]] = k;
    std::vector<Eigen::Triplet<double>> all, inner;
    const auto add = [&](const int i, const int j, const double value) {
      if (row_of[i] < 0)
        return;
      all.emplace_back(row_of[i], j, value);
      if (row_of[j] >= 0)
        inner.emplace_back(row_of[i], row_of[j], value);
    };
    for (int column = 0; column < system.stiffness.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(system.stiffness, column); it; ++it)
        add(it.row(), it.col(), it.value());
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const std::vector<int> &eq = (*elements)[h].equations();
        for (unsigned int i = 0; i < eq.size(); ++i)
          for (unsigned int j = 0; j < eq.size(); ++j)
            if (eq[i] >= 0 && eq[j] >= 0)
              add(eq[i], eq[j], tangent_change_entry(tangent_change, h, i, j));
      }
    rows.resize(massless.size(), n);
    rows.setFromTriplets(all.begin(), all.end());
    square.resize(massless.size(), massless.size());
    square.setFromTriplets(inner.begin(), inner.end());
  }
} // namespace poundfe
