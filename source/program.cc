// poundfe command line: poundfe <command> [FILE] [--output DIR] [--set
// Section/Entry=value]... Parses the command line and turns what the shared
// dispatcher (commands/dispatch.h) returns or throws into messages and exit
// statuses. Compiled into the program module poundfe-program.so, which the
// executable (source/main.cc) loads for every command line but a lone
// --version.
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/launched_job.h>
#include <poundfe/base/thread_limit.h>
#include <poundfe/commands/command_table.h>
#include <poundfe/commands/dispatch.h>

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
  /// "poundfe (git REVISION), deal.II VERSION", written by scripts/revision.cmake at build time.
  extern const char *const version_line;
} // namespace poundfe

namespace
{
  /// The arguments without the options, and the options' values.
  struct CommandLine
  {
    std::vector<std::string> args;
    poundfe::CommandRequest  request; // its arguments are args without the command's name
    std::string              error;   // not empty: the message for bad options
    bool                     help    = false;
    bool                     version = false;
    /// --threads: deal.II's (TBB's) thread limit, 1 unless given.
    unsigned int threads       = 1;
    bool         threads_given = false;
  };

  /// An option's whole-number value in [1, largest], written in decimal
  /// digits alone (no blank, sign or leading zero, which std::stol would
  /// pass), or 0 with the message in line.error.
  long
  whole_number_option(const std::string &option, const std::string &text, const long largest,
                      CommandLine &line)
  {
    const bool  digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos &&
                        text[0] != '0';
    std::size_t end    = 0;
    long        n      = 0;
    try
      {
        if (digits)
          n = std::stol(text, &end);
      }
    catch (const std::exception &)
      {
        end = 0;
      }
    if (digits && end == text.size() && n >= 1 && n <= largest)
      return n;
    line.error = "poundfe: error: " + option + " needs a whole number in 1.." +
                 std::to_string(largest) + ", got '" + text + "'\n";
    return 0;
  }

  /// --threads's value: deal.II's (TBB's) thread limit, 1..256.
  void
  parse_threads(const std::string &text, CommandLine &line)
  {
    line.threads_given = true;
    if (const long n = whole_number_option("--threads", text, 256, line))
      line.threads = n;
  }

  /// --realizations's value: 1..100000.
  void
  parse_realizations(const std::string &text, CommandLine &line)
  {
    if (const long n = whole_number_option("--realizations", text, 100000, line))
      line.request.n_realizations = n;
  }

