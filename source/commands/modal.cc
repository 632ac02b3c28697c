// `poundfe modal`: the frequencies, periods and participating masses of the
// model and of each building (summary.json), and the mode shapes (modes.pvd).
#include <poundfe/commands/command.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/vtu_series.h>
#include <poundfe/report/run_summary.h>

#include <cstdio>
#include <ostream>

namespace poundfe
{
  namespace
  {
    /// summary.json: the model, its modes, and each building's modes and
    /// Rayleigh coefficients.
    std::string
    modal_summary(const Analysis &analysis, const InputFile &input)
    {
      JsonWriter json;
      json.begin_object().value("program", "poundfe").value("command", "modal").value(
        "input", input.file);
      write_model(json, analysis);
      json.begin_array("buildings");
      for (unsigned int b = 0; b < analysis.model.buildings.size(); ++b)
        {
          json.begin_object().value("name", analysis.model.buildings[b].name);
          write_modes(json, "modes", analysis.building_modes[b]);
          write_damping(json, analysis, b);
          json.end_object();
        }
      json.end_array().end_object();
      return json.str();
    }

    /// The table of the model's modes.
    void
    print_modes(const Modes &modes, std::ostream &out)
    {
      const bool plan = !modes.participating_mass_ratio_y.empty(); // a 3D model
      out << "mode  frequency (Hz)  period (s)  mass ratio (x)"
          << (plan ? "  mass ratio (y)  mass ratio (rz)\n" : "\n");
      for (unsigned int i = 0; i < modes.n_modes(); ++i)
        {
          char line[120];
          std::snprintf(line, sizeof(line), "%4u  %14.4f  %10.4f  %14.4f", i + 1,
                        modes.frequency(i), modes.period(i), modes.participating_mass_ratio[i]);
          out << line;
          if (plan)
            {
              std::snprintf(line, sizeof(line), "  %14.4f  %15.4f",
                            modes.participating_mass_ratio_y[i], modes.participating_mass_ratio_rz[i]);
              out << line;
            }
          out << "\n";
        }
    }
  } // namespace
} // namespace poundfe

namespace poundfe::commands
{
  int
  modal(const CommandRun &run)
  {
    const Analysis analysis = prepare_analysis(*run.input);
    prepare_output_directory(run.directory);
    const std::string summary = modal_summary(analysis, *run.input);
    VtuSeries         modes(analysis.model, run.directory, "modes");
    for (unsigned int i = 0; i < analysis.modes.n_modes(); ++i)
      modes.write_mode(i + 1, analysis.modes.frequency(i), analysis.modes.shapes.col(i));
    modes.finish();
    write_file_atomically(run.directory + "/summary.json", summary);

    print_modes(analysis.modes, run.out);
    run.out << "results in " << run.directory << "/ (summary.json, modes.pvd)\n";
    return 0;
  }
} // namespace poundfe::commands
