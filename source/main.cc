// poundfe command line: poundfe <command> [FILE] [--output DIR]
#include <poundfe/analysis/analysis.h>
#include <poundfe/analysis/bifurcation.h>
#include <poundfe/analysis/command_guard.h>
#include <poundfe/analysis/montecarlo.h>
#include <poundfe/analysis/subset.h>
#include <poundfe/analysis/sweep.h>
#include <poundfe/analysis/run.h>
#include <poundfe/analysis/spectrum.h>
#include <poundfe/analysis/site_hazard_command.h>
#include <poundfe/analysis/separation.h>
#include <poundfe/analysis/stationary_pdf.h>
#include <poundfe/analysis/templates.h>
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/model/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <iostream>
#include <optional>
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

  const char *usage =
    "usage: poundfe <command> [FILE] [--output DIR]\n"
    "       poundfe --help | --version\n"
    "commands:\n"
    "  run FILE            time-history analysis (summary.json, CSV, VTU, PNG)\n"
    "  modal FILE          frequencies, periods, participating masses, modes.pvd\n"
    "  ground-motion FILE [--realizations N]\n"
    "                      the ground acceleration a run would use (CSV, PNG); with N,\n"
    "                      realizations 0..N-1 and their ensemble PSD against the target\n"
    "  spectrum FILE [--realizations N]\n"
    "                      response spectrum (Sd, PSV, PSA), PGA/PGV/PGD, Arias intensity,\n"
    "                      D5-95 of the ground motion; with N, the ensemble mean spectrum\n"
    "                      against the Spectrum section's target and the S0 that matches it\n"
    "  montecarlo FILE     Monte Carlo over the random loading (MPI: mpirun -np P ...)\n"
    "  subset FILE         Subset Simulation of a small exceedance probability (MPI)\n"
    "  fragility FILE      Monte Carlo over PGA levels, lognormal fragility curves (MPI)\n"
    "  stationary-pdf FILE stationary PDFs of a noisy response: histogram, kernel density,\n"
    "                      peaks, joint p(x, v) (MPI)\n"
    "  sweep FILE          the run's peaks against the values of the Sweep section's\n"
    "                      parameter (sweep.csv, sweep.png, summary.json)\n"
    "  bifurcation FILE    Poincare samples, their period and the largest Lyapunov\n"
    "                      exponent against the Bifurcation section's parameter\n"
    "  site-hazard FILE    site intensity and PGA of a catalogue's earthquakes, Gumbel or\n"
    "                      Poisson fit, return periods, fragility x hazard\n"
    "  separation FILE     joint width of adjacent buildings: ABS, SRSS, DDC, EC8 and\n"
    "                      ASCE 7 rules against the time history without contact (or\n"
    "                      by response spectrum, Separation/Peak displacements); with\n"
    "                      random loading, P(pounding) against the gap (MPI)\n"
    "                      and, with a site hazard, P(pounding in T years) and the gap\n"
    "                      for a target (Separation/Site hazard)\n"
    "  print-parameters    every parameter with its documentation and default\n"
    "  template KIND       a commented starting file on standard output, KIND one of\n"
    "                      frame, shear, mesh, pounding, stochastic\n"
    "                      (poundfe template frame > my-frame.prm)\n"
    "--output DIR overrides the file's 'Output/Directory'. Any other option is an error.\n"
    "Exit status: 0 done, 1 bad input or command line (one message, nothing written),\n"
    "2 numerical failure (results so far kept), 128 + signal when interrupted.\n"
    "SIGINT (Ctrl-C) or SIGTERM stops run, montecarlo, subset, fragility, stationary-pdf\n"
    "and separation after the step or realizations under way, with the results so far\n"
    "(status \"interrupted\", exit status 128 + signal); the same command resumes all but\n"
    "run and subset. Any other command stops at its next file write or time step: no\n"
    "*.tmp left, summary.json says \"interrupted\". A file that cannot be written (full\n"
    "disk) exits 1 with summary.json \"failed\" and the reason, when it still fits.\n"
    "A second signal kills. Progress shows on a terminal (POUNDFE_PROGRESS=1: always).\n";

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
    CommandLine line;
    std::string realizations;
    for (std::size_t i = 0; i < args.size(); ++i)
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
      else if (args[i] == "--help" || args[i] == "-h")
        line.help = true;
      else if (args[i] == "--version")
        line.version = true;
      else if (args[i].size() > 1 && args[i][0] == '-')
        {
          line.error = "poundfe: error: unknown option '" + args[i] + "' (see poundfe --help)\n";
          return line;
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

  /// `poundfe template KIND`: the starting file on standard output.
  int
  template_command(const std::vector<std::string> &args, std::ostream &err)
  {
    std::string kinds;
    for (const std::string &kind : poundfe::template_kinds())
      kinds += (kinds.empty() ? "" : ", ") + kind;
    const std::string *text = args.size() == 2 ? poundfe::input_template(args[1]) : nullptr;
    if (text == nullptr)
      {
        err << "poundfe: error: 'template' needs one kind of model, one of: " << kinds
            << (args.size() == 2 ? " (not '" + args[1] + "')" : std::string()) << "\n";
        return 1;
      }
    std::cout << *text;
    return 0;
  }

  /// The commands that split their work over MPI ranks.
  bool
  runs_over_mpi(const std::string &command)
  {
    return command == "montecarlo" || command == "subset" || command == "fragility" ||
           command == "stationary-pdf" || command == "separation";
  }
} // namespace

