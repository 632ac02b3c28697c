// `poundfe opensees SCRIPT [ARGS...]` without deal.II: the main of the
// module poundfe-opensees.so, which the executable (source/main.cc) loads
// for that command line instead of the program, poundfe-program.so. The
// interpreter and what it needs (CMakeLists.txt, POUNDFE_LEAN_SOURCES)
// reference nothing of deal.II, MPI, PETSc or Trilinos, whose ~200 shared
// libraries the program's loading costs (doc/benchmarks.md, "Start-up").
// It runs the command as the program's dispatcher does for a row that
// reads no parameter file (commands/dispatch.cc): the script and its
// arguments, no output directory, messages and exit statuses alike
// (commands/command_failure.cc). Under mpirun every rank runs the script
// (getPID and getNP say which and how many): rank 0 alone prints the
// warnings, which all ranks give alike; a failure is printed by every rank
// that has it (a script may differ per rank), "rank N: " before it on the
// ranks other than 0. SIGINT or SIGTERM stops the script at its next
// analysis step or Tcl's next safe point, through any `catch`
// (opensees_command.cc, CancelOnSignal): the recorders' temporaries are removed (no file of an unfinished script
// appears, as after an error) and the exit status is 128 + the signal.
#include <poundfe/base/interruption.h>
#include <poundfe/base/launched_job.h>
#include <poundfe/commands/command.h>
#include <poundfe/commands/dispatch.h>

#include <iostream>
#include <string>
#include <vector>

namespace poundfe
{
  namespace commands
  {
    int opensees(const CommandRun &); // opensees_command.cc
  } // namespace commands
} // namespace poundfe

/// The module's main, called by the executable with the whole command line
/// `poundfe opensees SCRIPT [ARGS...]` (SCRIPT no option: main.cc sends any
/// other command line to the program, which parses and refuses it).
extern "C" int
poundfe_opensees_main(int argc, char **argv)
{
  using namespace poundfe;
  const std::vector<std::string> arguments(argv + 2, argv + argc);
  const std::string              no_output_directory;
  std::ostream &err = launched_rank() == 0 ? std::cerr : silent_stream();
  install_interruption_handlers();
  try
    {
      // the communicator: none, as MPI is not loaded (the interpreter uses none)
      return commands::opensees(
        {arguments, nullptr, no_output_directory, 0, MPI_Comm(), err, std::cout});
    }
  catch (...)
    {
      const CommandFailure failure = command_failure(std::current_exception());
      std::cout.flush();
      std::cerr << from_this_rank(failure.message) << std::flush;
      return failure.status;
    }
}
