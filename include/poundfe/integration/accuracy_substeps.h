// Sub-steps for accuracy (Time integration/Steps per shortest period):
// the average-acceleration Newmark rule lengthens a mode of frequency omega
// by T_h / T - 1 = (omega h)^2 / 12 + O(h^4) at the step h (Chopra 2012,
// §5.5, Fig. 5.5.2; Hilber, Hughes & Taylor 1977). A step Time step = dt
// is integrated in 2^c equal sub-steps, c the smallest level with
// h = dt / 2^c <= T_min / N, T_min = 2 pi / omega_max, so that every mode
// is followed with at least N sub-steps per period (period error at most
// pi^2 / (3 N^2)). omega_max^2 is bounded by Gershgorin's theorem applied
// to M^-1 K, exact for a lumped (diagonal) M:
//   omega_max^2 <= max_i sum_j |K_ij| / M_ii   over the rows i with mass;
// condensing the massless equations only lowers the stiffness (the Schur
// complement K_mm - K_ms K_ss^-1 K_sm <= K_mm), so it stays a bound.
// With a consistent mass it is an estimate, not a bound.
// Source: Gershgorin (1931); Golub & Van Loan, Matrix Computations, 4th
// ed., Thm. 7.2.1. doc/theory.md §3.7b.
#ifndef poundfe_integration_accuracy_substeps_h
#define poundfe_integration_accuracy_substeps_h

#include <poundfe/assembly/linear_system.h>

namespace poundfe
{
  /// The Gershgorin bound of the highest circular frequency of K phi =
  /// omega^2 M phi over the rows with mass, rad/s (0 with no mass).
  double highest_frequency_bound(const SparseMatrix &stiffness, const SparseMatrix &mass);

  /// The smallest c with (time_step / 2^c) omega_max <= 2 pi / steps_per_period,
  /// at most max_level; 0 when steps_per_period is 0 (off).
  unsigned int accuracy_level(double time_step, double omega_max,
                              unsigned int steps_per_period, unsigned int max_level);
} // namespace poundfe

#endif
