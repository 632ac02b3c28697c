// A table written row by row (the time series of the recorders) in the
// format Output/Format chooses: CSV text (csv_writer.h, the default, for
// people and spreadsheets) or NumPy .npy (npy_writer.h: float64 rows that
// NumPy, pandas and ParaView's Python read without parsing, for long or
// large runs). Each writer keeps one buffer and writes it into an
// AtomicFile when full: nothing is allocated per row.
#ifndef poundfe_output_table_writer_h
#define poundfe_output_table_writer_h

#include <poundfe/base/choices.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class NumberText;

  enum class OutputFormat
  {
    csv, // <stem>.csv: a header line, then numbers in the shortest exact form
    npy  // <stem>.npy (rows x columns of float64) and <stem>.columns.txt
  };

  const NameTable<OutputFormat> &output_format_names();

  class TableWriter
  {
  public:
    virtual ~TableWriter() = default;
    /// One row: `first` (the time), then `values`: as many numbers as the
    /// header has names.
    virtual void add_row(double first, const std::vector<double> &values) = 0;
    /// Write what is buffered and rename the file(s) into place; once.
    virtual void commit() = 0;
  };

  /// The files a table named `stem` is written to, the table first
  /// ("drift" -> drift.csv; drift.npy, drift.columns.txt).
  std::vector<std::string> table_files(OutputFormat format, const std::string &stem);

  /// A writer of <directory>/<stem> in `format` with the column names
  /// `header`; CSV writers share `text` (output/number_text.h).
  std::unique_ptr<TableWriter> make_table_writer(OutputFormat format, const std::string &directory,
                                                 const std::string              &stem,
                                                 const std::vector<std::string> &header,
                                                 const std::shared_ptr<NumberText> &text);
} // namespace poundfe

#endif
