#include <poundfe/base/exceptions.h>
#include <poundfe/excitation/records.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

namespace poundfe
{
  namespace
  {
    std::vector<std::string>
    read_lines(const std::string &file)
    {
      std::ifstream in(file, std::ios::binary);
      if (!in)
        throw InputError(file, 0, "", "cannot open the record file");
      std::vector<std::string> lines;
      std::string              line;
      while (std::getline(in, line))
        {
          while (!line.empty() && (line.back() == '\r' || line.back() == '\n'))
            line.pop_back();
          lines.push_back(line);
        }
      return lines;
    }

    /// Split a line into numbers; false if a token is not a number.
    bool
    parse_numbers(const std::string &line, std::vector<double> &numbers)
    {
      numbers.clear();
      std::istringstream in(line);
      std::string        token;
      while (in >> token)
        {
          if (token.back() == ',')
            token.pop_back();
          char  *end   = nullptr;
          double value = std::strtod(token.c_str(), &end);
          if (end != token.c_str() + token.size() || !std::isfinite(value))
            return false;
          numbers.push_back(value);
        }
      return true;
    }

    GroundMotion
    read_at2(const std::string &file, const std::vector<std::string> &lines)
    {
      static const std::regex nga("NPTS\\s*=\\s*([0-9]+)\\s*,?\\s*DT\\s*=\\s*([-+0-9.eEdD]+)",
                                  std::regex::icase);
      static const std::regex west2("^\\s*([0-9]+)\\s+([-+0-9.eE]+)\\s+NPTS", std::regex::icase);
      std::size_t header_end = lines.size();
      long        npts       = -1;
      double      dt         = 0;
      for (std::size_t i = 0; i < lines.size() && i < 64; ++i)
        {
          std::smatch m;
          if (std::regex_search(lines[i], m, nga) || std::regex_search(lines[i], m, west2))
            {
              npts       = std::stol(m[1]);
              dt         = std::stod(m[2]);
              header_end = i + 1;
              break;
            }
        }
      if (npts < 0)
        throw InputError(file, 0, "", "no 'NPTS=..., DT=...' header line in the first 64 "
                                      "lines: not a PEER AT2 file");
      if (!(dt > 0) || npts < 2)
        throw InputError(file, header_end, "", "NPTS must be at least 2 and DT positive");
      std::vector<double> values, numbers;
      values.reserve(npts);
      // Some files close with a trailer ("*** End Data ***"): stop at NPTS.
      for (std::size_t i = header_end;
           i < lines.size() && static_cast<long>(values.size()) < npts;
           ++i)
        {
          if (!parse_numbers(lines[i], numbers))
            throw InputError(file, i + 1, "", "not a list of numbers: '" + lines[i] + "'");
          values.insert(values.end(), numbers.begin(), numbers.end());
        }
      if (static_cast<long>(values.size()) < npts)
        throw InputError(file, lines.size(), "",
                         "the header promises NPTS = " + std::to_string(npts) + " values, found " +
                           std::to_string(values.size()));
      values.resize(npts);
      for (double &a : values)
        a *= standard_gravity;
      return GroundMotion(dt, std::move(values), file);
    }

    GroundMotion
    read_text(const std::string &file, const RecordFormat &format)
    {
      const ColumnTable table = read_columns(file);
      std::vector<double> values = table.values;
      double dt = format.time_step;
      if (table.columns == 2)
        {
          const auto &times = table.times;
          dt = times[1] - times[0];
          for (std::size_t i = 1; i < times.size(); ++i)
            if (!(dt > 0) || std::abs(times[i] - times[i - 1] - dt) > 1e-6 * dt + 1e-12)
              throw InputError(file, 0, "", "the time column must be uniformly spaced and "
                                            "increasing (at row " + std::to_string(i + 1) + ")");
        }
      else if (!(dt > 0))
        throw InputError(file, 0, "Ground motion/Record/Time step",
                         "a one-column record needs a positive time step");
      if (format.units == RecordUnits::g)
        for (double &a : values)
          a *= standard_gravity;
      return GroundMotion(dt, std::move(values), file);
    }
  } // namespace

  ColumnTable
  read_columns(const std::string &file)
  {
    const auto          lines = read_lines(file);
    ColumnTable         table;
    std::vector<double> numbers;
    for (std::size_t i = 0; i < lines.size(); ++i)
      {
        std::string line = lines[i];
        const auto  hash = line.find_first_of("#%");
        if (hash != std::string::npos)
          line.erase(hash);
        for (char &c : line)
          if (c == ',' || c == ';')
            c = ' ';
        if (line.find_first_not_of(" \t") == std::string::npos)
          continue;
        if (!parse_numbers(line, numbers))
          {
            if (table.values.empty())
              continue; // a header row of names
            throw InputError(file, i + 1, "", "not a list of numbers: '" + lines[i] + "'");
          }
        if (table.columns == 0)
          table.columns = numbers.size();
        if (numbers.size() != table.columns || table.columns > 2)
          throw InputError(file, i + 1, "",
                           "expected 1 or 2 columns throughout, found " +
                             std::to_string(numbers.size()));
        if (table.columns == 2)
          table.times.push_back(numbers[0]);
        table.values.push_back(numbers.back());
      }
    if (table.values.size() < 2)
      throw InputError(file, 0, "", "needs at least two rows of numbers");
    return table;
  }

  GroundMotion
  read_record(const std::string &file, const RecordFormat &format)
  {
    RecordFileFormat kind = format.format;
    if (kind == RecordFileFormat::automatic)
      {
        std::string extension = file.substr(file.find_last_of('.') + 1);
        for (char &c : extension)
          c = std::tolower(static_cast<unsigned char>(c));
        kind = (extension == "at2") ? RecordFileFormat::at2 : RecordFileFormat::text;
      }
    return kind == RecordFileFormat::at2 ? read_at2(file, read_lines(file)) :
                                           read_text(file, format);
  }
} // namespace poundfe
