#include <poundfe/assembly/low_rank_update.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace poundfe
{
  namespace
  {
    /// x = y - w (d b^T y) / (1 + d g), g = b^T A^{-1} b: one active column of
    /// a one-column block, the capacitance a number. The operations of the
    /// general path for k = 1 (S = 1 + d g, its LU with no elimination, the
    /// one substitution), so the same bits, without its loops and pivots.
    void
    solve_one_column(const double d, const double g, const double bty, const Vector &y,
                     const Eigen::Ref<const Vector> &w, Vector &x)
    {
      const double capacitance = 1.0 + d * g;
      if (!(std::abs(capacitance) > 0))
        throw NumericalError("the tangent matrix is singular (Woodbury capacitance "
                             "matrix has a zero pivot)");
      const double coefficient = d * bty / capacitance;
      x                        = y;
      x.noalias() -= coefficient * w;
    }

    /// The columns of the blocks whose D_e has an entry other than 0, in order.
    void
    list_active_columns(const std::vector<unsigned int> &block_start,
                        const std::vector<unsigned int> &d_offset, const std::vector<double> &d,
                        std::vector<unsigned int> &active)
    {
      active.clear();
      for (unsigned int e = 0; e + 1 < block_start.size(); ++e)
        {
          const double      *block     = d.data() + d_offset[e];
          const unsigned int n_entries = d_offset[e + 1] - d_offset[e];
          for (unsigned int q = 0; q < n_entries; ++q)
            if (block[q] != 0)
              {
                for (unsigned int c = block_start[e]; c < block_start[e + 1]; ++c)
                  active.push_back(c);
                break;
              }
        }
    }
  } // namespace

  void
  LowRankUpdateSolver::initialize(LinearSolver                    &factorised,
                                  const std::vector<SparseColumn> &columns,
                                  const unsigned int               n_rows,
                                  const std::vector<unsigned int> &block_sizes,
                                  const unsigned int               max_columns)
  {
    base                 = &factorised;
    const unsigned int m = columns.size();
    column_start.assign(1, 0);
    entry_row.clear();
    entry_value.clear();
    for (const SparseColumn &column : columns)
      {
        AssertDimension(column.rows.size(), column.values.size());
        for (unsigned int i = 0; i < column.rows.size(); ++i)
          if (column.rows[i] >= 0)
            {
              entry_row.push_back(column.rows[i]);
              entry_value.push_back(column.values[i]);
            }
        column_start.push_back(entry_row.size());
      }

    block_start.assign(1, 0);
    d_offset.assign(1, 0);
    column_block.resize(m);
    const std::vector<unsigned int> sizes =
      block_sizes.empty() ? std::vector<unsigned int>(m, 1) : block_sizes;
    for (const unsigned int size : sizes)
      {
        for (unsigned int c = block_start.back(); c < block_start.back() + size && c < m; ++c)
          column_block[c] = block_start.size() - 1;
        block_start.push_back(block_start.back() + size);
        d_offset.push_back(d_offset.back() + size * size);
      }
    AssertThrow(block_start.back() == m,
                dealii::ExcMessage("the block sizes must add up to the number of columns"));

    const unsigned int n_slots = (max_columns == 0 || max_columns >= m) ? m : max_columns;
    W.resize(n_rows, n_slots);
    G.resize(n_slots, n_slots);
    S.resize(std::min(m, n_slots), std::min(m, n_slots));
    y.resize(n_rows);
    bty.resize(m);
    rhs_small.resize(m);
    column_buffer.resize(n_rows);
    w_buffer.resize(n_rows);
    active.reserve(m);
    pivot.reserve(m);
    factored_active.reserve(m);
    factored = false; // a new A: new W and G
    is_active.assign(m, 0);
    slot_of.assign(m, -1);
    column_in.assign(n_slots, -1);
    columns_computed = 0;
    if (n_slots == m) // every column in its own slot, computed now
      {
        for (unsigned int c = 0; c < m; ++c)
          {
            column_buffer.setZero();
            for (unsigned int q = column_start[c]; q < column_start[c + 1]; ++q)
              column_buffer[entry_row[q]] += entry_value[q];
            base->solve(column_buffer, w_buffer);
            W.col(c)     = w_buffer;
            slot_of[c]   = c;
            column_in[c] = c;
          }
        for (unsigned int c = 0; c < m; ++c)
          for (unsigned int g = 0; g < m; ++g)
            G(c, g) = column_dot(c, W.col(g));
        columns_computed = m;
      }
  }

  void
  LowRankUpdateSolver::compute_column(const unsigned int c, const unsigned int slot)
  {
    column_buffer.setZero();
    for (unsigned int q = column_start[c]; q < column_start[c + 1]; ++q)
      column_buffer[entry_row[q]] += entry_value[q];
    // the slot changes hands only once its column is solved: a solve that
    // throws leaves every slot, and the capacitance LU that counts them,
    // as they were (its old column still listed in it and still found)
    base->solve(column_buffer, w_buffer);
    if (const int old = column_in[slot]; old >= 0)
      slot_of[old] = -1;
    W.col(slot)     = w_buffer;
    slot_of[c]      = slot;
    column_in[slot] = c;
    ++columns_computed;
    for (unsigned int t = 0; t < column_in.size(); ++t)
      if (const int g = column_in[t]; g >= 0)
        {
          G(slot, t) = column_dot(c, W.col(t));
          G(t, slot) = column_dot(g, W.col(slot));
        }
  }

  bool
  LowRankUpdateSolver::fill_slots()
  {
    if (active.size() > column_in.size())
      return false;
    unsigned int next = 0; // slots are searched once, in order, for room
    for (const unsigned int c : active)
      if (slot_of[c] < 0)
        {
          while (column_in[next] >= 0 && is_active[column_in[next]])
            ++next;
          compute_column(c, next++);
        }
    return true;
  }

  double
  LowRankUpdateSolver::column_dot(const unsigned int c, const Eigen::Ref<const Vector> &v) const
  {
    double value = 0;
    for (unsigned int q = column_start[c]; q < column_start[c + 1]; ++q)
      value += entry_value[q] * v[entry_row[q]];
    return value;
  }

  bool
  LowRankUpdateSolver::solve(const Vector &r, const std::vector<double> &d, Vector &x)
  {
    AssertDimension(d.size(), d_offset.back());
    for (const unsigned int c : active)
      is_active[c] = 0;
    list_active_columns(block_start, d_offset, d, active);
    for (const unsigned int c : active)
      is_active[c] = 1;
    if (!fill_slots())
      return false;
    const unsigned int k = active.size();
    if (k == 0) // x = A^{-1} r: the solve writes x without reading it
      {
        base->solve(r, x);
        return true;
      }
    base->solve(r, y);
    if (const unsigned int c = active[0], e = column_block[c];
        k == 1 && block_start[e + 1] - block_start[e] == 1)
      {
        const int slot = slot_of[c];
        solve_one_column(d[d_offset[e]], G(slot, slot), column_dot(c, y), y, W.col(slot), x);
        factored = false; // as the general path leaves it for k = 1
        return true;
      }

    for (unsigned int a = 0; a < k; ++a)
      bty[a] = column_dot(active[a], y);
    // one column: its elimination costs less than the comparison
    const bool reuse = k > 1 && reuses_capacitance(d);
    form_capacitance(k, d, reuse);
    if (!reuse)
      {
        // reuses_capacitance has unmarked the LU: an elimination that
        // throws (a zero pivot) leaves it to be formed again next time
        factor_capacitance(k);
        factored = k > 1; // what one column overwrote is no longer the LU noted
      }
    substitute_capacitance(k);
    x = y;
    for (unsigned int a = 0; a < k; ++a)
      x.noalias() -= rhs_small[a] * W.col(slot_of[active[a]]);
    return true;
  }

  void
  LowRankUpdateSolver::form_capacitance(const unsigned int k, const std::vector<double> &d,
                                        const bool reuse)
  {
    // S = I + D_a G_aa and rhs = D_a B_a^T y. Row a is row i of its block
    // D_e, whose columns are the active positions first, ..., first + r_e - 1.
    // Each sum starts from its first term, so that for r_e = 1 the entries
    // are d G and d b^T y exactly.
    for (unsigned int a = 0; a < k; ++a)
      {
        const unsigned int c = active[a], e = column_block[c];
        const unsigned int size  = block_start[e + 1] - block_start[e];
        const unsigned int i     = c - block_start[e];
        const unsigned int first = a - i;
        const double      *D     = d.data() + d_offset[e]; // D(i, j) = D[i + j size]
        double             rhs   = D[i] * bty[first];
        for (unsigned int j = 1; j < size; ++j)
          rhs += D[i + j * size] * bty[first + j];
        rhs_small[a] = rhs;
        if (reuse)
          continue;
        if (size == 1) // the common case, kept lean
          {
            const int row = slot_of[c];
            for (unsigned int b = 0; b < k; ++b)
              S(a, b) = (a == b ? 1.0 : 0.0) + D[0] * G(row, slot_of[active[b]]);
          }
        else
          for (unsigned int b = 0; b < k; ++b)
            {
              const int column = slot_of[active[b]];
              double    value  = D[i] * G(slot_of[block_start[e]], column);
              for (unsigned int j = 1; j < size; ++j)
                value += D[i + j * size] * G(slot_of[block_start[e] + j], column);
              S(a, b) = (a == b ? 1.0 : 0.0) + value;
            }
      }
  }

  bool
  LowRankUpdateSolver::reuses_capacitance(const std::vector<double> &d)
  {
    // bit for bit (memcmp, not ==: -0 and NaN too), so that the reused LU is
    // the one the elimination would form again
    if (factored && factored_columns == columns_computed && factored_active == active &&
        factored_d.size() == d.size() &&
        std::memcmp(factored_d.data(), d.data(), d.size() * sizeof(double)) == 0)
      return true;
    factored = false; // until solve has factorised S for them
    factored_active.assign(active.begin(), active.end());
    factored_d.assign(d.begin(), d.end());
    factored_columns = columns_computed;
    return false;
  }

  void
  LowRankUpdateSolver::factor_capacitance(const unsigned int k)
  {
    // in place in the leading k x k block of the preallocated S; a row
    // swap moves only the columns from j on (those left of j are
    // multipliers, kept where their step found them for the substitution)
    pivot.resize(k);
    for (unsigned int j = 0; j < k; ++j)
      {
        unsigned int p = j;
        for (unsigned int i = j + 1; i < k; ++i)
          if (std::abs(S(i, j)) > std::abs(S(p, j)))
            p = i;
        if (!(std::abs(S(p, j)) > 0))
          throw NumericalError("the tangent matrix is singular (Woodbury capacitance "
                               "matrix has a zero pivot)");
        pivot[j] = p;
        if (p != j)
          for (unsigned int c = j; c < k; ++c)
            std::swap(S(j, c), S(p, c));
        const double inverse_pivot = 1.0 / S(j, j);
        for (unsigned int i = j + 1; i < k; ++i)
          {
            const double f = S(i, j) * inverse_pivot;
            S(i, j)        = f;
            if (f == 0)
              continue;
            for (unsigned int c = j + 1; c < k; ++c)
              S(i, c) -= f * S(j, c);
          }
      }
  }

  void
  LowRankUpdateSolver::substitute_capacitance(const unsigned int k)
  {
    for (unsigned int j = 0; j < k; ++j)
      {
        if (pivot[j] != j)
          std::swap(rhs_small[j], rhs_small[pivot[j]]);
        for (unsigned int i = j + 1; i < k; ++i)
          if (const double f = S(i, j); f != 0)
            rhs_small[i] -= f * rhs_small[j];
      }
    for (int i = k - 1; i >= 0; --i)
      {
        double value = rhs_small[i];
        for (unsigned int c = i + 1; c < k; ++c)
          value -= S(i, c) * rhs_small[c];
        rhs_small[i] = value / S(i, i);
      }
  }
} // namespace poundfe
