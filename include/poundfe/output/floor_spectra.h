// Floor response spectra of a run: the elastic response spectra
// (excitation/response_spectrum.h, Nigam & Jennings 1969) of every floor's
// absolute acceleration a_abs = u'' + a_g (output/floor_response.h) and of
// the ground acceleration, computed while the run steps: the spectral
// oscillators are advanced from one observed state to the next, a_abs
// linear in between, at the steps and at the sub-steps of a cut step (the
// step varies near contacts), so no history is stored. The spectra end
// with the run (no free vibration is added: the floors would keep moving).
// Written at the end as floor_spectra.csv: period_s, then for each damping
// ratio the ground's and each floor's pseudo-acceleration omega^2 Sd.
#ifndef poundfe_output_floor_spectra_h
#define poundfe_output_floor_spectra_h

#include <poundfe/excitation/response_spectrum.h>
#include <poundfe/output/observer.h>
#include <poundfe/output/peak_response.h>

#include <string>
#include <vector>

namespace poundfe
{
  class MemoryResults;

  class FloorSpectra : public StepObserver
  {
  public:
    /// Reads the floors' absolute accelerations from `peaks`, which must be
    /// observed before this. With `memory` the table goes there, not to a
    /// file (output/table_writer.h).
    FloorSpectra(const PeakResponse &peaks, const std::vector<double> &periods,
                 const std::vector<double> &damping_ratios, std::string directory,
                 MemoryResults *memory = nullptr);

    void initialize(const ResponseView &state) override;
    void observe_step(const ResponseView &state) override;
    void observe_substep(const ResponseView &state) override { observe_step(state); }
    void finish(const ResponseView &state, const RunStatus &status) override;
    /// Observation by rank, before finish(): each floor's peaks from the
    /// rank that owns its building, on rank 0. Collective.
    void merge(const RankMerge &ranks) override;

    static constexpr const char *file_name = "floor_spectra.csv";
    /// Column of floor f (FloorResponse index) at damping d; 1-based, for gnuplot.
    unsigned int column(unsigned int d, unsigned int f) const;

  private:
    /// Floor f's peak displacement of oscillator `oscillator`, merged or its own.
    double peak_displacement(unsigned int f, unsigned int oscillator) const;

    const PeakResponse              &peaks;
    const std::string                directory;
    MemoryResults                   *memory;
    SpectralOscillators              ground;
    std::vector<SpectralOscillators> floors;
    /// After merge(): floor f's peak displacements (oscillator i) at
    /// [f * n + i], n oscillators per floor; empty: the floors' own.
    std::vector<double> merged;
  };
} // namespace poundfe

#endif
