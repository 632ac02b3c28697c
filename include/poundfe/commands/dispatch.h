// The one way a command of the table runs, shared by the command line
// (source/program.cc) and the Python module (poundfe.command): the command
// line checked against the row (its arguments, --realizations, --set), the
// parameter file read with the overrides, MPI started when the row or the
// input needs it, the input checked against the row's rules (a distributed
// solver on several ranks, Partition = buildings, field output), the ranks'
// agreement, then the command inside guard_command. The callers keep their
// own parsing and how they report: program.cc prints a message and exits with
// a status, Python raises the message as an exception.
#ifndef poundfe_commands_dispatch_h
#define poundfe_commands_dispatch_h

#include <poundfe/commands/command.h>
#include <poundfe/input/input_parameters.h>

#include <exception>
#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace poundfe
{
  /// What a caller asks of a command: the words after its name and the
  /// options.
  struct CommandRequest
  {
    /// The words after the command's name (the parameter file, a template's kind).
    std::vector<std::string> arguments;
    /// --output DIR ("": the file's Output/Directory).
    std::string output;
    /// --realizations N (0: not given).
    unsigned int n_realizations = 0;
    /// --set Section/Entry=value, in order: applied by the file's reader
    /// (read_parameters) before its checks.
    std::vector<ParameterOverride> overrides;
    /// --write-at2.
    bool write_at2 = false;
    /// The results in memory instead of an output directory (Python
    /// without output=; only for a row with CommandRule::in_memory): no
    /// file written, not even the guard's summary.
    MemoryResults *memory = nullptr;
  };

  /// A command line the command's row refuses (a wrong number of
  /// arguments, an option the command does not take): the message, and
  /// what the command line prints after it (the usage text, or ""). A
  /// std::invalid_argument, so Python sees a ValueError.
  class CommandLineError : public std::invalid_argument
  {
  public:
    explicit CommandLineError(const std::string &problem, std::string trailer = "");

    const std::string &
    trailer() const
    {
      return after;
    }

  private:
    std::string after;
  };

  /// How the caller starts MPI (with PETSc and Trilinos) when the row or
  /// the input needs it: program.cc from its own argc and argv, Python once
  /// per process. Called only while MPI is not initialised.
  using MpiStarter = std::function<void()>;

  /// Whether MPI must be initialised before the input is read, with
  /// `launched_processes` processes in mpirun's job: for a command that
  /// runs over MPI, and, under mpirun with several processes, for one that
  /// may spread one run over them (a distributed solver, Partition =
  /// buildings), so that the ranks can agree on their inputs before any of
  /// them starts collective work. (MPI_InitFinalize costs ~0.5 s: not for
  /// a serial run.)
  bool initialises_mpi_first(const Command &command, unsigned int launched_processes);

  /// Runs `command` as `request` asks and returns its exit status (that of
  /// a signal after its summary). Writes the command's report on standard
  /// output on the process that writes the results, its messages on `err`.
  /// A refusal throws before anything is written: CommandLineError,
  /// InputError (file, line, parameter), or what the reader throws; so do
  /// the guard's OutputError and NumericalError after their summary. Under
  /// MPI with several ranks a refusal on any rank is instead printed once by
  /// rank 0 on `err`, and every rank returns its status (rank_agreement.h).
  int dispatch_command(const Command &command, const CommandRequest &request,
                       const MpiStarter &start_mpi, std::ostream &err);

  /// A stream that drops what it is given: the messages and report of a
  /// rank that does not speak.
  std::ostream &silent_stream();

  /// What a command line says of what a command threw, and its exit status.
  struct CommandFailure
  {
    std::string  message; // "poundfe: error: ...\n" (CommandLineError: and its trailer)
    int          status = 1; // 1 a refusal or bad input, 2 a numerical failure,
                             // 128 + the signal for Interrupted
    /// Not one of poundfe's refusals (which every rank makes alike): any
    /// rank may have thrown it alone, so that rank says it.
    bool         any_rank = false;
  };

  /// The failure that `thrown` (dispatch_command's, or a command's) is
  /// (commands/command_failure.cc).
  CommandFailure command_failure(const std::exception_ptr &thrown);
} // namespace poundfe

#endif
