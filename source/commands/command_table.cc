#include <poundfe/commands/command_table.h>

#include <sstream>

namespace poundfe
{
  // The entry point of each command, one file each in source/commands/.
  namespace commands
  {
    int run(const CommandRun &);            // run_command.cc
    int modal(const CommandRun &);          // modal_command.cc
    int pushover(const CommandRun &);       // pushover_command.cc
    int ground_motion(const CommandRun &);  // ground_motion_command.cc
    int spectrum(const CommandRun &);       // spectrum_command.cc
    int montecarlo(const CommandRun &);     // montecarlo_command.cc
    int subset(const CommandRun &);         // subset_command.cc
    int fragility(const CommandRun &);      // fragility_command.cc
    int stationary_pdf(const CommandRun &); // stationary_pdf_command.cc
    int sweep(const CommandRun &);          // sweep_command.cc
    int bifurcation(const CommandRun &);    // bifurcation_command.cc
    int site_hazard(const CommandRun &);    // site_hazard_command.cc
    int separation(const CommandRun &);     // separation_command.cc
    int reliability(const CommandRun &);    // reliability_command.cc
    int dynamic_form(const CommandRun &);   // dynamic_form_command.cc
    int mitigation(const CommandRun &);     // mitigation_command.cc
    int switching(const CommandRun &);      // switching_command.cc
    int moment_curvature(const CommandRun &); // moment_curvature_command.cc
    int print_parameters(const CommandRun &); // print_parameters_command.cc
    int input_template(const CommandRun &); // template_command.cc
    int opensees(const CommandRun &);       // opensees_command.cc
    int export_opensees(const CommandRun &); // export_opensees_command.cc
    int ida(const CommandRun &);            // ida_command.cc
    int msa(const CommandRun &);            // msa_command.cc
    int select_records(const CommandRun &); // select_records_command.cc
  } // namespace commands

