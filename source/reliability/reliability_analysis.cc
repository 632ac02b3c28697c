// The methods of the `reliability` command in turn (reliability_analysis.h).
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/numbers.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/reliability/limit_state.h>
#include <poundfe/reliability/reliability_analysis.h>
#include <poundfe/reliability/sampling.h>
#include <poundfe/reliability/subset.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

namespace poundfe
{
  namespace
  {
    bool
    has(const ReliabilityAnalysisParameters &p, const ReliabilityMethod m)
    {
      return std::find(p.methods.begin(), p.methods.end(), m) != p.methods.end();
    }

    double
    seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    /// Adds `text` to the report's failures (one line: "; " between them).
    void
    add_failure(ReliabilityReport &report, const std::string &text)
    {
      report.failure += (report.failure.empty() ? "" : "; ") + text;
    }

    /// FORM's Pf of limit state k checked by importance sampling around its
    /// design point on that limit state alone (unbiased whatever its
    /// curvature): a warning in the report when they disagree.
    void
    check_form(const ReliabilityAnalysisParameters &p, const ReliabilityProblem &problem,
               const unsigned int k, ReliabilityReport &report)
    {
      LimitStateReliability &ls = report.limit_states[k];
      const ReliabilityProblem alone{problem.transformation, {problem.limit_states[k]},
                                     SystemType::series};
      SamplingSettings sampling;
      sampling.max_samples = p.importance_samples;
      sampling.seed        = p.seed;
      ls.form_check        = importance_sampling(alone, {ls.form->design_point_u}, sampling);
      report.interrupted |= ls.form_check->interrupted;
      const std::string warning = form_disagreement(ls.form->probability, *ls.form_check);
      if (!warning.empty() && !ls.form_check->interrupted)
        report.warnings.push_back("limit state '" + ls.name + "': " + warning);
    }

    /// FORM (and SORM) of every limit state, each FORM checked by
    /// importance sampling; false when FORM did not converge on one (the
    /// report says why, the sampling methods still run).
    bool
    run_form(const ReliabilityAnalysisParameters &p, const ReliabilityProblem &problem,
             ReliabilityReport &report)
    {
      FormSettings settings;
      settings.max_iterations     = p.form_max_iterations;
      settings.tolerance_g        = p.form_tolerance;
      settings.tolerance_u        = p.form_tolerance;
      settings.gradient_step      = p.gradient_step;
      settings.central_difference = p.central_difference;
      bool converged = true;
      for (unsigned int k = 0; k < problem.limit_states.size() && !report.interrupted; ++k)
        {
          LimitStateReliability &ls = report.limit_states[k];
          ls.form                   = form(problem, k, settings);
          if (!ls.form->converged)
            {
              add_failure(report, "FORM failed on limit state '" + ls.name + "' (" +
                                    ls.expression + "): " + ls.form->failure +
                                    (ls.form->zero_gradient_at_start ? "" :
                                       " (Reliability/FORM/Maximum iterations; a limit state "
                                       "without a design point, e.g. never failing)"));
              converged = false;
              continue;
            }
          check_form(p, problem, k, report);
          if (has(p, ReliabilityMethod::sorm))
            ls.sorm = sorm(problem, k, *ls.form, p.hessian_step);
        }
      return converged;
    }

    void
    add_form_estimates(const ReliabilityAnalysisParameters &p, const ReliabilityProblem &problem,
                       ReliabilityReport &report)
    {
      std::vector<double>              betas;
      std::vector<std::vector<double>> alphas;
      unsigned long                    form_evaluations = 0, sorm_evaluations = 0;
      for (const LimitStateReliability &ls : report.limit_states)
        {
          betas.push_back(ls.form->beta);
          alphas.push_back(ls.form->alpha);
          form_evaluations += ls.form->n_evaluations;
          if (ls.sorm)
            sorm_evaluations += ls.sorm->n_evaluations;
        }
      if (betas.size() > 1)
        report.bounds = system_bounds(problem.system, betas, alphas);
      else
        {
          report.estimates.push_back({"FORM", report.limit_states[0].form->probability, 0,
                                      form_evaluations, 0});
          if (has(p, ReliabilityMethod::sorm))
            {
              report.estimates.push_back({"SORM Breitung", report.limit_states[0].sorm->breitung,
                                          0, sorm_evaluations, 0});
              report.estimates.push_back({"SORM Tvedt", report.limit_states[0].sorm->tvedt, 0,
                                          sorm_evaluations, 0});
            }
        }
    }

    /// g_k(x), a NaN (an expression undefined at x: neither safe nor
    /// failed) a NumericalError naming the limit state and x.
    double
    checked_value(const LimitStateExpression &g, const ReliabilityAnalysisParameters &p,
                  const std::size_t k, const std::vector<double> &x)
    {
      const double value = g(x);
      if (!std::isnan(value))
        return value;
      std::string point;
      for (const unsigned int i : g.used_variables())
        point += (point.empty() ? "" : ", ") + p.variable_names[i] + " = " + number_text(x[i]);
      throw NumericalError("limit state '" + p.limit_state_names[k] + "' (" + p.expressions[k] +
                           ") is NaN at x = (" + point +
                           "): the expression is undefined there, neither safe nor failed "
                           "(Reliability/Limit states)");
    }

