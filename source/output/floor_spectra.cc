#include <poundfe/output/csv_writer.h>
#include <poundfe/output/floor_spectra.h>
#include <poundfe/output/memory_results.h>

#include <cmath>
#include <memory>

namespace poundfe
{
  FloorSpectra::FloorSpectra(const PeakResponse &peaks, const std::vector<double> &periods,
                             const std::vector<double> &damping_ratios, std::string directory,
                             MemoryResults *memory)
    : peaks(peaks)
    , directory(std::move(directory))
    , memory(memory)
    , ground(periods, damping_ratios)
    , floors(peaks.floors().n_floors(), SpectralOscillators(periods, damping_ratios))
  {}

  void
  FloorSpectra::initialize(const ResponseView &state)
  {
    const std::vector<double> &a = peaks.floors().absolute_acceleration();
    ground.start(state.time(), state.ground_acceleration());
    for (unsigned int f = 0; f < floors.size(); ++f)
      floors[f].start(state.time(), a[f]);
  }

  void
  FloorSpectra::observe_step(const ResponseView &state)
  {
    const std::vector<double> &a = peaks.floors().absolute_acceleration();
    ground.advance_to(state.time(), state.ground_acceleration());
    for (unsigned int f = 0; f < floors.size(); ++f)
      floors[f].advance_to(state.time(), a[f]);
  }

  double
  FloorSpectra::peak_displacement(const unsigned int f, const unsigned int oscillator) const
  {
    const std::vector<double> &own = floors[f].peak_displacement();
    return merged.empty() ? own[oscillator] : merged[f * own.size() + oscillator];
  }

  void
  FloorSpectra::merge(const RankMerge &ranks)
  {
    merged.clear();
    std::vector<unsigned int> floor_of;
    for (unsigned int f = 0; f < floors.size(); ++f)
      {
        const std::vector<double> &own = floors[f].peak_displacement();
        merged.insert(merged.end(), own.begin(), own.end());
        floor_of.insert(floor_of.end(), own.size(), f);
      }
    ranks.owned(Owner::floor, floor_of, merged);
  }

  unsigned int
  FloorSpectra::column(const unsigned int d, const unsigned int f) const
  {
    return 2 + d * (1 + floors.size()) + 1 + f;
  }

  void
  FloorSpectra::finish(const ResponseView &, const RunStatus &)
  {
    const std::vector<double> &periods = ground.periods();
    const std::vector<double> &zetas   = ground.damping_ratios();
    std::vector<std::string>   header{"period_s"};
    for (const double zeta : zetas)
      {
        const std::string suffix = "psa_m_s2_" + damping_label(zeta);
        header.push_back("ground_" + suffix);
        for (const std::string &name : peaks.floors().column_names("floor", suffix))
          header.push_back(name);
      }
    const std::string            stem = "floor_spectra";
    std::unique_ptr<TableWriter> table =
      memory ? memory->table_writer(stem, header) :
               std::make_unique<CsvWriter>(directory + "/" + file_name, header);
    std::vector<double> row;
    for (unsigned int i = 0; i < periods.size(); ++i)
      {
        const double w2 = std::pow(2 * M_PI / periods[i], 2);
        row.clear();
        for (unsigned int d = 0; d < zetas.size(); ++d)
          {
            row.push_back(w2 * ground.peak_displacement()[ground.index(d, i)]);
            for (unsigned int f = 0; f < floors.size(); ++f)
              row.push_back(w2 * peak_displacement(f, floors[f].index(d, i)));
          }
        table->add_row(periods[i], row);
      }
    table->commit();
  }
} // namespace poundfe
