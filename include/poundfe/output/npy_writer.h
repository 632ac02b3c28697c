// NumPy .npy tables (format version 1.0, numpy.org/neps/nep-0001-npy-format):
// the magic "\x93NUMPY", the version (1, 0), a little-endian uint16 header
// length and a Python dict literal
//   {'descr': '<f8', 'fortran_order': False, 'shape': (rows, columns), }
// padded with spaces to a 128-byte header (a multiple of 64, as NumPy
// writes them), then the rows of float64 in C order. numpy.load reads it;
// pandas: pd.DataFrame(np.load("drift.npy"), columns=open("drift.columns.txt").read().split()).
// The number of rows is known only at the end, so the header is written
// again at commit with the fixed length kept. The column names, one per
// line, go to <stem>.columns.txt, written (atomically) just before the
// table is renamed into place.
#ifndef poundfe_output_npy_writer_h
#define poundfe_output_npy_writer_h

#include <poundfe/output/atomic_file.h>
#include <poundfe/output/table_writer.h>

#include <string>
#include <vector>

namespace poundfe
{
  class NpyWriter : public TableWriter
  {
  public:
    /// Bytes before the data: magic, version, length and the padded dict.
    static constexpr std::size_t header_size = 128;

    /// `path` ends in ".npy"; `header` names the columns.
    NpyWriter(const std::string &path, const std::vector<std::string> &header);

    void add_row(double first, const std::vector<double> &values) override;
    void commit() override;

    /// The header of a table of rows x columns float64 in this machine's
    /// byte order ('<f8' on little-endian ones).
    static std::string header_text(unsigned long rows, std::size_t columns);
    /// <stem>.columns.txt next to <stem>.npy.
    static std::string columns_path(const std::string &path);

  private:
    void write_buffer();

    AtomicFile          file;
    const std::string   names; // the columns file's text
    const std::vector<std::string> columns; // the header, for messages
    const std::size_t   n_columns;
    std::vector<double> buffer; // whole rows
    std::size_t         used = 0;
    unsigned long       rows = 0;
  };
} // namespace poundfe

#endif
