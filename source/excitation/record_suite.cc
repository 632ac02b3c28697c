// The record-suite reader (record_suite.h): CSV, JSON or a folder of AT2
// files, every record read and checked when the suite is read.
#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_file.h>
#include <poundfe/base/input_text.h>
#include <poundfe/base/numbers.h>
#include <poundfe/excitation/record_suite.h>
#include <poundfe/excitation/records.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// `name` relative to the suite's folder unless absolute.
    std::string
    suite_path(const std::string &suite, const bool folder, const std::string &name)
    {
      const std::filesystem::path path(name);
      if (path.is_absolute())
        return name;
      const std::filesystem::path base =
        folder ? std::filesystem::path(suite) : std::filesystem::path(suite).parent_path();
      return (base / path).lexically_normal().string();
    }

    /// A field of a suite line as a number, else an InputError naming it.
    double
    suite_number(const std::string &suite, const int line, const std::string &field,
                 const std::string &text)
    {
      const std::optional<double> value = parse_number(text, Exponent::e);
      if (!value)
        throw InputError(suite, line, field, "expected a number, got '" + text + "'");
      return *value;
    }

    /// A CSV field without its blanks and enclosing double quotes.
    std::string
    csv_field(const std::string &text)
    {
      std::string field = trimmed(text);
      if (field.size() >= 2 && field.front() == '"' && field.back() == '"')
        field = field.substr(1, field.size() - 2);
      return field;
    }

    std::vector<std::string>
    split_csv(const std::string &line)
    {
      std::vector<std::string> fields;
      std::istringstream       in(line);
      for (std::string field; std::getline(in, field, ',');)
        fields.push_back(csv_field(field));
      if (!line.empty() && line.back() == ',')
        fields.emplace_back();
      return fields;
    }

    /// One value of a record's column into `record` (the files resolved later).
    void
    set_field(SuiteRecord &record, const std::string &suite, const std::string &column,
              const std::string &value)
    {
      if (value.empty())
        return;
      if (column == "file" || column == "file2")
        record.files[column == "file" ? 0 : 1] = value;
      else if (column == "name")
        record.name = value;
      else if (column == "event")
        record.event = value;
      else if (column == "station")
        record.station = value;
      else
        {
          const double x = suite_number(suite, record.line, column, value);
          (column == "scale" ? record.scale_factor :
           column == "magnitude" ? record.magnitude :
           column == "distance_km" ? record.distance_km : record.vs30_m_s) = x;
        }
    }

    /// The columns of the header row, each known and given once.
    std::vector<std::string>
    csv_header(const std::string &suite, const int line, const std::string &text)
    {
      const std::vector<std::string> &known   = record_suite_columns();
      std::vector<std::string>        columns = split_csv(text);
      for (std::string &c : columns)
        {
          std::transform(c.begin(), c.end(), c.begin(),
                         [](unsigned char ch) { return std::tolower(ch); });
          if (std::find(known.begin(), known.end(), c) == known.end())
            throw InputError(suite, line, c, "not a column of a record suite (the columns: "
                                               "file, file2, name, scale, event, station, "
                                               "magnitude, distance_km, vs30_m_s)");
          if (std::count(columns.begin(), columns.end(), c) > 1)
            throw InputError(suite, line, c, "the column is named twice");
        }
      if (std::find(columns.begin(), columns.end(), "file") == columns.end())
        throw InputError(suite, line, "file", "the header row has no 'file' column (the "
                                              "record of each line)");
      return columns;
    }

    std::vector<SuiteRecord>
    read_csv_suite(const std::string &suite)
    {
      std::istringstream       in(read_input_text(suite, "record suite"));
      std::vector<std::string> columns;
      std::vector<SuiteRecord> records;
      int                      line = 0;
      for (std::string text; std::getline(in, text);)
        {
          ++line;
          const std::string content = trimmed(text);
          if (content.empty() || content[0] == '#')
            continue;
          if (columns.empty())
            {
              columns = csv_header(suite, line, content);
              continue;
            }
          const std::vector<std::string> fields = split_csv(content);
          if (fields.size() != columns.size())
            throw InputError(suite, line, "", "expected " + std::to_string(columns.size()) +
                                                " fields as in the header, found " +
                                                std::to_string(fields.size()));
          SuiteRecord record;
          record.line = line;
          record.files.resize(2);
          for (std::size_t c = 0; c < columns.size(); ++c)
            set_field(record, suite, columns[c], fields[c]);
          if (record.files[0].empty())
            throw InputError(suite, line, "file", "no record file on this line");
          if (record.files[1].empty())
            record.files.pop_back();
          records.push_back(std::move(record));
        }
      return records;
    }

    /// One entry of a JSON suite's "records".
    SuiteRecord
    json_record(const std::string &suite, const boost::property_tree::ptree &entry,
                const std::size_t index)
    {
      const std::string where = "records[" + std::to_string(index) + "]";
      SuiteRecord       record;
      for (const auto &[key, value] : entry)
        {
          if (key == "files")
            {
              for (const auto &file : value)
                record.files.push_back(file.second.get_value<std::string>());
              if (record.files.empty() || record.files.size() > 2)
                throw InputError(suite, 0, where + ".files",
                                 "expected one or two record files (a horizontal pair)");
              continue;
            }
          const auto &known = record_suite_columns();
          if (key == "file" || key == "file2" ||
              std::find(known.begin(), known.end(), key) == known.end())
            throw InputError(suite, 0, where + "." + key,
                             "not a field of a suite record (files, name, scale, event, "
                             "station, magnitude, distance_km, vs30_m_s)");
          set_field(record, suite, key, value.get_value<std::string>());
        }
      if (record.files.empty())
        throw InputError(suite, 0, where + ".files", "no record file");
      return record;
    }

    std::vector<SuiteRecord>
    read_json_suite(const std::string &suite)
    {
      boost::property_tree::ptree tree;
      try
        {
          std::istringstream in(read_json_text(suite, "record suite"));
          boost::property_tree::read_json(in, tree);
        }
      catch (const boost::property_tree::json_parser_error &e)
        {
          throw InputError(suite, e.line(), "", "not a JSON record suite: " + e.message());
        }
      const auto records = tree.get_child_optional("records");
      if (!records)
        throw InputError(suite, 0, "records", "a JSON suite is an object with a 'records' array");
      std::vector<SuiteRecord> result;
      for (const auto &entry : *records)
        result.push_back(json_record(suite, entry.second, result.size()));
      return result;
    }

    /// Every .AT2 file of `folder`, in the order of their names.
    std::vector<SuiteRecord>
    read_folder_suite(const std::string &folder)
    {
      std::vector<std::string> names;
      std::error_code          error;
      for (const auto &entry : std::filesystem::directory_iterator(folder, error))
        {
          std::string extension = entry.path().extension().string();
          std::transform(extension.begin(), extension.end(), extension.begin(),
                         [](unsigned char c) { return std::tolower(c); });
          if (extension == ".at2")
            names.push_back(entry.path().filename().string());
        }
      if (error)
        throw InputError(folder, 0, "", "cannot list the folder: " + error.message());
      std::sort(names.begin(), names.end());
      std::vector<SuiteRecord> records;
      for (const std::string &name : names)
        {
          SuiteRecord record;
          record.files = {name};
          records.push_back(std::move(record));
        }
      return records;
    }

    /// The record's components read, checked against each other and scaled.
    void
    load_record(const std::string &suite, const bool folder, SuiteRecord &record)
    {
      const std::string field_of[2] = {record.line > 0 ? "file" : "files",
                                       record.line > 0 ? "file2" : "files"};
      for (std::size_t c = 0; c < record.files.size(); ++c)
        {
          record.files[c] = suite_path(suite, folder, record.files[c]);
          try
            {
              record.components.push_back(read_record(record.files[c], RecordFormat{}));
            }
          catch (const InputError &e)
            {
              throw InputError(suite, record.line, field_of[c],
                               "record '" + record.files[c] + "'" +
                                 (e.line() > 0 ? " (its line " + std::to_string(e.line()) + ")" : "") +
                                 ": " + e.problem());
            }
        }
      if (record.components.size() == 2)
        {
          const GroundMotion &a = record.components[0], &b = record.components[1];
          if (std::abs(a.time_step() - b.time_step()) > 1e-9 * a.time_step() ||
              a.samples().size() != b.samples().size())
            throw InputError(suite, record.line, field_of[1],
                             "the components of a pair must share their time step and length: '" +
                               record.files[0] + "' has " + std::to_string(a.samples().size()) +
                               " values at dt = " + number_text(a.time_step()) + " s, '" +
                               record.files[1] + "' " + std::to_string(b.samples().size()) +
                               " at dt = " + number_text(b.time_step()) + " s");
        }
      for (GroundMotion &motion : record.components)
        motion.scale(record.scale_factor);
    }

    /// Names (the first file's stem by default) distinct; scale factors positive;
    /// one or two components throughout.
    void
    check_records(const std::string &suite, std::vector<SuiteRecord> &records)
    {
      std::map<std::string, int> seen;
      for (SuiteRecord &record : records)
        {
          if (record.name.empty())
            record.name = std::filesystem::path(record.files[0]).stem().string();
          if (!(record.scale_factor > 0))
            throw InputError(suite, record.line, "scale",
                             "the scale factor of '" + record.name + "' must be positive, got " +
                               number_text(record.scale_factor));
          const auto [it, inserted] = seen.emplace(record.name, record.line);
          if (!inserted)
            throw InputError(suite, record.line, "name",
                             "the name '" + record.name + "' is given twice" +
                               (it->second > 0 ? " (also on line " + std::to_string(it->second) + ")" : ""));
          if (record.files.size() != records[0].files.size())
            throw InputError(suite, record.line, "file2",
                             "every record of a suite has the same number of components (" +
                               std::to_string(records[0].files.size()) + " on the first)");
        }
    }
  } // namespace

  const std::vector<std::string> &
  record_suite_columns()
  {
    static const std::vector<std::string> columns{"file",      "file2",       "name",
                                                  "scale",     "event",       "station",
                                                  "magnitude", "distance_km", "vs30_m_s"};
    return columns;
  }

  std::string
  ResolvedPeriods::text() const
  {
    return rounded(shortest, 6) + " to " + rounded(longest, 6) +
           " s: from twice the time step (the Nyquist period) of record '" + shortest_of +
           "' to the duration of record '" + longest_of + "'";
  }

  ResolvedPeriods
  resolved_periods(const RecordSuite &suite)
  {
    ResolvedPeriods resolved;
    for (const SuiteRecord &record : suite.records)
      for (const GroundMotion &component : record.components)
        {
          if (2 * component.time_step() > resolved.shortest)
            resolved.shortest = 2 * component.time_step(), resolved.shortest_of = record.name;
          if (component.duration() < resolved.longest)
            resolved.longest = component.duration(), resolved.longest_of = record.name;
        }
    return resolved;
  }

  RecordSuite
  read_record_suite(const std::string &path, const std::string &parameter)
  {
    std::error_code error;
    const bool      folder = std::filesystem::is_directory(path, error);
    std::string     extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (!folder && extension != ".csv" && extension != ".json")
      throw InputError(path, 0, parameter, "a record suite is a .csv or .json file or a folder "
                                           "of .AT2 files");
    RecordSuite suite;
    suite.file    = path;
    suite.records = folder ? read_folder_suite(path) :
                    extension == ".csv" ? read_csv_suite(path) : read_json_suite(path);
    if (suite.records.empty())
      throw InputError(path, 0, parameter, folder ? "the folder holds no .AT2 file" :
                                                    "the suite lists no record");
    check_records(path, suite.records);
    for (SuiteRecord &record : suite.records)
      load_record(path, folder, record);
    return suite;
  }
} // namespace poundfe
