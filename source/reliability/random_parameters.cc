// The `Random parameters` section (reliability/random_parameters.h): random
// model parameters through the Nataf transformation (Liu & Der Kiureghian
// 1986; reliability/nataf.h) and limit states g(responses, x) <= 0 over the
// rows of a time-history sampling run, estimated by crude Monte Carlo
// P = n_f / n, CoV = sqrt((1 - P)/(n P)) (Melchers & Beck 2018, sec. 3.3).
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/dynamics/model_parameter.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/model/parameters.h>
#include <poundfe/reliability/random_parameters.h>
#include <poundfe/reliability/reliability_analysis_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <regex>
#include <stdexcept>

namespace poundfe
{
  namespace
  {
    const std::string section = "Random parameters/";

    /// Whether `d`, a distribution unbounded above, reaches a finite `upper`:
    /// its mean within ten standard deviations of it, the rule of 1e150
    /// (samples_beyond_model_values). A bound far above any sensible value
    /// (a section's f'c, fy or E: sections/material_bounds.h) then leaves a
    /// lognormal of a realistic mean and spread its place; a sample beyond
    /// it, as unlikely as a normal's beyond 10 sigma, is still refused by
    /// ModelParameter::set.
    bool
    tail_reaches(const Distribution &d, const double upper)
    {
      return std::isfinite(upper) && !(d.mean() + 10 * d.standard_deviation() < upper);
    }

    /// Whether `d` can sample a value below range.lower (lower itself too
    /// when !lower_included).
    bool
    samples_below(const Distribution &d, const ModelParameter::Range &range)
    {
      const std::vector<double> &p = d.parameters();
      double lowest = -std::numeric_limits<double>::infinity(); // normal, Gumbel
      switch (d.type())
        {
          case DistributionType::lognormal:
          case DistributionType::weibull:
            return !(range.lower <= 0); // support (0, inf): 0 itself is never sampled
          case DistributionType::uniform:
            lowest = p[0];
            break;
          case DistributionType::truncated_normal:
            lowest = p[2];
            break;
          case DistributionType::normal:
          case DistributionType::gumbel:
            break;
        }
      return range.lower_included ? lowest < range.lower : lowest <= range.lower;
    }

    /// Whether `d` can sample a value above range.upper (upper itself too
    /// when !upper_included; a distribution unbounded above by tail_reaches).
    bool
    samples_above(const Distribution &d, const ModelParameter::Range &range)
    {
      const std::vector<double> &p = d.parameters();
      switch (d.type())
        {
          case DistributionType::uniform:
            return range.upper_included ? p[1] > range.upper : p[1] >= range.upper;
          case DistributionType::truncated_normal:
            return range.upper_included ? p[3] > range.upper : p[3] >= range.upper;
          default: // lognormal, Weibull, normal, Gumbel: unbounded above
            return tail_reaches(d, range.upper);
        }
    }

    /// Whether `d` can sample a value outside [lower, upper].
    bool
    samples_out_of_range(const Distribution &d, const ModelParameter::Range &range)
    {
      return samples_below(d, range) || samples_above(d, range);
    }

    /// Whether `d` can sample a value beyond 1e150 in size (largest_model_value),
    /// which no model entry may take (the builder refuses it, or the K or M it
    /// enters): a uniform reaching there, or another whose mean (a truncated
    /// normal's: mu, unless its bounds stay inside) is within ten standard
    /// deviations of it.
    bool
    samples_beyond_model_values(const Distribution &d)
    {
      const std::vector<double> &p = d.parameters();
      switch (d.type())
        {
          case DistributionType::uniform:
            return std::max(std::abs(p[0]), std::abs(p[1])) > largest_model_value;
          case DistributionType::truncated_normal: // (mu, sigma, lower, upper)
            return std::min(std::max(std::abs(p[2]), std::abs(p[3])),
                            std::abs(p[0]) + 10 * p[1]) > largest_model_value;
          default:
            return !(std::abs(d.mean()) + 10 * d.standard_deviation() <= largest_model_value);
        }
    }

