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
// Output speed (issue 12): build/poundfe-bench --output [repeats]
//   times the four models of the issue (bench/shear-pair-linear.prm,
//   bench/shear-pair-jankowski.prm, input/three-storey-frame.prm,
//   input/bouc-wen-sdof.prm) with every default output written at every
//   step (Output interval = Time step, no VTU, no plots) as CSV and as
//   NumPy .npy (Output/Format), against the same run without an output
//   directory (peaks only); best of `repeats` (10).
// Step rate: build/poundfe-bench --step-rate [repeats] [MODEL...] [off|csv|npy]
//   the models of bench/step-rate.txt (default: all of them) with outputs off
//   (peaks only) and/or with every default CSV output at every step (or, named,
//   as .npy), best of
//   `repeats` (5), one line per model and case "step-rate MODEL CASE STEPS/S";
//   bench/check-step-rate.sh compares them with the recorded figures.
//   `writer` runs with two threads, the outputs formatted and written on a
//   writer thread (output/output_queue.h); `whole` divides by the whole run
//   (recorders made, steps, files finished) instead of the time loop alone.
// Modes: build/poundfe-bench --modes [storeys ...]
//   times the dense and the sparse eigensolver (6 modes, best of 3; the dense
//   one once above 1000 equations) on generated 3-bay frames with 2 elements
//   per member (33 equations per storey; default 15 30 60 150 storeys, i.e.
//   495 to 4950 equations), and prints the largest frequency difference.
// Reliability: build/poundfe-bench --reliability [FILE]
//   (input/thesis-cantilever-reliability.prm by default): evaluations per
//   second of the file's first limit-state expression alone (muParser byte
//   code, values copied in), of g(T(u)) with the transformation and the
//   random numbers (crude Monte Carlo), and FORM's iterations, gradients
//   and evaluations on every limit state (best of 3 for the rates).
// Distributed solve: [mpirun -np P] build/poundfe-bench --distributed FILE
//   the run of FILE (its solver, e.g. petsc-mumps on input/city-block.prm)
//   with the CSV outputs on rank 0: equations, set-up (reading and assembly;
//   the engine with the analysis and first factorisation), steps/s, where
//   the stepping time goes (numeric factorisations, solves, the rest) and
//   the peak resident memory per rank; bench/city_block.sh runs it on 1 and
//   2 ranks.
// Partitioned by building: [mpirun -np P] build/poundfe-bench --partitioned
//   FILE [END [SAVE]] steps FILE to END (s; default its End time) with
//   each rank owning a run of buildings (dynamics/partitioned_history.h):
//   the partition, set-up time, steps/s, iterations, and the peak resident
//   memory per rank; SAVE (optional) gets the final displacement of every
//   equation, one per line, from rank 0. --serial FILE [END [SAVE]] does the
//   same with the whole model on one process (the reference);
//   bench/city_block.sh runs both.
// Times the stepping loop with its outputs; set-up (assembly, modes,
// factorisation) is reported separately.
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/partitioned_history.h>
#include <poundfe/dynamics/bifurcation.h>
#include <poundfe/dynamics/modal.h>
#include <poundfe/reliability/montecarlo.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/input/bifurcation_input.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/model/model_builder.h>
#include <poundfe/report/run_outputs.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <sys/resource.h>

