// `poundfe ground-motion`: the ground acceleration a run would use, or N realizations of it.
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/run.h>

namespace poundfe::commands
{
  int
  ground_motion(const CommandRun &run)
  {
    return ground_motion_command(*run.input, run.directory, run.n_realizations);
  }
} // namespace poundfe::commands
