// `poundfe separation`: the joint width of adjacent buildings and P(pounding).
#include <poundfe/commands/command.h>
#include <poundfe/separation/separation.h>

namespace poundfe::commands
{
  int
  separation(const CommandRun &run)
  {
    return separation_command(*run.input, run.directory, run.communicator);
  }
} // namespace poundfe::commands
