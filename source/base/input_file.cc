#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_file.h>

#include <cmath>
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

  void
  InputFile::positive(const std::string &path, const double v) const
  {
    if (!(v > 0) || !std::isfinite(v))
      fail(path, "must be positive and finite, got " + std::to_string(v));
  }

  void
  InputFile::non_negative(const std::string &path, const double v) const
  {
    if (!(v >= 0) || !std::isfinite(v))
      fail(path, "must be zero or positive, got " + std::to_string(v));
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

  std::string
  trimmed(const std::string &text)
  {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos)
      return "";
    return text.substr(first, text.find_last_not_of(" \t\r") + 1 - first);
  }
} // namespace poundfe
