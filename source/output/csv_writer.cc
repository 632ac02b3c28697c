#include <poundfe/output/csv_writer.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/finite_row.h>
#include <poundfe/output/number_text.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    constexpr std::size_t block = 1 << 16; // bytes per write(2) at least
    constexpr std::size_t cell  = NumberText::max_length + 1; // a number and its separator
  } // namespace

  CsvWriter::CsvWriter(const std::string &path, const std::vector<std::string> &header,
                       std::shared_ptr<NumberText> shared_text)
    : file(path)
    , columns(header)
    , text(shared_text ? std::move(shared_text) : std::make_shared<NumberText>())
    // room for a block and a whole row (add_row checks once per row)
    , buffer(block + header.size() * cell, '\0')
  {
    std::string line;
    for (std::size_t i = 0; i < header.size(); ++i)
      line += (i ? "," : "") + header[i];
    line += '\n';
    file.write(line);
  }

  void
  CsvWriter::make_room(const std::size_t size)
  {
    if (used + size > buffer.size())
      {
        file.write(buffer.data(), used);
        used = 0;
      }
  }

  void
  CsvWriter::check(const double value, const std::size_t column) const
  {
    if (!std::isfinite(value))
      throw_not_finite(value, column < columns.size() ? columns[column] : "column " + std::to_string(column + 1),
                       file.path());
  }

  void
  CsvWriter::begin_row(const double first)
  {
    check(first, column = 0);
    make_room(cell);
    used = text->write(buffer.data() + used, first) - buffer.data();
  }

  void
  CsvWriter::add(const double value)
  {
    check(value, ++column);
    make_room(cell);
    buffer[used++] = ',';
    used = text->write(buffer.data() + used, value) - buffer.data();
  }

  void
  CsvWriter::end_row()
  {
    make_room(1);
    buffer[used++] = '\n';
  }

  void
  CsvWriter::add_row(const double first, const std::vector<double> &values)
  {
    Assert(buffer.size() >= block + (values.size() + 1) * cell,
           dealii::ExcMessage("a row wider than the header"));
    if (used > block) // the whole row fits after `block` (see the constructor)
      {
        file.write(buffer.data(), used);
        used = 0;
      }
    check_row_finite(first, values, columns, file.path());
    char *out = text->write(buffer.data() + used, first);
    for (const double v : values)
      {
        *out++ = ',';
        out    = text->write(out, v);
      }
    *out++ = '\n';
    used   = out - buffer.data();
  }

  void
  CsvWriter::commit()
  {
    file.write(buffer.data(), used);
    used = 0;
    file.commit();
  }
} // namespace poundfe
