// Dynamic FORM (reliability/dynamic_form.h): the time-history limit state as
// a ReliabilityProblem in the standard normals of the loading and the
// parameters, solved by form().
#include <poundfe/dynamics/realization.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/reliability/dynamic_form.h>
#include <poundfe/reliability/random_parameters.h>

#include <deal.II/base/exceptions.h>

namespace poundfe
{
  namespace
  {
    /// The marginals of dynamic FORM's variables: the scale factor's, then
    /// standard normals for the excitation's and the parameters'; their
    /// names appended to `names`.
    std::vector<Distribution>
    variables_of(const RealizationRunner &runner, const DynamicFormSettings &settings,
                 std::vector<std::string> &names)
    {
      const unsigned int        n_p = runner.n_parameters(), n_e = settings.n_excitation;
      std::vector<Distribution> marginals = settings.scale;
      for (unsigned int i = 0; i < n_e + n_p; ++i)
        marginals.push_back(Distribution::from_moments(DistributionType::normal, 0, 1));
      if (!settings.scale.empty())
        names.push_back("scale");
      for (unsigned int i = 0; i < n_e; ++i)
        names.push_back("xi" + std::to_string(i + 1));
      const std::vector<std::string> &columns = runner.response_names();
      names.insert(names.end(), columns.end() - n_p, columns.end());
      return marginals;
    }
  } // namespace

  DynamicFormResult
  dynamic_form(RealizationRunner &runner, const ResponseLimitStates &limit_states,
               const DynamicFormSettings &settings)
  {
    const unsigned int n_load = runner.n_load_variables(), n_p = runner.n_parameters();
    const unsigned int n_s = settings.scale.size(), n_e = settings.n_excitation;
    AssertThrow(n_e <= n_load && n_s <= 1, dealii::ExcMessage("dynamic FORM variables"));

    DynamicFormResult               result;
    const std::vector<Distribution> marginals =
      variables_of(runner, settings, result.variable_names);

    // the held normals of the loading, then G(x) = system value of one run
    std::vector<double> held(runner.n_variables());
    standard_normals(runner.stochastic_load().seed(), settings.realization, held);
    std::vector<double> xi, row;
    bool                gradients = true; // FORM, SORM: an infinite g is no value either
    const auto          run = [&](const std::vector<double> &x) {
      xi = held;
      std::copy(x.begin() + n_s, x.begin() + n_s + n_e, xi.begin());
      std::copy(x.begin() + n_s + n_e, x.end(), xi.begin() + n_load);
      ++result.n_time_histories;
      if (!runner.run(xi, row, n_s ? x[0] : 1.0))
        ++result.n_failed_runs;
      return limit_states.system_value(row,
                                       "time history " + std::to_string(result.n_time_histories) +
                                         " of dynamic FORM",
                                       gradients);
    };
    ReliabilityProblem problem{NatafTransformation(marginals), {run}, SystemType::series};
    result.form = form(problem, 0, settings.form);
    if (result.form.converged && settings.sorm)
      {
        const unsigned long before = result.n_time_histories;
        result.sorm = sorm(problem, 0, result.form, settings.form.gradient_step);
        result.n_sorm_time_histories = result.n_time_histories - before;
      }
    if (result.form.converged && settings.importance_samples > 0)
      {
        // the check of FORM's Pf: unbiased whatever the curvature
        SamplingSettings sampling;
        sampling.max_samples = settings.importance_samples;
        sampling.seed        = settings.importance_seed;
        gradients            = false;
        result.importance = importance_sampling(problem, {result.form.design_point_u}, sampling);
        gradients         = true;
        if (!result.importance->interrupted)
          result.form_check = form_disagreement(result.form.probability, *result.importance);
      }

    if (!result.form.design_point_x.empty())
      {
        result.design_limit_state = run(result.form.design_point_x);
        result.design_responses   = row;
        result.design_point.assign(result.form.design_point_x.begin(),
                                   result.form.design_point_x.begin() + n_s + n_e);
        result.design_point.insert(result.design_point.end(), row.end() - n_p, row.end());
      }
    return result;
  }
} // namespace poundfe
