// `poundfe reliability FILE`: failure probabilities of algebraic limit
// states (the Reliability section) by FORM, SORM, importance sampling,
// Monte Carlo and Subset Simulation (reliability/reliability_analysis.h).
// Writes summary.json, design_points.csv (per limit state and variable: x*,
// u*, alpha, d beta/d mean, d beta/d sd) and estimates.csv (per method: Pf,
// generalized beta = -Phi^{-1}(Pf), COV, evaluations); each FORM is checked
// by importance sampling around its design point (a warning when they
// disagree). Exit 2, with those files, when FORM does not converge (Monte
// Carlo and subset still run), Subset Simulation stops short or a limit
// state is NaN at a sample.
#include <poundfe/base/interruption.h>
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/reliability/distribution.h>
#include <poundfe/reliability/reliability_analysis.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>

namespace poundfe::commands
{
  namespace
  {
    double
    generalized_beta(const double probability)
    {
      return probability > 0 && probability < 1 ? -standard_normal_quantile(probability) :
                                                  std::numeric_limits<double>::quiet_NaN();
    }

    std::string
    design_points_csv(const ReliabilityAnalysisParameters &p, const ReliabilityReport &report)
    {
      std::ostringstream csv;
      csv.precision(12);
      csv << "limit_state,variable,distribution,mean,sd,x_star,u_star,alpha,"
             "dbeta_dmean,dbeta_dsd\n";
      for (const LimitStateReliability &ls : report.limit_states)
        if (ls.form && ls.form->converged)
          for (std::size_t i = 0; i < p.variable_names.size(); ++i)
            {
              const Distribution &d = p.distributions[i];
              csv << ls.name << ',' << p.variable_names[i] << ',' << distribution_name(d.type())
                  << ',' << d.mean() << ',' << d.standard_deviation() << ','
                  << ls.form->design_point_x[i] << ',' << ls.form->design_point_u[i] << ','
                  << ls.form->alpha[i] << ',' << ls.form->dbeta_dmean[i] << ','
                  << ls.form->dbeta_dsd[i] << '\n';
            }
      return csv.str();
    }

    std::string
    estimates_csv(const ReliabilityReport &report)
    {
      std::ostringstream csv;
      csv.precision(12);
      // Subset Simulation's CoV lies between two bounds (the levels
      // uncorrelated, fully correlated); the other methods' upper bound is their CoV.
      csv << "method,failure_probability,generalized_beta,coefficient_of_variation,"
             "evaluations,wall_time_s,coefficient_of_variation_upper_bound\n";
      for (const SystemEstimate &e : report.estimates)
        csv << e.method << ',' << e.probability << ',' << generalized_beta(e.probability) << ','
            << e.coefficient_of_variation << ',' << e.n_evaluations << ',' << e.wall_time_s
            << ',' << e.coefficient_of_variation_upper_bound.value_or(e.coefficient_of_variation)
            << '\n';
      return csv.str();
    }

    void
    write_limit_state(JsonWriter &json, const LimitStateReliability &ls)
    {
      json.begin_object().value("name", ls.name).value("expression", ls.expression);
      if (ls.form)
        {
          const FormResult &f = *ls.form;
          json.begin_object("form")
            .value("converged", f.converged)
            .value("beta", f.beta)
            .value("failure_probability", f.probability)
            .value("iterations", f.iterations)
            .value("gradient_evaluations", f.n_gradients)
            .value("limit_state_evaluations", f.n_evaluations)
            .value("design_point_x", f.design_point_x)
            .value("design_point_u", f.design_point_u)
            .value("alpha", f.alpha)
            .value("dbeta_dmean", f.dbeta_dmean)
            .value("dbeta_dsd", f.dbeta_dsd);
          if (!f.converged)
            json.value("failure", f.failure);
          json.end_object();
        }
      if (ls.form_check)
        json.begin_object("form_check")
          .value("method", "importance sampling around the design point")
          .value("failure_probability", ls.form_check->probability)
          .value("coefficient_of_variation",
                 undefined_if_infinite(ls.form_check->coefficient_of_variation))
          .value("samples", ls.form_check->n_samples)
          .value("failures", ls.form_check->n_failures)
          .end_object();
      if (ls.sorm)
        json.begin_object("sorm")
          .value("curvatures", ls.sorm->curvatures)
          .value("breitung", ls.sorm->breitung)
          .value("tvedt", ls.sorm->tvedt)
          .value("beta_breitung", ls.sorm->beta_breitung)
          .value("beta_tvedt", ls.sorm->beta_tvedt)
          .value("limit_state_evaluations", ls.sorm->n_evaluations)
          .end_object();
      json.end_object();
    }

