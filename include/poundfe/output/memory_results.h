// A run's results kept in memory instead of files (Python's poundfe.run
// without output=): the same observers add the same rows to a memory table
// (a TableWriter beside the CSV and NPY writers) and write the texts of
// their other files (summary.json, impacts.csv, the profiles) by name, so
// that what Python gets is what the files would hold, double for double.
// Implemented in table_writer.cc, beside the file writers' factory.
#ifndef poundfe_output_memory_results_h
#define poundfe_output_memory_results_h

#include <poundfe/output/table_writer.h>

#include <deque>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace poundfe
{
  /// A run's results in memory: each table as rows of doubles (time first,
  /// as its file's), each other file as its text.
  class MemoryResults
  {
  public:
    struct Table
    {
      std::string              stem;   // "drift": what drift.csv or drift.npy would hold
      std::vector<std::string> header; // time_s first
      std::vector<double>      values; // row after row, header.size() per row
    };

    /// A writer adding its rows to a new table `stem` (every number
    /// checked finite, as the file writers check them).
    std::unique_ptr<TableWriter> table_writer(const std::string              &stem,
                                              const std::vector<std::string> &header);
    /// The text a file `name` would hold (replacing an earlier one).
    void set_text(const std::string &name, std::string text);

    /// In the order they were made (a deque: a writer keeps its table).
    std::deque<Table>                                tables;
    std::vector<std::pair<std::string, std::string>> texts;
  };

  /// `text` as the file <directory>/<name> (written atomically), or into
  /// `memory` when given: the one place a run's text files go.
  void write_result_text(MemoryResults *memory, const std::string &directory,
                         const std::string &name, const std::string &text);

  /// A writer of the table <directory>/<stem>.csv, or of `memory`'s table
  /// `stem` when given: the one place a command's tables of numbers go.
  std::unique_ptr<TableWriter> result_table_writer(MemoryResults *memory, const std::string &directory,
                                                   const std::string              &stem,
                                                   const std::vector<std::string> &header);
} // namespace poundfe

#endif
