// `poundfe montecarlo`: Monte Carlo over the random loading, on the MPI ranks.
#include <poundfe/commands/command.h>
#include <poundfe/reliability/montecarlo.h>

namespace poundfe::commands
{
  int
  montecarlo(const CommandRun &run)
  {
    return montecarlo_command(prepare_analysis(*run.input), run.directory, run.communicator);
  }
} // namespace poundfe::commands
