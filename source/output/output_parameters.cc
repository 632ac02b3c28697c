#include <poundfe/output/output_parameters.h>

#include <deal.II/base/parameter_handler.h>

namespace poundfe
{
  void
  OutputParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.add_parameter("Directory", directory,
                      "Results directory (relative to the working directory).");
    prm.add_parameter("Output interval", interval,
                      "Interval of the time series' rows, s (0: every step); rounded to a whole "
                      "number of time steps.");
    add_choice(prm, "Format", recorders.format,
               "Format of the time series: csv (<name>.csv: a header line, then numbers in the "
               "shortest form that reads back exactly) or npy (<name>.npy: NumPy format 1.0, "
               "float64 rows x columns, little-endian, C order, with the column names in "
               "<name>.columns.txt; for long or large runs; no plots of time series).",
               output_format_names());
    prm.add_parameter("VTU interval", vtu_interval, "Interval of VTU frames, s (0: none).");
    prm.add_parameter("Plots", plots, "Make PNG plots with gnuplot.");
    prm.add_parameter("Floor spectra", floor_spectra,
                      "A run also writes floor_spectra.csv (and floor_spectra.png): the "
                      "response spectra of every floor's absolute acceleration (and of the "
                      "ground) at the periods and damping ratios of the Spectrum section, "
                      "computed while the run steps (sub-steps included).");
    prm.add_parameter("Number of modes", n_modes,
                      "Modes reported (0: no modal analysis, for a large model whose "
                      "damping needs no modes).",
                      dealii::Patterns::Integer(0));
    prm.enter_subsection("Recorders");
    recorders.declare(prm);
    prm.leave_subsection();
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
