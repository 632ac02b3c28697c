// One realization of the random loading through the model, and the scalar
// responses the probabilistic analyses use. The model, the excitation and
// the time-history engine are built once; a realization only rewrites the
// random samples (StochasticLoad::apply) and restarts from rest.
// With random model parameters (set_random_parameters), a realization's
// standard normals are those of the loading followed by one per parameter
// (the loading's are the same with and without them); the parameters'
// values are written into a working copy of the model
// (dynamics/model_parameter.h): the time-history engine is made again only
// when one enters M, K or C, otherwise only its nonlinear elements are.
#ifndef poundfe_dynamics_realization_h
#define poundfe_dynamics_realization_h

#include <poundfe/dynamics/model_parameter.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/excitation/stochastic_load.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/section_limit_states.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class RealizationRunner
  {
  public:
    /// Throws InputError when the input has no random loading.
    RealizationRunner(const Analysis &analysis, const TimeHistoryParameters &parameters);
    ~RealizationRunner();

    /// The standard normals of a realization: the loading's, then one per
    /// random model parameter.
    unsigned int n_variables() const { return load.n_variables() + n_parameters(); }
    unsigned int n_load_variables() const { return load.n_variables(); }
    unsigned int n_parameters() const { return structure ? structure->parameters().size() : 0; }

    /// Maps the parameters' standard normals u to their values x.
    using ParameterTransform =
      std::function<void(const std::vector<double> &u, std::vector<double> &x)>;
    /// Makes `parameters` random: their values are to_physical of the last
    /// n_parameters() normals of each realization, and response columns
    /// named `names` after the others. `eigensolver`: for the modes of a
    /// building whose K and Rayleigh damping at modes change. Call once,
    /// before any run.
    void set_random_parameters(std::vector<ModelParameter> random_parameters,
                               const std::vector<std::string> &names,
                               ParameterTransform to_physical, Eigensolver eigensolver);
    /// Responses a realization computes only when asked (a limit state
    /// names them, or the demand tables need them): per storey the residual
    /// drift ratio IDR(t_end) at the end of the record, signed (abs() for
    /// its size) ("<building>_storey<i>_residual_drift_ratio"), per gap j
    /// (1-based, Model's order) the largest peak force of its impacts
    /// ("gap<j>_peak_contact_force", N), per gap its impacts
    /// ("gap<j>_impacts") and their largest approach speed
    /// ("gap<j>_peak_impact_velocity", m/s), the peak ground acceleration
    /// of the realization as applied ("peak_ground_acc_m_s2", along x), and
    /// of a 3D model per floor the peak rotation |theta_z|
    /// ("<building>_floor<i>_peak_rotation_rad"), the peak ground
    /// acceleration along y ("peak_ground_acc_y_m_s2") and per storey the
    /// residual drift ratio along y, signed
    /// ("<building>_storey<i>_residual_drift_ratio_y").
    std::vector<std::string> optional_response_names() const;
    /// Adds the columns of those of `wanted` that are optional responses
    /// (others are ignored), after the standard ones. Call before
    /// set_random_parameters and before any run.
    void add_optional_responses(const std::vector<std::string> &wanted);
    const StochasticLoad &stochastic_load() const { return load; }
    bool has_gaps() const { return !analysis.model.gaps.empty(); }
    /// The model as built (before any random parameter is applied).
    const Model &model() const { return analysis.model; }

    /// The limits the fibre members' damage states are measured against
    /// (default: the Section limits section's defaults). Call before any run.
    void set_section_limits(const SectionLimitParameters &limits) { section_limits = limits; }
    /// A model with members on fibre sections has a column per storey of
    /// each building, "<building>_storey<i>_damage_state": the damage state
    /// of the realization's worst member of that storey (output/
    /// section_limit_states.h, the pushover's damage_state columns), as the
    /// number of the worst limit reached, 0 none, 1 bar yield, 2 spalling,
    /// 3 crushing, 4 bar fracture (damage_state_name(n - 1)). Those
    /// columns, in FloorResponse order (none without fibre members).
    const std::vector<unsigned int> &damage_state_columns() const { return damage_columns; }

    /// Names of the response columns (realizations.csv, after 'realization,completed').
    const std::vector<std::string> &response_names() const { return names; }
    /// Column of a named response; throws std::out_of_range if absent.
    unsigned int column(const std::string &name) const;
    /// Columns of the peak drift ratios of a building's storeys (building
    /// 1-based), or of storey `storey` alone (1-based; 0: all): along x and,
    /// for a 3D model, along y.
    std::vector<unsigned int> drift_columns(unsigned int building, unsigned int storey = 0) const;
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
    unsigned long n_steps() const { return history->n_steps(excitation); }

  private:
    /// Writes the parameters of the normals xi[n_load_variables()...] into
    /// the working model, remakes what they enter and records their values
    /// in `parameter_values`.
    void apply_parameters(const std::vector<double> &xi);
    /// The optional responses' columns of a run's row.
    void fill_optional_responses(std::vector<double> &responses) const;
    /// The time history of the normals xi (parameters applied first);
    /// `damage`: with the fibre members' limit states observed too.
    RunStatus run_with(const std::vector<double> &xi, const Observers &observers,
                       double amplitude_factor, bool damage = false);
    /// The damage state columns of a run's row.
    void fill_damage_states(std::vector<double> &responses) const;

    const Analysis          &analysis;
    const TimeHistoryParameters parameters;
    Excitation               excitation;
    StochasticLoad           load; // after the excitation it is made from
    std::unique_ptr<ModelRealization> structure; // random model parameters (or none)
    ParameterTransform                to_physical;
    std::vector<double>               parameter_normals, parameter_values;
    /// on the working model of `structure` when there is one
    std::unique_ptr<TimeHistory>  history;
    std::unique_ptr<PeakResponse> peaks; // the one observer of a realization
    /// The fibre members' limit states of the last run (with damage state
    /// columns): made again for each run, on the elements it runs.
    SectionLimitParameters              section_limits;
    std::unique_ptr<SectionLimitStates> section_states;
    std::vector<unsigned int>           damage_columns;
    std::vector<std::string> names;
    std::vector<double>      xi;
    std::vector<unsigned int> roof_floor; // FloorResponse index of each building's roof
    unsigned int first_floor_column = 0, first_roof_column = 0, max_drift_column = 0;
    unsigned int first_plan_column = 0, first_parameter_column = 0;
    /// An optional response: what it is, of which storey (FloorResponse
    /// index) or gap.
    struct OptionalResponse
    {
      enum Kind : unsigned char
      {
        residual_drift,
        peak_force,
        impacts,
        impact_velocity,
        ground_acceleration,
        rotation,
        ground_acceleration_y,
        residual_drift_y
      } kind;
      unsigned int index;
      std::string  name;
    };
    /// Every optional response, in the order of optional_response_names().
    std::vector<OptionalResponse> optional_responses() const;
    /// the optional responses asked for, in that order: the columns from
    /// first_residual_column on
    std::vector<OptionalResponse> chosen;
    unsigned int                  first_residual_column = 0;
  };
} // namespace poundfe

#endif
