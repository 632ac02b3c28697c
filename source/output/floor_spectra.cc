#include <poundfe/output/csv_writer.h>
#include <poundfe/output/floor_spectra.h>

#include <cmath>

namespace poundfe
{
  FloorSpectra::FloorSpectra(const PeakResponse &peaks, const std::vector<double> &periods,
                             const std::vector<double> &damping_ratios, std::string directory)
    : peaks(peaks)
    , directory(std::move(directory))
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
    CsvWriter csv(directory + "/" + file_name, header);
    for (unsigned int i = 0; i < periods.size(); ++i)
      {
        const double w2 = std::pow(2 * M_PI / periods[i], 2);
        csv.begin_row(periods[i]);
        for (unsigned int d = 0; d < zetas.size(); ++d)
          {
            csv.add(w2 * ground.peak_displacement()[ground.index(d, i)]);
            for (unsigned int f = 0; f < floors.size(); ++f)
              csv.add(w2 * peak_displacement(f, floors[f].index(d, i)));
          }
        csv.end_row();
      }
    csv.commit();
  }
} // namespace poundfe
