// Columns of a CSV table of this program's (output/csv_writer.h) read back
// in one pass. A run's figures are drawn from its files; gnuplot reads a
// file once per curve, which for a wide table (a city block's hinges.csv:
// 29,197 columns, 63 MB) takes most of a second per curve, so the figures
// of a few of its columns are given to gnuplot as data blocks of those
// columns alone (report/run_plots.h).
#ifndef poundfe_output_csv_columns_h
#define poundfe_output_csv_columns_h

#include <string>
#include <vector>

namespace poundfe
{
  /// The values (rows after the header) of columns `columns` (0: the first;
  /// in any order, repeated or not) of the CSV file `path`, one vector per
  /// requested column. Reads a row at a time: no copy of the file in memory.
  /// OutputError if the file cannot be read, a row is shorter than a
  /// requested column or a value is not a number.
  std::vector<std::vector<double>>
  read_csv_columns(const std::string &path, const std::vector<unsigned int> &columns);

  /// The column names of the CSV file `path` (its first line); OutputError
  /// if it cannot be read.
  std::vector<std::string> read_csv_header(const std::string &path);
} // namespace poundfe

#endif