int
main(int argc, char **argv)
{
  const CommandLine line    = parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
  const std::string command = line.args.empty() ? "" : line.args[0];
  // MPI_InitFinalize (MPI, PETSc, Trilinos) costs ~0.5 s at start: only the
  // commands that run over MPI initialise it here, and any command whose
  // linear solver needs it once the input is read.
  std::optional<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  if (runs_over_mpi(command))
    mpi.emplace(argc, argv, 1);
  else
    dealii::MultithreadInfo::set_thread_limit(1); // what MPI_InitFinalize(argc, argv, 1) sets
  dealii::deal_II_exceptions::disable_abort_on_exception();
  // Every rank reads the same input and fails the same way: rank 0 speaks.
  const bool    root = !mpi || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ostream &err  = root ? std::cerr : silent;
  if (!line.error.empty())
    {
      err << line.error;
      return 1;
    }
  const std::vector<std::string> &args = line.args;
  if (line.version)
    {
      std::cout << "poundfe (git " << poundfe::git_revision << "), deal.II "
                << DEAL_II_PACKAGE_VERSION << "\n";
      return 0;
    }
  if (args.empty() || line.help)
    {
      (line.help ? std::cout : err) << usage;
      return line.help ? 0 : 1;
    }
  // Every command that writes files stops cleanly on SIGINT/SIGTERM: at its
  // own safe points, or at the next file write (analysis/command_guard.h).
  if (command != "print-parameters" && command != "template")
    poundfe::install_interruption_handlers();
  try
    {
      if (command == "print-parameters")
        {
          if (args.size() != 1)
            {
              err << "poundfe: error: 'print-parameters' takes no argument, got '" << args[1]
                  << "'\n";
              return 1;
            }
          poundfe::print_parameters(std::cout);
          return 0;
        }
      if (command == "template")
        return template_command(args, err);
      if (command != "run" && command != "modal" && command != "ground-motion" &&
          command != "spectrum" &&
          command != "sweep" && command != "bifurcation" && command != "site-hazard" &&
          !runs_over_mpi(command))
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
      if (!mpi && poundfe::linear_solver_needs_mpi(input.time_integration.linear_solver))
        mpi.emplace(argc, argv, 1);
      // A distributed solver needs every rank in the same analysis: `run`
      // (the probabilistic commands give each rank its own realizations).
      if (mpi && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1 &&
          poundfe::linear_solver_is_distributed(input.time_integration.linear_solver) &&
          command != "run")
        input.fail("Time integration/Linear solver",
                   input.time_integration.linear_solver + " spreads one run over the MPI ranks: "
                   "on more than one rank only 'run' can use it, not '" + command + "'");
      const std::string directory = line.output.empty() ? input.output.directory : line.output;
      const bool writes = !mpi || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      const poundfe::GuardedCommand guarded{
        command, input, directory, writes, !poundfe::handles_interruption_itself(command)};
      return poundfe::guard_command(guarded, [&]() -> int {
        if (command == "stationary-pdf" && line.n_realizations == 0)
          return poundfe::stationary_pdf_command(input, directory, MPI_COMM_WORLD);
        if (command == "ground-motion")
          return poundfe::ground_motion_command(input, directory, line.n_realizations);
        if (command == "spectrum")
          return poundfe::spectrum_command(input, directory, line.n_realizations);
        if (line.n_realizations > 0)
          {
            err << "poundfe: error: --realizations belongs to ground-motion and spectrum\n";
            return 1;
          }
        if (command == "separation") // builds its model without contact
          return poundfe::separation_command(input, directory, MPI_COMM_WORLD);
        if (command == "sweep") // an analysis per value
          return poundfe::sweep_command(input, directory);
        if (command == "bifurcation")
          return poundfe::bifurcation_command(input, directory);
        if (command == "site-hazard") // no model
          return poundfe::site_hazard_command(input, directory);
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
      });
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
      if (mpi && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    }
}
