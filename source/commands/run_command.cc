// `poundfe run`: the time history of the model, with every output of the
// Output section (recorders, floor spectra, VTU series, summary.json, plots).
//   set-up:       the analysis (model, M, K, modes, C) and the excitation
//   time history: the run with the standard observers (report/run_outputs.h)
//   report:       the run's scalars on the console; the exit status
#include <poundfe/base/console.h>
#include <poundfe/base/interruption.h>
#include <poundfe/commands/command.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/report/run_outputs.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <ostream>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// The run's steps (and over how many ranks, `n_parts` > 0, it was
    /// partitioned), Newton iterations, impacts and energy balance, its
    /// warnings on `err`, and where the results are.
    void
    report_run(const Analysis &analysis, const RunResult &result, const std::string &directory,
               const unsigned int n_parts, std::ostream &out, std::ostream &err)
    {
      const RunStatus &status = result.status;
      out << "poundfe run: " << status.steps << " steps to t = " << status.end_time << " s in "
          << status.wall_time << " s";
      if (n_parts > 0)
        out << " (partitioned by building over " << n_parts << (n_parts == 1 ? " rank)" : " ranks)");
      out << "\n";
      if (result.n_nonlinear_elements > 0)
        out << result.n_nonlinear_elements << " nonlinear elements; Newton "
            << double(result.statistics.iterations) / std::max(1ul, result.statistics.steps)
            << " iterations per step (max " << result.statistics.max_iterations << "), "
            << result.statistics.step_cuts << " step cuts\n";
      if (!analysis.model.gaps.empty())
        out << analysis.model.gaps.size() << " gap elements, " << result.n_impacts
            << " impacts (impacts.csv)\n";
      out << "energy balance error " << result.max_energy_error << " (max relative)\n";
      for (const std::string &warning : result.warnings)
        err << "poundfe: warning: " << warning << "\n";
      out << "results in " << directory << "/ (summary.json lists the files)\n";
    }

    /// 1 when a file could not be written, 2 on a numerical failure, 128 +
    /// signal when interrupted, else 0; what stopped the run on `err`.
    int
    exit_status(const RunStatus &status, std::ostream *err)
    {
      if (status.output_failed)
        {
          std::ostringstream message; // one write: mpirun would interleave pieces with the report
          message << "poundfe: error: " << status.message << " (the run stopped at t = "
                  << status.end_time << " s; every other file is complete to that time, "
                  << "and summary.json says what failed unless it is the file named)\n";
          if (err)
            *err << message.str() << std::flush;
          return 1;
        }
      if (status.kind == RunStatus::Kind::failed)
        {
          if (err)
            *err << "poundfe: numerical failure: " << status.message
                 << " (results up to that time are written)\n";
          return 2;
        }
      if (status.kind == RunStatus::Kind::interrupted)
        {
          if (err)
            *err << "poundfe: interrupted at t = " << status.end_time
                 << " s (results up to that time are written)\n";
          return interrupted_exit_status();
        }
      return 0;
    }
  } // namespace
} // namespace poundfe

namespace poundfe::commands
{
  int
  run(const CommandRun &run)
  {
    const InputParameters &input = *run.input;
    // every rank of a distributed solver runs the analysis, or (Partition =
    // buildings) steps its own buildings; rank 0 writes
    const bool          root = writes_outputs();
    dealii::TimerOutput timer(run.out, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);

    const RunParameters parameters = run_parameters(input);
    const bool partitioned = input.time_integration.partition == RunPartition::buildings;
    RunOptions options;
    // partitioned: every rank observes its own buildings for rank 0's files
    options.output_directory = root || partitioned ? run.directory : "";
    options.progress         = root;
    options.interruptible    = true;
    options.console          = &run.out;

    timer.enter_subsection("set-up");
    // partitioned: this rank's buildings only (theory §3.5d)
    Analysis analysis =
      partitioned ? prepare_rank_analysis(input, run.communicator) : prepare_analysis(input);
    timer.leave_subsection();

    timer.enter_subsection("time history");
    const RunResult result =
      partitioned ?
        run_partitioned_time_history(analysis, parameters, options, run.communicator) :
        run_time_history(analysis, parameters, make_excitation(analysis, parameters.time_history),
                         options);
    timer.leave_subsection();
    // mpirun ends the job as soon as one rank exits with a non-zero status
    // (interrupted, a numerical failure): not before rank 0 has finished
    // its files
    if (int initialized = 0; MPI_Initialized(&initialized), initialized)
      MPI_Barrier(run.communicator);
    if (!root)
      return exit_status(result.status, nullptr);

    report_run(analysis, result, run.directory,
               partitioned ? dealii::Utilities::MPI::n_mpi_processes(run.communicator) : 0,
               run.out, run.err);
    print_timing(timer);
    return exit_status(result.status, &run.err);
  }
} // namespace poundfe::commands