    /// Subset Simulation of the system, over the ranks of `comm`.
    void
    run_subset(const ReliabilityAnalysisParameters &p, const ReliabilityProblem &problem,
               ReliabilityReport &report, const MPI_Comm comm)
    {
      const auto     start = std::chrono::steady_clock::now();
      SubsetSettings settings;
      settings.samples_per_level       = p.subset_samples_per_level;
      settings.conditional_probability = p.subset_conditional_probability;
      settings.max_levels              = p.subset_max_levels;
      settings.proposal_spread         = p.subset_proposal_spread;
      settings.seed                    = p.seed;
      const StandardSpaceLimitStates G(problem);
      // Y = -G_system: Subset Simulation estimates P(Y > 0) = P(G_system < 0).
      // A limit state undefined at a sample of one rank stops every rank
      // at the end of the level (where they meet) before it is reported.
      std::string        undefined;
      const SubsetResult r = subset_simulation(
        [&](const std::vector<double> &u) {
          try
            {
              return undefined.empty() ? -G.system_value(u) :
                                         -std::numeric_limits<double>::infinity();
            }
          catch (const NumericalError &e)
            {
              undefined = e.what();
              request_stop();
              return -std::numeric_limits<double>::infinity(); // the level is dropped
            }
        },
        problem.transformation.n_variables(), 0.0, settings, comm);
      request_stop(false);
      for (const std::string &message : dealii::Utilities::MPI::all_gather(comm, undefined))
        if (!message.empty())
          throw NumericalError(message);
      report.estimates.push_back({"subset", r.probability, r.coefficient_of_variation,
                                  r.model_runs * problem.limit_states.size(),
                                  seconds_since(start)});
      report.estimates.back().coefficient_of_variation_upper_bound =
        r.coefficient_of_variation_upper_bound;
      report.interrupted |= r.interrupted;
      if (!r.reached_threshold && !r.interrupted)
        add_failure(report, "Subset Simulation stopped at Reliability/Subset/Maximum levels "
                            "before reaching the failure domain");
    }

    /// The methods of `p` in turn on `problem`.
    void
    run_methods(const ReliabilityAnalysisParameters &p, const ReliabilityProblem &problem,
                ReliabilityReport &report, const MPI_Comm comm)
    {
      const bool needs_form = has(p, ReliabilityMethod::form) ||
                              has(p, ReliabilityMethod::sorm) ||
                              has(p, ReliabilityMethod::importance_sampling);
      // a FORM that failed leaves no design point for SORM and importance
      // sampling, but Monte Carlo and subset need none
      const bool form_converged = needs_form && run_form(p, problem, report);
      if (form_converged)
        add_form_estimates(p, problem, report);
      SamplingSettings sampling;
      sampling.target_cov = p.target_cov;
      sampling.seed       = p.seed;
      const auto add      = [&](const std::string &method, const SamplingResult &r,
                           const std::chrono::steady_clock::time_point start) {
        report.estimates.push_back(
          {method, r.probability, r.coefficient_of_variation, r.n_evaluations, seconds_since(start)});
        report.interrupted |= r.interrupted;
      };
      if (has(p, ReliabilityMethod::importance_sampling) && form_converged && !report.interrupted)
        {
          const auto start     = std::chrono::steady_clock::now();
          sampling.max_samples = p.importance_samples;
          std::vector<std::vector<double>> centres;
          for (const LimitStateReliability &ls : report.limit_states)
            centres.push_back(ls.form->design_point_u);
          add("importance sampling", importance_sampling(problem, centres, sampling), start);
        }
      if (has(p, ReliabilityMethod::monte_carlo) && !report.interrupted)
        {
          const auto start     = std::chrono::steady_clock::now();
          sampling.max_samples = p.monte_carlo_samples;
          add("Monte Carlo", monte_carlo(problem, sampling), start);
        }
      if (has(p, ReliabilityMethod::subset) && !report.interrupted)
        run_subset(p, problem, report, comm);
    }
  } // namespace

  ReliabilityReport
  run_reliability_analysis(const ReliabilityAnalysisParameters &p, const MPI_Comm comm)
  {
    ReliabilityReport report;
    // one parser per limit state, shared by the methods (run one at a time)
    std::vector<std::shared_ptr<LimitStateExpression>> parsers;
    ReliabilityProblem problem{NatafTransformation(p.distributions, p.correlation), {}, p.system};
    for (std::size_t k = 0; k < p.expressions.size(); ++k)
      {
        parsers.push_back(
          std::make_shared<LimitStateExpression>(p.expressions[k], p.variable_names, p.constants));
        const std::shared_ptr<LimitStateExpression> g = parsers.back();
        problem.limit_states.push_back(
          [g, &p, k](const std::vector<double> &x) { return checked_value(*g, p, k, x); });
        report.limit_states.push_back({p.limit_state_names[k], p.expressions[k], {}, {}, {}});
      }
    try
      {
        run_methods(p, problem, report, comm);
      }
    catch (const NumericalError &e)
      {
        // a limit state undefined at a sample: the estimates so far are kept
        add_failure(report, e.what());
      }
    return report;
  }
} // namespace poundfe