#include <poundfe/reliability/form.h>
#include <poundfe/reliability/limit_state.h>
#include <poundfe/reliability/sampling.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
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
    const RunParameters parameters = run_parameters(input);
    const Excitation excitation = make_excitation(analysis, parameters.time_history);
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
            result = run_time_history(analysis, parameters, excitation, options);
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

  /// Whether a step rate divides by the whole run_time_history call (the
  /// recorders made, the steps, every file finished: what a writer thread
  /// still owes at the last step counts) instead of the time loop's steps.
  bool whole_run = false;

  /// Best steps/s of `repeats` runs of `analysis` writing into `directory`
  /// (empty: no output).
  double
  best_steps_per_second(const Analysis &analysis, const RunParameters &parameters,
                        const Excitation &excitation, const std::string &directory,
                        const unsigned int repeats, unsigned long &steps)
  {
    double best = 0;
    for (unsigned int r = 0; r < repeats; ++r)
      {
        RunOptions options;
        options.output_directory = directory;
        options.vtu              = false;
        options.plots            = false;
        const auto      start    = std::chrono::steady_clock::now();
        const RunResult result   = run_time_history(analysis, parameters, excitation, options);
        const double    call =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        steps = result.status.steps;
        best  = std::max(best, result.status.steps / (whole_run ? call : result.status.wall_time));
      }
    return best;
  }

  /// Steps/s with every default output at every step in `format`, and the
  /// megabytes written.
  std::pair<double, double>
  output_speed(InputParameters input, const OutputFormat format, const unsigned int repeats,
               unsigned long &steps)
  {
    input.output.recorders.format = format;
    const Analysis      analysis   = prepare_analysis(input);
    const RunParameters parameters = run_parameters(input);
    const Excitation    excitation = make_excitation(analysis, parameters.time_history);
    const std::string dir = std::filesystem::temp_directory_path() / "poundfe-bench-output";
    std::filesystem::remove_all(dir);
    const double   speed =
      best_steps_per_second(analysis, parameters, excitation, dir, repeats, steps);
    std::uintmax_t bytes = 0;
    for (const auto &file : std::filesystem::directory_iterator(dir))
      bytes += file.file_size();
    std::filesystem::remove_all(dir);
    return {speed, bytes / 1e6};
  }

  /// Steps/s with every default output at every step, and without output.
  void
  measure_output_speed(const char *label, InputParameters input, const unsigned int repeats)
  {
    input.output.interval                  = input.time_integration.newmark.time_step;
    input.output.recorders.output_interval = input.output.interval;
    unsigned long steps = 0;
    const auto    csv   = output_speed(input, OutputFormat::csv, repeats, steps);
    const auto    npy   = output_speed(input, OutputFormat::npy, repeats, steps);
    const Analysis   analysis   = prepare_analysis(input);
    const RunParameters parameters = run_parameters(input);
    const double        none       = best_steps_per_second(
      analysis, parameters, make_excitation(analysis, parameters.time_history), "", repeats, steps);
    std::printf("%-30s %3u eqs %7lu steps  no output %9.0f steps/s  csv %9.0f steps/s (%5.1f MB)"
                "  npy %9.0f steps/s (%5.1f MB)\n",
                label, analysis.model.n_equations(), steps, none, csv.first, csv.second,
                npy.first, npy.second);
  }

  int
  measure_output(const unsigned int repeats)
  {
    measure_output_speed("3+2 shear pair, linear gaps", read_parameters("bench/shear-pair-linear.prm"),
                         repeats);
    measure_output_speed("3+2 shear pair, Jankowski gaps",
                         read_parameters("bench/shear-pair-jankowski.prm"), repeats);
    measure_output_speed("3-storey 1-bay elastic frame",
                         read_parameters("input/three-storey-frame.prm"), repeats);
    measure_output_speed("Bouc-Wen SDOF", read_parameters("input/bouc-wen-sdof.prm"), repeats);
    return 0;
  }

  /// The step-rate models: name and input file, from bench/step-rate.txt's
  /// first two columns (one shared list for this and the check script).
  std::vector<std::pair<std::string, std::string>>
  step_rate_models()
  {
    std::ifstream in("bench/step-rate.txt");
    if (!in)
      throw std::runtime_error("cannot read bench/step-rate.txt (run from the repository root)");
    std::vector<std::pair<std::string, std::string>> models;
    std::set<std::string>                            seen;
    for (std::string line; std::getline(in, line);)
      {
        std::istringstream fields(line);
        std::string        name, file;
        if (line.empty() || line[0] == '#' || !(fields >> name >> file) || !seen.insert(name).second)
          continue;
        models.emplace_back(name, file);
      }
    return models;
  }

  /// Steps/s of the recorded models with outputs off and with CSV at every
  /// step; `only` names the models to run and the cases (off, csv), each
  /// all when it names none; .npy at every step (npy) only when named.
  int
  measure_step_rate(const unsigned int repeats, std::set<std::string> only)
  {
    const bool off_only = only.erase("off") > 0, csv_only = only.erase("csv") > 0;
    const bool run_npy = only.erase("npy") > 0;
    whole_run          = only.erase("whole") > 0;
    if (only.erase("writer") > 0) // two threads: the outputs' writer thread (output/output_queue.h)
      dealii::MultithreadInfo::set_thread_limit(2);
    const bool run_off = off_only || (!csv_only && !run_npy),
               run_csv = csv_only || (!off_only && !run_npy);
    const auto models  = step_rate_models();
    for (const std::string &name : only)
      if (std::none_of(models.begin(), models.end(), [&](const auto &m) { return m.first == name; }))
        throw std::runtime_error("no model '" + name + "' in bench/step-rate.txt");
    for (const auto &[name, file] : models)
      {
        if (!only.empty() && !only.count(name))
          continue;
        InputParameters input = read_parameters(file);
        input.output.interval                  = input.time_integration.newmark.time_step;
        input.output.recorders.output_interval = input.output.interval;
        unsigned long steps = 0;
        if (run_off)
          {
            const Analysis      analysis   = prepare_analysis(input);
            const RunParameters parameters = run_parameters(input);
            const double        off        = best_steps_per_second(
              analysis, parameters, make_excitation(analysis, parameters.time_history), "",
              repeats, steps);
            std::printf("step-rate %s off %.0f\n", name.c_str(), off);
          }
        if (run_csv)
          std::printf("step-rate %s csv %.0f\n", name.c_str(),
                      output_speed(input, OutputFormat::csv, repeats, steps).first);
        if (run_npy)
          std::printf("step-rate %s npy %.0f\n", name.c_str(),
                      output_speed(input, OutputFormat::npy, repeats, steps).first);
        std::fflush(stdout);
      }
    return 0;
  }

  int
  measure_monte_carlo(const std::string &file, const unsigned long n, const MPI_Comm comm)
  {
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const auto         t0      = std::chrono::steady_clock::now();
    const InputParameters input    = read_parameters(file);
    const Analysis        analysis = prepare_analysis(input);
    RealizationRunner     runner(analysis, time_history_parameters(input));
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
    d.symmetric_factorizations -= before.symmetric_factorizations;
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
    const InputParameters input      = read_parameters(file);
    const Analysis        analysis   = prepare_analysis(input);
    const RunParameters   parameters = run_parameters(input);
    const Excitation      excitation = make_excitation(analysis, parameters.time_history);
    const double          prepare    = seconds_since(start);
    // The engine alone (elements, K_eff, MUMPS analysis and first
    // factorisation), to separate its set-up from the stepping below.
    const DistributedSolverProfile before_engine = distributed_solver_profile();
    start = std::chrono::steady_clock::now();
    {
      TimeHistory history(analysis, parameters.time_history);
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
    const RunResult result = run_time_history(analysis, parameters, excitation, options);
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
    std::printf("  MUMPS factors (%s): %.3g entries, %.0f MB on the largest rank, %.0f MB in all\n",
                in_engine.symmetric_factorizations > 0 ? "L D L^T" : "L U",
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

  /// Peak resident memory of this process, MiB.
  double
  peak_memory_mib()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0;
  }

  /// The process's private (anonymous) resident memory now, MiB: what
  /// it holds of its own. The rest of its resident memory is file pages,
  /// chiefly the shared libraries' (about 135 MiB of deal.II, PETSc,
  /// Trilinos, MPI), which the page cache shares between all ranks of a
  /// machine; peak_memory_mib counts them once per rank.
  double
  private_memory_mib()
  {
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      if (line.rfind("RssAnon:", 0) == 0)
        return std::stod(line.substr(8)) / 1024.0; // kB
    return 0;
  }

  void
  save_vector(const std::string &file, const Vector &x)
  {
    std::FILE *out = std::fopen(file.c_str(), "w");
    if (!out)
      throw std::runtime_error("cannot write " + file);
    for (Eigen::Index i = 0; i < x.size(); ++i)
      std::fprintf(out, "%.17g\n", x[i]);
    std::fclose(out);
  }

  /// What --partitioned and --serial print (rank 0).
  struct PartitionedReport
  {
    std::string   first_line, solver;
    double        prepare = 0, engine = 0, stepping = 0, energy_error = 0;
    unsigned long n_steps = 0;
    IterationStatistics statistics;
    double        max_rss = 0, sum_rss = 0, max_set_up_rss = 0;
    /// Private memory: the largest of the samples after set-up and after
    /// each step, on the largest rank, and summed over the ranks.
    double        max_private = 0, sum_private = 0;

    void
    print() const
    {
      const IterationStatistics &s = statistics;
      std::printf("%s\n", first_line.c_str());
      std::printf("  set-up: read and assemble %.2f s; engine %.2f s (%s)\n", prepare, engine,
                  solver.c_str());
      std::printf("  stepping: %lu steps (%lu with sub-steps) in %.2f s: %.3f steps/s; %.2f "
                  "Newton iterations/step, %lu factorisations, %lu step cuts, energy balance "
                  "error %.2e\n",
                  n_steps, s.steps, stepping, n_steps / stepping,
                  s.steps ? double(s.iterations) / s.steps : 0.0, s.refactorizations,
                  s.step_cuts, energy_error);
      std::printf("  peak resident memory: %.0f MiB on the largest rank (%.0f after set-up), "
                  "%.0f MiB in all\n",
                  max_rss, max_set_up_rss, sum_rss);
      std::printf("  peak private memory: %.0f MiB on the largest rank, %.0f MiB in all "
                  "(without the shared libraries' pages)\n",
                  max_private, sum_private);
    }
  };

  /// --partitioned (over the ranks of `comm`) or --serial (one process,
  /// the whole model: the reference).
  int
  measure_partitioned(const std::string &file, const double end, const std::string &save,
                      const bool serial, const MPI_Comm comm)
  {
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
    PartitionedReport  report;
    auto               start = std::chrono::steady_clock::now();
    const InputParameters input      = read_parameters(file);
    // --partitioned: each rank assembles only its own buildings
    Analysis analysis = serial ? prepare_analysis(input) : prepare_rank_analysis(input, comm);
    const TimeHistoryParameters parameters = time_history_parameters(input);
    report.prepare                   = seconds_since(start);
    const double dt                  = parameters.time_integration.newmark.time_step;
    report.n_steps = std::lround((end > 0 ? end : parameters.time_integration.end_time) / dt);
    const unsigned int n_equations   = analysis.model.n_equations();

    start = std::chrono::steady_clock::now();
    std::unique_ptr<WholeModelHistory>  whole;
    std::unique_ptr<PartitionedHistory> partitioned;
    if (serial)
      whole = std::make_unique<WholeModelHistory>(analysis, parameters);
    else
      {
        partitioned = std::make_unique<PartitionedHistory>(analysis, parameters, comm);
        partitioned->initialize();
      }
    report.engine         = seconds_since(start);
    report.max_set_up_rss = dealii::Utilities::MPI::max(peak_memory_mib(), comm);

    double private_memory = private_memory_mib();
    start = std::chrono::steady_clock::now();
    for (unsigned long step = 0; step < report.n_steps; ++step)
      {
        serial ? whole->advance() : partitioned->advance();
        private_memory = std::max(private_memory, private_memory_mib()); // ~20 us
      }
    report.stepping = seconds_since(start);
    report.max_private = dealii::Utilities::MPI::max(private_memory, comm);
    report.sum_private = dealii::Utilities::MPI::sum(private_memory, comm);
    const TimeStepper &stepper = serial ? static_cast<const TimeStepper &>(whole->integrator()) :
                                          partitioned->integrator();
    report.statistics   = stepper.statistics();
    report.energy_error = stepper.max_energy_error();
    const Vector final_u =
      serial ? stepper.displacement() : partitioned->gather(stepper.displacement());
    report.max_rss = dealii::Utilities::MPI::max(peak_memory_mib(), comm);
    report.sum_rss = dealii::Utilities::MPI::sum(peak_memory_mib(), comm);
    if (rank != 0)
      return 0;
    report.solver = serial ? whole->integrator().linear_solver_name() :
                             partitioned->linear_solver_name();
    if (serial)
      report.first_line = "serial " + file + ": " + std::to_string(n_equations) +
                          " equations on one process";
    else
      {
        const BuildingPartition &p = partitioned->partition();
        report.first_line =
          "partitioned " + file + " on " + std::to_string(p.n_parts()) + " rank(s): " +
          std::to_string(n_equations) + " equations, " + std::to_string(p.n_blocks) +
          " separable runs of buildings; rank 0: buildings [0, " +
          std::to_string(p.first_building[1]) + "), equations [0, " +
          std::to_string(p.first_equation[1]) + "), " +
          std::to_string(partitioned->n_local_elements()) + " nonlinear elements, " +
          std::to_string(partitioned->n_ghosts()) + " ghosts";
      }
    report.print();
    if (!save.empty())
      save_vector(save, final_u);
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

  /// Best wall time of `repeats` calls of `f`.
  template <typename Function>
  double
  best_time(const unsigned int repeats, const Function &f)
  {
    double best = 1e300;
    for (unsigned int r = 0; r < repeats; ++r)
      {
        const auto start = std::chrono::steady_clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      }
    return best;
  }

  int
  measure_modes(std::vector<unsigned int> storeys)
  {
    if (storeys.empty())
      storeys = {15, 30, 60, 150};
    for (const unsigned int n_storeys : storeys)
      {
        InputParameters     p = read_parameters("input/three-storey-frame.prm");
        BuildingParameters &b = p.model.buildings[0];
        b.n_storeys           = n_storeys;
        b.n_bays              = 3;
        b.elements_per_member = 2;
        const Model model = build_model(p.model, p.contact, p, p.springs, p.friction);
        const LinearSystem s = assemble_mass_and_stiffness(model);
        Modes              dense, sparse;
        const double       t_sparse = best_time(3, [&] {
          sparse = compute_modes_sparse(s.mass, s.stiffness, s.influence, 6);
        });
        const double t_dense = best_time(s.n_equations() > 1000 ? 1 : 3, [&] {
          dense = compute_modes_dense(s.mass, s.stiffness, s.influence, 6);
        });
        double difference = 0;
        for (unsigned int j = 0; j < 6; ++j)
          difference = std::max(difference, std::abs(sparse.omega[j] / dense.omega[j] - 1));
        std::printf("modes: %3u storeys, %5u equations: dense %9.3f s, sparse %7.3f s "
                    "(%.0fx), frequencies differ by %.1e\n",
                    n_storeys, s.n_equations(), t_dense, t_sparse, t_dense / t_sparse, difference);
        std::fflush(stdout);
      }
    return 0;
  }
  int
  measure_reliability(const std::string &file)
  {
    const InputParameters                input = read_parameters(file);
    const ReliabilityAnalysisParameters &p     = input.reliability;
    p.require_problem(input);
    const LimitStateExpression g(p.expressions[0], p.variable_names, p.constants);
    std::vector<double>        x;
    for (const Distribution &d : p.distributions)
      x.push_back(d.mean());
    const unsigned long n   = 2000000;
    double              sum = 0;
    const double        t_expression = best_time(3, [&] {
      for (unsigned long i = 0; i < n; ++i)
        {
          x[0] += 1e-12; // a new value each time, as in sampling
          sum += g(x);
        }
    });
    ReliabilityProblem problem{NatafTransformation(p.distributions, p.correlation),
                               {[&](const std::vector<double> &v) { return g(v); }},
                               SystemType::series};
    SamplingSettings   settings;
    settings.max_samples = n;
    SamplingResult mc;
    const double   t_sampling = best_time(3, [&] { mc = monte_carlo(problem, settings); });
    std::printf("reliability %s: expression '%s'\n  %.3g evaluations/s of the expression "
                "alone, %.3g samples/s of crude Monte Carlo (g(T(u)) with the random "
                "numbers; Pf = %.4g)\n",
                file.c_str(), p.expressions[0].c_str(), n / t_expression, n / t_sampling,
                mc.probability);
    ReliabilityProblem all{NatafTransformation(p.distributions, p.correlation), {}, p.system};
    std::vector<std::unique_ptr<LimitStateExpression>> parsers;
    for (const std::string &e : p.expressions)
      {
        parsers.push_back(std::make_unique<LimitStateExpression>(e, p.variable_names, p.constants));
        LimitStateExpression *parser = parsers.back().get();
        all.limit_states.push_back([parser](const std::vector<double> &v) { return (*parser)(v); });
      }
    for (unsigned int k = 0; k < all.limit_states.size(); ++k)
      {
        const FormResult f = form(all, k);
        std::printf("  FORM on %s: beta %.6f, %u iterations, %u gradients, %lu evaluations%s\n",
                    p.limit_state_names[k].c_str(), f.beta, f.iterations, f.n_gradients,
                    f.n_evaluations, f.converged ? "" : " (not converged)");
      }
    return sum == 12345.678; // keeps `sum` alive
  }
} // namespace

namespace
{
  const char *const bench_usage =
    "usage: poundfe-bench [FILE [REPEATS]]      steps/s of FILE (default input/two-buildings.prm)\n"
    "                                          and of the benchmark models, per linear solver\n"
    "       poundfe-bench --output [REPEATS]    every output at every step, CSV and .npy\n"
    "       poundfe-bench --montecarlo FILE N   N realizations of FILE (mpirun -np P ...)\n"
    "       poundfe-bench --distributed FILE    one model over the MPI ranks (bench/city_block.sh)\n"
    "       poundfe-bench --partitioned FILE [END [SAVE]]  the model over the ranks by building\n"
    "       poundfe-bench --serial FILE [END [SAVE]]       the same on one process (reference)\n"
    "       poundfe-bench --bifurcation FILE    the values of FILE's Bifurcation section\n"
    "       poundfe-bench --step-rate [REPEATS [MODEL...] [off|csv|npy]]  bench/step-rate.txt\n"
    "       poundfe-bench --modes [STOREYS...]  dense against sparse eigensolver\n"
    "       poundfe-bench --reliability [FILE]  limit-state evaluations per second\n"
    "       poundfe-bench --help\n"
    "Run from the repository root (the inputs are named relative to it); Release build.\n";
} // namespace

int
main(int argc, char **argv)
try
{
  if (argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))
    {
      std::cout << bench_usage;
      return 0;
    }
  if (argc > 1 && argv[1][0] == '-' &&
      !std::set<std::string>{"--montecarlo", "--distributed", "--partitioned", "--serial",
                             "--bifurcation", "--output", "--step-rate",
                             "--modes", "--reliability"}
         .count(argv[1]))
    {
      std::cerr << "poundfe-bench: unknown option '" << argv[1] << "'\n" << bench_usage;
      return 1;
    }
  // --montecarlo runs over MPI, and the solver comparison includes PETSc and
  // Trilinos, which need it initialised: both modes initialise it.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc > 3 && std::string(argv[1]) == "--montecarlo")
    return measure_monte_carlo(argv[2], std::stoul(argv[3]), MPI_COMM_WORLD);
  if (argc > 2 && std::string(argv[1]) == "--distributed")
    return measure_distributed(argv[2], MPI_COMM_WORLD);
  if (argc > 2 && (std::string(argv[1]) == "--partitioned" || std::string(argv[1]) == "--serial"))
    return measure_partitioned(argv[2], argc > 3 ? std::stod(argv[3]) : 0,
                               argc > 4 ? argv[4] : "", std::string(argv[1]) == "--serial",
                               MPI_COMM_WORLD);
  if (argc > 2 && std::string(argv[1]) == "--bifurcation")
    return measure_bifurcation(argv[2]);
  if (argc > 1 && std::string(argv[1]) == "--reliability")
    return measure_reliability(argc > 2 ? argv[2] : "input/thesis-cantilever-reliability.prm");
  if (argc > 1 && std::string(argv[1]) == "--output")
    return measure_output(argc > 2 ? std::stoi(argv[2]) : 10);
  if (argc > 1 && std::string(argv[1]) == "--step-rate")
    return measure_step_rate(argc > 2 ? std::stoi(argv[2]) : 5,
                             std::set<std::string>(argv + std::min(argc, 3), argv + argc));
  if (argc > 1 && std::string(argv[1]) == "--modes")
    {
      std::vector<unsigned int> storeys;
      for (int i = 2; i < argc; ++i)
        storeys.push_back(std::stoul(argv[i]));
      return measure_modes(storeys);
    }
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
catch (const InputError &e)
{
  std::cerr << "poundfe-bench: error: " << e.what() << "\n";
  return 1;
}
catch (const std::exception &e) // std::stoul of a bad count, a failed run
{
  std::cerr << "poundfe-bench: error: " << e.what() << "\n" << bench_usage;
  return 1;
}
