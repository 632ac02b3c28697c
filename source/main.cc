// poundfe command line: poundfe <command> [FILE] [--output DIR]
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/commands/command_guard.h>
#include <poundfe/commands/command_table.h>
#include <poundfe/commands/rank_agreement.h>
#include <poundfe/input/input_parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace poundfe
{
  /// `git describe` of the sources, written by scripts/revision.cmake at build time.
  extern const char *const git_revision;
} // namespace poundfe

namespace
{
  /// Where the ranks other than 0 send their messages.
  std::ostream silent(nullptr);

  /// The arguments without the options, and the options' values.
  struct CommandLine
  {
    std::vector<std::string> args;
    std::string              output;
    unsigned int             n_realizations = 0;
    std::string              error; // not empty: the message for bad options
    bool                     help    = false;
    bool                     version = false;
  };

  CommandLine
  parse_command_line(std::vector<std::string> args)
  {
    CommandLine           line;
    std::string           realizations;
    std::set<std::string> given; // the options seen (-h is --help)
    for (std::size_t i = 0; i < args.size(); ++i)
      {
        const bool        option = args[i].size() > 1 && args[i][0] == '-';
        const std::string name   = args[i] == "-h" ? "--help" : args[i];
        if (option && !given.insert(name).second)
          {
            // which of two values was meant cannot be known
            line.error = "poundfe: error: " + name + " is given twice (see poundfe --help)\n";
            return line;
          }
        if (args[i] == "--output" || args[i] == "--realizations")
          {
            if (i + 1 >= args.size() || args[i + 1].empty())
              {
                line.error = "poundfe: error: " + args[i] + " needs a value (see poundfe --help)\n";
                return line;
              }
            (args[i] == "--output" ? line.output : realizations) = args[i + 1];
            args.erase(args.begin() + i, args.begin() + i + 2);
            --i;
          }
        else if (name == "--help")
          line.help = true;
        else if (args[i] == "--version")
          line.version = true;
        else if (option)
          {
            line.error = "poundfe: error: unknown option '" + args[i] + "' (see poundfe --help)\n";
            return line;
          }
      }
    line.args = std::move(args);
    if (!realizations.empty())
      {
        std::size_t end = 0;
        long        n   = 0;
        try
          {
            n = std::stol(realizations, &end);
          }
        catch (const std::exception &)
          {
            end = 0;
          }
        if (end != realizations.size() || n < 1 || n > 100000)
          line.error = "poundfe: error: --realizations needs a whole number in 1..100000, got '" +
                       realizations + "'\n";
        else
          line.n_realizations = n;
      }
    return line;
  }

  /// The answer to a command line that runs no command (a bad option,
  /// --version, --help, no or an unknown command): its exit status, after
  /// printing what it says; nothing when a command is to run.
  std::optional<int>
  answer_without_command(const CommandLine &line, const poundfe::Command *command, std::ostream &err)
  {
    using namespace poundfe;
    if (!line.error.empty())
      {
        err << line.error;
        return 1;
      }
    if (line.version)
      {
        std::cout << "poundfe (git " << git_revision << "), deal.II " << DEAL_II_PACKAGE_VERSION
                  << "\n";
        return 0;
      }
    if (line.args.empty() || line.help)
      {
        (line.help ? std::cout : err) << usage_text();
        return line.help ? 0 : 1;
      }
    if (command == nullptr)
      {
        err << "poundfe: error: unknown command '" << line.args[0] << "'\n" << usage_text();
        return 1;
      }
    return std::nullopt;
  }