    /// Whether `later` writes into every value of the model that `earlier`
    /// writes (the variables act in their order): the same kind of entry of
    /// the same building, list and field, on the same storey (or member,
    /// entry) or, `later`, on every one. A variable of a whole list followed
    /// by one of its entries is not: both act, the entry overriding the list
    /// there.
    /// InputError at Random parameters/Variables for a variable whose name
    /// a column of realizations.csv has already (a limit state would read
    /// one of the two for the other), or whose path writes into the value
    /// of an earlier variable entirely (only the last would act, while both
    /// would be written as sampled).
    void
    refuse_shadowed_variables(const RandomParameterParameters   &p,
                              const std::vector<ModelParameter> &parameters,
                              const RealizationRunner &runner, const InputFile &input)
    {
      std::vector<std::string> columns = runner.response_names();
      for (const std::string &name : runner.optional_response_names())
        columns.push_back(name);
      columns.insert(columns.end(), {"realization", "seed", "completed"});
      for (unsigned int i = 0; i < p.names.size(); ++i)
        {
          if (std::find(columns.begin(), columns.end(), p.names[i]) != columns.end())
            input.fail(section + "Variables",
                       "variable '" + p.names[i] + "' has the name of a response column of "
                       "realizations.csv (a limit state could not tell them apart): rename it");
          for (unsigned int j = 0; j < i; ++j)
            if (parameters[i].overwrites(parameters[j]))
              input.fail(section + "Variables",
                         "variables '" + p.names[j] + "' (" + p.paths[j] + ") and '" +
                           p.names[i] + "' (" + p.paths[i] + ") set the same model value: '" +
                           p.names[i] + "' writes over every value of '" + p.names[j] +
                           "', so only it would act (a whole list may come first and one "
                           "of its entries after it, overriding that entry)");
        }
    }

    /// "<= 0", "> 5e+10", "< 0 or > 1": the values outside the range that
    /// `d` can sample.
    std::string
    outside_text(const Distribution &d, const ModelParameter::Range &range)
    {
      const std::string below = (range.lower_included ? "< " : "<= ") + number_text(range.lower);
      const std::string above = (range.upper_included ? "> " : ">= ") + number_text(range.upper);
      if (!samples_above(d, range))
        return below;
      return samples_below(d, range) ? below + " or " + above : above;
    }

    /// ">= 0", "> 0", "and <= 1": the bounds a distribution's support must keep.
    std::string
    inside_text(const ModelParameter::Range &range)
    {
      const std::string text = (range.lower_included ? ">= " : "> ") + number_text(range.lower);
      return std::isfinite(range.upper) ?
               text + (range.upper_included ? " and upper <= " : " and upper < ") +
                 number_text(range.upper) :
               text;
    }

    /// The distributions to use instead: a lognormal or Weibull when their
    /// support (0, inf) keeps above the lower bound (with their mean ten
    /// standard deviations below a finite upper one, tail_reaches), and a
    /// uniform or truncated normal inside the range.
    std::string
    remedy_text(const ModelParameter::Range &range)
    {
      std::string text = "use ";
      if (range.lower <= 0)
        text += std::isfinite(range.upper) ?
                  "a lognormal or Weibull whose mean lies more than ten standard deviations "
                  "below " + number_text(range.upper) + ", or " :
                  "a lognormal or Weibull, or ";
      return text + "a uniform or truncated normal with lower " + inside_text(range);
    }
  } // namespace

