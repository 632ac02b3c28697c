#include <poundfe/base/thread_limit.h>

#include <atomic>

namespace poundfe
{
  namespace
  {
    std::atomic<unsigned int> limit{1};
  }

  unsigned int
  thread_limit()
  {
    return limit.load(std::memory_order_relaxed);
  }

  void
  set_thread_limit(const unsigned int n_threads)
  {
    limit.store(n_threads == 0 ? 1 : n_threads, std::memory_order_relaxed);
  }
} // namespace poundfe
