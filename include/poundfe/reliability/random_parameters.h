// The `Random parameters` section: numeric parameters of the model that are
// random in the time-history sampling commands (montecarlo, subset,
// fragility), and limit states over a realization's responses and those
// parameters (uncertain structures).
//   set Variables    = NAME: PATH ~ DISTRIBUTION KEY VALUE ...; ...
//       PATH: an input entry (dynamics/model_parameter.h lists them), a
//       list entry with [i]; DISTRIBUTION and KEYs as Reliability/Random
//       variables (reliability/distribution.h).
//   set Correlation  = rows separated by ';' (Nataf; empty: independent)
//   set Limit states = NAME: EXPRESSION; ...   failure: g <= 0
//       over the response columns of realizations.csv (e.g.
//       A_storey2_peak_drift_ratio, max_drift_ratio, peak_contact_force,
//       n_impacts; A_storey2_residual_drift_ratio and gap1_peak_contact_force
//       are computed, and written, only when named) and the variables' NAMEs
//       (muParser, limit_state.h)
//   set System       = series | parallel
// A realization's standard normals are the loading's, then one per variable
// (u), mapped by the Nataf transformation to the values x = T(u) that the
// model takes (dynamics/realization.h): Subset Simulation moves in the
// joint standard normal space of loading and structure.
#ifndef poundfe_reliability_random_parameters_h
#define poundfe_reliability_random_parameters_h

#include <poundfe/base/input_file.h>
#include <poundfe/dynamics/modal_parameters.h>
#include <poundfe/reliability/form.h>
#include <poundfe/reliability/limit_state.h>
#include <poundfe/reliability/nataf.h>
#include <poundfe/reliability/reliability_problem.h>
#include <poundfe/reliability/statistics.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  class RealizationRunner;
  struct InputFile;
  struct ModelParameters;
  struct ContactParameters;

  struct RandomParameterParameters
  {
    // as written
    std::string variables_text, correlation_text, limit_states_text;
    SystemType  system = SystemType::series;

    // dynamic FORM (`poundfe form`): the subsection FORM
    std::string   form_excitation_text = "0", form_scale_text;
    unsigned long form_realization     = 0;
    FormSettings  form{20, 1e-3, 1e-3, 1e-2, false};
    /// dynamic-form after FORM: SORM (Breitung, Tvedt) from the Hessian at
    /// u*, and importance sampling around u*, the check of FORM's Pf (0
    /// samples: none)
    bool          form_sorm               = false;
    unsigned long form_importance_samples = 400;

    // parsed by check()
    std::vector<std::string>  names, paths;
    /// "all" in Excitation variables: every normal of the loading.
    bool                      form_all_excitation = false;
    unsigned int              form_n_excitation   = 0;
    std::vector<Distribution> form_scale; // the scale factor's, or none
    std::vector<Distribution> distributions;
    DenseMatrix               correlation; // empty: independent
    std::vector<std::string>  limit_state_names, expressions;

    void declare(dealii::ParameterHandler &prm);
    /// Parses the section (InputError naming the entry: a variable not
    /// 'NAME: PATH ~ DISTRIBUTION ...' or named twice, impossible
    /// distribution parameters, a correlation matrix that is not symmetric
    /// positive definite, a limit state not 'NAME: EXPRESSION' or given
    /// twice). The paths and the expressions' names
    /// are checked against the model by attach_random_parameters and
    /// ResponseLimitStates.
    void check(const InputFile &input);
    void declare_form(dealii::ParameterHandler &prm);
    void check_form(const InputFile &input);
    bool has_variables() const { return !names.empty(); }
    bool has_limit_states() const { return !expressions.empty(); }
  };

  /// Adds to `runner` the optional responses the limit states name
  /// (RealizationRunner::optional_response_names) and makes the section's
  /// variables random in it: InputError at
  /// Random parameters/Variables for a path the model does not have or
  /// cannot vary, a distribution that can sample values the parameter
  /// cannot take (e.g. a normal stiffness: use a lognormal or a truncated
  /// normal with lower >= 0), a variable named like a column of
  /// realizations.csv, or two variables that write into one model value.
  /// `input` is the file (for messages) and `model_input`, `contact_input`
  /// its model and contact sections, which the runner's model was built
  /// from (the hinges' origins, what the builder maps: dynamics/
  /// model_parameter.h).
  void attach_random_parameters(RealizationRunner &runner, const RandomParameterParameters &p,
                                const InputFile &input, const ModelParameters &model_input,
                                const ContactParameters &contact_input, Eigensolver eigensolver);

  /// The section's limit states g_k over a row of responses (the runner's
  /// response_names(), which end with the variables' values).
  class ResponseLimitStates
  {
  public:
    /// InputError at Random parameters/Limit states for an expression that
    /// names something that is neither a response nor a variable.
    ResponseLimitStates(const RandomParameterParameters &p, const std::vector<std::string> &columns,
                        const InputFile &input);

    unsigned int n_limit_states() const { return limit_states.size(); }
    const std::vector<std::string> &names() const { return limit_state_names; }
    SystemType system() const { return system_type; }
    /// g_k of a row. A NaN (an expression undefined there, e.g. the sqrt
    /// of a negative: the row is neither safe nor failed), or an infinite
    /// value when `refuse_infinite` (a gradient method), is a
    /// NumericalError naming the limit state, its expression, `sample`
    /// ("realization 3") and the values the expression reads.
    double operator()(unsigned int k, const std::vector<double> &row, const std::string &sample,
                      bool refuse_infinite = false) const;
    /// min_k g_k (series) or max_k g_k (parallel): the system fails when <= 0.
    /// Each g_k checked as by operator().
    double system_value(const std::vector<double> &row, const std::string &sample,
                        bool refuse_infinite = false) const;

  private:
    std::string undefined_message(unsigned int k, double g, const std::string &sample) const;

    std::vector<std::string>          limit_state_names;
    std::vector<LimitStateExpression> limit_states;
    /// per limit state, the names it reads and their places in `values`
    std::vector<std::vector<std::pair<unsigned int, std::string>>> used_names;
    std::vector<unsigned int>         used_columns; // of the row, in the expressions' order
    SystemType                        system_type;
    mutable std::vector<double>       values;
  };

  /// P(g_k <= 0) of each limit state and of the system over the rows of
  /// `completed` realizations (crude Monte Carlo: failures / n, CoV
  /// sqrt((1 - P)/(n P))); `realizations`: the rows' numbers, for the
  /// NumericalError of a limit state that is NaN on one.
  struct LimitStateProbabilities
  {
    std::vector<ProbabilityEstimate> limit_states;
    ProbabilityEstimate              system;
  };
  LimitStateProbabilities
  limit_state_probabilities(const ResponseLimitStates                &limit_states,
                            const std::vector<std::vector<double>> &rows,
                            const std::vector<bool>                &completed,
                            const std::vector<std::uint64_t>       &realizations);
} // namespace poundfe

#endif
