#include <poundfe/base/exceptions.h>

#include <cerrno>
#include <cstring>

namespace poundfe
{
  namespace
  {
    std::string
    compose(const std::string &file,
            const int          line,
            const std::string &parameter,
            const std::string &problem)
    {
      std::string text = file.empty() ? std::string("input") : file;
      if (line > 0)
        text += ":" + std::to_string(line);
      text += ": ";
      if (!parameter.empty())
        text += "parameter '" + parameter + "': ";
      return text + problem;
    }
  } // namespace

  InputError::InputError(std::string file,
                         const int   line,
                         std::string parameter,
                         std::string problem)
    : std::runtime_error(compose(file, line, parameter, problem))
    , file_name(std::move(file))
    , line_number(line)
    , parameter_name(std::move(parameter))
    , problem_text(std::move(problem))
  {}

  namespace
  {
    /// The cause first where the user has to act on it: the disk, the
    /// permissions, a read-only file system.
    std::string
    compose_output_error(const std::string &action, const std::string &path,
                         const int error_number)
    {
      const std::string what = "cannot " + action + " " + path;
      if (error_number == ENOSPC || error_number == EDQUOT)
        return "disk full: " + what + ": " + std::strerror(error_number);
      if (error_number == EACCES || error_number == EPERM)
        return "permission denied: " + what;
      if (error_number == EROFS)
        return "read-only file system: " + what;
      return what + ": " + std::strerror(error_number);
    }
  } // namespace

  OutputError::OutputError(const std::string &action, const std::string &path,
                           const int error_number)
    : std::runtime_error(compose_output_error(action, path, error_number))
  {}
} // namespace poundfe
