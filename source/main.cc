// poundfe command line: poundfe <command> [FILE] [--output DIR]
#include <poundfe/analysis/analysis.h>
#include <poundfe/analysis/montecarlo.h>
#include <poundfe/analysis/subset.h>
#include <poundfe/analysis/run.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/model/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <iostream>
#include <string>
#include <vector>

namespace
{
  /// Where the ranks other than 0 send their messages.
  std::ostream silent(nullptr);

  const char *usage =
    "usage: poundfe <command> [FILE] [--output DIR]\n"
    "commands:\n"
    "  run FILE            time-history analysis (summary.json, CSV, VTU, PNG)\n"
    "  modal FILE          frequencies, periods, participating masses, modes.pvd\n"
    "  ground-motion FILE [--realizations N]\n"
    "                      the ground acceleration a run would use (CSV, PNG); with N,\n"
    "                      realizations 0..N-1 and their ensemble PSD against the target\n"
    "  montecarlo FILE     Monte Carlo over the random loading (MPI: mpirun -np P ...)\n"
    "  subset FILE         Subset Simulation of a small exceedance probability (MPI)\n"
    "  fragility FILE      Monte Carlo over PGA levels, lognormal fragility curves (MPI)\n"
    "  print-parameters    every parameter with its documentation and default\n"
    "--output DIR overrides the file's 'Output/Directory'.\n";
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::deal_II_exceptions::disable_abort_on_exception();
  // Every rank reads the same input and fails the same way: rank 0 speaks.
  const bool               root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ostream            &err  = root ? std::cerr : silent;
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string              output, realizations;
  for (std::size_t i = 0; i < args.size(); ++i)
    if (args[i] == "--output" || args[i] == "--realizations")
      {
        if (i + 1 >= args.size())
          {
            err << "poundfe: error: " << args[i] << " needs a value\n" << usage;
            return 1;
          }
        (args[i] == "--output" ? output : realizations) = args[i + 1];
        args.erase(args.begin() + i, args.begin() + i + 2);
        --i;
      }
  unsigned int n_realizations = 0;
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
        {
          err << "poundfe: error: --realizations needs a whole number in 1..100000, got '"
              << realizations << "'\n";
          return 1;
        }
      n_realizations = n;
    }
  if (args.empty() || args[0] == "--help" || args[0] == "-h")
    {
      std::cout << usage;
      return args.empty() ? 1 : 0;
    }
  const std::string command = args[0];
  try
    {
      if (command == "print-parameters")
        {
          poundfe::print_parameters(std::cout);
          return 0;
        }
      if (command != "run" && command != "modal" && command != "ground-motion" &&
          command != "montecarlo" && command != "subset" && command != "fragility")
        {
          err << "poundfe: error: unknown command '" << command << "'\n" << usage;
          return 1;
        }
      if (args.size() != 2)
        {
          err << "poundfe: error: '" << command << "' needs exactly one parameter file\n"
                    << usage;
          return 1;
        }
      const poundfe::InputParameters input = poundfe::read_parameters(args[1]);
      const std::string directory = output.empty() ? input.output_directory : output;
      if (command == "ground-motion")
        return poundfe::ground_motion_command(input, directory, n_realizations);
      if (n_realizations > 0)
        {
          err << "poundfe: error: --realizations belongs to ground-motion\n";
          return 1;
        }
      const poundfe::Analysis analysis = poundfe::prepare_analysis(input);
      if (command == "modal")
        return poundfe::modal_command(analysis, directory);
      if (command == "montecarlo")
        return poundfe::montecarlo_command(analysis, directory, MPI_COMM_WORLD);
      if (command == "subset")
        return poundfe::subset_command(analysis, directory, MPI_COMM_WORLD);
      if (command == "fragility")
        return poundfe::fragility_command(analysis, directory, MPI_COMM_WORLD);
      return poundfe::run_command(analysis, directory);
    }
  catch (const poundfe::InputError &e)
    {
      err << "poundfe: error: " << e.what() << "\n";
      return 1;
    }
  catch (const poundfe::NumericalError &e)
    {
      err << "poundfe: numerical failure: " << e.what() << "\n";
      return 2;
    }
  catch (const std::exception &e)
    {
      // not necessarily on every rank: the others may wait forever
      std::cerr << "poundfe: error: " << e.what() << "\n";
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    }
}
