#include <poundfe/commands/command_table.h>

#include <sstream>

namespace poundfe
{
  // The entry point of each command, one file each in source/commands/.
  namespace commands
  {
    int run(const CommandRun &);            // run_command.cc
    int modal(const CommandRun &);          // modal_command.cc
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
    int print_parameters(const CommandRun &); // print_parameters_command.cc
    int input_template(const CommandRun &); // template_command.cc
  } // namespace commands

  const std::vector<Command> &
  command_table()
  {
    // name, arguments, description,
    // reads parameters, runs over MPI, handles interruption itself, takes --realizations, function
    static const std::vector<Command> table = {
      {"run", "FILE", "time-history analysis (summary.json, CSV, VTU, PNG)",
       true, false, true, false, commands::run},
      {"modal", "FILE", "frequencies, periods, participating masses, modes.pvd",
       true, false, false, false, commands::modal},
      {"ground-motion", "FILE [--realizations N]",
       "the ground acceleration a run would use (CSV, PNG); with N,\n"
       "realizations 0..N-1 and their ensemble PSD against the target",
       true, false, false, true, commands::ground_motion},
      {"spectrum", "FILE [--realizations N]",
       "response spectrum (Sd, PSV, PSA), PGA/PGV/PGD, Arias intensity,\n"
       "D5-95 of the ground motion; with N, the ensemble mean spectrum\n"
       "against the Spectrum section's target and the S0 that matches it",
       true, false, false, true, commands::spectrum},
      {"montecarlo", "FILE", "Monte Carlo over the random loading (MPI: mpirun -np P ...)",
       true, true, true, false, commands::montecarlo},
      {"subset", "FILE", "Subset Simulation of a small exceedance probability (MPI)",
       true, true, true, false, commands::subset},
      {"fragility", "FILE", "Monte Carlo over PGA levels, lognormal fragility curves (MPI)",
       true, true, true, false, commands::fragility},
      {"stationary-pdf", "FILE",
       "stationary PDFs of a noisy response: histogram, kernel density,\n"
       "peaks, joint p(x, v) (MPI)",
       true, true, true, false, commands::stationary_pdf},
      {"sweep", "FILE",
       "the run's peaks against the values of the Sweep section's\n"
       "parameter (sweep.csv, sweep.png, summary.json)",
       true, false, true, false, commands::sweep},
      {"bifurcation", "FILE",
       "Poincare samples, their period and the largest Lyapunov\n"
       "exponent against the Bifurcation section's parameter",
       true, false, true, false, commands::bifurcation},
      {"site-hazard", "FILE",
       "site intensity and PGA of a catalogue's earthquakes, Gumbel or\n"
       "Poisson fit, return periods, fragility x hazard; the earthquake\n"
       "coefficient, OBE and MCE of a Site study",
       true, false, false, false, commands::site_hazard},
      {"separation", "FILE",
       "joint width of adjacent buildings: ABS, SRSS, DDC, EC8 and\n"
       "ASCE 7 rules against the time history without contact (or\n"
       "by response spectrum, Separation/Peak displacements); with\n"
       "random loading, P(pounding) against the gap (MPI)\n"
       "and, with a site hazard, P(pounding in T years) and the gap\n"
       "for a target (Separation/Site hazard)",
       true, true, true, false, commands::separation},
      {"mitigation", "FILE",
       "the bare pair against viscous dampers of each size and bumpers\n"
       "(Mitigation section): drifts, floor accelerations, impacts,\n"
       "P(pounding) and the required gap of each case (MPI)",
       true, true, true, false, commands::mitigation},
      {"reliability", "FILE",
       "failure probability of algebraic limit states (Reliability\n"
       "section): FORM, SORM, importance sampling, Monte Carlo, subset",
       true, true, true, false, commands::reliability},
      {"dynamic-form", "FILE",
       "FORM on a time-history limit state (Random parameters):\n"
       "beta, Pf, design point, alpha, number of time histories",
       true, false, false, false, commands::dynamic_form},
      {"switching", "FILE",
       "Filippov switching analysis of a small model: each hit of a\n"
       "gap, its rate in contact or a slip velocity classified as\n"
       "crossing, sliding (stick), grazing or sliding exit; sliding by\n"
       "the convex method (switching.csv, phase_portrait.png)",
       true, false, false, false, commands::switching},
      {"print-parameters", "", "every parameter with its documentation and default",
       false, false, false, false, commands::print_parameters},
      {"template", "KIND",
       "a commented starting file on standard output, KIND one of\n"
       "frame, shear, mesh, pounding, stochastic\n"
       "(poundfe template frame > my-frame.prm)",
       false, false, false, false, commands::input_template},
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

  namespace
  {
    /// The names of the commands with `property`, as "a, b, c and d".
    std::string
    names_of(bool Command::*property)
    {
      std::vector<std::string> names;
      for (const Command &command : command_table())
        if (command.*property)
          names.push_back(command.name);
      std::string list;
      for (std::size_t i = 0; i < names.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
      return list;
    }
  } // namespace

  std::string
  usage_text()
  {
    const std::size_t  column = 22; // where the descriptions start
    std::ostringstream out;
    out << "usage: poundfe <command> [FILE] [--output DIR]\n"
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
    out << "--output DIR overrides the file's 'Output/Directory'. Any other option is an error.\n"
           "Exit status: 0 done (summary.json \"completed\", or \"completed with warnings\"\n"
           "listing the figures gnuplot could not draw), 1 bad input or command line (one\n"
           "message, nothing written), 2 numerical failure (results so far kept; also a\n"
           "result that would be NaN or inf, named), 128 + signal when interrupted.\n"
           "SIGINT (Ctrl-C) or SIGTERM stops "
        << names_of(&Command::handles_interruption_itself)
        << "\nafter the step, value or realizations under way, with the results so far\n"
           "(status \"interrupted\", exit status 128 + signal); montecarlo, fragility,\n"
           "stationary-pdf and separation resume when run again, the others start over.\n"
           "Any other command stops at its next file write or\n"
           "time step: no *.tmp left, summary.json says \"interrupted\". A file that cannot be\n"
           "written (full disk) exits 1 with summary.json \"failed\" and the reason, when it\n"
           "still fits; so does an output estimated larger than the free disk, before it starts.\n"
           "A second signal kills. Progress shows on a terminal (POUNDFE_PROGRESS=1: always).\n";
    return out.str();
  }
} // namespace poundfe
