// The ring of blocks between the stepping thread and the writer thread
// (output/output_queue.h). A block holds records [sink, n, n numbers], the
// sink's address and the count stored in the bits of a double. The
// counters `handed` and `written` only grow; block k of the ring is
// handed % n_blocks while filling and free again once `written` passes it.
#include <poundfe/output/output_queue.h>

#include <poundfe/base/lean_assert.h>
#include <poundfe/base/thread_limit.h>

#include <cstdint>
#include <cstring>
#include <system_error>

namespace poundfe
{
  namespace
  {
    constexpr std::size_t record_head = 2; // the sink and the count

    double
    as_double(const std::uint64_t bits)
    {
      double x;
      std::memcpy(&x, &bits, sizeof x);
      return x;
    }

    std::uint64_t
    as_bits(const double x)
    {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      return bits;
    }
  } // namespace

  OutputQueue::OutputQueue(const bool threaded)
  {
    if (!threaded)
      return;
    for (Block &block : blocks)
      block.numbers.resize(block_size);
    try
      {
        writer = std::thread([this] { write_blocks(); });
      }
    catch (const std::system_error &) // no thread to be had: inline
      {}
  }

  OutputQueue::~OutputQueue()
  {
    if (!threaded())
      return;
    drain();
    {
      const std::lock_guard<std::mutex> lock(mutex);
      stopping = true;
    }
    changed.notify_all();
    writer.join();
  }

  double *
  OutputQueue::room(Sink &sink, const std::size_t n)
  {
    if (record_head + n > block_size)
      return nullptr;
    if (blocks[handed % n_blocks].used + record_head + n > block_size)
      hand_over(true);
    Block  &block = blocks[handed % n_blocks];
    double *out   = block.numbers.data() + block.used;
    out[0]        = as_double(reinterpret_cast<std::uintptr_t>(&sink));
    out[1]        = as_double(n);
    block.used += record_head + n;
    return out + record_head;
  }

  void
  OutputQueue::push(Sink &sink, const double first, const std::vector<double> &values)
  {
    double *out = threaded() ? room(sink, values.size() + 1) : nullptr;
    if (out)
      {
        out[0] = first;
        std::memcpy(out + 1, values.data(), values.size() * sizeof(double));
        return;
      }
    oversized.assign(1, first); // inline, or a row larger than a block
    oversized.insert(oversized.end(), values.begin(), values.end());
    push(sink, oversized.data(), oversized.size());
  }

  void
  OutputQueue::push(Sink &sink, const double *numbers, const std::size_t n)
  {
    if (!threaded())
      return sink.consume(numbers, n);
    if (double *out = room(sink, n))
      {
        std::memcpy(out, numbers, n * sizeof(double));
        return;
      }
    // larger than a block: on this thread once the writer has caught up
    drain();
    take_error(sink);
    sink.consume(numbers, n);
  }

  void
  OutputQueue::hand_over(const bool wait_for_room)
  {
    std::unique_lock<std::mutex> lock(mutex);
    ++handed;
    changed.notify_all();
    if (wait_for_room) // the next block free: the writer at most the ring behind
      changed.wait(lock, [this] { return handed - written < n_blocks; });
    blocks[handed % n_blocks].used = 0;
    if (first_error)
      std::rethrow_exception(first_error);
  }

  void
  OutputQueue::drain() noexcept
  {
    if (!threaded())
      return;
    std::unique_lock<std::mutex> lock(mutex);
    if (blocks[handed % n_blocks].used > 0)
      {
        changed.wait(lock, [this] { return handed - written < n_blocks - 1; });
        ++handed;
        blocks[handed % n_blocks].used = 0;
        changed.notify_all();
      }
    changed.wait(lock, [this] { return written == handed; });
  }

  void
  OutputQueue::take_error(const Sink &sink)
  {
    if (sink.error)
      std::rethrow_exception(sink.error);
  }

  void
  OutputQueue::write_blocks()
  {
    std::unique_lock<std::mutex> lock(mutex);
    for (;;)
      {
        changed.wait(lock, [this] { return written < handed || stopping; });
        if (written == handed) // stopping, and nothing left
          return;
        const Block &block = blocks[written % n_blocks];
        lock.unlock();
        const std::exception_ptr error = consume(block);
        lock.lock();
        if (error && !first_error)
          first_error = error;
        ++written;
        changed.notify_all();
      }
  }

  std::exception_ptr
  OutputQueue::consume(const Block &block)
  {
    std::exception_ptr first;
    for (std::size_t i = 0; i < block.used;)
      {
        Sink *const sink = reinterpret_cast<Sink *>(static_cast<std::uintptr_t>(as_bits(block.numbers[i])));
        const std::size_t n    = as_bits(block.numbers[i + 1]);
        const double     *row  = block.numbers.data() + i + record_head;
        i += record_head + n;
        if (sink->error) // a failed sink takes no more rows
          continue;
        try
          {
            sink->consume(row, n);
          }
        catch (...)
          {
            sink->error = std::current_exception();
            if (!first)
              first = sink->error;
          }
      }
    return first;
  }

  bool
  output_writer_threaded()
  {
    return thread_limit() > 1;
  }
} // namespace poundfe
