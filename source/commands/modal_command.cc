// `poundfe modal`: the frequencies, periods and participating masses of the
// model and of each building (summary.json), the mass-normalised mode shapes
// as tables (mode_shapes.csv, mode_shapes_<building>.csv: what Python's
// Modes holds, double for double) and drawn (modes.pvd, with a directory
// only: results in memory draw none).
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/foundation_periods.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/recorders.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/vtu_series.h>
#include <poundfe/report/run_summary.h>

#include <cstdio>
#include <ostream>

namespace poundfe
{
  namespace
  {
    /// summary.json's `foundations`: each compliant base's first periods.
    void
    write_foundation_periods(JsonWriter &json, const Model &model,
                             const std::vector<FoundationPeriods> &periods)
    {
      if (periods.empty())
        return;
      json.begin_array("foundations");
      for (const FoundationPeriods &p : periods)
        json.begin_object()
          .value("building", model.buildings[p.building].name)
          .value("fixed_base_period_s", p.fixed_base_period)
          .value("flexible_base_period_s", p.flexible_base_period)
          .value("period_ratio", p.ratio())
          .value("asce7_period_ratio", p.code_ratio)
          .value("effective_stiffness_N_m", p.effective_stiffness)
          .value("effective_height_m", p.effective_height)
          .end_object();
      json.end_array();
    }

    /// The table of the first periods on fixed and compliant bases.
    void
    print_foundation_periods(const Model &model, const std::vector<FoundationPeriods> &periods,
                             std::ostream &out)
    {
      if (periods.empty())
        return;
      out << "\nbuilding      T fixed (s)  T flexible (s)  T~/T  ASCE 7-16 19.2.1.1 T~/T\n";
      for (const FoundationPeriods &p : periods)
        {
          char line[160];
          std::snprintf(line, sizeof(line), "%-12s  %11.4f  %14.4f  %6.4f  %24.4f\n",
                        model.buildings[p.building].name.c_str(), p.fixed_base_period,
                        p.flexible_base_period, p.ratio(), p.code_ratio);
          out << line;
        }
    }

    /// summary.json: the model, its modes, and each building's modes and
    /// Rayleigh coefficients.
    std::string
    modal_summary(const Analysis &analysis, const InputFile &input,
                  const std::vector<FoundationPeriods> &periods)
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
      json.end_array();
      write_foundation_periods(json, analysis.model, periods);
      json.end_object();
      return json.str();
    }

    /// mode_shapes<suffix>.csv: one row per mode (its number, ω in rad/s,
    /// then its mass-normalised shape over the equations `labels`).
    void
    write_mode_shapes(const CommandRun &run, const std::string &suffix, const Modes &modes,
                      const std::vector<std::string> &labels)
    {
      std::vector<std::string> header{"mode", "omega_rad_s"};
      header.insert(header.end(), labels.begin(), labels.end());
      const std::unique_ptr<TableWriter> table =
        result_table_writer(run.memory, run.directory, "mode_shapes" + suffix, header);
      std::vector<double> row(labels.size() + 1);
      for (unsigned int i = 0; i < modes.n_modes(); ++i)
        {
          row[0] = modes.omega[i];
          for (std::size_t k = 0; k < labels.size(); ++k)
            row[k + 1] = modes.shapes(k, i);
          table->add_row(i + 1, row);
        }
      table->commit();
    }

    /// The model's mode shapes and each building's (its own equations).
    void
    write_all_mode_shapes(const CommandRun &run, const Analysis &analysis)
    {
      const std::vector<std::string> labels = equation_labels(analysis.model);
      write_mode_shapes(run, "", analysis.modes, labels);
      for (unsigned int b = 0; b < analysis.model.buildings.size(); ++b)
        {
          const auto range = analysis.model.equation_range(b);
          write_mode_shapes(run, "_" + analysis.model.buildings[b].name, analysis.building_modes[b],
                            std::vector<std::string>(labels.begin() + range[0],
                                                     labels.begin() + range[1]));
        }
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
    if (!run.memory)
      prepare_output_directory(run.directory);
    const std::vector<FoundationPeriods> periods = foundation_periods(analysis.model);
    const std::string summary = modal_summary(analysis, *run.input, periods);
    const FieldFormat format = run.input->output.field_format;
    if (!run.memory) // the drawn shapes: files only
      {
        VtuSeries modes(analysis.model, run.directory, "modes", format);
        for (unsigned int i = 0; i < analysis.modes.n_modes(); ++i)
          modes.write_mode(i + 1, analysis.modes.frequency(i), analysis.modes.shapes.col(i));
        modes.finish();
      }
    write_all_mode_shapes(run, analysis);
    write_result_text(run.memory, run.directory, "summary.json", summary);

    print_modes(analysis.modes, run.out);
    print_foundation_periods(analysis.model, periods, run.out);
    run.out << "results in " << run.results_place() << " (summary.json, mode_shapes*.csv"
            << (run.memory ? "" : format == FieldFormat::xdmf ? ", modes.xdmf" : ", modes.pvd")
            << ")\n";
    return 0;
  }
} // namespace poundfe::commands