    std::string
    summary_json(const InputParameters &input, const ReliabilityReport &report,
                 const std::string &status)
    {
      const ReliabilityAnalysisParameters &p = input.reliability;
      JsonWriter                           json;
      begin_summary(json, "reliability", input, status);
      if (!report.failure.empty())
        json.value("failure", report.failure);
      if (!report.warnings.empty())
        json.value("warnings", report.warnings);
      json.value("system", p.system == SystemType::series ? "series" : "parallel");
      json.begin_array("random_variables");
      for (std::size_t i = 0; i < p.variable_names.size(); ++i)
        json.begin_object()
          .value("name", p.variable_names[i])
          .value("distribution", distribution_name(p.distributions[i].type()))
          .value("parameters", p.distributions[i].parameters())
          .value("mean", p.distributions[i].mean())
          .value("sd", p.distributions[i].standard_deviation())
          .end_object();
      json.end_array().begin_array("limit_states");
      for (const LimitStateReliability &ls : report.limit_states)
        write_limit_state(json, ls);
      json.end_array();
      if (report.bounds)
        json.begin_object("form_system_bounds")
          .value("lower", report.bounds->lower)
          .value("upper", report.bounds->upper)
          .end_object();
      json.begin_array("estimates");
      for (const SystemEstimate &e : report.estimates)
        {
          json.begin_object()
            .value("method", e.method)
            .value("failure_probability", e.probability)
            .value("generalized_beta", generalized_beta(e.probability))
            .value("coefficient_of_variation", undefined_if_infinite(e.coefficient_of_variation));
          if (e.coefficient_of_variation_upper_bound)
            json.value("coefficient_of_variation_upper_bound",
                       undefined_if_infinite(*e.coefficient_of_variation_upper_bound));
          json.value("limit_state_evaluations", e.n_evaluations)
            .value("wall_time_s", e.wall_time_s)
            .end_object();
        }
      json.end_array().end_object();
      return json.str();
    }
  } // namespace

  int
  reliability(const CommandRun &run)
  {
    const InputParameters &input = *run.input;
    input.reliability.require_problem(input);
    const bool writes = dealii::Utilities::MPI::this_mpi_process(run.communicator) == 0;
    if (writes && !run.memory)
      prepare_output_directory(run.directory);
    const ReliabilityReport report = run_reliability_analysis(input.reliability, run.communicator);
    const int status = report.interrupted ? interrupted_exit_status() :
                       !report.failure.empty() ? 2 : 0;
    if (!writes)
      return status;
    write_result_text(run.memory, run.directory, "design_points.csv",
                      design_points_csv(input.reliability, report));
    write_result_text(run.memory, run.directory, "estimates.csv", estimates_csv(report));
    write_result_text(run.memory, run.directory, "summary.json",
                      summary_json(input, report,
                                   report.interrupted        ? "interrupted" :
                                   !report.failure.empty()   ? "failed" :
                                   !report.warnings.empty()  ? "completed with warnings" :
                                                               "completed"));
    std::ostringstream out;
    for (const LimitStateReliability &ls : report.limit_states)
      if (ls.form && !ls.form->converged)
        out << "limit state " << ls.name << ": FORM failed (" << ls.form->failure << ")\n";
      else if (ls.form)
        out << "limit state " << ls.name << ": FORM beta = " << ls.form->beta << " ("
            << ls.form->iterations << " iterations, " << ls.form->n_evaluations
            << " evaluations)" << (ls.sorm ? ", SORM Tvedt beta = " : "")
            << (ls.sorm ? std::to_string(ls.sorm->beta_tvedt) : "") << "\n";
    if (report.bounds)
      out << "system (" << (input.reliability.system == SystemType::series ? "series" : "parallel")
          << "): FORM bounds " << report.bounds->lower << " <= Pf <= " << report.bounds->upper << "\n";
    for (const SystemEstimate &e : report.estimates)
      {
        out << e.method << ": Pf = " << e.probability;
        if (e.coefficient_of_variation_upper_bound)
          out << " (COV between " << e.coefficient_of_variation << ", the levels uncorrelated, and "
              << *e.coefficient_of_variation_upper_bound << ", fully correlated)";
        else if (e.coefficient_of_variation > 0)
          out << " (COV " << e.coefficient_of_variation << ")";
        out << ", " << e.n_evaluations << " evaluations\n";
      }
    if (report.interrupted)
      out << "reliability interrupted: the estimates above are over the samples drawn "
             "before the signal, the methods after it were not run\n";
    run.out << out.str() << "results in " << run.results_place()
            << " (summary.json, design_points.csv, estimates.csv)\n";
    for (const std::string &warning : report.warnings)
      run.err << "poundfe: warning: " << warning << "\n";
    if (!report.failure.empty())
      run.err << "poundfe: numerical failure: " << report.failure << "\n";
    return status;
  }
} // namespace poundfe::commands
