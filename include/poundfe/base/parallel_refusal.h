// The elements' state determination over deal.II's threads (TBB's pool,
// created once per process and sized by --threads): evaluate(h) for each h
// in [0, n), in ranges of a few elements, and the first h, in order, whose
// evaluation refused. Each evaluation writes only its own element's
// storage, so the results do not depend on the threads or their order; the
// caller sums the elements' forces and tangents afterwards in its fixed
// order, and the run keeps its bits on any number of threads.
#ifndef poundfe_base_parallel_refusal_h
#define poundfe_base_parallel_refusal_h

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>

namespace poundfe
{
  /// evaluate(h) for h in [0, n) over deal.II's threads; the first h (in
  /// order) whose evaluate returned false, or n. A range stops at its
  /// refusal; the others run to their end, so the elements after a refusal
  /// may hold new trial states: callers revert every element on a refusal.
  template <typename Evaluate>
  unsigned int
  first_refusal_in_parallel(const unsigned int n, const Evaluate &evaluate)
  {
    constexpr unsigned int    elements_per_range = 4;
    std::atomic<unsigned int> first{n};
    // TBB directly (the pool deal.II's thread limit sizes): the interpreter's
    // module, which uses it too, links without deal.II
    tbb::parallel_for(
      tbb::blocked_range<unsigned int>(0u, n, elements_per_range),
      [&](const tbb::blocked_range<unsigned int> &range) {
        for (unsigned int h = range.begin(); h < range.end(); ++h)
          if (!evaluate(h))
            {
              unsigned int seen = first.load();
              while (h < seen && !first.compare_exchange_weak(seen, h))
                {
                }
              return;
            }
      });
    return first.load();
  }

  /// The first h in [0, n) whose evaluate(h) refused, or n: over the
  /// threads when on_threads, else in order, stopping at the refusal (the
  /// elements past it untouched).
  template <typename Evaluate>
  unsigned int
  first_refusal(const unsigned int n, const Evaluate &evaluate, const bool on_threads)
  {
    if (on_threads)
      return first_refusal_in_parallel(n, evaluate);
    for (unsigned int h = 0; h < n; ++h)
      if (!evaluate(h))
        return h;
    return n;
  }
} // namespace poundfe

#endif
