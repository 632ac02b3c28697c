// The table writers' formats, and the memory a run's results go to instead
// of files (output/memory_results.h).
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/finite_row.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/npy_writer.h>
#include <poundfe/output/table_writer.h>


namespace poundfe
{
  namespace
  {
    /// Rows appended to a MemoryResults table.
    class MemoryTableWriter : public TableWriter
    {
    public:
      explicit MemoryTableWriter(MemoryResults::Table &table)
        : table(table)
      {}

      void
      add_row(const double first, const std::vector<double> &values) override
      {
        // the message a file would give, naming the table as its CSV
        check_row_finite(first, values, table.header, table.stem + ".csv");
        table.values.push_back(first);
        table.values.insert(table.values.end(), values.begin(), values.end());
      }

      void commit() override {}

    private:
      MemoryResults::Table &table;
    };
  } // namespace

  std::unique_ptr<TableWriter>
  MemoryResults::table_writer(const std::string &stem, const std::vector<std::string> &header)
  {
    tables.push_back({stem, header, {}});
    return std::make_unique<MemoryTableWriter>(tables.back());
  }

  void
  MemoryResults::set_text(const std::string &name, std::string text)
  {
    for (auto &[file, contents] : texts)
      if (file == name)
        {
          contents = std::move(text);
          return;
        }
    texts.emplace_back(name, std::move(text));
  }

  void
  write_result_text(MemoryResults *memory, const std::string &directory, const std::string &name,
                    const std::string &text)
  {
    if (memory)
      memory->set_text(name, text);
    else
      write_file_atomically(directory + "/" + name, text);
  }

  std::unique_ptr<TableWriter>
  result_table_writer(MemoryResults *memory, const std::string &directory, const std::string &stem,
                      const std::vector<std::string> &header)
  {
    if (memory)
      return memory->table_writer(stem, header);
    return std::make_unique<CsvWriter>(directory + "/" + stem + ".csv", header);
  }

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
