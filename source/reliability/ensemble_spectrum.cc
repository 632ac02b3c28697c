// The response spectra of an ensemble of stochastic ground motions
// (reliability/ensemble_spectrum.h).
#include <poundfe/reliability/ensemble_spectrum.h>
#include <poundfe/base/interruption.h>
#include <poundfe/excitation/response_spectrum.h>

#include <cmath>

namespace poundfe
{
  EnsembleSpectrum
  compute_ensemble_spectrum(const MotionGenerator &generator, const double scale_factor,
                   std::vector<double> periods, const std::vector<double> &damping_ratios,
                   const unsigned int n_realizations)
  {
    EnsembleSpectrum                         ensemble;
    const unsigned int               n_columns = damping_ratios.size() * periods.size();
    std::vector<std::vector<double>> psa(n_columns), measures(5);
    std::vector<double>              xi(generator.n_variables()), samples;
    for (unsigned int r = 0; r < n_realizations; ++r)
      {
        throw_if_interrupted();
        standard_normals(generator.motion().seed, r, xi);
        generator.generate(xi.data(), samples);
        GroundMotion motion(generator.motion().sample_interval, samples,
                            generator.description(), generator.held());
        motion.scale(scale_factor);
        const ResponseSpectrum spectrum = response_spectrum(motion, periods, damping_ratios);
        for (unsigned int d = 0; d < damping_ratios.size(); ++d)
          for (unsigned int i = 0; i < periods.size(); ++i)
            psa[d * periods.size() + i].push_back(spectrum.psa(d, i));
        const GroundMotionIntensity m = ground_motion_intensity(motion);
        const double values[] = {m.pga, m.pgv, m.pgd, m.arias_intensity, m.significant_duration};
        for (unsigned int k = 0; k < 5; ++k)
          measures[k].push_back(values[k]);
      }
    for (const std::vector<double> &values : psa)
      ensemble.psa.push_back(describe(values));
    for (const std::vector<double> &values : measures)
      ensemble.measures.push_back(describe(values));
    ensemble.periods = std::move(periods);
    return ensemble;
  }

  SpectrumMatching
  match_target(const EnsembleSpectrum &ensemble, const SpectrumParameters &s, const double t1,
               const std::string &source)
  {
    SpectrumMatching m;
    m.period     = t1;
    m.source     = source;
    m.damping_ratio = s.damping_ratios.front();
    m.target_psa = s.target_psa(s.damping_ratios.front(), t1);
    m.mean_psa   = ensemble.at(0, ensemble.n_grid).mean; // T1 follows the grid
    m.std_psa    = ensemble.at(0, ensemble.n_grid).standard_deviation;
    m.s0_factor  = m.mean_psa > 0 ? std::pow(m.target_psa / m.mean_psa, 2) : 0;
    return m;
  }
} // namespace poundfe
