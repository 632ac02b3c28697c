// `poundfe bifurcation`: Poincare samples, periods and Lyapunov exponents against a parameter.
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/bifurcation.h>

namespace poundfe::commands
{
  int
  bifurcation(const CommandRun &run)
  {
    return bifurcation_command(*run.input, run.directory);
  }
} // namespace poundfe::commands