  const std::vector<Command> &
  command_table()
  {
    // The columns of the rules (CommandRule in command.h): what a row may
    // be given and what it does.
    constexpr CommandRules file = CommandRule::reads_file; // one parameter file
    constexpr CommandRules mpi  = CommandRule::over_mpi;   // splits its work over the ranks
    constexpr CommandRules own_interruption = CommandRule::own_interruption; // finishes its files
    constexpr CommandRules realizations     = CommandRule::takes_realizations; // --realizations N
    constexpr CommandRules distributed_solver = CommandRule::distributed_solver; // on > 1 rank
    constexpr CommandRules partition = CommandRule::partition_by_building; // Partition = buildings
    constexpr CommandRules fields    = CommandRule::field_output; // Output/Field format = xdmf
    constexpr CommandRules rigid     = CommandRule::rigid_contact; // Contact/Model = nonsmooth
    constexpr CommandRules resumable = CommandRule::resumable;    // resumes its table
    constexpr CommandRules script    = CommandRule::script_arguments; // SCRIPT [ARGS...]
    constexpr CommandRules memory    = CommandRule::in_memory; // results in memory (Python)
    constexpr CommandRules none;
    const std::string      summary = "summary.json"; // what the guard writes
    // name, arguments, description, rules, summary, function
    static const std::vector<Command> table = {
      {"run", "FILE", "time-history analysis (summary.json, CSV, VTU, PNG)",
       file | own_interruption | distributed_solver | partition | fields | rigid, summary,
       commands::run},
      {"modal", "FILE",
       "frequencies, periods, participating masses, mode shapes\n"
       "(mode_shapes.csv, modes.pvd)",
       file | fields | memory, summary, commands::modal},
      {"pushover", "FILE",
       "static pushover after the gravity state: capacity curve, storey\n"
       "drifts and hinges (pushover.csv, PNG), EC8 bilinear curve, N2 and\n"
       "ASCE 41 target displacements",
       file | memory, summary, commands::pushover},
      {"ground-motion", "FILE [--realizations N [--write-at2]]",
       "the ground acceleration a run would use (CSV, PNG); with N,\n"
       "realizations 0..N-1 and their ensemble PSD against the target;\n"
       "--write-at2: each also as a PEER AT2 file, with a record suite\n"
       "(records/suite.csv) for the IDA section",
       file | realizations | CommandRule::writes_at2 | memory, summary, commands::ground_motion},
      {"spectrum", "FILE [--realizations N]",
       "response spectrum (Sd, PSV, PSA), PGA/PGV/PGD, Arias intensity,\n"
       "D5-95 of the ground motion; with N, the ensemble mean spectrum\n"
       "against the Spectrum section's target and the S0 that matches it",
       file | realizations | memory, summary, commands::spectrum},
      {"montecarlo", "FILE", "Monte Carlo over the random loading (MPI: mpirun -np P ...)",
       file | mpi | own_interruption | resumable | memory | rigid, summary, commands::montecarlo},
      {"subset", "FILE", "Subset Simulation of a small exceedance probability (MPI)",
       file | mpi | own_interruption | resumable | memory | rigid, summary, commands::subset},
      {"fragility", "FILE", "Monte Carlo over PGA levels, lognormal fragility curves (MPI)",
       file | mpi | own_interruption | resumable | memory | rigid, summary, commands::fragility},
      {"ida", "FILE",
       "incremental dynamic analysis of the IDA section's record suite:\n"
       "hunt and fill to collapse per record, every demand at every\n"
       "intensity, fractile curves, collapse fragility (MPI)",
       file | mpi | own_interruption | resumable | memory | rigid, summary, commands::ida},
      {"msa", "FILE",
       "multiple-stripe and cloud analysis of the IDA section's suite at\n"
       "the MSA section's intensities or hazard return periods: fragility\n"
       "of collapse and each limit state, annual rates of exceedance (MPI)",
       file | mpi | own_interruption | resumable | memory | rigid, summary, commands::msa},
      {"select-records", "FILE",
       "select and scale records of a suite to a target spectrum (EC8,\n"
       "ASCE 7, a table, BSSA14's conditional mean spectrum): a suite file",
       file, summary, commands::select_records},
      {"stationary-pdf", "FILE",
       "stationary PDFs of a noisy response: histogram, kernel density,\n"
       "peaks, joint p(x, v) (MPI)",
       file | mpi | own_interruption | resumable | memory | rigid, summary,
       commands::stationary_pdf},
      {"sweep", "FILE",
       "the run's peaks against the values of the Sweep section's\n"
       "parameter (sweep.csv, sweep.png, summary.json)",
       file | own_interruption | memory | rigid, summary, commands::sweep},
      {"bifurcation", "FILE",
       "Poincare samples, their period and the largest Lyapunov\n"
       "exponent against the Bifurcation section's parameter",
       file | own_interruption | memory, summary, commands::bifurcation,
       "its Lyapunov exponent follows a neighbouring trajectory by Newmark's scheme on the "
       "contact law, and rigid contact has no law to follow it on (the neighbour of an "
       "impacting orbit needs the impacts' own linearisation); use a stiff penalty law"},
      {"site-hazard", "FILE",
       "site intensity and PGA of a catalogue's earthquakes, Gumbel or\n"
       "Poisson fit, return periods, fragility x hazard; the earthquake\n"
       "coefficient, OBE and MCE of a Site study",
       file | memory, summary, commands::site_hazard},
      {"separation", "FILE",
       "joint width of adjacent buildings: ABS, SRSS, DDC, EC8 and\n"
       "ASCE 7 rules against the time history without contact (or\n"
       "by response spectrum, Separation/Peak displacements); with\n"
       "random loading, P(pounding) against the gap (MPI)\n"
       "and, with a site hazard, P(pounding in T years) and the gap\n"
       "for a target (Separation/Site hazard)",
       file | mpi | own_interruption | resumable | memory | rigid, summary, commands::separation},
      {"mitigation", "FILE",
       "the bare pair against viscous dampers of each size and bumpers\n"
       "(Mitigation section): drifts, floor accelerations, impacts,\n"
       "P(pounding) and the required gap of each case (MPI)",
       file | mpi | own_interruption | resumable | memory | rigid, summary, commands::mitigation},
      {"reliability", "FILE",
       "failure probability of algebraic limit states (Reliability\n"
       "section): FORM, SORM, importance sampling, Monte Carlo, subset",
       file | mpi | own_interruption | memory, summary, commands::reliability},
      {"dynamic-form", "FILE",
       "FORM on a time-history limit state (Random parameters):\n"
       "beta, Pf, design point, alpha, number of time histories",
       file | memory, summary, commands::dynamic_form,
       "FORM differentiates the limit state by finite differences (Random "
       "parameters/FORM/Gradient step), and Moreau-Jean's time stepping takes an impact at "
       "the step in which the gap closes: a perturbation that moves an impact to the next step changes the peaks by "
       "a jump of the order of the step times the closing velocity, which a difference cannot "
       "tell from a slope; use a penalty law, whose contacts are located in time"},
      {"switching", "FILE",
       "Filippov switching analysis of a small model: each hit of a\n"
       "gap, its rate in contact or a slip velocity classified as\n"
       "crossing, sliding (stick), grazing or sliding exit; sliding by\n"
       "the convex method (switching.csv, phase_portrait.png)",
       file | memory, summary, commands::switching},
      {"moment-curvature", "FILE",
       "moment-curvature of a fibre section (Sections, Moment curvature)\n"
       "at constant axial force: first yield, peak, ultimate, ductility\n"
       "(moment_curvature.csv, summary.json, moment_curvature.png)",
       file, summary, commands::moment_curvature},
      {"export-opensees", "FILE",
       "the model as an OpenSees 3.8 Tcl script (model.tcl) with its ground\n"
       "motion (ground_motion.txt): shear buildings, linear gaps, Rayleigh\n"
       "damping, Newmark at the time step; what OpenSees cannot express is refused",
       file, "", commands::export_opensees},
      {"opensees", "SCRIPT [ARGS...]",
       "runs an OpenSees Tcl script (Tcl 8.6, OpenSees's commands on\n"
       "poundfe's engine; ARGS are the script's argv; see the user guide)",
       script, "", commands::opensees},
      {"print-parameters", "", "every parameter with its documentation and default",
       none, "", commands::print_parameters},
      {"template", "KIND",
       "a commented starting file on standard output, KIND one of\n"
       "frame, shear, mesh, pounding, stochastic\n"
       "(poundfe template frame > my-frame.prm)",
       none, "", commands::input_template},
    };
    return table;
  }

