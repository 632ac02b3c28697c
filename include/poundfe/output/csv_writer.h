// CSV tables: a header row, then rows of numbers in std::to_chars's shortest
// form that reads back to the same double (output/number_text.h), formatted
// into one buffer per file, so writing a row allocates nothing. Written
// atomically (see AtomicFile).
#ifndef poundfe_output_csv_writer_h
#define poundfe_output_csv_writer_h

#include <poundfe/output/atomic_file.h>
#include <poundfe/output/table_writer.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class CsvWriter : public TableWriter
  {
  public:
    /// Writers of one run share `text` (a memory of numbers written lately,
    /// which the same step's files repeat); without it the writer has its own.
    CsvWriter(const std::string &path, const std::vector<std::string> &header,
              std::shared_ptr<NumberText> text = nullptr);

    /// A row a number at a time.
    void begin_row(double first);
    void add(double value);
    void end_row();

    void add_row(double first, const std::vector<double> &values) override;
    void commit() override;
    const std::string &path() const { return file.path(); }

  private:
    /// Write out the buffer unless `size` more characters fit.
    void make_room(std::size_t size);

    /// Throws NumericalError naming the column unless `value` is finite
    /// (output/finite_output.h); `column` 0 is the first.
    void check(double value, std::size_t column) const;

    AtomicFile                  file;
    const std::vector<std::string> columns; // the header, for messages
    std::size_t                 column = 0; // of begin_row/add
    std::shared_ptr<NumberText> text;
    std::string                 buffer;
    std::size_t                 used = 0;
  };
} // namespace poundfe

#endif
