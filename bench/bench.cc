// Steps per second and Newton iterations per step of the Newmark run, with
// every output but VTU on (CSV rows every output interval, peaks and energy
// balance every step):
//   - the default example (input/two-buildings.prm: Bouc-Wen hinges and
//     Hertz-damp contact) for each solver backend and both tangent updates,
//     without contact, and elastic;
//   - the pounding examples floor-to-column, three-buildings-row and
//     spillway-abutment;
//   - the hinge examples input/three-storey-frame-hinges.prm and
//     input/bouc-wen-sdof.prm;
//   - two 10-storey, 3-bay frames side by side (a larger model).
// Usage: build/poundfe-bench [input/two-buildings.prm] [repeats]
// (run from the repository root).
// Monte Carlo: [mpirun -np P] build/poundfe-bench --montecarlo FILE N
//   times one realization (best of 3, on rank 0) and N realizations of FILE
//   through the montecarlo driver (realizations.csv in a fresh temporary
//   directory), and prints realizations per second on P ranks;
//   bench/montecarlo.sh runs it on 1 and 2 ranks and prints the speed-up.
// Bifurcation: build/poundfe-bench --bifurcation FILE
//   times the points of FILE's Bifurcation section (each: read, prepare,
//   transient + sampled periods, and the second trajectory when asked) and
//   prints the points per second and the steps per second.
// Distributed solve: [mpirun -np P] build/poundfe-bench --distributed FILE
//   the run of FILE (its solver, e.g. petsc-mumps on input/city-block.prm)
//   with the CSV outputs on rank 0: equations, set-up (reading and assembly;
//   the engine with the analysis and first factorisation), steps/s, where
//   the stepping time goes (numeric factorisations, solves, the rest) and
//   the peak resident memory per rank; bench/city_block.sh runs it on 1 and
//   2 ranks.
// Times the stepping loop with its outputs; set-up (assembly, modes,
// factorisation) is reported separately.
#include <poundfe/analysis/analysis.h>
#include <poundfe/analysis/bifurcation.h>
#include <poundfe/analysis/montecarlo.h>
#include <poundfe/analysis/realization.h>
#include <poundfe/analysis/run.h>
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/analysis/input_parameters.h>

#include <deal.II/base/mpi.h>

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

using namespace poundfe;

namespace
{
  InputParameters
  ten_storey_pair(const InputParameters &base)
  {
    InputParameters p = base;
    p.model.buildings.resize(2);
    for (unsigned int b = 0; b < 2; ++b)
      {
        BuildingParameters &x = p.model.buildings[b];
        x                     = base.model.buildings[0];
        x.name                = b == 0 ? "T10a" : "T10b";
        x.n_storeys           = 10;
        x.n_bays              = 3;
        x.storey_heights      = {3.0};
        x.floor_masses        = {60000};
        x.column_area         = {b == 0 ? 0.36 : 0.25};
        x.column_second_moment = {b == 0 ? 1.08e-2 : 5.2e-3};
        x.damping_modes       = {1, 3};
      }
    p.model.separations = {0.1};
    return p;
  }

  void
  measure(const char *label, const InputParameters &input, const unsigned int repeats,
          const std::vector<std::string> &solvers = linear_solver_names())
  {
    const auto     t0       = std::chrono::steady_clock::now();
    const Analysis analysis = prepare_analysis(input);
    const double   setup    = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const Excitation excitation = make_excitation(analysis);
    const std::string dir = std::filesystem::temp_directory_path() / "poundfe-bench";
    for (const std::string &solver : solvers)
      {
        double best = 1e300;
        RunResult result;
        for (unsigned int r = 0; r < repeats; ++r)
          {
            RunOptions options;
            options.output_directory = dir;
            options.linear_solver    = solver;
            options.vtu              = false;
            options.plots            = false;
            result = run_time_history(analysis, excitation, options);
            best   = std::min(best, result.status.wall_time);
          }
        const IterationStatistics &s = result.statistics;
        std::printf("%-34s %4u eqs %3u nl %2zu gaps %-10s %-11s %7lu steps %9.0f steps/s  %5.2f "
                    "it/step  %lu cuts %4zu impacts (set-up %.3f s)\n",
                    label, analysis.model.n_equations(), result.n_nonlinear_elements,
                    analysis.model.gaps.size(),
                    solver.c_str(), tangent_update_names().name(input.time_integration.newmark.newton.tangent_update).c_str(), result.status.steps,
                    result.status.steps / best, s.steps ? double(s.iterations) / s.steps : 0.0,
                    s.step_cuts, result.n_impacts, setup);
      }
    std::filesystem::remove_all(dir);
  }

