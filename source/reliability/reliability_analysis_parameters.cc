#include <poundfe/base/choices.h>
#include <poundfe/reliability/limit_state.h>
#include <poundfe/reliability/reliability_analysis_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace poundfe
{
  namespace
  {
    const std::string section = "Reliability/";

    const NameTable<ReliabilityMethod> &
    method_names()
    {
      static const NameTable<ReliabilityMethod> table(
        {{ReliabilityMethod::form, "FORM"},
         {ReliabilityMethod::sorm, "SORM"},
         {ReliabilityMethod::importance_sampling, "importance sampling"},
         {ReliabilityMethod::monte_carlo, "Monte Carlo"},
         {ReliabilityMethod::subset, "subset"}});
      return table;
    }


    double
    number(const InputFile &input, const std::string &path, const std::string &text,
           const std::string &what)
    {
      char        *end   = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
        input.fail(path, what + ": '" + text + "' is not a number");
      return value;
    }

    /// The native parameter names of each distribution, in from_native's order.
    std::vector<std::string>
    native_keys(const DistributionType type)
    {
      switch (type)
        {
          case DistributionType::normal:
            return {"mu", "sigma"};
          case DistributionType::lognormal:
            return {"lambda", "zeta"};
          case DistributionType::uniform:
            return {"lower", "upper"};
          case DistributionType::truncated_normal:
            return {"mu", "sigma", "lower", "upper"};
          case DistributionType::gumbel:
            return {"location", "scale"};
          case DistributionType::weibull:
            return {"shape", "scale"};
        }
      return {};
    }
  } // namespace

  std::vector<std::string>
  input_items(const std::string &text, const char separator)
  {
    std::vector<std::string> result;
    std::stringstream        in(text);
    std::string              item;
    while (std::getline(in, item, separator))
      if (!trimmed(item).empty())
        result.push_back(trimmed(item));
    return result;
  }

  std::vector<std::string>
  input_words(const std::string &text)
  {
    std::vector<std::string> result;
    std::istringstream       in(text);
    for (std::string w; in >> w;)
      result.push_back(w);
    return result;
  }

  Distribution
  parse_distribution(const InputFile &input, const std::string &path,
                     const std::vector<std::string> &w)
  {
    const std::string &name = w.at(0);
    if (w.size() < 2)
      input.fail(path, "'" + name + "' needs a distribution and its parameters");
    // "truncated normal" is two words
    const bool        two  = w.size() > 2 && w[1] == "truncated" && w[2] == "normal";
    const std::string kind = two ? "truncated normal" : w[1];
    DistributionType  type = DistributionType::normal;
    try
      {
        type = distribution_type(kind);
      }
    catch (const std::invalid_argument &e)
      {
        input.fail(path, "variable '" + name + "': " + e.what());
      }
    std::map<std::string, double> given;
    for (std::size_t i = two ? 3 : 2; i < w.size(); i += 2)
      {
        if (i + 1 >= w.size())
          input.fail(path, "variable '" + name + "': '" + w[i] + "' has no value");
        if (!given.emplace(w[i], number(input, path, w[i + 1], "variable '" + name + "'")).second)
          input.fail(path, "variable '" + name + "': '" + w[i] + "' given twice");
      }
    const std::vector<std::string> keys = native_keys(type);
    std::string                    native_list;
    for (const std::string &k : keys)
      native_list += " " + k;
    try
      {
        if (given.count("mean") && (given.count("sd") || given.count("cov")) && given.size() == 2)
          {
            const double mean = given["mean"];
            const double sd   = given.count("sd") ? given["sd"] : given["cov"] * std::abs(mean);
            return Distribution::from_moments(type, mean, sd);
          }
        std::vector<double> p;
        for (const std::string &k : keys)
          if (given.count(k))
            p.push_back(given[k]);
        if (p.size() == keys.size() && given.size() == keys.size())
          return Distribution::from_native(type, p);
      }
    catch (const std::invalid_argument &e)
      {
        input.fail(path, "variable '" + name + "' (" + kind + "): " + e.what());
      }
    input.fail(path,
               "variable '" + name + "' (" + kind + ") takes 'mean M sd S', 'mean M cov C'" +
                 (type == DistributionType::truncated_normal ? " (not for this one)" : "") +
                 " or its native parameters" + native_list);
  }

  DenseMatrix
  parse_correlation(const InputFile &input, const std::string &path, const std::string &text,
                    const std::vector<Distribution> &distributions)
  {
    DenseMatrix correlation;
    for (const std::string &row : input_items(text, ';'))
      {
        correlation.emplace_back();
        for (const std::string &x : input_words(row))
          correlation.back().push_back(number(input, path, x, "correlation"));
      }
    try
      {
        NatafTransformation(distributions, correlation);
      }
    catch (const std::invalid_argument &e)
      {
        input.fail(path, e.what());
      }
    return correlation;
  }

  const NameTable<SystemType> &
  system_names()
  {
    static const NameTable<SystemType> table(
      {{SystemType::series, "series"}, {SystemType::parallel, "parallel"}});
    return table;
  }

  const std::string &
  reliability_method_name(const ReliabilityMethod method)
  {
    return method_names().name(method);
  }

  namespace
  {
    /// Reliability/FORM, Sampling and Subset: the settings of each method.
    void
    declare_method_entries(dealii::ParameterHandler &prm, ReliabilityAnalysisParameters &p)
    {
      using dealii::Patterns::Double;
      using dealii::Patterns::Integer;
      prm.enter_subsection("FORM");
      prm.add_parameter("Maximum iterations", p.form_max_iterations,
                        "HL-RF steps before FORM gives up (exit 2). Unit: count.", Integer(1));
      prm.add_parameter("Tolerance", p.form_tolerance,
                        "e1 = e2: |G|/|G(u0)| and the distance of u from the line of alpha. "
                        "Unit: dimensionless (standard deviations for e2).", Double(1e-14, 0.1));
      prm.add_parameter("Gradient step", p.gradient_step,
                        "Finite-difference step in the standard normal space. Unit: "
                        "dimensionless (standard deviations).", Double(1e-10, 0.5));
      prm.add_parameter("Central differences", p.central_difference,
                        "Central (2n evaluations) rather than forward (n) differences for the "
                        "gradient. Unit: -.");
      prm.add_parameter("Hessian step", p.hessian_step,
                        "SORM: finite-difference step of the Hessian at the design point. Unit: "
                        "dimensionless (standard deviations).", Double(1e-8, 0.5));
      prm.leave_subsection();
      prm.enter_subsection("Sampling");
      prm.add_parameter("Monte Carlo samples", p.monte_carlo_samples,
                        "Largest number of crude Monte Carlo samples. Unit: count.", Integer(1));
      prm.add_parameter("Importance samples", p.importance_samples,
                        "Largest number of importance samples: of the method, and of the check "
                        "of each FORM around its design point. Unit: count.", Integer(1));
      prm.add_parameter("Target COV", p.target_cov,
                        "Stop sampling once the estimator's COV reaches this (0: all samples). "
                        "Unit: dimensionless.", Double(0, 1));
      prm.leave_subsection();
      prm.enter_subsection("Subset");
      prm.add_parameter("Samples per level", p.subset_samples_per_level, "N. Unit: count.",
                        Integer(2));
      prm.add_parameter("Conditional probability", p.subset_conditional_probability,
                        "p0 in (0, 0.5]. Unit: dimensionless.", Double(0, 0.5));
      prm.add_parameter("Maximum levels", p.subset_max_levels, "Unit: count.", Integer(1, 100));
      prm.add_parameter("Proposal spread", p.subset_proposal_spread,
                        "Standard deviation of the modified Metropolis proposal. Unit: "
                        "dimensionless.", Double(1e-3, 10));
      prm.leave_subsection();
    }
  } // namespace

  void
  ReliabilityAnalysisParameters::declare(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    prm.enter_subsection("Reliability");
    prm.add_parameter("Random variables", random_variables_text,
                      "'NAME DISTRIBUTION KEY VALUE ...' separated by ';'. Distributions: "
                      "normal, lognormal, uniform, truncated normal, Gumbel, Weibull. Keys: "
                      "'mean M sd S' or 'mean M cov C' (all but truncated normal), or the "
                      "native parameters: normal mu sigma; lognormal lambda zeta (of ln X); "
                      "uniform lower upper; truncated normal mu sigma lower upper (the parent "
                      "normal's); Gumbel location scale; Weibull shape scale. Unit: per field "
                      "(each variable's own).");
    prm.add_parameter("Correlation", correlation_text,
                      "Correlation matrix of the random variables in their order, rows "
                      "separated by ';' (empty: independent); symmetric positive definite. "
                      "Nataf transformation. Unit: dimensionless.");
    prm.add_parameter("Constants", constants_text,
                      "'NAME VALUE' separated by ';': named numbers for the expressions. "
                      "Unit: per field (each constant's own).");
    prm.add_parameter("Limit states", limit_states_text,
                      "'NAME: EXPRESSION' separated by ';'; failure when the expression is "
                      "<= 0. muParser syntax (+ - * / ^, sqrt, exp, ln, log10, abs, min, max, "
                      "sin, ...) over the random variables and constants. Unit: that of the "
                      "expression.");
    add_choice(prm, "System", system,
               "How several limit states combine: series (failure when any fails) or "
               "parallel (when all fail). Unit: -.",
               system_names());
    prm.add_parameter("Methods", methods_text,
                      "Comma-separated: FORM, SORM (needs FORM's design point), importance "
                      "sampling (around the design points), Monte Carlo, subset. Unit: -.");
    prm.add_parameter("Seed", seed, "Seed of the random streams of the sampling methods. "
                      "Unit: -.", Integer(0));
    declare_method_entries(prm, *this);
    prm.leave_subsection();
  }

  namespace
  {
    /// Reliability/Limit states `text`, "NAME: EXPRESSION; ...": each name
    /// once, each expression parsed over the variables and constants.
    void
    read_limit_states(const InputFile &input, const std::string &text,
                      const std::vector<std::string>                    &variable_names,
                      const std::vector<std::pair<std::string, double>> &constants,
                      std::vector<std::string> &names, std::vector<std::string> &expressions)
    {
      for (const std::string &item : input_items(text, ';'))
        {
          const std::size_t colon = item.find(':');
          const std::string name  = colon == std::string::npos ? "" : trimmed(item.substr(0, colon));
          if (!is_identifier(name))
            input.fail(section + "Limit states", "'" + item + "' is not 'NAME: EXPRESSION'");
          if (std::find(names.begin(), names.end(), name) != names.end())
            input.fail(section + "Limit states", "limit state '" + name + "' is given twice");
          const std::string expression = trimmed(item.substr(colon + 1));
          try
            {
              LimitStateExpression(expression, variable_names, constants);
            }
          catch (const std::invalid_argument &e)
            {
              input.fail(section + "Limit states", "limit state '" + name + "': " + e.what());
            }
          names.push_back(name);
          expressions.push_back(expression);
        }
    }
  } // namespace

  void
  ReliabilityAnalysisParameters::check(const InputFile &input)
  {
    variable_names.clear(), distributions.clear(), correlation.clear(), constants.clear();
    limit_state_names.clear(), expressions.clear(), methods.clear();
    for (const std::string &item : input_items(random_variables_text, ';'))
      {
        const std::vector<std::string> w = input_words(item);
        if (!is_identifier(w[0]))
          input.fail(section + "Random variables", "'" + w[0] + "' cannot name a variable "
                                                   "(a letter or '_', then letters, digits, '_')");
        for (const std::string &n : variable_names)
          if (n == w[0])
            input.fail(section + "Random variables", "'" + n + "' is named twice");
        distributions.push_back(parse_distribution(input, section + "Random variables", w));
        variable_names.push_back(w[0]);
      }
    for (const std::string &item : input_items(constants_text, ';'))
      {
        const std::vector<std::string> w = input_words(item);
        if (w.size() != 2 || !is_identifier(w[0]))
          input.fail(section + "Constants", "'" + item + "' is not 'NAME VALUE'");
        // one name, one value: the parser would take one of the two silently
        if (std::find(variable_names.begin(), variable_names.end(), w[0]) != variable_names.end())
          input.fail(section + "Constants", "constant '" + w[0] +
                                              "' has the name of a random variable: rename one");
        for (const auto &[name, value] : constants)
          if (name == w[0])
            input.fail(section + "Constants", "constant '" + name + "' is given twice");
        constants.emplace_back(w[0], number(input, section + "Constants", w[1], "constant " + w[0]));
      }
    correlation = parse_correlation(input, section + "Correlation", correlation_text, distributions);
    read_limit_states(input, limit_states_text, variable_names, constants, limit_state_names,
                      expressions);
    for (const std::string &m : input_items(methods_text, ','))
      {
        try
          {
            methods.push_back(method_names().value(m));
          }
        catch (const std::invalid_argument &)
          {
            input.fail(section + "Methods", "unknown method '" + m +
                                              "' (FORM, SORM, importance sampling, Monte "
                                              "Carlo, subset)");
          }
      }
    const double n_seeds = std::round(subset_conditional_probability * subset_samples_per_level);
    if (n_seeds < 1 || n_seeds >= subset_samples_per_level)
      input.fail(section + "Subset/Conditional probability",
                 "p0 N must round to at least one seed and fewer than N = " +
                   std::to_string(subset_samples_per_level));
  }

  void
  ReliabilityAnalysisParameters::require_problem(const InputFile &input) const
  {
    if (distributions.empty())
      input.fail(section + "Random variables", "the reliability command needs at least one");
    if (expressions.empty())
      input.fail(section + "Limit states", "the reliability command needs at least one");
    if (methods.empty())
      input.fail(section + "Methods", "the reliability command needs at least one");
  }
} // namespace poundfe
