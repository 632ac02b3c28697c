// `poundfe template`: a commented starting file on standard output.
#include <poundfe/commands/command.h>
#include <poundfe/input/templates.h>

#include <ostream>

namespace poundfe::commands
{
  int
  input_template(const CommandRun &run)
  {
    std::string kinds;
    for (const std::string &kind : template_kinds())
      kinds += (kinds.empty() ? "" : ", ") + kind;
    const std::string *text =
      run.arguments.size() == 1 ? poundfe::input_template(run.arguments[0]) : nullptr;
    if (text == nullptr)
      {
        run.err << "poundfe: error: 'template' needs one kind of model, one of: " << kinds
                << (run.arguments.size() == 1 ? " (not '" + run.arguments[0] + "')" : std::string())
                << "\n";
        return 1;
      }
    run.out << *text;
    return 0;
  }
} // namespace poundfe::commands
