// Sub-steps for accuracy: omega_max^2 <= max_i sum_j |K_ij| / M_ii
// (Gershgorin 1931; Golub & Van Loan, Matrix Computations, 4th ed.,
// Thm. 7.2.1) and the level c with (dt / 2^c) omega_max <= 2 pi / N, N
// sub-steps per shortest period for a Newmark period error
// (omega h)^2 / 12 (Chopra 2012, §5.5). doc/theory.md §3.7b.
#include <poundfe/integration/accuracy_substeps.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace poundfe
{
  double
  highest_frequency_bound(const SparseMatrix &stiffness, const SparseMatrix &mass)
  {
    const Eigen::Index  n = stiffness.rows();
    std::vector<double> row_sum(n, 0.0), diagonal_mass(n, 0.0);
    for (int column = 0; column < stiffness.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(stiffness, column); it; ++it)
        row_sum[it.row()] += std::abs(it.value());
    for (int column = 0; column < mass.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(mass, column); it; ++it)
        if (it.row() == it.col())
          diagonal_mass[it.row()] = it.value();
    double omega_squared = 0;
    for (Eigen::Index i = 0; i < n; ++i)
      if (diagonal_mass[i] > 0)
        omega_squared = std::max(omega_squared, row_sum[i] / diagonal_mass[i]);
    return std::sqrt(omega_squared);
  }

  unsigned int
  accuracy_level(const double time_step, const double omega_max,
                 const unsigned int steps_per_period, const unsigned int max_level)
  {
    if (steps_per_period == 0 || !(omega_max > 0))
      return 0;
    const double longest = 2 * M_PI / (omega_max * steps_per_period);
    unsigned int level   = 0;
    while (level < max_level && time_step / std::ldexp(1.0, level) > longest)
      ++level;
    return level;
  }
} // namespace poundfe
