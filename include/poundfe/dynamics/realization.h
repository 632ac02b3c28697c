// One realization of the random loading through the model, and the scalar
// responses the probabilistic analyses use. The model, the excitation and
// the time-history engine are built once; a realization only rewrites the
// random samples (StochasticLoad::apply) and restarts from rest.
#ifndef poundfe_dynamics_realization_h
#define poundfe_dynamics_realization_h

#include <poundfe/dynamics/run.h>
#include <poundfe/excitation/stochastic_load.h>
#include <poundfe/output/peak_response.h>

#include <cstdint>
#include <string>
#include <vector>

namespace poundfe
{
  class RealizationRunner
  {
  public:
    /// Throws InputError when the input has no random loading.
    RealizationRunner(const Analysis &analysis, const TimeHistoryParameters &parameters);

    unsigned int n_variables() const { return load.n_variables(); }
    const StochasticLoad &stochastic_load() const { return load; }
    bool has_gaps() const { return !analysis.model.gaps.empty(); }

    /// Names of the response columns (realizations.csv, after 'realization,completed').
    const std::vector<std::string> &response_names() const { return names; }
    /// Column of a named response; throws std::out_of_range if absent.
    unsigned int column(const std::string &name) const;
    /// Columns of the peak drift ratios of a building's storeys (building 1-based).
    std::vector<unsigned int> drift_columns(unsigned int building) const;
    unsigned int roof_displacement_column(unsigned int building) const;

    /// Runs the sample of xi (amplitudes times amplitude_factor); fills
    /// `responses` in the order of response_names(); returns false when the
    /// integration failed (the responses are then those reached so far).
    bool run(const std::vector<double> &xi, std::vector<double> &responses,
             double amplitude_factor = 1);
    /// The same for the normals of (seed, realization).
    bool run(std::uint64_t realization, std::vector<double> &responses, double amplitude_factor = 1);

    /// Runs the noise of (seed, realization) (amplitudes times
    /// amplitude_factor) with `observers` in place of the peak responses;
    /// returns false when the integration failed.
    bool run(std::uint64_t realization, const Observers &observers, double amplitude_factor = 1);

    /// The PGA (g) of the input's Kanai-Tajimi or Clough-Penzien motion at
    /// amplitude factor 1: peak factor x its stationary standard deviation
    /// at the input's S0 x scale factor. S0 is proportional to PGA^2, so the
    /// amplitude factor a / reference_pga() gives PGA a. Throws InputError
    /// for another ground motion; `purpose` (e.g. "fragility curves") says
    /// what needs the scaling.
    double reference_pga(const std::string &purpose) const;
    /// Steps of the analysis time step in a realization.
    unsigned long n_steps() const { return history.n_steps(excitation); }

  private:
    const Analysis          &analysis;
    const TimeHistoryParameters parameters;
    Excitation               excitation;
    StochasticLoad           load; // after the excitation it is made from
    TimeHistory              history;
    PeakResponse             peaks; // the one observer of a realization
    std::vector<std::string> names;
    std::vector<double>      xi;
    std::vector<unsigned int> roof_floor; // FloorResponse index of each building's roof
    unsigned int first_floor_column = 0, first_roof_column = 0, max_drift_column = 0;
  };
} // namespace poundfe

#endif
