// The `Output` section: where and how often results are written, with its
// `Recorders` subsection (output/recorder_parameters.h).
#ifndef poundfe_output_output_parameters_h
#define poundfe_output_output_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/output/recorder_parameters.h>

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// The format of the field output (Output/Field format): ParaView's VTU
  /// files with a .pvd index, or one HDF5 file with an XDMF index.
  enum class FieldFormat
  {
    vtu,
    xdmf
  };

  const NameTable<FieldFormat> &field_format_names();

  struct OutputParameters
  {
    std::string        directory    = "results";
    double             interval     = 0.0; // of CSV rows, s; 0 = every step
    double             vtu_interval = 0.1; // 0 = no VTU
    unsigned int       max_vtu_frames = 2000; // a longer run widens the VTU interval
    bool               vtu_impact_peaks = false; // a frame at each impact's peak too
    FieldFormat        field_format   = FieldFormat::vtu;
    bool               plots        = true;
    unsigned int       n_modes      = 6;
    bool               floor_spectra = false; // floor_spectra.csv of a run
    bool               demand_tables = false; // demands_<building>.csv (pelicun) of a run
    RecorderParameters recorders;
    /// Output/Warnings (output/response_range.h); 0: no warning.
    double             drift_warning    = 0.10; // storey drift ratio, roof displacement / height
    double             rotation_warning = 0.10; // rad, of any node

    /// Declare the `Output` section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// Parse the recorders and check. Throws InputError.
    void finalize(const InputFile &input);
  };
} // namespace poundfe

#endif