  /// This process's rank in mpirun's job before MPI is initialised (Open
  /// MPI's, MPICH's and PMIx's launchers say it in the environment); 0 when
  /// launched alone.
  int
  launched_rank()
  {
    for (const char *name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
      if (const char *rank = std::getenv(name))
        return std::atoi(rank);
    return 0;
  }

  /// The number of processes of mpirun's job before MPI is initialised (Open
  /// MPI's and MPICH's launchers say it); 1 when launched alone.
  int
  launched_size()
  {
    for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
      if (const char *size = std::getenv(name))
        return std::max(1, std::atoi(size));
    return 1;
  }

  /// Whether MPI is initialised before the input is read: for a command
  /// that runs over MPI, and for run under mpirun with several processes
  /// (its input may partition it by building or choose a distributed
  /// solver): the ranks must be able to agree on their inputs before any
  /// of them starts collective work, also when one of them cannot read its
  /// own. (MPI_InitFinalize costs ~0.5 s: not for a serial run.)
  bool
  initialises_mpi_first(const poundfe::Command &command)
  {
    return command.runs_over_mpi || (command.name == "run" && launched_size() > 1);
  }

  /// Refuses (InputError at the entry's line) an input that asks for what
  /// the command cannot do: a distributed linear solver on several ranks, or
  /// Partition = buildings, for anything but `run` (the probabilistic
  /// commands give each rank its own realizations), XDMF fields from a
  /// command that writes no fields.
  void
  check_command_takes_input(const poundfe::Command        &command,
                            const poundfe::InputParameters &input,
                            const bool                      several_ranks)
  {
    using namespace poundfe;
    if (several_ranks && linear_solver_is_distributed(input.time_integration.linear_solver) &&
        command.name != "run")
      input.fail("Time integration/Linear solver",
                 input.time_integration.linear_solver + " spreads one run over the MPI ranks: "
                 "on more than one rank only 'run' can use it, not '" + command.name + "'");
    if (input.time_integration.partition == RunPartition::buildings && command.name != "run")
      input.fail("Time integration/Partition",
                 "buildings spreads one run over the MPI ranks: only 'run' takes it, not '" +
                   command.name + "'");
    // Only run (the frames) and modal (the modes) write fields.
    if (input.output.field_format == FieldFormat::xdmf && command.name != "run" &&
        command.name != "modal")
      input.fail("Output/Field format",
                 "xdmf chooses the field output of 'run' and 'modal'; '" + command.name +
                   "' writes no fields (leave it at vtu)");
  }

  /// The input of `command`: the parameter file read and checked against
  /// the command and the command line, MPI initialised when its input needs
  /// it. Throws InputError (or what the reader throws).
  poundfe::InputParameters
  read_command_input(const poundfe::Command &command, const CommandLine &line,
                     std::optional<dealii::Utilities::MPI::MPI_InitFinalize> &mpi, int &argc,
                     char **&argv)
  {
    using namespace poundfe;
    InputParameters input = read_parameters(line.args[1]);
    if (!mpi && (linear_solver_needs_mpi(input.time_integration.linear_solver) ||
                 input.time_integration.partition == RunPartition::buildings))
      {
        mpi.emplace(argc, argv, 1);
        install_interruption_handlers(); // PETSc's initialisation replaced them
      }
    check_command_takes_input(command, input,
                              mpi && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1);
    return input;
  }

  /// What this process read before the command runs (rank_agreement.h):
  /// `input` set, or the status and message of the failure.
  poundfe::RankInput
  read_rank_input(const poundfe::Command &command, const CommandLine &line,
                  std::optional<dealii::Utilities::MPI::MPI_InitFinalize> &mpi, int &argc,
                  char **&argv, std::optional<poundfe::InputParameters> &input)
  {
    using namespace poundfe;
    if (line.args.size() != 2)
      return {1, "poundfe: error: ", "'" + command.name + "' needs exactly one parameter file",
              usage_text(), {}};
    if (line.n_realizations > 0 && !command.takes_realizations)
      return {1, "poundfe: error: ", "--realizations belongs to ground-motion and spectrum", "", {}};
    try
      {
        input.emplace(read_command_input(command, line, mpi, argc, argv));
        return {};
      }
    catch (const InputError &e)
      {
        return {1, "poundfe: error: ", e.what(), "", {}};
      }
    catch (const NumericalError &e)
      {
        return {2, "poundfe: numerical failure: ", e.what(), "", {}};
      }
    catch (const std::exception &e)
      {
        return {1, "poundfe: error: ", e.what(), "", {}};
      }
  }

  /// Nothing when the input was read (by every rank, and the same, under
  /// MPI); otherwise the exit status, after one message on `err`.
  std::optional<int>
  refusal(poundfe::RankInput &rank, const std::optional<poundfe::InputParameters> &input,
          const CommandLine &line, const bool mpi, std::ostream &err)
  {
    using namespace poundfe;
    if (mpi && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      {
        if (rank.status == 0)
          rank.items = input_items(line.args[0], line.output, line.n_realizations, *input);
        return ranks_disagree(rank, MPI_COMM_WORLD, err);
      }
    if (rank.status == 0)
      return std::nullopt;
    err << rank.prefix << rank.problem << "\n" << rank.trailer;
    return rank.status;
  }

} // namespace

int
main(int argc, char **argv)
{
  using namespace poundfe;
  const CommandLine line = parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
  const Command    *command = line.args.empty() ? nullptr : find_command(line.args[0]);
  // MPI_InitFinalize (MPI, PETSc, Trilinos) costs ~0.5 s at start: only the
  // commands that run over MPI (and run under mpirun) initialise it here,
  // and any command whose linear solver needs it once the input is read.
  std::optional<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  if (command && command->reads_parameters && initialises_mpi_first(*command))
    mpi.emplace(argc, argv, 1);
  else
    dealii::MultithreadInfo::set_thread_limit(1); // what MPI_InitFinalize(argc, argv, 1) sets
  dealii::deal_II_exceptions::disable_abort_on_exception();
  // Rank 0 speaks (also before MPI is initialised): the ranks agree on their
  // inputs before a command runs, and rank 0 prints any rank's refusal.
  const bool    root = mpi ? dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 :
                             launched_rank() == 0;
  std::ostream &err  = root ? std::cerr : silent;
  if (const std::optional<int> status = answer_without_command(line, command, err))
    return *status;
  const std::vector<std::string> arguments(line.args.begin() + 1, line.args.end());
  if (!command->reads_parameters) // print-parameters, template
    return command->run({arguments, nullptr, line.output, 0, MPI_COMM_SELF, err, std::cout});
  // Every command that writes files stops cleanly on SIGINT/SIGTERM: at its
  // own safe points, or at the next file write (commands/command_guard.h).
  install_interruption_handlers();
  std::optional<InputParameters> read;
  RankInput rank = read_rank_input(*command, line, mpi, argc, argv, read);
  if (const std::optional<int> status = refusal(rank, read, line, mpi.has_value(), err))
    return *status;
  const InputParameters &input = *read;
  try
    {
      const std::string directory = line.output.empty() ? input.output.directory : line.output;
      const bool writes = !mpi || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      const GuardedCommand guarded{
        command->name, input, directory, writes, !command->handles_interruption_itself};
      return guard_command(guarded, [&]() -> int {
        return command->run({arguments, &input, directory, line.n_realizations,
                             mpi ? MPI_COMM_WORLD : MPI_COMM_SELF, err,
                             writes ? std::cout : silent});
      });
    }
  catch (const InputError &e)
    {
      err << "poundfe: error: " << e.what() << "\n";
      return 1;
    }
  catch (const NumericalError &e)
    {
      err << "poundfe: numerical failure: " << e.what() << "\n";
      return 2;
    }
  catch (const std::exception &e)
    {
      // not necessarily on every rank: the others may wait forever
      std::cerr << "poundfe: error: " << e.what() << "\n";
      if (mpi && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    }
}
