#include <poundfe/output/csv_writer.h>

#include <charconv>

namespace poundfe
{
  namespace
  {
    constexpr std::size_t buffer_size = 1 << 16;
    constexpr std::size_t max_number  = 32; // to_chars of a double needs <= 24
  } // namespace

  CsvWriter::CsvWriter(const std::string &path, const std::vector<std::string> &header)
    : file(path)
    , buffer(buffer_size, '\0')
  {
    std::string line;
    for (std::size_t i = 0; i < header.size(); ++i)
      line += (i ? "," : "") + header[i];
    line += '\n';
    file.write(line);
  }

  void
  CsvWriter::flush_buffer()
  {
    file.write(buffer.data(), used);
    used = 0;
  }

  void
  CsvWriter::begin_row(const double first)
  {
    if (used + max_number > buffer_size)
      flush_buffer();
    used = std::to_chars(buffer.data() + used, buffer.data() + buffer_size, first).ptr -
           buffer.data();
  }

  void
  CsvWriter::add(const double value)
  {
    if (used + max_number + 1 > buffer_size)
      flush_buffer();
    buffer[used++] = ',';
    used = std::to_chars(buffer.data() + used, buffer.data() + buffer_size, value).ptr -
           buffer.data();
  }

  void
  CsvWriter::end_row()
  {
    if (used + 1 > buffer_size)
      flush_buffer();
    buffer[used++] = '\n';
  }

  void
  CsvWriter::commit()
  {
    flush_buffer();
    file.commit();
  }
} // namespace poundfe
