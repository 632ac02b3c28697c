// poundfe command line: poundfe <command> [FILE] [--output DIR]
#include <poundfe/analysis/analysis.h>
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
  const char *usage =
    "usage: poundfe <command> [FILE] [--output DIR]\n"
    "commands:\n"
    "  run FILE            time-history analysis (summary.json, CSV, VTU, PNG)\n"
    "  modal FILE          frequencies, periods, participating masses, modes.pvd\n"
    "  ground-motion FILE  the ground acceleration a run would use (CSV, PNG)\n"
    "  print-parameters    every parameter with its documentation and default\n"
    "--output DIR overrides the file's 'Output/Directory'.\n";
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  dealii::deal_II_exceptions::disable_abort_on_exception();
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string              output;
  for (std::size_t i = 0; i < args.size(); ++i)
    if (args[i] == "--output")
      {
        if (i + 1 >= args.size())
          {
            std::cerr << "poundfe: error: --output needs a directory\n" << usage;
            return 1;
          }
        output = args[i + 1];
        args.erase(args.begin() + i, args.begin() + i + 2);
        --i;
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
      if (command != "run" && command != "modal" && command != "ground-motion")
        {
          std::cerr << "poundfe: error: unknown command '" << command << "'\n" << usage;
          return 1;
        }
      if (args.size() != 2)
        {
          std::cerr << "poundfe: error: '" << command << "' needs exactly one parameter file\n"
                    << usage;
          return 1;
        }
      const poundfe::InputParameters input = poundfe::read_parameters(args[1]);
      const std::string directory = output.empty() ? input.output_directory : output;
      if (command == "ground-motion")
        return poundfe::ground_motion_command(input, directory);
      const poundfe::Analysis analysis = poundfe::prepare_analysis(input);
      if (command == "modal")
        return poundfe::modal_command(analysis, directory);
      return poundfe::run_command(analysis, directory);
    }
  catch (const poundfe::InputError &e)
    {
      std::cerr << "poundfe: error: " << e.what() << "\n";
      return 1;
    }
  catch (const poundfe::NumericalError &e)
    {
      std::cerr << "poundfe: numerical failure: " << e.what() << "\n";
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "poundfe: error: " << e.what() << "\n";
      return 1;
    }
}
