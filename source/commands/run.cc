// `poundfe run`: the time history of the model, with every output of the Output section.
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/run.h>

namespace poundfe::commands
{
  int
  run(const CommandRun &run)
  {
    return run_command(prepare_analysis(*run.input), run.directory);
  }
} // namespace poundfe::commands
