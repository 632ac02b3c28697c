// The one table of poundfe's commands (source/commands/command_table.cc):
// one row per command, its rules as columns (CommandRule, command.h). The
// dispatcher shared by the command line and Python (dispatch.h) checks a
// row's rules, the usage text is printed from the table and the output
// guard asks the row how the command stops and which summary it leaves. A
// new command is one file in source/commands/ and one row of the table.
#ifndef poundfe_commands_command_table_h
#define poundfe_commands_command_table_h

#include <poundfe/commands/command.h>

#include <string>
#include <vector>

namespace poundfe
{
  /// Every command, in the order of the usage text.
  const std::vector<Command> &command_table();

  /// The command called `name`, or nullptr.
  const Command *find_command(const std::string &name);

  /// The names of the commands with `rule`, each between `quote`s, as
  /// "a, b and c" (for messages and the usage text).
  std::string command_names(CommandRule rule, const std::string &quote = "");

  /// `poundfe --help`: the synopsis, every command of the table, the
  /// options, exit statuses and what a signal does.
  std::string usage_text();
} // namespace poundfe

#endif
