#pragma once

// What the output tests share: a CSV table read back from a file written by
// poundfe, and a fresh scratch directory.

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace poundfe_test
{
  struct Table
  {
    std::vector<std::string>         header;
    std::vector<std::vector<double>> rows;

    unsigned int
    column(const std::string &name) const
    {
      const auto it = std::find(header.begin(), header.end(), name);
      BOOST_REQUIRE_MESSAGE(it != header.end(), "no column " << name);
      return it - header.begin();
    }
  };

  inline std::string
  read_bytes(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    BOOST_REQUIRE_MESSAGE(in, "cannot read " << path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }

  /// A CSV table with a header line; numbers through strtod (correctly
  /// rounded, so a written shortest round-trip text reads back exactly).
  inline Table
  read_csv(const std::string &path)
  {
    std::istringstream in(read_bytes(path));
    Table              table;
    std::string        line, cell;
    std::getline(in, line);
    for (std::istringstream s(line); std::getline(s, cell, ',');)
      table.header.push_back(cell);
    while (std::getline(in, line))
      {
        std::vector<double> row;
        for (std::istringstream s(line); std::getline(s, cell, ',');)
          row.push_back(std::strtod(cell.c_str(), nullptr));
        BOOST_REQUIRE_MESSAGE(row.size() == table.header.size(),
                              path << ": a row of " << row.size() << " cells under "
                                   << table.header.size() << " names");
        table.rows.push_back(row);
      }
    return table;
  }

  /// <tmp>/poundfe-<name>, removed if it was there.
  inline std::string
  fresh_directory(const std::string &name)
  {
    const std::string dir = std::filesystem::temp_directory_path() / ("poundfe-" + name);
    std::filesystem::remove_all(dir);
    return dir;
  }
} // namespace poundfe_test
