// The `Separation` section: the code-rule factors of the `separation`
// command (Eurocode 8 §4.4.2.7, ASCE 7-16 §12.12.3), its probability of
// pounding against the gap width (target probability, gap grid, band) and
// where the peak displacements come from (a time history, or the modal
// combination of the Eurocode 8 spectrum: separation/separation_spectrum.h).
#ifndef poundfe_separation_separation_parameters_h
#define poundfe_separation_separation_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/hazard/pounding_hazard_parameters.h>
#include <poundfe/base/input_file.h>

#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// Where the peak displacements of the rules come from.
  enum class PeakDisplacements
  {
    time_history,     // the run without contact (one record, or the Monte Carlo means)
    response_spectrum // modal combination of the Spectrum section's EC8 target
  };
  const NameTable<PeakDisplacements> &peak_displacements_names();

  /// How the modal peaks of the response-spectrum route are combined.
  enum class ModalCombination
  {
    cqc, // Der Kiureghian (1981)
    srss
  };
  const NameTable<ModalCombination> &modal_combination_names();

  struct SeparationParameters
  {
    /// One value for every building or one per building.
    std::vector<double> deflection_amplification{1.0}; // ASCE 7 C_d
    std::vector<double> importance_factor{1.0};        // ASCE 7 I_e
    std::vector<double> behaviour_factor{1.0};         // EC8 q (d_s = q d_e)
    double              coinciding_levels_factor = 0.7; // EC8 §4.4.2.7(4)
    double              target_probability       = 0.1; // of pounding, per event
    unsigned int        n_gap_values             = 200;
    std::vector<double> gap_values;                     // m; empty: the grid
    double              confidence_level         = 0.95;
    PeakDisplacements   peak_displacements       = PeakDisplacements::time_history;
    ModalCombination    modal_combination        = ModalCombination::cqc;
    unsigned int        n_spectrum_modes         = 0; // 0: EN 1998-1 §4.3.3.3.1(3)
    PoundingHazardParameters hazard; // the subsection Site hazard

    /// Declare the section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// `n_buildings`: the length of a per-building list. Throws InputError.
    void check(const InputFile &input, unsigned int n_buildings) const;
  };
} // namespace poundfe

#endif
