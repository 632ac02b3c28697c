// Formatting and writing a run's CSV tables and OpenSees recorder files off
// the stepping thread (an .npy row is a copy into its buffer already, no
// dearer than the copy into a block: those tables stay inline). At
// each record the stepping thread copies the raw doubles of a row into a
// block (64 KiB of doubles) of a ring of four; a full block is handed to one
// writer thread, which gives every row to its sink (CsvWriter's text,
// NpyWriter's bytes, an OpenSees recorder's -precision text) and writes the
// files. The stepping thread takes the lock once per block, allocates
// nothing per row, and waits only when the writer is the whole ring (256
// KiB) behind. A sink's output is the same byte for byte as when it is
// written inline: the writer thread calls the same code in the same order.
//
// Errors: a sink that throws on the writer thread (a full disk: OutputError;
// a signal at a safe point: Interrupted) keeps its exception; the stepping
// thread rethrows the first one at its next hand-over, so a run stops on a
// write error within one block, as it stops at once inline, and each sink's
// own error again when it is committed (`drain` then `take_error`).
// Inline (`threaded` false, or no thread to be had): push() hands each row
// to its sink at once, exceptions and all, as a plain writer would.
#ifndef poundfe_output_output_queue_h
#define poundfe_output_output_queue_h

#include <array>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace poundfe
{
  class TableWriter;

  class OutputQueue
  {
  public:
    /// What the writer thread hands a row to.
    class Sink
    {
    public:
      virtual ~Sink() = default;
      /// One row: `n` numbers. Runs on the writer thread when threaded.
      virtual void consume(const double *numbers, std::size_t n) = 0;

    private:
      friend class OutputQueue;
      std::exception_ptr error; // its first failure on the writer thread
    };

    /// Doubles per block, and blocks in the ring.
    static constexpr std::size_t block_size = std::size_t(1) << 13, n_blocks = 4;

    explicit OutputQueue(bool threaded);
    /// Writes what was pushed (errors are kept by their sinks) and joins.
    ~OutputQueue();
    OutputQueue(const OutputQueue &)            = delete;
    OutputQueue &operator=(const OutputQueue &) = delete;

    bool threaded() const { return writer.joinable(); }

    /// A row of `first` and `values` for `sink`.
    void push(Sink &sink, double first, const std::vector<double> &values);
    /// A row of `n` numbers for `sink`.
    void push(Sink &sink, const double *numbers, std::size_t n);

    /// Waits until every row pushed has been consumed; never throws.
    void drain() noexcept;

    /// After drain(): rethrows the first exception `sink` threw on the
    /// writer thread, if any.
    static void take_error(const Sink &sink);

  private:
    struct Block
    {
      std::vector<double> numbers; // records: sink, n, then n numbers
      std::size_t         used = 0;
    };

    /// Room for a record of `n` numbers in the block being filled (handing
    /// it over when full); nullptr when a record is larger than a block.
    double *room(Sink &sink, std::size_t n);
    /// Hands the block being filled to the writer and waits for a free one.
    void hand_over(bool wait_for_room);
    /// The writer thread: consumes blocks as they come, until stopped.
    void write_blocks();
    /// Every record of `block` to its sink; the first exception thrown.
    static std::exception_ptr consume(const Block &block);

    std::array<Block, n_blocks> blocks;
    std::vector<double>         oversized; // a record larger than a block

    std::mutex              mutex;      // guards what follows
    std::condition_variable changed;    // handed, written or stopping moved
    unsigned long           handed  = 0; // blocks given to the writer
    unsigned long           written = 0; // blocks it has consumed
    bool                    stopping = false;
    std::exception_ptr      first_error; // the first of any sink

    std::thread writer; // last: started once the rest exists
  };

  /// Whether a run's outputs get a writer thread: when the program may use
  /// more than one thread (`--threads N`, N > 1, deal.II's thread limit).
  bool output_writer_threaded();

  /// `writer` (of `file`, with the column names `header`) fed through
  /// `queue`: each row checked finite at once (NumericalError at the step
  /// that made it, as inline), then written on the writer thread; committed
  /// once everything before has been written. `writer` itself when the
  /// queue is inline.
  std::unique_ptr<TableWriter> queued_table_writer(std::unique_ptr<TableWriter>        writer,
                                                   const std::shared_ptr<OutputQueue> &queue,
                                                   const std::vector<std::string>     &header,
                                                   const std::string                  &file);
} // namespace poundfe

#endif
