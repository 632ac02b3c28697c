// A command of the poundfe command line: what program.cc, the usage text and
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
  class MemoryResults;

  /// What a command is given when it runs.
  struct CommandRun
  {
    /// The words after the command's name (`template frame`: {"frame"}).
    const std::vector<std::string> &arguments;
    /// The parameter file, read and checked; nullptr for a command that
    /// takes none (no CommandRule::reads_file).
    const InputParameters *input;
    /// Where the results go (--output, else the file's Output/Directory).
    const std::string &directory;
    /// --realizations N (0: not given); only for CommandRule::takes_realizations.
    const unsigned int n_realizations;
    /// MPI_COMM_WORLD for a command that runs over MPI (or whose linear
    /// solver initialised MPI), MPI_COMM_SELF otherwise.
    const MPI_Comm communicator;
    /// Where messages for the user go (silent on ranks other than 0).
    std::ostream &err;
    /// Where the command's report goes: standard output on the process
    /// that writes the results (writes_outputs()), silent on the others.
    std::ostream &out;
    /// --write-at2; only for CommandRule::writes_at2.
    const bool write_at2 = false;
    /// Where the results go instead of `directory` (Python without
    /// output=): each file's text or table by name, nothing written, no
    /// figure drawn; nullptr: into `directory`. Only for
    /// CommandRule::in_memory.
    MemoryResults *const memory = nullptr;

    /// Where the report says the results are: "DIR/", or "memory".
    std::string
    results_place() const
    {
      return memory ? std::string("memory") : directory + "/";
    }
  };

  /// One rule of a command: a column of the command table. A row lists the
  /// rules it has (`CommandRule::reads_file | CommandRule::resumable`); the
  /// dispatcher (dispatch.h), the usage text and the guard ask the row,
  /// never the command's name.
  enum class CommandRule : unsigned
  {
    /// Takes exactly one parameter file, read (with --set's overrides)
    /// before the command runs, with interruption and output errors
    /// handled by guard_command().
    reads_file = 1u << 0,
    /// Splits its work over the MPI ranks (MPI initialised at start).
    over_mpi = 1u << 1,
    /// Finishes its own files on SIGINT/SIGTERM (polls
    /// interruption_requested()); otherwise it stops at the next safe point.
    own_interruption = 1u << 2,
    /// Accepts --realizations N.
    takes_realizations = 1u << 3,
    /// May use a linear solver that spreads one run over the ranks
    /// (petsc-mumps, ...) on more than one rank; the others give each rank
    /// its own runs.
    distributed_solver = 1u << 4,
    /// May take Time integration/Partition = buildings (one run, a rank's
    /// buildings on each rank).
    partition_by_building = 1u << 5,
    /// Writes fields (VTU, or HDF5 + XDMF with Output/Field format = xdmf).
    field_output = 1u << 6,
    /// Resumes from the table an earlier run left in its output directory.
    resumable = 1u << 7,
    /// Takes a script and its own arguments: the words after the script
    /// go to it as they are (options included), never to poundfe.
    script_arguments = 1u << 8,
    /// Accepts --write-at2 (generated records as PEER AT2 files).
    writes_at2 = 1u << 9,
    /// Can leave its results in memory (CommandRun::memory) instead of
    /// files: what Python's call of the command gets without output=.
    in_memory = 1u << 10,
    /// May take Contact/Model = nonsmooth (rigid contact, Moreau-Jean).
    rigid_contact = 1u << 11,
  };

  /// A set of rules, written `CommandRule::a | CommandRule::b`.
  class CommandRules
  {
  public:
    constexpr CommandRules() = default;
    /// Not explicit: one rule is a set of one.
    constexpr CommandRules(const CommandRule rule)
      : bits(static_cast<unsigned>(rule))
    {}

    constexpr bool
    has(const CommandRule rule) const
    {
      return (bits & static_cast<unsigned>(rule)) != 0;
    }

    friend constexpr CommandRules
    operator|(CommandRules a, const CommandRules b)
    {
      a.bits |= b.bits;
      return a;
    }

  private:
    unsigned bits = 0;
  };

  constexpr CommandRules
  operator|(const CommandRule a, const CommandRule b)
  {
    return CommandRules(a) | CommandRules(b);
  }

  struct Command
  {
    /// The name on the command line: `poundfe NAME ...`.
    std::string name;
    /// What follows the name in the usage text ("FILE [--realizations N]").
    std::string arguments;
    /// One or more lines of the usage text (without indentation).
    std::string description;
    /// What it may be given and what it does (CommandRule).
    CommandRules rules;
    /// The file the guard writes when the command stops early, and whose
    /// status it turns into "completed with warnings" ("summary.json"; ""
    /// for a command that reads no file and runs unguarded).
    std::string summary;
    /// Runs the command; returns the exit status.
    int (*run)(const CommandRun &) = nullptr;
    /// Without CommandRule::rigid_contact, what in the command's method
    /// rigid contact cannot give (the refusal of Contact/Model = nonsmooth
    /// says it); empty: not taken yet.
    std::string without_rigid_contact = {};

    bool
    has(const CommandRule rule) const
    {
      return rules.has(rule);
    }
  };
} // namespace poundfe

#endif
