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

  OutputError::OutputError(const std::string &action, const std::string &path,
                           const int error_number)
    : std::runtime_error(
        std::string(error_number == ENOSPC || error_number == EDQUOT ? "disk full: " : "") +
        "cannot " + action + " " + path + ": " + std::strerror(error_number))
  {}
} // namespace poundfe
