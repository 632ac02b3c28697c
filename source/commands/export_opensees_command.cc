// `poundfe export-opensees`: the model of a parameter file as an OpenSees
// 3.8 Tcl script (report/opensees_export.h describes it): DIR/model.tcl and
// the ground motion it reads, DIR/ground_motion.txt (a_g in m/s^2 at the
// time step). The script runs unchanged in OpenSees and in `poundfe
// opensees`; its recorders write floor_disp.out (time, then each floor's
// displacement relative to the ground) and gap_force.out beside it or in
// the directory its first argument names.
#include <poundfe/base/console.h>
#include <poundfe/commands/command.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/report/opensees_export.h>

#include <ostream>
#include <set>
#include <sstream>

namespace poundfe
{
  namespace
  {
    std::string
    joined(const std::vector<int> &tags)
    {
      std::string text;
      for (const int tag : tags)
        text += " " + std::to_string(tag);
      return text;
    }

    /// The recorders, with the names poundfe's own files give the columns.
    void
    write_recorders(const OpenSeesExport &e, std::ostream &tcl)
    {
      tcl << "# floor displacements relative to the ground (a floor of several nodes: their "
             "mean); columns: time";
      for (const std::string &name : e.floor_names)
        tcl << " " << comment_word(name);
      tcl << "\nrecorder Node -file [file join $out floor_disp.out] -time -precision 16 -node"
          << joined(e.floor_nodes) << " -dof " << e.floor_dofs << " disp\n";
      if (e.gap_elements.empty())
        return;
      tcl << "# gap forces (zeroLength force: node i, node j; compression closes); gaps:";
      for (const std::string &name : e.gap_names)
        tcl << " " << comment_word(name);
      tcl << "\nrecorder Element -file [file join $out gap_force.out] -time -precision 16 -ele"
          << joined(e.gap_elements) << " force\n";
    }

    std::string
    script_text(const OpenSeesExport &e, const std::string &input_file)
    {
      std::ostringstream tcl;
      tcl.precision(17);
      tcl << "# OpenSees 3.8 script of " << input_file << ", written by poundfe export-opensees.\n"
          << "# Runs in OpenSees and in `poundfe opensees`; argv: the directory of the\n"
          << "# recorder files (default: the script's own). Newmark at poundfe's time step,\n"
          << "# without poundfe's event location and step cutting at impacts.\n"
          << "set here [file dirname [info script]]\n"
          << "set out [expr {[info exists argv] && [llength $argv] > 0 ? [lindex $argv 0] : "
             "$here}]\n"
          << "wipe\nmodel basic -ndm " << e.ndm << " -ndf " << e.ndf << "\n";
      for (const std::string &line : e.model)
        tcl << line << "\n";
      for (const std::string &line : e.gravity)
        tcl << line << "\n";
      if (e.member_stiffness_damping != 0)
        tcl << "# the members' a1 K of the Rayleigh damping (betaKinit)\n"
            << "rayleigh 0.0 0.0 " << e.member_stiffness_damping << " 0.0\n";
      if (!e.damping_regions.empty())
        tcl << "# each frame's a1 K of the Rayleigh damping (betaKinit) on its members and "
               "hinges\n";
      for (const OpenSeesExport::DampingRegion &r : e.damping_regions)
        tcl << "region " << r.building << " -eleOnly" << joined(r.elements) << " -rayleigh 0.0 0.0 "
            << r.a1 << " 0.0 ;# " << comment_word(r.name) << "\n";
      tcl << "# the ground motion, a_g (m/s^2) at the time step\n"
          << "timeSeries Path 1 -dt " << e.time_step
          << " -filePath [file join $here ground_motion.txt]\n"
          << "pattern UniformExcitation 1 1 -accel 1\n";
      write_recorders(e, tcl);
      tcl << "constraints " << e.constraints() << "\nnumberer Plain\nsystem BandGeneral\n"
          << (e.nonlinear ? "test NormDispIncr 1.0e-12 " + std::to_string(e.test_iterations) +
                              "\nalgorithm Newton\n" :
                            std::string("algorithm Linear\n"))
          << "integrator Newmark " << e.gamma << " " << e.beta << "\n"
          << "analysis Transient\n"
          << "set status [analyze " << e.n_steps << " " << e.time_step << "]\n"
          << "puts \"status $status time [getTime]\"\n";
      return tcl.str();
    }
  } // namespace
} // namespace poundfe

namespace poundfe::commands
{
  int
  export_opensees(const CommandRun &run)
  {
    const InputParameters      &input      = *run.input;
    const TimeHistoryParameters parameters = time_history_parameters(input);
    const Analysis              analysis   = prepare_analysis(input);
    const OpenSeesExport        e =
      describe_opensees(analysis, parameters, make_excitation(analysis, parameters));

    prepare_output_directory(run.directory);
    std::ostringstream record;
    record.precision(17);
    for (const double a : e.ground_acceleration)
      record << a << "\n";
    write_file_atomically(run.directory + "/ground_motion.txt", record.str());
    write_file_atomically(run.directory + "/model.tcl", script_text(e, parameters.input.file));
    const std::set<std::string> floors(e.floor_names.begin(), e.floor_names.end());
    run.out << "poundfe export-opensees: " << floors.size() / (e.ndm == 3 ? 3 : 1) << " floors, "
            << e.gap_elements.size() << " gaps, " << e.n_steps << " steps of " << e.time_step
            << " s\nresults in " << run.directory << "/ (model.tcl, ground_motion.txt)\n";
    return 0;
  }
} // namespace poundfe::commands
