// `poundfe sweep`: the run's peaks against the values of one parameter.
#include <poundfe/commands/command.h>
#include <poundfe/input/sweep.h>

namespace poundfe::commands
{
  int
  sweep(const CommandRun &run)
  {
    return sweep_command(*run.input, run.directory);
  }
} // namespace poundfe::commands
