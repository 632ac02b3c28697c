#include <poundfe/output/csv_writer.h>
#include <poundfe/output/npy_writer.h>
#include <poundfe/output/table_writer.h>

namespace poundfe
{
  const NameTable<OutputFormat> &
  output_format_names()
  {
    static const NameTable<OutputFormat> table({{OutputFormat::csv, "csv"}, {OutputFormat::npy, "npy"}});
    return table;
  }

  std::vector<std::string>
  table_files(const OutputFormat format, const std::string &stem)
  {
    if (format == OutputFormat::npy)
      return {stem + ".npy", stem + ".columns.txt"};
    return {stem + ".csv"};
  }

  std::unique_ptr<TableWriter>
  make_table_writer(const OutputFormat format, const std::string &directory, const std::string &stem,
                    const std::vector<std::string> &header, const std::shared_ptr<NumberText> &text)
  {
    const std::string path = directory + "/" + table_files(format, stem).front();
    if (format == OutputFormat::npy)
      return std::make_unique<NpyWriter>(path, header);
    return std::make_unique<CsvWriter>(path, header, text);
  }
} // namespace poundfe
