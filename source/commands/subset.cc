// `poundfe subset`: Subset Simulation of a small exceedance probability.
#include <poundfe/commands/command.h>
#include <poundfe/reliability/subset.h>

namespace poundfe::commands
{
  int
  subset(const CommandRun &run)
  {
    return subset_command(prepare_analysis(*run.input), run.directory, run.communicator);
  }
} // namespace poundfe::commands
