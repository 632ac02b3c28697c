// The `Reliability` section: random variables, their correlation, limit-state
// expressions, the system they form and the methods of the `reliability`
// command (algebraic limit states: no time history).
//   set Random variables = NAME DISTRIBUTION KEY VALUE ...; ...
//     KEY VALUE pairs: mean and sd (or cov) for every distribution but the
//     truncated normal; or the native parameters: normal mu sigma,
//     lognormal lambda zeta, uniform lower upper, truncated normal mu sigma
//     lower upper (the parent normal's mu, sigma), Gumbel location scale,
//     Weibull shape scale (distribution.h has the formulas).
//   set Correlation      = rows of the correlation matrix separated by ';'
//                          (empty: independent)
//   set Constants        = NAME VALUE; ...
//   set Limit states     = NAME: EXPRESSION; ...   (failure: g <= 0)
#ifndef poundfe_reliability_reliability_analysis_parameters_h
#define poundfe_reliability_reliability_analysis_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/reliability/nataf.h>
#include <poundfe/reliability/reliability_problem.h>

#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  enum class ReliabilityMethod
  {
    form,
    sorm,
    importance_sampling,
    monte_carlo,
    subset
  };

  /// The non-empty trimmed items of `text` separated by `separator`.
  std::vector<std::string> input_items(const std::string &text, char separator);
  /// The words of `text` (separated by white space).
  std::vector<std::string> input_words(const std::string &text);
  /// The distribution of one random variable written as the words
  /// "NAME DISTRIBUTION KEY VALUE ..." in the entry `path` (section/entry):
  /// InputError naming the variable and what is wrong (an unknown
  /// distribution or key, impossible parameters).
  Distribution parse_distribution(const InputFile &input, const std::string &path,
                                  const std::vector<std::string> &words);

  /// The correlation matrix written in `text` (rows separated by ';'; empty:
  /// independent) of variables with `distributions`: InputError at `path`
  /// when it is not a matrix Nataf can take (not symmetric, not positive
  /// definite, out of the marginals' reach).
  DenseMatrix parse_correlation(const InputFile &input, const std::string &path,
                                const std::string &text,
                                const std::vector<Distribution> &distributions);

  /// "series", "parallel".
  const NameTable<SystemType> &system_names();

  /// "FORM", "SORM", "importance sampling", "Monte Carlo", "subset".
  const std::string &reliability_method_name(ReliabilityMethod method);

  struct ReliabilityAnalysisParameters
  {
    // as written (parsed by check())
    std::string random_variables_text, correlation_text, constants_text, limit_states_text;
    std::string system_text  = "series";
    std::string methods_text = "FORM, SORM";

    // parsed
    std::vector<std::string>                     variable_names;
    std::vector<Distribution>                    distributions;
    DenseMatrix                                  correlation; // empty: independent
    std::vector<std::pair<std::string, double>> constants;
    std::vector<std::string>                     limit_state_names, expressions;
    SystemType                                   system = SystemType::series;
    std::vector<ReliabilityMethod>               methods;

    unsigned int form_max_iterations = 100;
    double       form_tolerance      = 1e-6;
    double       gradient_step       = 1e-4;
    bool         central_difference  = true;
    double       hessian_step        = 1e-3;

    unsigned long monte_carlo_samples = 100000;
    unsigned long importance_samples  = 10000;
    double        target_cov          = 0;
    unsigned int  seed                = 1;

    unsigned int subset_samples_per_level = 1000;
    double       subset_conditional_probability = 0.1;
    unsigned int subset_max_levels             = 20;
    double       subset_proposal_spread        = 1.0;

    void declare(dealii::ParameterHandler &prm);
    /// Parses and checks the section (InputError naming the entry and what is
    /// wrong: an unknown distribution or key, impossible parameters, a
    /// correlation matrix that is not symmetric positive definite, an
    /// expression that does not parse or names an unknown variable). An empty
    /// section is accepted here: only the `reliability` command needs one
    /// (require_problem()).
    void check(const InputFile &input);
    /// InputError unless there is at least one random variable and one limit state.
    void require_problem(const InputFile &input) const;
  };
} // namespace poundfe

#endif
