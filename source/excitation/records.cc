#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>
#include <poundfe/base/numbers.h>
#include <poundfe/excitation/records.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// The lines of a record file (LF, CR LF or CR line ends).
    std::vector<std::string>
    read_lines(const std::string &file)
    {
      std::istringstream       in(read_input_text(file, "record file"));
      std::vector<std::string> lines;
      for (std::string line; std::getline(in, line);)
        lines.push_back(line);
      return lines;
    }

    /// Split a line into numbers (Fortran D exponents allowed); false if a
    /// field is not wholly a finite number.
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
          if (token.empty())
            continue; // a lone separator
          const std::optional<double> value = parse_number(token, Exponent::e_or_fortran_d);
          if (!value)
            return false;
          numbers.push_back(*value);
        }
      return true;
    }

    /// `motion` if every sample is finite and normal after the conversion
    /// to m/s^2 (`from` says from what); else an InputError.
    GroundMotion
    checked(const std::string &file, GroundMotion motion, const std::string &from)
    {
      const std::size_t i = motion.first_unusable_sample();
      if (i < motion.samples().size())
        throw InputError(file, 0, "", "value " + std::to_string(i + 1) + " becomes " +
                                        number_text(motion.samples()[i]) + " m/s^2 " + from +
                                        ": not a finite, normal number (check the units)");
      return motion;
    }

    /// The field of `line` that starts at `from` (blanks skipped) and ends
    /// at a blank or a comma.
    std::string
    field_at(const std::string &line, std::size_t from)
    {
      from = std::min(line.find_first_not_of(" \t", from), line.size());
      const std::size_t end = std::min(line.find_first_of(" \t,", from), line.size());
      return line.substr(from, end - from);
    }

    /// The AT2 header's NPTS and DT fields, as written.
    struct At2Header
    {
      std::size_t line = 0; // 1-based; 0: none found
      std::string npts, dt;
    };

    /// The first header line within the first 64: NGA "NPTS= 5590, DT= .005
    /// SEC" (any case, blanks optional) or NGA-West2 "5590 0.005 NPTS, DT".
    At2Header
    find_at2_header(const std::vector<std::string> &lines)
    {
      for (std::size_t i = 0; i < lines.size() && i < 64; ++i)
        {
          std::string upper = lines[i];
          for (char &c : upper)
            c = std::toupper(static_cast<unsigned char>(c));
          const std::size_t npts = upper.find("NPTS");
          if (npts == std::string::npos)
            continue;
          const std::size_t equals = upper.find_first_not_of(" \t", npts + 4);
          if (equals != std::string::npos && upper[equals] == '=')
            {
              const std::size_t dt = upper.find("DT", equals);
              const std::size_t dt_equals =
                dt == std::string::npos ? dt : upper.find_first_not_of(" \t", dt + 2);
              return {i + 1, field_at(lines[i], equals + 1),
                      dt_equals != std::string::npos && upper[dt_equals] == '=' ?
                        field_at(lines[i], dt_equals + 1) : ""};
            }
          std::istringstream fields(lines[i].substr(0, npts)); // "n dt NPTS, DT"
          std::string        n, dt, extra;
          fields >> n >> dt;
          if (fields >> extra)
            n.clear(); // not the West2 form: refused below with this line
          return {i + 1, n, dt};
        }
      return {};
    }

    /// Most points an AT2 record may have: 10^8 values (800 MB), far above
    /// any recording (hours at 200 Hz are ~10^6), far below what would fail
    /// to allocate on a workstation.
    constexpr unsigned long max_record_points = 100000000;

    GroundMotion
    read_at2(const std::string &file, const std::vector<std::string> &lines)
    {
      const At2Header header = find_at2_header(lines);
      if (header.line == 0)
        throw InputError(file, 0, "", "no 'NPTS=..., DT=...' header line in the first 64 "
                                      "lines: not a PEER AT2 file");
      const int                          line = header.line;
      const std::optional<unsigned long> npts = parse_count(header.npts, max_record_points);
      if (!npts || *npts < 2)
        throw InputError(file, line, "", "header field NPTS: expected a whole number of points "
                                         "from 2 to " + std::to_string(max_record_points) +
                                           ", got '" + header.npts + "'");
      const std::optional<double> dt = parse_number(header.dt, Exponent::e_or_fortran_d);
      if (!dt || !(*dt > 0))
        throw InputError(file, line, "", "header field DT: expected a positive time step in s "
                                         "(e.g. 0.005 or .5D-02), got '" + header.dt + "'");
      std::vector<double> values, numbers;
      // Some files close with a trailer ("*** End Data ***"): the values
      // end at the first line after NPTS of them that is not numbers.
      std::size_t i = header.line;
      for (; i < lines.size(); ++i)
        {
          if (!parse_numbers(lines[i], numbers))
            {
              if (values.size() >= *npts)
                break;
              throw InputError(file, i + 1, "", "not a list of numbers: '" + lines[i].substr(0, 80) +
                                                  (lines[i].size() > 80 ? "...'" : "'"));
            }
          values.insert(values.end(), numbers.begin(), numbers.end());
        }
      // fewer or more values than NPTS: the header or the data is wrong,
      // and which of them cannot be told
      if (values.size() != *npts)
        throw InputError(file, i, "",
                         "the header (line " + std::to_string(line) + ") promises NPTS = " +
                           std::to_string(*npts) + " values, found " +
                           std::to_string(values.size()));
      for (double &a : values)
        a *= standard_gravity;
      return checked(file, GroundMotion(*dt, std::move(values), file), "in g (AT2)");
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
      return checked(file, GroundMotion(dt, std::move(values), file),
                     format.units == RecordUnits::g ? "in g" : "as given");
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
        if (numbers.empty())
          continue; // other blanks only (form feed, vertical tab): found by tests/fuzz
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

  std::string
  at2_text(const std::vector<double> &acceleration, const double dt, const std::string &title)
  {
    std::ostringstream out;
    out << "PEER-format record written by poundfe (not a recording)\n"
        << title.substr(0, title.find('\n')) << "\n"
        << "ACCELERATION TIME SERIES IN UNITS OF G\n"
        << "NPTS= " << acceleration.size() << ", DT= " << std::setprecision(17) << dt
        << " SEC\n";
    out << std::scientific << std::setprecision(8);
    for (std::size_t i = 0; i < acceleration.size(); ++i)
      out << (i % 5 ? " " : "") << std::setw(15) << acceleration[i] / standard_gravity
          << (i % 5 == 4 || i + 1 == acceleration.size() ? "\n" : "");
    return out.str();
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
