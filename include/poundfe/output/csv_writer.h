// Time-history CSV: a header row, then rows of numbers formatted with
// std::to_chars (shortest round-trip form) into a buffer, so writing a row
// allocates nothing. Written atomically (see AtomicFile).
#ifndef poundfe_output_csv_writer_h
#define poundfe_output_csv_writer_h

#include <poundfe/output/atomic_file.h>

#include <string>
#include <vector>

namespace poundfe
{
  class CsvWriter
  {
  public:
    CsvWriter(const std::string &path, const std::vector<std::string> &header);

    void begin_row(double first);
    void add(double value);
    void end_row();
    /// Rename the file into place; may be called once.
    void commit();
    const std::string &path() const { return file.path(); }

  private:
    void flush_buffer();

    AtomicFile  file;
    std::string buffer;
    std::size_t used = 0;
  };
} // namespace poundfe

#endif
