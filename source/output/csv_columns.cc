#include <poundfe/base/exceptions.h>
#include <poundfe/output/csv_columns.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>

namespace poundfe
{
  std::vector<std::vector<double>>
  read_csv_columns(const std::string &path, const std::vector<unsigned int> &columns)
  {
    std::ifstream file(path);
    std::string   row;
    if (!file || !std::getline(file, row)) // the header
      throw OutputError("read", path, file ? EINVAL : errno);
    // the requested columns in the order a row is scanned, each with where
    // its values go
    std::vector<std::pair<unsigned int, unsigned int>> wanted; // column, output
    for (unsigned int i = 0; i < columns.size(); ++i)
      wanted.emplace_back(columns[i], i);
    std::sort(wanted.begin(), wanted.end());
    std::vector<std::vector<double>> values(columns.size());
    for (unsigned long n = 2; std::getline(file, row); ++n)
      {
        if (row.empty())
          continue;
        const char  *p   = row.data();
        const char  *end = p + row.size();
        unsigned int column = 0;
        for (auto w = wanted.begin(); w != wanted.end();)
          {
            for (; column < w->first && p != end; ++column) // to the next wanted column
              {
                const void *comma = std::memchr(p, ',', end - p);
                p = comma ? static_cast<const char *>(comma) + 1 : end;
              }
            double x = 0;
            const auto [next, error] = std::from_chars(p, end, x);
            if (column < w->first || error != std::errc() || (next != end && *next != ','))
              throw OutputError("read row " + std::to_string(n) + ", column " +
                                  std::to_string(w->first + 1) + " of",
                                path, EINVAL);
            for (const unsigned int column_wanted = w->first;
                 w != wanted.end() && w->first == column_wanted; ++w)
              values[w->second].push_back(x);
          }
      }
    if (file.bad())
      throw OutputError("read", path, errno);
    return values;
  }

  std::vector<std::string>
  read_csv_header(const std::string &path)
  {
    std::ifstream file(path);
    std::string   line;
    if (!file || !std::getline(file, line))
      throw OutputError("read", path, file ? EINVAL : errno);
    std::vector<std::string> names;
    for (std::size_t start = 0;;)
      {
        const std::size_t comma = line.find(',', start);
        names.push_back(line.substr(start, comma - start));
        if (comma == std::string::npos)
          return names;
        start = comma + 1;
      }
  }
} // namespace poundfe
