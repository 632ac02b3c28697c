// A table writer whose rows go through the run's OutputQueue
// (output/output_queue.h): checked here, formatted and written there.
#include <poundfe/output/finite_row.h>
#include <poundfe/output/output_queue.h>
#include <poundfe/output/table_writer.h>

namespace poundfe
{
  namespace
  {
    class QueuedTableWriter final : public TableWriter, public OutputQueue::Sink
    {
    public:
      QueuedTableWriter(std::unique_ptr<TableWriter> writer, std::shared_ptr<OutputQueue> queue,
                        const std::vector<std::string> &header, const std::string &file)
        : writer(std::move(writer))
        , queue(std::move(queue))
        , header(header)
        , file(file)
      {}

      /// The rows already pushed reach `writer` before it goes (an
      /// uncommitted writer then removes its temporary).
      ~QueuedTableWriter() override { queue->drain(); }

      void
      add_row(const double first, const std::vector<double> &values) override
      {
        check_row_finite(first, values, header, file);
        queue->push(*this, first, values);
      }

      void
      commit() override
      {
        queue->drain();
        OutputQueue::take_error(*this);
        writer->commit();
      }

      void
      consume(const double *numbers, const std::size_t n) override
      {
        row.assign(numbers + 1, numbers + n); // its capacity kept: no allocation
        writer->add_row(numbers[0], row);
      }

    private:
      const std::unique_ptr<TableWriter> writer;
      const std::shared_ptr<OutputQueue> queue;
      const std::vector<std::string>     header; // for messages, as the writer's
      const std::string                  file;
      std::vector<double>                row; // the writer thread's
    };
  } // namespace

  std::unique_ptr<TableWriter>
  queued_table_writer(std::unique_ptr<TableWriter> writer, const std::shared_ptr<OutputQueue> &queue,
                      const std::vector<std::string> &header, const std::string &file)
  {
    if (!writer || !queue || !queue->threaded())
      return writer;
    return std::make_unique<QueuedTableWriter>(std::move(writer), queue, header, file);
  }
} // namespace poundfe
