// `poundfe modal`: frequencies, periods, participating masses and mode shapes.
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/run.h>

namespace poundfe::commands
{
  int
  modal(const CommandRun &run)
  {
    return modal_command(prepare_analysis(*run.input), run.directory);
  }
} // namespace poundfe::commands
