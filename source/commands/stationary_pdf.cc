// `poundfe stationary-pdf`: stationary densities of a noisy response.
#include <poundfe/commands/command.h>
#include <poundfe/reliability/stationary_pdf.h>

namespace poundfe::commands
{
  int
  stationary_pdf(const CommandRun &run)
  {
    return stationary_pdf_command(*run.input, run.directory, run.communicator);
  }
} // namespace poundfe::commands
