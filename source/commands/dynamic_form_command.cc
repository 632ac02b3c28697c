// `poundfe dynamic-form FILE`: FORM on the time-history limit state of the
// Random parameters section (its Limit states as a series or parallel
// system) in the loading's first normals, an optional scale factor and the
// random model parameters (reliability/dynamic_form.h). Writes summary.json
// (beta, Pf, design point, alpha, time histories) and design_point.csv (per
// variable: x*, u*, alpha), with FORM's Pf checked by importance sampling
// around the design point (a warning when they disagree). Exit 2, with
// those files, when FORM does not converge (no design point at all when
// the gradient is zero at the start).
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/reliability/dynamic_form.h>
#include <poundfe/reliability/random_parameters.h>

#include <sstream>

namespace poundfe::commands
{
  namespace
  {
    /// The engine's settings from the section, checked against the runner.
    DynamicFormSettings
    form_settings(const InputParameters &input, const RealizationRunner &runner)
    {
      const RandomParameterParameters &p = input.random_parameters;
      if (!p.has_limit_states())
        input.fail("Random parameters/Limit states",
                   "dynamic-form needs a limit state over the responses");
      DynamicFormSettings settings;
      settings.n_excitation =
        p.form_all_excitation ? runner.n_load_variables() : p.form_n_excitation;
      if (settings.n_excitation > runner.n_load_variables())
        input.fail("Random parameters/FORM/Excitation variables",
                   std::to_string(p.form_n_excitation) + " is more than the loading's " +
                     std::to_string(runner.n_load_variables()) + " normals");
      if (settings.n_excitation + runner.n_parameters() + p.form_scale.size() == 0)
        input.fail("Random parameters/FORM/Excitation variables",
                   "FORM has no variable: no Variables, no Scale factor and 0 excitation "
                   "variables");
      settings.realization = p.form_realization;
      settings.scale       = p.form_scale;
      settings.form        = p.form;
      settings.sorm               = p.form_sorm;
      settings.importance_samples = p.form_importance_samples;
      settings.importance_seed    = runner.stochastic_load().seed();
      return settings;
    }

    std::string
    design_point_csv(const DynamicFormResult &r)
    {
      std::ostringstream csv;
      csv.precision(12);
      csv << "variable,x_star,u_star,alpha\n";
      for (std::size_t i = 0; i < r.variable_names.size(); ++i)
        csv << r.variable_names[i] << ',' << r.design_point[i] << ','
            << r.form.design_point_u[i] << ',' << r.form.alpha[i] << '\n';
      return csv.str();
    }

    /// Why FORM failed, naming the limit states ("" when it converged).
    std::string
    form_failure(const InputParameters &input, const DynamicFormResult &r)
    {
      if (r.form.converged)
        return "";
      const RandomParameterParameters &p = input.random_parameters;
      std::string                      named;
      for (std::size_t k = 0; k < p.limit_state_names.size(); ++k)
        named += (k == 0 ? "'" : ", '") + p.limit_state_names[k] + "' (" + p.expressions[k] + ")";
      return "dynamic FORM on limit state" + std::string(p.limit_state_names.size() > 1 ? "s " : " ") +
             named + ": " + r.form.failure +
             (r.form.zero_gradient_at_start ? "" : " (the last iterate is reported)");
    }

    void
    write_checks(JsonWriter &json, const DynamicFormResult &r)
    {
      if (r.sorm)
        json.begin_object("sorm")
          .value("curvatures", r.sorm->curvatures)
          .value("breitung", r.sorm->breitung)
          .value("tvedt", r.sorm->tvedt)
          .value("beta_breitung", r.sorm->beta_breitung)
          .value("beta_tvedt", r.sorm->beta_tvedt)
          .value("time_histories", r.n_sorm_time_histories)
          .end_object();
      if (r.importance)
        json.begin_object("importance_sampling")
          .value("failure_probability", r.importance->probability)
          .value("cov", undefined_if_infinite(r.importance->coefficient_of_variation))
          .value("samples", r.importance->n_samples)
          .value("failures", r.importance->n_failures)
          .value("agrees_with_form", r.form_check.empty())
          .end_object();
    }

    std::string
    summary_json(const InputParameters &input, const DynamicFormResult &r)
    {
      JsonWriter json;
      begin_summary(json, "dynamic-form", input,
                    !r.form.converged        ? "failed" :
                    !r.form_check.empty()    ? "completed with warnings" :
                                               "completed");
      if (!r.form.converged)
        json.value("failure", form_failure(input, r));
      if (!r.form_check.empty())
        json.value("warnings", std::vector<std::string>{r.form_check});
      json.value("converged", r.form.converged);
      // no direction at all: no beta, Pf or design point to report
      if (!r.form.zero_gradient_at_start)
        json.value("beta", r.form.beta)
          .value("failure_probability", r.form.probability)
          .value("iterations", r.form.iterations);
      json.value("gradient_evaluations", r.form.n_gradients)
        .value("time_histories", r.n_time_histories)
        .value("failed_time_histories", r.n_failed_runs);
      if (!r.form.zero_gradient_at_start)
        json.value("limit_state_at_design_point", r.design_limit_state)
          .value("variables", r.variable_names)
          .value("design_point_x", r.design_point)
          .value("design_point_u", r.form.design_point_u)
          .value("alpha", r.form.alpha);
      write_checks(json, r);
      json.end_object();
      return json.str();
    }

    void
    report(const CommandRun &run, const DynamicFormResult &result)
    {
      if (!result.form.zero_gradient_at_start)
        run.out << "dynamic FORM: beta = " << result.form.beta
                << ", Pf = " << result.form.probability << " (" << result.form.iterations
                << " iterations, " << result.n_time_histories << " time histories)\n";
      if (result.sorm)
        run.out << "SORM: Pf = " << result.sorm->breitung << " (Breitung), "
                << result.sorm->tvedt << " (Tvedt)\n";
      if (result.importance)
        run.out << "importance sampling: Pf = " << result.importance->probability << " (COV "
                << result.importance->coefficient_of_variation << ", "
                << result.importance->n_samples << " time histories)\n";
      if (!result.form_check.empty())
        run.err << "poundfe: warning: " << result.form_check << "\n";
      run.out << "results in " << run.results_place() << " (summary.json"
              << (result.form.design_point_u.empty() ? "" : ", design_point.csv") << ")\n";
    }
  } // namespace

  int
  dynamic_form(const CommandRun &run)
  {
    const InputParameters &input    = *run.input;
    const Analysis         analysis = prepare_analysis(input);
    RealizationRunner      runner(analysis, time_history_parameters(input));
    attach_random_parameters(runner, input.random_parameters, input, input.model, input.contact, input.modal.eigensolver);
    const ResponseLimitStates limit_states(input.random_parameters, runner.response_names(),
                                           input);
    const DynamicFormSettings settings = form_settings(input, runner);
    if (!run.memory)
      prepare_output_directory(run.directory);
    const DynamicFormResult result = poundfe::dynamic_form(runner, limit_states, settings);
    if (!result.form.design_point_u.empty())
      write_result_text(run.memory, run.directory, "design_point.csv", design_point_csv(result));
    write_result_text(run.memory, run.directory, "summary.json", summary_json(input, result));
    report(run, result);
    if (!result.form.converged)
      {
        run.err << "poundfe: numerical failure: " << form_failure(input, result) << "\n";
        return 2;
      }
    return 0;
  }
} // namespace poundfe::commands