  const Command *
  find_command(const std::string &name)
  {
    for (const Command &command : command_table())
      if (command.name == name)
        return &command;
    return nullptr;
  }

  std::string
  command_names(const CommandRule rule, const std::string &quote)
  {
    std::vector<std::string> names;
    for (const Command &command : command_table())
      if (command.has(rule))
        names.push_back(quote + command.name + quote);
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i)
      list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return list;
  }

  std::string
  usage_text()
  {
    const std::size_t  column = 22; // where the descriptions start
    std::ostringstream out;
    out << "usage: poundfe <command> [FILE] [--output DIR] [--set Section/Entry=value]...\n"
           "       [--threads N]\n"
           "       poundfe --help | --version\n"
           "commands:\n";
    for (const Command &command : command_table())
      {
        const std::string synopsis =
          "  " + command.name + (command.arguments.empty() ? "" : " " + command.arguments);
        out << synopsis;
        if (synopsis.size() + 1 > column)
          out << "\n" << std::string(column, ' ');
        else
          out << std::string(column - synopsis.size(), ' ');
        for (const char c : command.description)
          out << c << (c == '\n' ? std::string(column, ' ') : "");
        out << "\n";
      }
    out << "--output DIR overrides the file's 'Output/Directory'. --set Section/Entry=value\n"
           "(repeatable, in order) sets an entry of FILE before it is checked, as the file\n"
           "would ('Section/Entry:k' sets the k-th field of a list entry). --threads N (1 by\n"
           "default) evaluates a time history's elements on N threads when at least 8 are\n"
           "other than uniaxial (fibre or 3D hinge members, biaxial storeys, plan contacts;\n"
           "under opensees: beam-column members), with the same numbers, and from 2 on\n"
           "formats and writes a run's CSV tables and opensees's recorder files on a thread\n"
           "of their own, with the same bytes; a command that runs no time history ignores\n"
           "it, one that reads no file refuses it. Any other option\n"
           "is an error. Time integration/Partition = buildings is taken only by "
        << command_names(CommandRule::partition_by_building, "'")
        << ",\na distributed linear solver on more than one rank only by "
        << command_names(CommandRule::distributed_solver, "'")
        << ", Output/Field\nformat = xdmf only by " << command_names(CommandRule::field_output, "'")
        << ".\n"
           "Exit status: 0 done (summary.json \"completed\", or \"completed with warnings\"\n"
           "listing the figures gnuplot could not draw), 1 bad input or command line (one\n"
           "message, nothing written), 2 numerical failure (results so far kept; also a\n"
           "result that would be NaN or inf, named), 128 + signal when interrupted.\n"
           "SIGINT (Ctrl-C) or SIGTERM stops "
        << command_names(CommandRule::own_interruption)
        << "\nafter the step, value or realizations under way, with the results so far\n"
           "(status \"interrupted\", exit status 128 + signal);\n"
        << command_names(CommandRule::resumable)
        << " resume when run again,\nthe others start over.\n"
           "Any other command stops at its next file write or\n"
           "time step: no *.tmp left, summary.json says \"interrupted\". A file that cannot be\n"
           "written (full disk) exits 1 with summary.json \"failed\" and the reason, when it\n"
           "still fits; so does an output estimated larger than the free disk, before it starts.\n"
           "A second signal kills. Progress shows on a terminal (POUNDFE_PROGRESS=1: always).\n";
    return out.str();
  }
} // namespace poundfe