  int
  measure_monte_carlo(const std::string &file, const unsigned long n, const MPI_Comm comm)
  {
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const auto         t0      = std::chrono::steady_clock::now();
    const Analysis     analysis = prepare_analysis(read_parameters(file));
    RealizationRunner  runner(analysis);
    const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double       one   = 1e300;
    std::vector<double> responses;
    if (rank == 0)
      for (unsigned int r = 0; r < 3; ++r)
        {
          const auto start = std::chrono::steady_clock::now();
          runner.run(r, responses);
          one = std::min(one, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
    const std::string dir = std::filesystem::temp_directory_path() /
                            ("poundfe-bench-mc-" + std::to_string(n_ranks));
    if (rank == 0)
      {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
      }
    const MonteCarloTable table = run_monte_carlo(runner, n, 1.0, dir + "/realizations.csv", comm, "  ");
    if (rank == 0)
      {
        std::filesystem::remove_all(dir);
        std::printf("montecarlo %s: %u variables, one realization %.3f s (best of 3, set-up "
                    "%.3f s once); %lu realizations on %u rank%s in %.2f s: %.2f realizations/s\n",
                    file.c_str(), runner.n_variables(), one, setup, n, n_ranks,
                    n_ranks > 1 ? "s" : "", table.wall_time, n / table.wall_time);
      }
    return 0;
  }

  double
  seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  /// after - before, counts and times.
  DistributedSolverProfile
  difference(const DistributedSolverProfile &after, const DistributedSolverProfile &before)
  {
    DistributedSolverProfile d = after;
    d.analyses -= before.analyses;
    d.factorizations -= before.factorizations;
    d.solves -= before.solves;
    d.analysis_time -= before.analysis_time;
    d.factorization_time -= before.factorization_time;
    d.solve_time -= before.solve_time;
    return d;
  }

  int
  measure_distributed(const std::string &file, const MPI_Comm comm)
  {
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    auto               start   = std::chrono::steady_clock::now();
    const Analysis     analysis   = prepare_analysis(read_parameters(file));
    const Excitation   excitation = make_excitation(analysis);
    const double       prepare    = seconds_since(start);
    // The engine alone (elements, K_eff, MUMPS analysis and first
    // factorisation), to separate its set-up from the stepping below.
    const DistributedSolverProfile before_engine = distributed_solver_profile();
    start = std::chrono::steady_clock::now();
    {
      TimeHistory history(analysis);
    }
    const double engine = seconds_since(start);
    const DistributedSolverProfile in_engine =
      difference(distributed_solver_profile(), before_engine);

    const std::string dir = std::filesystem::temp_directory_path() / "poundfe-bench-distributed";
    RunOptions        options;
    options.output_directory = rank == 0 ? dir : "";
    options.vtu              = false;
    options.plots            = false;
    const DistributedSolverProfile before_run = distributed_solver_profile();
    const RunResult result = run_time_history(analysis, excitation, options);
    const DistributedSolverProfile in_steps =
      difference(difference(distributed_solver_profile(), before_run), in_engine);
    if (rank == 0)
      std::filesystem::remove_all(dir);

    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    const double rss     = usage.ru_maxrss / 1024.0; // MiB
    const double max_rss = dealii::Utilities::MPI::max(rss, comm);
    const double sum_rss = dealii::Utilities::MPI::sum(rss, comm);
    if (rank != 0)
      return 0;
    const double               wall  = result.status.wall_time;
    const DistributedSolverProfile &p = in_steps;
    const double rest  = wall - p.analysis_time - p.factorization_time - p.solve_time;
    const IterationStatistics &s     = result.statistics;
    const bool completed = result.status.kind == RunStatus::Kind::completed;
    std::printf("distributed %s on %u rank(s)%s: %u equations, %u nonlinear elements, %zu gaps\n",
                file.c_str(), n_ranks, completed ? "" : " (NOT completed)",
                analysis.model.n_equations(), result.n_nonlinear_elements,
                analysis.model.gaps.size());
    std::printf("  set-up: read and assemble %.2f s; engine %.2f s (MUMPS analysis %.2f s, "
                "first factorisation %.2f s)\n",
                prepare, engine, in_engine.analysis_time, in_engine.factorization_time);
    std::printf("  MUMPS factors: %.3g entries, %.0f MB on the largest rank, %.0f MB in all\n",
                in_engine.factor_entries, in_engine.factor_megabytes_per_rank,
                in_engine.factor_megabytes_total);
    std::printf("  stepping: %lu steps (%lu with sub-steps) in %.2f s: %.3f steps/s; %.2f Newton "
                "iterations/step, %lu step cuts, %zu impacts\n",
                result.status.steps, s.steps, wall, result.status.steps / wall,
                s.steps ? double(s.iterations) / s.steps : 0.0, s.step_cuts, result.n_impacts);
    const auto share = [wall](const double t) { return 100 * t / wall; };
    std::printf("  stepping time: %lu numeric factorisations %.2f s (%.1f %%, %.3f s each), "
                "%lu solves %.2f s (%.1f %%, %.4f s each), %lu analyses (new step sizes) "
                "%.2f s (%.1f %%), the rest (elements, residuals, outputs) %.2f s (%.1f %%)\n",
                p.factorizations, p.factorization_time, share(p.factorization_time),
                p.factorizations ? p.factorization_time / p.factorizations : 0.0, p.solves,
                p.solve_time, share(p.solve_time), p.solves ? p.solve_time / p.solves : 0.0,
                p.analyses, p.analysis_time, share(p.analysis_time), rest, share(rest));
    std::printf("  peak resident memory: %.0f MiB on the largest rank, %.0f MiB in all\n",
                max_rss, sum_rss);
    return 0;
  }

  int
  measure_bifurcation(const std::string &file)
  {
    const InputParameters     input  = read_parameters(file);
    const BifurcationParameters &b   = input.bifurcation;
    const std::vector<double> values = b.sweep.values();
    const auto                start  = std::chrono::steady_clock::now();
    double                    steps = 0, in_points = 0;
    for (const double value : values)
      {
        const BifurcationPoint point = bifurcation_point(input, value);
        steps += std::round(point.forcing_period / point.time_step) *
                 (b.transient_periods + b.sampled_periods) * (b.lyapunov_exponent ? 2 : 1);
        in_points += point.wall_time;
      }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("bifurcation %s: %zu values in %.3f s (%.1f values/s; reading the inputs "
                "%.3f s); %.3g integrator steps%s, %.3g steps/s\n",
                file.c_str(), values.size(), wall, values.size() / wall, wall - in_points, steps,
                b.lyapunov_exponent ? " (both trajectories)" : "", steps / in_points);
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  // --montecarlo runs over MPI, and the solver comparison includes PETSc and
  // Trilinos, which need it initialised: both modes initialise it.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc > 3 && std::string(argv[1]) == "--montecarlo")
    return measure_monte_carlo(argv[2], std::stoul(argv[3]), MPI_COMM_WORLD);
  if (argc > 2 && std::string(argv[1]) == "--distributed")
    return measure_distributed(argv[2], MPI_COMM_WORLD);
  if (argc > 2 && std::string(argv[1]) == "--bifurcation")
    return measure_bifurcation(argv[2]);
  const std::string  file    = argc > 1 ? argv[1] : "input/two-buildings.prm";
  const unsigned int repeats = argc > 2 ? std::stoi(argv[2]) : 3;
  const InputParameters input = read_parameters(file);
  measure("default example (hinges, contact)", input, repeats);
  InputParameters refactorize = input;
  refactorize.time_integration.newmark.newton.tangent_update = TangentUpdate::refactorize;
  measure("default example (hinges, contact)", refactorize, repeats, {"eigen-ldlt", "umfpack"});
  InputParameters no_contact = input;
  no_contact.contact.law     = "none";
  measure("default example (hinges only)", no_contact, repeats, {"eigen-ldlt"});
  InputParameters elastic = no_contact;
  for (auto &b : elastic.model.buildings)
    b.hinge_locations.clear();
  measure("default example, elastic", elastic, repeats, {"eigen-ldlt"});
  measure("floor-to-column (hinges, contact)", read_parameters("input/floor-to-column.prm"),
          repeats, {"eigen-ldlt"});
  measure("three-building row", read_parameters("input/three-buildings-row.prm"), repeats,
          {"eigen-ldlt"});
  measure("spillway-abutment (Jankowski)", read_parameters("input/spillway-abutment.prm"),
          repeats, {"eigen-ldlt"});
  measure("three-storey frame (hinges)", read_parameters("input/three-storey-frame-hinges.prm"),
          repeats, {"eigen-ldlt"});
  measure("Bouc-Wen SDOF", read_parameters("input/bouc-wen-sdof.prm"), repeats, {"eigen-ldlt"});
  measure("two 10-storey 3-bay frames (hinges)", ten_storey_pair(input), repeats);
  return 0;
}
