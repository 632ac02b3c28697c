// A command of the poundfe command line: what main.cc, the usage text and
// the output guard know of it (one row of the table in command_table.cc).
// A command reads its input, calls the engines and writes their results;
// engines never write files of their own accord.
#ifndef poundfe_commands_command_h
#define poundfe_commands_command_h

#include <mpi.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace poundfe
{
  struct InputParameters;

  /// What a command is given when it runs.
  struct CommandRun
  {
    /// The words after the command's name (`template frame`: {"frame"}).
    const std::vector<std::string> &arguments;
    /// The parameter file, read and checked; nullptr for a command that
    /// takes none (Command::reads_parameters false).
    const InputParameters *input;
    /// Where the results go (--output, else the file's Output/Directory).
    const std::string &directory;
    /// --realizations N (0: not given); only for Command::takes_realizations.
    const unsigned int n_realizations;
    /// MPI_COMM_WORLD for a command that runs over MPI (or whose linear
    /// solver initialised MPI), MPI_COMM_SELF otherwise.
    const MPI_Comm communicator;
    /// Where messages for the user go (silent on ranks other than 0).
    std::ostream &err;
    /// Where the command's report goes: standard output on the process
    /// that writes the results (writes_outputs()), silent on the others.
    std::ostream &out;
  };

  struct Command
  {
    /// The name on the command line: `poundfe NAME ...`.
    std::string name;
    /// What follows the name in the usage text ("FILE [--realizations N]").
    std::string arguments;
    /// One or more lines of the usage text (without indentation).
    std::string description;
    /// Takes exactly one parameter file, read before the command runs, with
    /// interruption and output errors handled by guard_command().
    bool reads_parameters = true;
    /// Splits its work over the MPI ranks (MPI initialised at start).
    bool runs_over_mpi = false;
    /// Finishes its own files on SIGINT/SIGTERM (polls
    /// interruption_requested()); otherwise it stops at the next safe point.
    bool handles_interruption_itself = false;
    /// Accepts --realizations N.
    bool takes_realizations = false;
    /// Runs the command; returns the exit status.
    int (*run)(const CommandRun &) = nullptr;
  };
} // namespace poundfe

#endif
