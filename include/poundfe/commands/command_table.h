// The one table of poundfe's commands (source/commands/command_table.cc):
// main.cc dispatches through it, the usage text is printed from it and the
// output guard asks it how a command stops. A new command is one file in
// source/commands/ and one row of the table.
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

  /// `poundfe --help`: the synopsis, every command of the table, the
  /// options, exit statuses and what a signal does.
  std::string usage_text();
} // namespace poundfe

#endif
