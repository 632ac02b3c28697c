#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_file.h>
#include <poundfe/base/numbers.h>

#include <cmath>
#include <limits>
#include <filesystem>

namespace poundfe
{
  int
  InputFile::line_of(const std::string &path) const
  {
    const auto it = lines.find(path);
    return it == lines.end() ? 0 : it->second;
  }

  std::string
  InputFile::resolve(const std::string &relative) const
  {
    const std::filesystem::path path(relative);
    if (path.is_absolute() || directory.empty())
      return relative;
    return (std::filesystem::path(directory) / path).lexically_normal().string();
  }

  void
  InputFile::fail(const std::string &path, const std::string &problem) const
  {
    throw InputError(file, line_of(path), path, problem);
  }

  std::string
  InputFile::warning(const std::string &path, const std::string &problem) const
  {
    return InputError(file, line_of(path), path, problem).what();
  }

  namespace
  {
    /// A nonzero value below DBL_MIN (~2.2e-308) has lost its precision and
    /// makes later quotients overflow (a floor mass of 4.9e-324 kg gives no
    /// modes): refused where it is written, not where it breaks something.
    void
    refuse_denormal(const InputFile &input, const std::string &path, const double v)
    {
      if (v != 0 && std::abs(v) < std::numeric_limits<double>::min())
        input.fail(path, "got " + number_text(v) + ", below the smallest normal double (" +
                           number_text(std::numeric_limits<double>::min()) +
                           "): not a usable value");
    }
  } // namespace

  void
  InputFile::positive(const std::string &path, const double v) const
  {
    if (!(v > 0) || !std::isfinite(v))
      fail(path, "must be positive and finite, got " + number_text(v));
    refuse_denormal(*this, path, v);
  }

  void
  InputFile::non_negative(const std::string &path, const double v) const
  {
    if (!(v >= 0) || !std::isfinite(v))
      fail(path, "must be zero or positive, got " + number_text(v));
    refuse_denormal(*this, path, v);
  }

  void
  InputFile::at_most(const std::string &path, const double v, const double bound,
                     const std::string &unit, const std::string &why) const
  {
    if (!(std::abs(v) <= bound))
      fail(path, "got " + number_text(v) + (unit.empty() ? "" : " " + unit) + ", at most " +
                   number_text(bound) + (unit.empty() ? "" : " " + unit) + " in size (" + why +
                   ")");
  }

  void
  InputFile::list(const std::string &path, const std::vector<double> &values, const std::size_t n,
                  const bool allow_zero, const std::string &what) const
  {
    if (values.size() != 1 && values.size() != n)
      fail(path, "needs 1 value or " + std::to_string(n) + " (" + what + "), got " +
                   std::to_string(values.size()));
    for (const double v : values)
      allow_zero ? non_negative(path, v) : positive(path, v);
  }

  void
  InputFile::distinct(const std::string &path, const std::vector<double> &values) const
  {
    for (std::size_t i = 0; i < values.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (values[j] == values[i])
          fail(path, "lists " + number_text(values[i]) + " twice (values " + std::to_string(j + 1) +
                       " and " + std::to_string(i + 1) + "): give each once");
  }

  std::string
  trimmed(const std::string &text)
  {
    // Every character that `>>` skips (std::isspace in the C locale): an
    // item that is only a vertical tab or a form feed is empty here too, so
    // the words read from a non-empty item are never none.
    const char *const space = " \t\r\n\v\f";
    const auto        first = text.find_first_not_of(space);
    if (first == std::string::npos)
      return "";
    return text.substr(first, text.find_last_not_of(space) + 1 - first);
  }
} // namespace poundfe
