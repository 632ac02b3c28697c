// `poundfe print-parameters`: every parameter with its documentation and default.
#include <poundfe/commands/command.h>
#include <poundfe/input/input_parameters.h>

#include <ostream>

namespace poundfe::commands
{
  int
  print_parameters(const CommandRun &run)
  {
    if (!run.arguments.empty())
      {
        run.err << "poundfe: error: 'print-parameters' takes no argument, got '"
                << run.arguments[0] << "'\n";
        return 1;
      }
    poundfe::print_parameters(run.out);
    return 0;
  }
} // namespace poundfe::commands
