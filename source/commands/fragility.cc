// `poundfe fragility`: Monte Carlo over PGA levels and lognormal fragility curves.
#include <poundfe/commands/command.h>
#include <poundfe/reliability/montecarlo.h>

namespace poundfe::commands
{
  int
  fragility(const CommandRun &run)
  {
    return fragility_command(prepare_analysis(*run.input), run.directory, run.communicator);
  }
} // namespace poundfe::commands
