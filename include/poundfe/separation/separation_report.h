// The tables and figures of the separation engine's results
// (separation/separation.h, separation/separation_spectrum.h) as text and
// gnuplot figures, apart from any file: `poundfe separation` writes them
// (separation.csv, pounding_probability.csv, spectrum_modes.csv, the pairs
// of summary.json); a caller of the library (Python) can take them without
// files.
#ifndef poundfe_separation_separation_report_h
#define poundfe_separation_separation_report_h

#include <poundfe/model/model.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/plots.h>
#include <poundfe/separation/separation.h>
#include <poundfe/separation/separation_parameters.h>
#include <poundfe/separation/separation_spectrum.h>

#include <string>
#include <vector>

namespace poundfe
{
  /// separation.csv: per pair and level the displacements, the five rules'
  /// joint widths and the time history's (or, by `spectrum`, the modal
  /// combinations).
  std::string separation_table(const Model &model, const std::vector<AdjacentPair> &pairs,
                               const std::vector<PairResult> &results,
                               const SpectrumPeaks *spectrum);
  /// separation.png, drawn from separation.csv: one panel per pair.
  Plot separation_plot(const std::vector<AdjacentPair> &pairs, const SpectrumPeaks *spectrum,
                       bool monte_carlo);

  /// pounding_probability.csv: per gap of the grid (gap_grid) each pair's
  /// exceedances, P(pounding) and its Wilson band.
  std::string pounding_probability_table(const SeparationParameters &separation,
                                         const std::vector<AdjacentPair> &pairs,
                                         const std::vector<PairResult> &results);
  /// pounding_probability.png, drawn from pounding_probability.csv: one panel per pair.
  Plot pounding_probability_plot(const SeparationParameters &separation,
                                 const std::vector<AdjacentPair> &pairs,
                                 const std::vector<PairResult> &results);

  /// spectrum_modes.csv: each building's modes, their participation and spectral values.
  std::string spectrum_modes_table(const Model &model, const SpectrumPeaks &peaks);

  /// One pair's object of summary.json (`time_history`: the route by time
  /// history, which has the time history's width).
  void write_pair_json(JsonWriter &json, const SeparationParameters &separation, const Model &model,
                       const AdjacentPair &pair, const PairResult &result, bool time_history);
} // namespace poundfe

#endif
