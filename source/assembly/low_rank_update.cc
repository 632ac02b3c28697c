#include <poundfe/assembly/low_rank_update.h>
#include <poundfe/base/exceptions.h>

#include <cmath>

namespace poundfe
{
  void
  LowRankUpdateSolver::initialize(LinearSolver &factorised,
                                  const std::vector<SparseColumn> &columns_of_b,
                                  const unsigned int n_rows)
  {
    base    = &factorised;
    columns = columns_of_b;
    const unsigned int m = columns.size();
    W.resize(n_rows, m);
    G.resize(m, m);
    S.resize(m, m);
    y.resize(n_rows);
    rhs_small.resize(m);
    active.reserve(m);
    Vector w(n_rows), column(n_rows);
    for (unsigned int h = 0; h < m; ++h)
      {
        column.setZero();
        for (unsigned int i = 0; i < 2; ++i)
          if (columns[h].rows[i] >= 0)
            column[columns[h].rows[i]] += columns[h].values[i];
        base->solve(column, w);
        W.col(h) = w;
      }
    for (unsigned int h = 0; h < m; ++h)
      for (unsigned int g = 0; g < m; ++g)
        {
          double value = 0;
          for (unsigned int i = 0; i < 2; ++i)
            if (columns[h].rows[i] >= 0)
              value += columns[h].values[i] * W(columns[h].rows[i], g);
          G(h, g) = value;
        }
  }

  void
  LowRankUpdateSolver::solve(const Vector &r, const std::vector<double> &d, Vector &x)
  {
    base->solve(r, y);
    active.clear();
    for (unsigned int h = 0; h < columns.size(); ++h)
      if (d[h] != 0)
        active.push_back(h);
    const unsigned int k = active.size();
    if (k == 0)
      {
        x = y;
        return;
      }

    // S = I + D_a G_aa and rhs = D_a B_a^T y, then LU with partial pivoting
    // in place (the leading k x k block of the preallocated S).
    for (unsigned int a = 0; a < k; ++a)
      {
        const unsigned int h = active[a];
        double             bty = 0;
        for (unsigned int i = 0; i < 2; ++i)
          if (columns[h].rows[i] >= 0)
            bty += columns[h].values[i] * y[columns[h].rows[i]];
        rhs_small[a] = d[h] * bty;
        for (unsigned int b = 0; b < k; ++b)
          S(a, b) = (a == b ? 1.0 : 0.0) + d[h] * G(h, active[b]);
      }
    for (unsigned int j = 0; j < k; ++j)
      {
        unsigned int p = j;
        for (unsigned int i = j + 1; i < k; ++i)
          if (std::abs(S(i, j)) > std::abs(S(p, j)))
            p = i;
        if (!(std::abs(S(p, j)) > 0))
          throw NumericalError("the tangent matrix is singular (Woodbury capacitance "
                               "matrix has a zero pivot)");
        if (p != j)
          {
            for (unsigned int c = 0; c < k; ++c)
              std::swap(S(j, c), S(p, c));
            std::swap(rhs_small[j], rhs_small[p]);
          }
        const double inverse_pivot = 1.0 / S(j, j);
        for (unsigned int i = j + 1; i < k; ++i)
          {
            const double f = S(i, j) * inverse_pivot;
            if (f == 0)
              continue;
            for (unsigned int c = j + 1; c < k; ++c)
              S(i, c) -= f * S(j, c);
            rhs_small[i] -= f * rhs_small[j];
          }
      }
    for (int i = k - 1; i >= 0; --i)
      {
        double value = rhs_small[i];
        for (unsigned int c = i + 1; c < k; ++c)
          value -= S(i, c) * rhs_small[c];
        rhs_small[i] = value / S(i, i);
      }
    x = y;
    for (unsigned int a = 0; a < k; ++a)
      x.noalias() -= rhs_small[a] * W.col(active[a]);
  }
} // namespace poundfe
