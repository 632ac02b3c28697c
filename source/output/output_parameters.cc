#include <poundfe/output/output_parameters.h>

#include <deal.II/base/parameter_handler.h>

namespace poundfe
{
  const NameTable<FieldFormat> &
  field_format_names()
  {
    static const NameTable<FieldFormat> table({{FieldFormat::vtu, "vtu"}, {FieldFormat::xdmf, "xdmf"}});
    return table;
  }

  namespace
  {
    /// Output/Warnings: the run's warning thresholds.
    void
    declare_warning_entries(dealii::ParameterHandler &prm, OutputParameters &p)
    {
      prm.enter_subsection("Warnings");
      prm.add_parameter("Drift ratio", p.drift_warning,
                        "A run warns (console and summary.json 'warnings') when a storey's peak "
                        "drift ratio, or a building's peak roof displacement over its height, "
                        "exceeds this: 2.5 times the collapse-prevention drift of concrete "
                        "frames (0.04, FEMA 356 Table C1-3), which the elastic members and the "
                        "Bouc-Wen hinges (no strength loss) cannot represent. 0: no warning. "
                        "Unit: dimensionless.",
                        dealii::Patterns::Double(0));
      prm.add_parameter("Rotation", p.rotation_warning,
                        "A run warns when a node of a frame rotates more than this: the frame "
                        "elements assume small displacements (at 0.1 rad sin(theta) differs from "
                        "theta by 0.17 % and a chord shortens by 0.5 %). 0: no warning. Unit: rad.",
                        dealii::Patterns::Double(0));
      prm.leave_subsection();
    }
  } // namespace

  void
  OutputParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.add_parameter("Directory", directory,
                      "Results directory (relative to the working directory). Unit: -.");
    prm.add_parameter("Output interval", interval,
                      "Interval of the time series' rows (0: every step); rounded to a whole "
                      "number of time steps. Unit: s.");
    add_choice(prm, "Format", recorders.format,
               "Format of the time series: csv (<name>.csv: a header line, then numbers in the "
               "shortest form that reads back exactly) or npy (<name>.npy: NumPy format 1.0, "
               "float64 rows x columns, little-endian, C order, with the column names in "
               "<name>.columns.txt; for long or large runs; no plots of time series). Unit: -.",
               output_format_names());
    prm.add_parameter("VTU interval", vtu_interval, "Interval of VTU frames (0: none). "
                      "Unit: s.");
    add_choice(prm, "Field format", field_format,
               "Format of the field output (the frames of VTU interval, and the modes of "
               "'modal'): vtu (solution.pvd indexing one solution/solution-NNNNN.vtu per "
               "frame) or xdmf (one HDF5 file, solution.h5: the points and cells once, then a "
               "group per frame with the same arrays as the VTU files, indexed by "
               "solution.xdmf, an XDMF 3 temporal collection that ParaView opens; for large "
               "models and many frames). Only run and modal write fields: other commands "
               "refuse xdmf. Unit: -.",
               field_format_names());
    prm.add_parameter("Maximum VTU frames", max_vtu_frames,
                      "Most VTU frames a run writes: when End time / VTU interval would give "
                      "more, the interval is widened to fit and the console says so. Unit: count.",
                      dealii::Patterns::Integer(2));
    prm.add_parameter("VTU impact peaks", vtu_impact_peaks,
                      "A run also writes a VTU frame at the peak of each impact (the step at "
                      "which the gaps' total force stops rising), besides the frames of VTU "
                      "interval; a run partitioned by building writes the same frames as the "
                      "whole model's run. These frames are not counted in Maximum VTU frames (a "
                      "run with much chatter writes many). Unit: -.");
    prm.add_parameter("Plots", plots, "Make PNG plots with gnuplot. Unit: -.");
    prm.add_parameter("Floor spectra", floor_spectra,
                      "A run also writes floor_spectra.csv (and floor_spectra.png): the "
                      "response spectra of every floor's absolute acceleration (and of the "
                      "ground) at the periods and damping ratios of the Spectrum section, "
                      "computed while the run steps (sub-steps included). Unit: -.");
    prm.add_parameter("Demand tables", demand_tables,
                      "A run also writes demands_<building>.csv: each building's peak "
                      "drifts, floor accelerations and displacements, roof drift, residual "
                      "drifts and displacements and its gaps' impacts in pelicun's demand-sample "
                      "convention (output/demand_table.h; user guide, \"Demands for a loss "
                      "model\"); montecarlo writes the same tables, without displacements, a "
                      "row per completed realization, and msa a table per stripe, "
                      "demands_<building>_stripe<j>.csv, a row per run that did not collapse. "
                      "Unit: -.");
    prm.add_parameter("Number of modes", n_modes,
                      "Modes reported (0: no modal analysis, for a large model whose "
                      "damping needs no modes). Unit: count.",
                      dealii::Patterns::Integer(0));
    prm.enter_subsection("Recorders");
    recorders.declare(prm);
    prm.leave_subsection();
    declare_warning_entries(prm, *this);
    prm.leave_subsection();
  }

  void
  OutputParameters::finalize(const InputFile &input)
  {
    recorders.finalize(input.file, input.line_of("Output/Recorders/Record"), interval);
    input.non_negative("Output/Output interval", interval);
    input.non_negative("Output/VTU interval", vtu_interval);
    if (directory.empty())
      input.fail("Output/Directory", "must not be empty");
  }
} // namespace poundfe
