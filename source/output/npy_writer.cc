#include <poundfe/output/finite_row.h>
#include <poundfe/output/npy_writer.h>

#include <deal.II/base/exceptions.h>

#include <cstring>

namespace poundfe
{
  namespace
  {
    constexpr std::size_t block = 1 << 13; // doubles per write(2) at least: 64 KiB

    std::string
    lines(const std::vector<std::string> &names)
    {
      std::string text;
      for (const std::string &name : names)
        text += name + '\n';
      return text;
    }
  } // namespace

  NpyWriter::NpyWriter(const std::string &path, const std::vector<std::string> &header)
    : file(path)
    , names(lines(header))
    , columns(header)
    , n_columns(header.size())
    , buffer(block + header.size())
  {
    Assert(path.size() > 4 && path.compare(path.size() - 4, 4, ".npy") == 0,
           dealii::ExcMessage("an .npy table's name ends in .npy"));
    file.write(header_text(0, n_columns)); // the row count comes at commit
  }

  std::string
  NpyWriter::header_text(const unsigned long rows, const std::size_t columns)
  {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    const char *descr = ">f8";
#else
    const char *descr = "<f8";
#endif
    std::string dict = std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': (" +
                       std::to_string(rows) + ", " + std::to_string(columns) + "), }";
    // the longest dict (20-digit counts) has 87 characters: it always fits
    Assert(dict.size() < header_size - 10, dealii::ExcInternalError());
    dict.resize(header_size - 10 - 1, ' ');
    dict += '\n';
    const std::size_t length = dict.size(); // little-endian uint16
    return std::string("\x93NUMPY\x01\x00", 8) + char(length & 0xff) + char(length >> 8) + dict;
  }

  std::string
  NpyWriter::columns_path(const std::string &path)
  {
    return path.substr(0, path.size() - 4) + ".columns.txt";
  }

  void
  NpyWriter::write_buffer()
  {
    file.write(reinterpret_cast<const char *>(buffer.data()), used * sizeof(double));
    used = 0;
  }

  void
  NpyWriter::add_row(const double first, const std::vector<double> &values)
  {
    Assert(values.size() + 1 == n_columns, dealii::ExcMessage("a row of the wrong width"));
    if (used >= block) // a whole row fits after `block` (see the constructor)
      write_buffer();
    check_row_finite(first, values, columns, file.path());
    buffer[used] = first;
    std::memcpy(buffer.data() + used + 1, values.data(), values.size() * sizeof(double));
    used += n_columns;
    ++rows;
  }

  void
  NpyWriter::commit()
  {
    write_buffer();
    const std::string header = header_text(rows, n_columns);
    file.overwrite(0, header.data(), header.size());
    write_file_atomically(columns_path(file.path()), names);
    file.commit();
  }
} // namespace poundfe