  /// --set's value: "Section/Entry=value" (split at the first '=': no
  /// entry's name holds one), an override for the file's reader.
  void
  parse_set(const std::string &text, CommandLine &line)
  {
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0)
      line.error = "poundfe: error: --set needs Section/Entry=value, got '" + text + "'\n";
    else
      line.request.overrides.push_back({text.substr(0, equals), text.substr(equals + 1)});
  }

  /// Whether args[script] is the script of a command whose row takes a
  /// script and its own arguments (the first word that is no option names
  /// the command).
  bool
  takes_script_arguments(const std::vector<std::string> &args, const std::size_t script)
  {
    for (std::size_t i = 0; i < script; ++i)
      if (!(args[i].size() > 1 && args[i][0] == '-'))
        {
          const poundfe::Command *command = poundfe::find_command(args[i]);
          return command && command->has(poundfe::CommandRule::script_arguments);
        }
    return false;
  }

  CommandLine
  parse_command_line(std::vector<std::string> args)
  {
    CommandLine           line;
    std::string           realizations, threads;
    std::set<std::string> given; // the options seen (-h is --help)
    std::size_t           words = 0; // the words that are no option, so far
    for (std::size_t i = 0; i < args.size() && line.error.empty(); ++i)
      {
        const bool        option = args[i].size() > 1 && args[i][0] == '-';
        if (!option && ++words == 2 && takes_script_arguments(args, i))
          break; // the script's own arguments follow

        const std::string name   = args[i] == "-h" ? "--help" : args[i];
        if (option && name != "--set" && !given.insert(name).second)
          // which of two values was meant cannot be known (--set: each is applied, in order)
          line.error = "poundfe: error: " + name + " is given twice (see poundfe --help)\n";
        else if (name == "--output" || name == "--realizations" || name == "--set" ||
                 name == "--threads")
          {
            if (i + 1 >= args.size() || args[i + 1].empty())
              line.error = "poundfe: error: " + name + " needs a value (see poundfe --help)\n";
            else if (name == "--set")
              parse_set(args[i + 1], line);
            else
              (name == "--output" ? line.request.output :
               name == "--threads" ? threads : realizations) = args[i + 1];
            args.erase(args.begin() + i, args.begin() + std::min(i + 2, args.size()));
            --i;
          }
        else if (name == "--help")
          line.help = true;
        else if (name == "--write-at2")
          { // a switch: no value, and not a word of the command
            line.request.write_at2 = true;
            args.erase(args.begin() + i);
            --i;
          }
        else if (name == "--version")
          line.version = true;
        else if (option)
          line.error = "poundfe: error: unknown option '" + args[i] + "' (see poundfe --help)\n";
      }
    if (!line.error.empty())
      return line;
    line.args = std::move(args);
    if (line.args.size() > 1)
      line.request.arguments.assign(line.args.begin() + 1, line.args.end());
    if (!realizations.empty())
      parse_realizations(realizations, line);
    if (!threads.empty() && line.error.empty())
      parse_threads(threads, line);
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
        std::cout << version_line << "\n";
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
    if (line.threads_given && !command->has(CommandRule::reads_file) &&
        !command->has(CommandRule::script_arguments))
      { // a command that reads neither a parameter file nor a script runs no time history
        err << "poundfe: error: --threads sets the threads of a time history's elements, and '"
            << command->name << "' reads no parameter file or script and runs none\n";
        return 1;
      }
    return std::nullopt;
  }

  /// The exit status of what dispatch_command threw, after its message on
  /// `err`: 1 for a refused command line or bad input, 2 for a numerical
  /// failure. The message goes in one write after the report is flushed:
  /// mpirun forwards every write of a rank as it comes, and a message
  /// written in pieces could be split by lines of the report. A script's
  /// failure (`script` true: the OpenSees interpreter, whose ranks may run
  /// differently) is printed by every rank that has it, as
  /// opensees_program.cc does.
  int
  exit_status_of(const std::exception_ptr &thrown,
                 std::ostream             &err,
                 const bool                several_ranks,
                 const bool                script)
  {
    const poundfe::CommandFailure failure = poundfe::command_failure(thrown);
    std::cout.flush();
    if (script)
      std::cerr << poundfe::from_this_rank(failure.message) << std::flush;
    else
      (failure.any_rank ? std::cerr : err) << failure.message << std::flush;
    if (failure.any_rank && several_ranks)
      MPI_Abort(MPI_COMM_WORLD, 1);
    return failure.status;
  }
} // namespace

/// The program's main, called by the executable (source/main.cc) once it
/// has loaded this module.
extern "C" int
poundfe_program_main(int argc, char **argv)
{
  using namespace poundfe;
  const CommandLine line = parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
  const Command    *command = line.args.empty() ? nullptr : find_command(line.args[0]);
  // MPI_InitFinalize (MPI, PETSc, Trilinos) costs ~0.5 s at start: only the
  // commands whose row asks for it (dispatch.h) initialise it here, and any
  // command whose input needs it once the input is read.
  std::optional<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  if (command && initialises_mpi_first(*command, launched_size()))
    mpi.emplace(argc, argv, line.threads);
  else
    // what MPI_InitFinalize(argc, argv, threads) sets: one thread unless --threads
    dealii::MultithreadInfo::set_thread_limit(line.threads);
  poundfe::set_thread_limit(line.threads); // the same for the parts built without deal.II
  dealii::deal_II_exceptions::disable_abort_on_exception();
  // Rank 0 speaks (also before MPI is initialised): the ranks agree on their
  // inputs before a command runs, and rank 0 prints any rank's refusal.
  const bool    root = mpi ? dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 :
                             launched_rank() == 0;
  std::ostream &err  = root ? std::cerr : silent_stream();
  if (const std::optional<int> status = answer_without_command(line, command, err))
    return *status;
  // Every command that writes files stops cleanly on SIGINT/SIGTERM: at its
  // own safe points, or at the next file write (commands/command_guard.h);
  // an OpenSees script at its next command or step (opensees_program.cc).
  if (command->has(CommandRule::reads_file) || command->has(CommandRule::script_arguments))
    install_interruption_handlers();
  const MpiStarter start_mpi = [&]() {
    mpi.emplace(argc, argv, line.threads);
    install_interruption_handlers(); // PETSc's initialisation replaced them
  };
  try
    {
      return dispatch_command(*command, line.request, start_mpi, err);
    }
  catch (...)
    {
      return exit_status_of(std::current_exception(), err,
                            mpi && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1,
                            command->has(CommandRule::script_arguments));
    }
}