  void
  RandomParameterParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Random parameters");
    prm.add_parameter("Variables", variables_text,
                      "Random model parameters of montecarlo, subset, fragility, separation and "
                      "dynamic-form: 'NAME: PATH ~ DISTRIBUTION KEY VALUE ...' separated by ';'. "
                      "PATH: Building b/Storey stiffnesses[i], Building b/Storey damping[i], "
                      "Building b/Storey yield drifts[i] (without [i]: every storey), Building "
                      "b/Floor masses[i] (without [i]: every floor), Building b/Column E[i], "
                      "Column A[i], Column I[i], Column mass per length[i] (storey i of a frame), "
                      "Building b/Beam E[i], Beam A[i], Beam I[i], Beam mass per length[i] (floor "
                      "i), Building b/Hinges/Yield moment, Hinges/Yield rotation, Hinges/Stiffness, "
                      "Hinges/Stiffness factor, Building b/Bouc-Wen/alpha (A, beta, gamma, n, "
                      "delta A, delta nu, delta eta: every hinge, 2D or 3D, and hysteretic "
                      "storey or resisting plane of b), "
                      "Building b/Damping/Damping ratio, Damping/a0, Damping/a1, Damping/Modal "
                      "ratios[i], Model/Separations[i], Contact/Barriers/gap[i] (barrier i), "
                      "Contact/Stiffness, Contact/Damping, "
                      "Friction/Static coefficient, Friction/Kinetic coefficient, Links/Viscous "
                      "dampers[i] (c), Links/LIST/FIELD[i] (entry i of a Links list, without "
                      "[i]: every one; Viscous dampers/c, alpha, Kelvin-Voigt links/k, c, alpha, "
                      "Maxwell links/k, c, Elastic-plastic links/k, Fy, r, Soil coupling/k, c, "
                      "Rocking soil coupling/k, c), Springs/SD springs/K[i] (L, H), "
                      "Springs/Cubic springs/k1[i] (k3), Bumpers/Stiffness, Bumpers/Thickness "
                      "(at most the smallest gap); 3D frames: Building b/Column E[i] (G, A, I, "
                      "Iz, J, Avy, Avz, mass per length), Beam ...[i]; meshes: Building b/Group E[i] (A, I, "
                      "mass per length; 3D: G, Iz, J too; group i of Group ids); 3D floor "
                      "masses (a polar moment not typed follows); Building b/Plan/Polar "
                      "moments[i] (typed ones, rigid slabs); Building b/Plan/Resisting planes/k[i] "
                      "(u_y; typed plane i of a 3D shear building, every storey); "
                      "Building b/Foundation/ENTRY (Shear-wave velocity, "
                      "Soil density, Poisson ratio, Length, Width, Embedment, the typed "
                      "stiffnesses and dampings, Mass, Rotary inertia, Rotary inertia x, Polar "
                      "inertia); Contact/Coefficient of restitution (the damping fitted "
                      "again); Friction/Stribeck velocity, Belt velocity, Normal force (per "
                      "displacement, per velocity, per velocity cubed), Stick stiffness, "
                      "Regularization velocity; Sections/Section k/Concrete strength (Yield "
                      "stress, Elastic modulus, Cover, Bar diameter: the section built again, "
                      "its fibre members' K with it). Geometry (heights, bays, plan, set-backs) is "
                      "refused. DISTRIBUTION and keys as Reliability/Random variables. "
                      "Unit: that of the parameter.");
    prm.add_parameter("Correlation", correlation_text,
                      "Correlation matrix of the Variables in their order, rows separated by "
                      "';' (empty: independent); Nataf transformation (separation: random "
                      "separations may be correlated too). Unit: dimensionless.");
    prm.add_parameter("Limit states", limit_states_text,
                      "'NAME: EXPRESSION' separated by ';', failure when <= 0: muParser "
                      "expressions over the response columns of realizations.csv (e.g. "
                      "max_drift_ratio, A_storey2_peak_drift_ratio, peak_contact_force, "
                      "n_impacts; also, computed when named, A_storey2_residual_drift_ratio, the "
                      "signed drift ratio at the end of the record, gap1_peak_contact_force, "
                      "gap1_impacts and gap1_peak_impact_velocity, of gap 1 alone, and "
                      "peak_ground_acc_m_s2) and the Variables' names. Unit: that of the "
                      "expression.");
    add_choice(prm, "System", system,
               "How the Limit states combine: series (failure when any fails) or parallel "
               "(when all fail). Unit: -.",
               system_names());
    declare_form(prm);
    prm.leave_subsection();
  }

  void
  RandomParameterParameters::declare_form(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    prm.enter_subsection("FORM");
    prm.add_parameter("Excitation variables", form_excitation_text,
                      "dynamic-form: how many of the loading's standard normals FORM varies, "
                      "the first ones ('all': every one); the others keep those of Realization. "
                      "Unit: count.");
    // bounded: an unsigned entry left to deal.II's own pattern takes "-5" as
    // a wrapped-around 2^64 - 5
    prm.add_parameter("Realization", form_realization,
                      "dynamic-form: the realization whose loading normals the held ones are "
                      "(as in realizations.csv). Unit: count.",
                      Integer(0));
    prm.add_parameter("Scale factor", form_scale_text,
                      "dynamic-form: the distribution of a random factor on the loading's "
                      "amplitude, 'DISTRIBUTION KEY VALUE ...' as in Variables (empty: 1). "
                      "Unit: dimensionless.");
    prm.add_parameter("Maximum iterations", form.max_iterations, "HL-RF steps. Unit: count.",
                      Integer(1, 1000));
    prm.add_parameter("Tolerance", form.tolerance_g,
                      "e1 = e2: |G(u)|/|G(0)| and the distance of u from the line of alpha (in "
                      "standard deviations) at convergence. Unit: dimensionless.",
                      Double(1e-12, 1));
    prm.add_parameter("Gradient step", form.gradient_step,
                      "Step of the finite differences in standard deviations (each a full time "
                      "history). Unit: dimensionless.",
                      Double(1e-8, 1));
    prm.add_parameter("Central differences", form.central_difference,
                      "Central differences (2n time histories per gradient) instead of forward "
                      "(n). Unit: -.");
    prm.add_parameter("SORM", form_sorm,
                      "dynamic-form: after FORM, SORM (Breitung and Tvedt) from the principal "
                      "curvatures at the design point, the Hessian by central differences with "
                      "the Gradient step (about 2n^2 time histories). Unit: -.");
    prm.add_parameter("Importance samples", form_importance_samples,
                      "dynamic-form: after FORM converges, importance sampling of this many "
                      "time histories around the design point, which checks FORM's Pf (a "
                      "warning when the two disagree beyond the sampling error; 0: no check). "
                      "Unit: count.",
                      Integer(0, 100000000));
    prm.leave_subsection();
  }

  void
  RandomParameterParameters::check_form(const InputFile &input)
  {
    form.tolerance_u = form.tolerance_g;
    form_scale.clear();
    const std::string entry = section + "FORM/Excitation variables";
    const std::string text  = trimmed(form_excitation_text);
    form_all_excitation     = text == "all";
    if (!form_all_excitation)
      {
        std::size_t end = 0;
        long        n   = -1;
        try
          {
            n = std::stol(text, &end);
          }
        catch (const std::exception &)
          {}
        if (n < 0 || end != text.size())
          input.fail(entry, "'" + text + "' is neither 'all' nor a whole number >= 0");
        form_n_excitation = n;
      }
    if (!trimmed(form_scale_text).empty())
      {
        std::vector<std::string> words = input_words(form_scale_text);
        words.insert(words.begin(), "scale");
        form_scale.push_back(parse_distribution(input, section + "FORM/Scale factor", words));
        if (samples_out_of_range(form_scale.back(), ModelParameter::Range{}))
          input.fail(section + "FORM/Scale factor",
                     "a " + distribution_name(form_scale.back().type()) +
                       " distribution can sample factors <= 0 (use a lognormal or Weibull, or "
                       "a uniform or truncated normal with lower > 0)");
      }
  }

  void
  RandomParameterParameters::check(const InputFile &input)
  {
    names.clear(), paths.clear(), distributions.clear(), correlation.clear();
    limit_state_names.clear(), expressions.clear();
    const std::string entry = section + "Variables";
    for (const std::string &item : input_items(variables_text, ';'))
      {
        const std::size_t colon = item.find(':'), tilde = item.find('~');
        if (colon == std::string::npos || tilde == std::string::npos || tilde < colon)
          input.fail(entry, "'" + item + "' is not 'NAME: PATH ~ DISTRIBUTION KEY VALUE ...'");
        const std::string name = trimmed(item.substr(0, colon));
        const std::string path = trimmed(item.substr(colon + 1, tilde - colon - 1));
        if (!is_identifier(name))
          input.fail(entry, "'" + name + "' cannot name a variable (a letter or '_', then "
                            "letters, digits, '_')");
        if (std::find(names.begin(), names.end(), name) != names.end())
          input.fail(entry, "'" + name + "' is named twice");
        if (path.empty())
          input.fail(entry, "variable '" + name + "' names no parameter");
        std::vector<std::string> words = input_words(item.substr(tilde + 1));
        words.insert(words.begin(), name);
        distributions.push_back(parse_distribution(input, entry, words));
        names.push_back(name);
        paths.push_back(path);
      }
    correlation = parse_correlation(input, section + "Correlation", correlation_text, distributions);
    for (const std::string &item : input_items(limit_states_text, ';'))
      {
        const std::size_t colon = item.find(':');
        const std::string name  = colon == std::string::npos ? "" : trimmed(item.substr(0, colon));
        if (!is_identifier(name) || trimmed(item.substr(colon + 1)).empty())
          input.fail(section + "Limit states", "'" + item + "' is not 'NAME: EXPRESSION'");
        if (std::find(limit_state_names.begin(), limit_state_names.end(), name) !=
            limit_state_names.end())
          input.fail(section + "Limit states", "limit state '" + name + "' is given twice");
        limit_state_names.push_back(name);
        expressions.push_back(trimmed(item.substr(colon + 1)));
      }
    check_form(input);
  }

  void
  attach_random_parameters(RealizationRunner &runner, const RandomParameterParameters &p,
                           const InputFile &input, const ModelParameters &model_input,
                           const ContactParameters &contact_input, const Eigensolver eigensolver)
  {
    // the responses the limit states name that a realization computes only when asked
    std::vector<std::string> named;
    static const std::regex  identifier("[A-Za-z_][A-Za-z0-9_]*");
    for (const std::string &expression : p.expressions)
      for (std::sregex_iterator i(expression.begin(), expression.end(), identifier), end; i != end;
           ++i)
        named.push_back(i->str());
    runner.add_optional_responses(named);
    if (!p.has_variables())
      return;
    const std::string           entry = section + "Variables";
    const Model                &model = runner.model();
    std::vector<ModelParameter> parameters;
    const auto origins = std::make_shared<const std::vector<HingeOrigin>>(
      hinge_origins(model, model_input)); // as the file has them
    const auto inputs = std::make_shared<const ModelInputs>(ModelInputs{model_input, contact_input});
    for (unsigned int i = 0; i < p.names.size(); ++i)
      {
        try
          {
            parameters.push_back(model_parameter(p.paths[i], model, origins, inputs));
          }
        catch (const std::invalid_argument &e)
          {
            input.fail(entry, "variable '" + p.names[i] + "': " + e.what());
          }
        const ModelParameter &parameter = parameters.back();
        const ModelParameter::Range range = parameter.range();
        if (samples_out_of_range(p.distributions[i], range))
          input.fail(entry, "variable '" + p.names[i] + "': a " +
                              distribution_name(p.distributions[i].type()) +
                              " distribution can sample values " +
                              outside_text(p.distributions[i], range) + ", which '" + p.paths[i] +
                              "' cannot take (" + remedy_text(range) + ")");
        if (samples_beyond_model_values(p.distributions[i]))
          input.fail(entry, "variable '" + p.names[i] + "': a " +
                              distribution_name(p.distributions[i].type()) +
                              " distribution can sample values beyond 1e150 in size, which '" +
                              p.paths[i] + "' cannot take (no model entry may)");
      }
    refuse_shadowed_variables(p, parameters, runner, input);
    settle_hinge_origins(parameters, *origins, model);
    const auto nataf = std::make_shared<const NatafTransformation>(p.distributions, p.correlation);
    runner.set_random_parameters(
      std::move(parameters), p.names,
      [nataf](const std::vector<double> &u, std::vector<double> &x) { nataf->to_physical(u, x); },
      eigensolver);
  }

  ResponseLimitStates::ResponseLimitStates(const RandomParameterParameters &p,
                                           const std::vector<std::string>  &columns,
                                           const InputFile                 &input)
    : limit_state_names(p.limit_state_names)
    , system_type(p.system)
  {
    // every column that can name a variable of an expression
    std::vector<std::string> variables;
    for (unsigned int c = 0; c < columns.size(); ++c)
      if (is_identifier(columns[c]))
        {
          variables.push_back(columns[c]);
          used_columns.push_back(c);
        }
    for (unsigned int k = 0; k < p.expressions.size(); ++k)
      {
        try
          {
            limit_states.emplace_back(p.expressions[k], variables);
            used_names.emplace_back();
            for (const unsigned int i : limit_states.back().used_variables())
              used_names.back().emplace_back(i, variables[i]);
          }
        catch (const std::invalid_argument &e)
          {
            input.fail(section + "Limit states",
                       "limit state '" + p.limit_state_names[k] + "': " + e.what() +
                         " (the names are the response columns of realizations.csv and the "
                         "random parameters)");
          }
      }
    values.resize(used_columns.size());
  }

  double
  ResponseLimitStates::operator()(const unsigned int k, const std::vector<double> &row,
                                  const std::string &sample, const bool refuse_infinite) const
  {
    for (unsigned int i = 0; i < used_columns.size(); ++i)
      values[i] = row[used_columns[i]];
    const double g = limit_states[k](values);
    if (std::isnan(g) || (refuse_infinite && std::isinf(g)))
      throw NumericalError(undefined_message(k, g, sample));
    return g;
  }

  std::string
  ResponseLimitStates::undefined_message(const unsigned int k, const double g,
                                         const std::string &sample) const
  {
    std::string point;
    for (const auto &[i, name] : used_names[k])
      point += (point.empty() ? "" : ", ") + name + " = " + number_text(values[i]);
    return "limit state '" + limit_state_names[k] + "' (" + limit_states[k].expression() +
           ") is " + (std::isnan(g) ? "NaN" : g > 0 ? "+inf" : "-inf") + " at " + sample + (point.empty() ? "" : " (" + point + ")") +
           ": " +
           (std::isnan(g) ? "the expression is undefined there, neither safe nor failed" :
                            "an infinite value leaves no gradient") +
           " (Random parameters/Limit states)";
  }

  double
  ResponseLimitStates::system_value(const std::vector<double> &row, const std::string &sample,
                                    const bool refuse_infinite) const
  {
    double value = (*this)(0, row, sample, refuse_infinite);
    for (unsigned int k = 1; k < limit_states.size(); ++k)
      {
        const double g = (*this)(k, row, sample, refuse_infinite);
        value = system_type == SystemType::series ? std::min(value, g) : std::max(value, g);
      }
    return value;
  }

  LimitStateProbabilities
  limit_state_probabilities(const ResponseLimitStates                &limit_states,
                            const std::vector<std::vector<double>> &rows,
                            const std::vector<bool>                &completed,
                            const std::vector<std::uint64_t>       &realizations)
  {
    const unsigned int         n_k = limit_states.n_limit_states();
    std::vector<unsigned long> failures(n_k, 0);
    unsigned long              system_failures = 0, n = 0;
    for (std::size_t r = 0; r < rows.size(); ++r)
      {
        if (!completed[r])
          continue;
        ++n;
        const std::string sample = "realization " + std::to_string(realizations[r]);
        for (unsigned int k = 0; k < n_k; ++k)
          failures[k] += limit_states(k, rows[r], sample) <= 0;
        system_failures += limit_states.system_value(rows[r], sample) <= 0;
      }
    LimitStateProbabilities result;
    for (unsigned int k = 0; k < n_k; ++k)
      result.limit_states.push_back(estimate_probability(failures[k], n));
    result.system = estimate_probability(system_failures, n);
    return result;
  }
} // namespace poundfe
