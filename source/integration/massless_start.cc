// The state at t = 0 of the massless equations of a run given initial
// conditions (NewmarkIntegrator::equilibrate_massless_start).
//   A massless equation (index 0; the massive ones m) carries no inertia, so
//   at every time r_0 = (p - C v - K u - f(u, v))_0 = 0. Given u_m and v_m:
//   - u_0 from the static equilibrium of those equations, without damping
//     forces: (K u + f(u, 0))_0 = p_0, Newton at v = 0 with the static
//     tangent K_t = K + sum_e B_e D_e B_e^T (a frame's joints rotated as the
//     floors' sway bends them; the same u_0 whatever the velocities);
//   - v_0 from the massless rows of the equations of motion: a row with
//     damping obeys the first-order equation C_0 v = -(K u + f - p)_0 = 0
//     (at the static u_0), so C_0 v = 0 there (Rayleigh's C = a0 M + a1 K:
//     K_00 v_0 = -K_0m v_m); a row without damping, the rate of the
//     equilibrium, K_t,0 v = 0. Then r_0 = 0 holds without moving u_0.
//   If C_00 on the damped rows is singular (modal damping with fewer modes
//   than rotations) or an element's force depends on v, r_0 at v_0 is not
//   zero: u_0 is then brought back to r_0 = 0 at that v_0 by Newton. A start
//   that does not converge is a numerical error.
// Why: the average-acceleration Newmark step's energy identity,
//   dt/2 (v_n + v_n+1)^T M (a_n + a_n+1)/2 = E_K,n+1 - E_K,n,
// takes M a = r at both ends. A massless equation with r_0 != 0 at t = 0
// (where M a_0 = 0) makes the first step do -du_0^T r_0 / 2 of work that no
// energy term holds (a frame's rotations at the floors' given sway: 12 % of
// the initial energy). Sources: N.M. Newmark (1959), J. Eng. Mech. Div. ASCE
// 85(3) 67; T.J.R. Hughes, The Finite Element Method (1987) §9.3 (the
// energy identity). Theory: doc/theory.md §3.8a.
#include <poundfe/assembly/modal_damping.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
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

    /// Rows `massless` of C (= its columns, C symmetric: Rayleigh's sparse
    /// part plus the modal U D U^T), all columns; `damped[k]`: row k has a
    /// nonzero.
    SparseMatrix
    massless_damping_rows(const LinearSystem &system, const std::vector<int> &massless,
                          std::vector<bool> &damped)
    {
      const unsigned int n = system.n_equations();
      std::vector<Eigen::Triplet<double>> entries;
      damped.assign(massless.size(), false);
      Vector unit = Vector::Zero(n);
      for (unsigned int k = 0; k < massless.size(); ++k)
        {
          unit[massless[k]]    = 1;
          const Vector column = damping_product(system, unit);
          unit[massless[k]]    = 0;
          for (unsigned int j = 0; j < n; ++j)
            if (column[j] != 0)
              {
                entries.emplace_back(k, j, column[j]);
                damped[k] = true;
              }
        }
      SparseMatrix rows(massless.size(), n);
      rows.setFromTriplets(entries.begin(), entries.end());
      return rows;
    }

    /// Rows `massless` of `all` where `use[k]`, of `other` elsewhere.
    SparseMatrix
    mixed_rows(const SparseMatrix &all, const SparseMatrix &other, const std::vector<bool> &use)
    {
      std::vector<Eigen::Triplet<double>> entries;
      for (const SparseMatrix *m : {&all, &other})
        for (int column = 0; column < m->outerSize(); ++column)
          for (SparseMatrix::InnerIterator it(*m, column); it; ++it)
            if (use[it.row()] == (m == &all))
              entries.emplace_back(it.row(), it.col(), it.value());
      SparseMatrix rows(all.rows(), all.cols());
      rows.setFromTriplets(entries.begin(), entries.end());
      return rows;
    }

    /// The massless columns of `rows`.
    SparseMatrix
    massless_columns(const SparseMatrix &rows, const std::vector<int> &massless)
    {
      std::vector<int> column_of(rows.cols(), -1);
      for (unsigned int k = 0; k < massless.size(); ++k)
        column_of[massless[k]] = k;
      std::vector<Eigen::Triplet<double>> entries;
      for (int column = 0; column < rows.outerSize(); ++column)
        for (SparseMatrix::InnerIterator it(rows, column); it; ++it)
          if (column_of[it.col()] >= 0)
            entries.emplace_back(it.row(), column_of[it.col()], it.value());
      SparseMatrix square(rows.rows(), massless.size());
      square.setFromTriplets(entries.begin(), entries.end());
      return square;
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
    const Vector given = v;
    v.setZero(); // the static equilibrium: no damping force
    relax_massless_displacements(load, massless);
    SparseMatrix stiffness_square, stiffness_rows;
    massless_tangent(massless, stiffness_square, stiffness_rows);
    std::vector<bool>  damped;
    const SparseMatrix damping_rows = massless_damping_rows(system, massless, damped);
    const SparseMatrix rows         = mixed_rows(damping_rows, stiffness_rows, damped);
    v = given;
    for (const int i : massless)
      v[i] = 0;
    // C_00 singular on the damped rows (modal damping with fewer modes than
    // massless equations): the rate of the equilibrium on every row
    const Eigen::SparseLU<SparseMatrix> lu(massless_columns(rows, massless));
    const Vector v_massless = lu.info() == Eigen::Success ?
                                Vector(lu.solve(-(rows * v))) :
                                solve_massless(stiffness_square, -(stiffness_rows * v));
    for (unsigned int k = 0; k < massless.size(); ++k)
      v[massless[k]] = v_massless[k];
    // r_0 = 0 already unless C_00 is singular or an element's force depends
    // on v; then u_0 follows (one evaluation when it already holds)
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
        if (relative <= massless_tolerance)
          return;
        if (it == max_massless_iterations)
          throw NumericalError("the state at t = 0: Newton on the massless equations (those "
                               "without mass, e.g. a frame's joint rotations) did not converge "
                               "in " + std::to_string(max_massless_iterations) +
                               " iterations (residual " + number_text(relative) +
                               " of the forces); the initial conditions may be beyond what "
                               "the elements can take");
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
