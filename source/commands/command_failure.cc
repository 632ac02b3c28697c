// What the command line says of a command's exception and with which exit
// status (commands/dispatch.h): shared by the program (program.cc) and the
// OpenSees interpreter's module (opensees_program.cc), which links without
// deal.II, so this file needs none of it.
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/commands/dispatch.h>

#include <ostream>

namespace poundfe
{
  CommandLineError::CommandLineError(const std::string &problem, std::string trailer)
    : std::invalid_argument(problem)
    , after(std::move(trailer))
  {}

  std::ostream &
  silent_stream()
  {
    static std::ostream silent(nullptr);
    return silent;
  }

  CommandFailure
  command_failure(const std::exception_ptr &thrown)
  {
    CommandFailure failure;
    try
      {
        std::rethrow_exception(thrown);
      }
    catch (const CommandLineError &e)
      {
        failure.message = "poundfe: error: " + std::string(e.what()) + "\n" + e.trailer();
      }
    catch (const InputError &e)
      {
        failure.message = "poundfe: error: " + std::string(e.what()) + "\n";
      }
    catch (const NumericalError &e)
      {
        failure.message = "poundfe: numerical failure: " + std::string(e.what()) + "\n";
        failure.status  = 2;
      }
    catch (const Interrupted &e) // the OpenSees interpreter's (the guarded commands catch theirs)
      {
        failure.message = "poundfe: " + std::string(e.what()) + "\n";
        failure.status  = interrupted_exit_status();
      }
    catch (const std::exception &e)
      {
        failure.message  = "poundfe: error: " + std::string(e.what()) + "\n";
        failure.any_rank = true;
      }
    return failure;
  }
} // namespace poundfe
