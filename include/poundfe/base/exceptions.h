// Errors that reach the user. Bad input is an InputError (exit status 1), a
// numerical breakdown during a run is a NumericalError (exit status 2), a
// results file that cannot be written is an OutputError (exit status 1).
#ifndef poundfe_base_exceptions_h
#define poundfe_base_exceptions_h

#include <stdexcept>
#include <string>

namespace poundfe
{
  /// Bad input: names the file, the line where known, and the parameter.
  class InputError : public std::runtime_error
  {
  public:
    InputError(std::string file,
               int         line,
               std::string parameter,
               std::string problem);

    const std::string &file() const { return file_name; }
    int line() const { return line_number; }
    const std::string &parameter() const { return parameter_name; }
    const std::string &problem() const { return problem_text; }

  private:
    std::string file_name;
    int         line_number;
    std::string parameter_name;
    std::string problem_text;
  };

  /// A solver or integrator could not continue (e.g. singular matrix).
  class NumericalError : public std::runtime_error
  {
  public:
    explicit NumericalError(const std::string &what)
      : std::runtime_error(what)
    {}
  };

  /// A results file could not be written: "cannot <action> <path>: <the
  /// operating system's reason>", prefixed "disk full: " when it is (ENOSPC,
  /// EDQUOT), so the user sees at once what to free.
  class OutputError : public std::runtime_error
  {
  public:
    /// `error_number`: the errno of the failed call.
    OutputError(const std::string &action, const std::string &path, int error_number);
  };
} // namespace poundfe

#endif
