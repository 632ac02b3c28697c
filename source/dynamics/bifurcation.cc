// Bifurcation diagrams: Poincaré sections x_k = x(k T) of the steady
// response to a harmonic force of period T, their period, and the largest
// Lyapunov exponent by Benettin's two-trajectory method,
//   lambda = (1 / (K T)) sum_{k=1..K} ln(d_k / d0),
// the second trajectory put back at distance d0 along the separation after
// every period (Benettin, Galgani, Giorgilli & Strelcyn 1980, Meccanica
// 15:9-20; Wolf, Swift, Swinney & Vastano 1985, Physica D 16:285-317),
// both trajectories integrated through the discontinuities (cf. Müller
// 1995, Chaos Solitons Fractals 5:1671-1681, for the variational route).
// See dynamics/bifurcation.h and doc/theory.md §8.4.
#include <poundfe/dynamics/bifurcation.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/choices.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/dynamics/run.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

namespace poundfe
{
  void
  BifurcationParameters::declare(dealii::ParameterHandler &prm)
  {
    namespace Patterns = dealii::Patterns;
    prm.enter_subsection("Bifurcation");
    sweep.declare_entries(prm);
    prm.add_parameter("Response", response,
                      "The sampled DOF: 'building floor node dof' (building: its number, "
                      "1-based, or its Name; floor 1-based, node 0-based from the left, dof "
                      "ux|uy|rz). Unit: -.");
    add_choice(prm, "Response quantity", quantity,
               "Displacement (relative to the ground, m) or velocity (m/s) of the DOF. Unit: -.",
               {"displacement", "velocity"});
    prm.add_parameter("Forcing period", forcing_period,
                      "T, the Poincaré section's period; 0: 2 pi / omega of the first "
                      "harmonic nodal force of the input at each value (so sweeping the "
                      "frequency moves the section). Unit: s.", Patterns::Double(0));
    prm.add_parameter("Transient periods", transient_periods,
                      "Forcing periods integrated before sampling. Unit: count.",
                      Patterns::Integer(0));
    prm.add_parameter("Sampled periods", sampled_periods,
                      "Poincaré samples per value (one per period; >= 32 to tell periods "
                      "up to 16). Unit: count.", Patterns::Integer(1, 100000));
    prm.add_parameter("Period tolerance", period_tolerance,
                      "Samples n periods apart are equal within this fraction of the "
                      "response's range over the sampled periods. Unit: dimensionless.",
                      Patterns::Double(0));
    prm.add_parameter("Continuation", continuation,
                      "Start each value from the previous value's final state (follow a "
                      "branch) instead of from rest. Unit: -.");
    prm.add_parameter("Lyapunov exponent", lyapunov_exponent,
                      "Also the largest Lyapunov exponent (a second, perturbed trajectory: "
                      "twice the work). Unit: -.");
    prm.add_parameter("Perturbation", perturbation,
                      "d0 of the Lyapunov exponent relative to the state's norm. "
                      "Unit: dimensionless.",
                      Patterns::Double(0));
    prm.leave_subsection();
  }

  void
  BifurcationParameters::check(const InputFile &input) const
  {
    sweep.check(input);
    if (lyapunov_exponent && !(perturbation > 0 && perturbation <= 1e-3))
      input.fail("Bifurcation/Perturbation", "must lie in (0, 1e-3], got " +
                                               format_value(perturbation));
  }

  unsigned int
  poincare_period(const std::vector<double> &samples, const double tolerance,
                  const unsigned int max_period)
  {
    for (unsigned int n = 1; n <= max_period && 2 * n <= samples.size(); ++n)
      {
        bool repeats = true;
        for (std::size_t k = 0; k + n < samples.size() && repeats; ++k)
          repeats = std::abs(samples[k + n] - samples[k]) <= tolerance;
        if (repeats)
          return n;
      }
    return 0;
  }

  namespace
  {
    /// The Poincaré samples x(k T), k = n_transient + 1 .. n_transient +
    /// n_sampled, of one DOF's displacement or velocity, and its range over
    /// those periods (every step).
    class PoincareSampler : public StepObserver
    {
    public:
      PoincareSampler(const unsigned int equation, const bool velocity,
                      const unsigned long steps_per_period, const unsigned int n_transient,
                      const unsigned int n_sampled)
        : equation(equation)
        , velocity(velocity)
        , steps_per_period(steps_per_period)
        , first_step(steps_per_period * n_transient)
      {
        samples.reserve(n_sampled);
      }

      void
      initialize(const ResponseView &) override
      {
        samples.clear();
        lowest  = std::numeric_limits<double>::infinity();
        highest = -lowest;
      }

      void
      observe_step(const ResponseView &state) override
      {
        if (state.step() < first_step)
          return;
        const double x = (velocity ? state.velocity() : state.displacement())[equation];
        lowest         = std::min(lowest, x);
        highest        = std::max(highest, x);
        if (state.step() > first_step && state.step() % steps_per_period == 0)
          samples.push_back(x);
      }

      void
      finish(const ResponseView &state, const RunStatus &) override
      {
        final_u = state.displacement();
        final_v = state.velocity();
      }

      std::vector<double> samples;
      double              lowest = 0, highest = 0;
      Vector              final_u, final_v; // the state at the end

    private:
      const unsigned int  equation;
      const bool          velocity;
      const unsigned long steps_per_period, first_step;
    };

    /// Benettin's second trajectory: its own elements and integrator, a
    /// step behind each step of the observed one, put back at d0 along the
    /// separation every period; ln(d_k / d0) summed over the sampled periods.
    class LyapunovEstimator : public StepObserver
    {
    public:
      LyapunovEstimator(const Analysis &analysis, const Excitation &excitation,
                        const unsigned long steps_per_period, const unsigned int n_transient,
                        const double period, const double perturbation)
        : elements(make_nonlinear_elements(analysis.model))
        , shadow(analysis.system, analysis.input.time_integration.linear_solver,
                 analysis.input.time_integration.newmark, &elements)
        , load([&excitation](const double t, Vector &p) { excitation.load(t, p); })
        , steps_per_period(steps_per_period)
        , first_step(steps_per_period * n_transient)
        , period(period)
        , omega(2 * M_PI / period)
        , delta(perturbation)
        , p(analysis.system.n_equations())
      {}

      void
      initialize(const ResponseView &state) override
      {
        load(0, p);
        shadow.initialize(p, state.displacement(), state.velocity()); // as the observed run
        d0 = 0, sum = 0, n_periods = 0;
      }

      void
      observe_step(const ResponseView &state) override
      {
        shadow.advance(load);
        if (state.step() % steps_per_period == 0)
          renormalise(state);
      }

      /// 1/s; 0 before any sampled period.
      double exponent() const { return n_periods > 0 ? sum / (n_periods * period) : 0; }

    private:
      /// |(du, dv / omega)|, the distance of the two states.
      double
      distance(const Vector &du, const Vector &dv) const
      {
        return std::sqrt(du.squaredNorm() + dv.squaredNorm() / (omega * omega));
      }

      void
      renormalise(const ResponseView &state)
      {
        du = shadow.displacement() - state.displacement();
        dv = shadow.velocity() - state.velocity();
        double d = distance(du, dv);
        if (d0 > 0 && state.step() > first_step)
          sum += std::log(d / d0), ++n_periods;
        const double scale = delta * distance(state.displacement(), state.velocity());
        if (!(scale > 0))
          return; // at rest: nothing to be relative to yet
        if (!(d > 0)) // the first time: along every displacement
          du.setConstant(1.0), dv.setZero(), d = distance(du, dv);
        d0 = scale;
        load(state.time(), p);
        shadow.restart(p, state.displacement() + (scale / d) * du,
                       state.velocity() + (scale / d) * dv);
      }

      NonlinearElements   elements; // before the integrator, which points to them
      NewmarkIntegrator   shadow;
      const LoadFunction  load;
      const unsigned long steps_per_period, first_step;
      const double        period, omega, delta;
      Vector              p, du, dv;
      double              d0 = 0, sum = 0;
      unsigned long       n_periods = 0;
    };

    /// T: the Forcing period, or 2 pi / omega of the first harmonic force.
    double
    forcing_period_of(const InputParameters &input)
    {
      const BifurcationParameters &b = input.bifurcation;
      if (b.forcing_period > 0)
        return b.forcing_period;
      for (const std::string &entry : input.nodal_forces.harmonic)
        {
          std::istringstream fields(entry); // building floor node dof amplitude omega phase
          std::string        skip;
          double             amplitude = 0, omega = 0;
          if (read_number(read_number(fields >> skip >> skip >> skip >> skip, amplitude), omega) &&
              omega > 0)
            return 2 * M_PI / omega;
          if (entry.find_first_not_of(" \t") != std::string::npos)
            break;
        }
      input.fail("Bifurcation/Forcing period",
                 "is 0, and the first harmonic nodal force gives no omega > 0 to take it from");
    }

    /// A value's input with dt' = T / round(T / dt) and the end time
    /// (transient + sampled) T, so that steps land on every k T.
    struct ValueInput
    {
      double          value = 0, period = 0;
      unsigned long   steps_per_period = 1;
      InputParameters input;
    };

    ValueInput
    input_at(const InputParameters &input, const double value)
    {
      const SweepParameters &sweep = input.bifurcation.sweep;
      const InputParameters  at    = sweep.input_for(input, value);
      ValueInput             v;
      v.value            = value;
      v.period           = forcing_period_of(at);
      v.steps_per_period = std::max(1.0, std::round(v.period / at.time_integration.newmark.time_step));
      const unsigned int n_periods =
        at.bifurcation.transient_periods + at.bifurcation.sampled_periods;
      v.input = sweep.input_for(input, value,
                                {{"Time integration/Time step",
                                  format_value(v.period / v.steps_per_period)},
                                 {"Time integration/End time", format_value(n_periods * v.period)}});
      return v;
    }

    /// A state to start from: the previous value's final one (Continuation).
    struct ModelState
    {
      Vector u, v;
    };

    /// The model of `v` prepared once and run once with the Poincaré
    /// sampler (and the second trajectory), from `state` when it is given
    /// and not empty, else from rest; `state` becomes the final state.
    BifurcationPoint
    run_point(const ValueInput &v, ModelState *state = nullptr)
    {
      const auto                   start = std::chrono::steady_clock::now();
      const InputParameters       &at    = v.input;
      const BifurcationParameters &b     = at.bifurcation;
      const unsigned long          n     = v.steps_per_period;
      const Analysis     analysis   = prepare_analysis(at);
      const Excitation   excitation = make_excitation(analysis);
      std::istringstream fields(b.response);
      const NodeDof dof = find_node_dof(at, analysis.model, fields, "Bifurcation/Response", b.response);
      const bool from_state = state && state->u.size() > 0;
      if (from_state && state->u.size() != analysis.system.n_equations())
        at.fail("Bifurcation/Continuation", "the model's equations change at " +
                                              format_value(v.value) + ": cannot continue");

      TimeHistory     history(analysis);
      PoincareSampler sampler(dof.equation, b.quantity == "velocity", n, b.transient_periods,
                              b.sampled_periods);
      Observers       observers{&sampler};
      std::optional<LyapunovEstimator> lyapunov;
      if (b.lyapunov_exponent)
        observers.push_back(&lyapunov.emplace(analysis, excitation, n, b.transient_periods,
                                              v.period, b.perturbation));
      const RunStatus status = from_state ? history.run(state->u, state->v, excitation, observers) :
                                            history.run(excitation, observers);
      if (state) // after a failure the next value starts from rest
        *state = status.completed() ? ModelState{sampler.final_u, sampler.final_v} : ModelState{};
      BifurcationPoint point;
      point.value          = v.value;
      point.forcing_period = v.period;
      point.time_step      = at.time_integration.newmark.time_step;
      point.completed      = status.completed();
      point.samples        = sampler.samples;
      point.response_range = sampler.samples.empty() ? 0 : sampler.highest - sampler.lowest;
      point.period = point.completed ?
                       poincare_period(point.samples, b.period_tolerance * point.response_range) :
                       0;
      point.lyapunov_exponent = lyapunov ? lyapunov->exponent() : 0;
      point.wall_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return point;
    }
  } // namespace

  BifurcationPoint
  bifurcation_point(const InputParameters &input, const double value)
  {
    return run_point(input_at(input, value));
  }

  namespace
  {
    /// "m", "m/s", "rad" or "rad/s".
    std::string
    response_unit(const BifurcationParameters &b)
    {
      const bool rotation = b.response.find("rz") != std::string::npos;
      return std::string(rotation ? "rad" : "m") + (b.quantity == "velocity" ? "/s" : "");
    }

    /// The response's CSV column: "displacement_m", "velocity_rad_s", ...
    std::string
    response_column(const BifurcationParameters &b)
    {
      std::string unit = response_unit(b);
      std::replace(unit.begin(), unit.end(), '/', '_');
      return b.quantity + "_" + unit;
    }

    void
    write_tables(const InputParameters &input, const std::vector<BifurcationPoint> &points,
                 const std::string &directory)
    {
      const BifurcationParameters &b = input.bifurcation;
      const std::string x = b.sweep.column_name();
      CsvWriter samples(directory + "/bifurcation.csv", {x, "sample", response_column(b)});
      CsvWriter classes(directory + "/bifurcation_classification.csv",
                        {x, "period", "lyapunov_exponent_1_s", "forcing_period_s", "time_step_s",
                         "response_range", "completed"});
      for (const BifurcationPoint &point : points)
        {
          for (std::size_t k = 0; k < point.samples.size(); ++k)
            {
              samples.begin_row(point.value);
              samples.add(k + 1);
              samples.add(point.samples[k]);
              samples.end_row();
            }
          classes.begin_row(point.value);
          for (const double c : {double(point.period), point.lyapunov_exponent,
                                 point.forcing_period, point.time_step, point.response_range,
                                 point.completed ? 1.0 : 0.0})
            classes.add(c);
          classes.end_row();
        }
      samples.commit();
      classes.commit();
    }

    /// summary.json: the settings, how time was stepped, and per value the
    /// period (0: non-periodic) and the Lyapunov exponent.
    void
    write_summary(const InputParameters &input, const std::vector<BifurcationPoint> &points,
                  const std::string &directory, const double wall_time, const bool interrupted)
    {
      const BifurcationParameters &b = input.bifurcation;
      std::vector<double> values, periods, exponents, forcing, steps;
      bool                all = true;
      for (const BifurcationPoint &point : points)
        {
          values.push_back(point.value), periods.push_back(point.period);
          exponents.push_back(point.lyapunov_exponent), forcing.push_back(point.forcing_period);
          steps.push_back(point.time_step), all = all && point.completed;
        }
      JsonWriter json;
      begin_summary(json, "bifurcation", input,
                    interrupted ? "interrupted" : all ? "completed" : "failed");
      json.value("parameter", b.sweep.parameter).value("response", b.response)
        .value("response_quantity", b.quantity).value("transient_periods", b.transient_periods)
        .value("sampled_periods", b.sampled_periods)
        .value("time_step_rule", "dt = T / round(T / dt_input): steps land on every k T, "
                                 "no interpolation")
        .value("period_rule", "smallest n <= 16 with |x_{k+n} - x_k| <= tolerance * range "
                              "for every sample; 0: non-periodic")
        .value("period_tolerance", b.period_tolerance)
        .value("continuation", b.continuation)
        .value("lyapunov_exponent", b.lyapunov_exponent)
        .value("lyapunov_method", "Benettin two-trajectory, renormalised every period, "
                                  "d0 = perturbation * |(u, v / omega)|")
        .value("perturbation", b.perturbation).value("wall_time_s", wall_time)
        .value("values", values).value("periods", periods).value("lyapunov_exponents_1_s", exponents)
        .value("forcing_periods_s", forcing).value("time_steps_s", steps).end_object();
      write_file_atomically(directory + "/summary.json", json.str());
    }

    /// The diagram (Poincaré samples as dots against the value) with the
    /// Lyapunov exponent in a panel under it.
    void
    draw_diagram(const InputParameters &input, const std::string &directory)
    {
      const BifurcationParameters &b = input.bifurcation;
      const std::string label = b.quantity + " (" + response_unit(b) + ")";
      Plot diagram{"bifurcation.png", "bifurcation diagram: Poincare samples of " + b.response +
                                        " " + b.quantity, b.sweep.axis_label(), label,
                   {{"bifurcation.csv", "1:3", "x(kT)", "points pt 7 ps 0.3"}}};
      if (b.lyapunov_exponent)
        diagram.below.push_back(Plot{"", "largest Lyapunov exponent", b.sweep.axis_label(),
                                     "lambda (1/s)",
                                     {{"bifurcation_classification.csv", "1:3", "lambda",
                                       "linespoints"}}});
      draw_plots(directory, {diagram});
    }
  } // namespace

  std::vector<BifurcationPoint>
  bifurcation_points(const InputParameters &input)
  {
    const BifurcationParameters &b = input.bifurcation;
    b.sweep.require(input);
    std::vector<ValueInput> inputs; // every value's input checked before any work
    for (const double value : b.sweep.values())
      inputs.push_back(input_at(input, value));
    std::vector<BifurcationPoint> points;
    Progress   progress(std::cerr, "bifurcation: values", inputs.size());
    ModelState state; // empty: from rest
    for (const ValueInput &v : inputs)
      {
        if (interruption_requested()) // the values done so far are the result
          break;
        points.push_back(run_point(v, b.continuation ? &state : nullptr));
        progress.update(points.size());
      }
    return points;
  }

  int
  bifurcation_command(const InputParameters &input, const std::string &directory)
  {
    const BifurcationParameters  &b     = input.bifurcation;
    const auto                    start = std::chrono::steady_clock::now();
    const std::vector<BifurcationPoint> points = bifurcation_points(input);
    const double wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // SIGINT/SIGTERM stop between values: the values finished are written
    // (status "interrupted"), as a Monte Carlo writes its realizations.
    const bool interrupted = interruption_requested();
    prepare_output_directory(directory);
    write_tables(input, points, directory);
    write_summary(input, points, directory, wall_time, interrupted);
    if (input.output.plots && !points.empty())
      draw_diagram(input, directory);
    if (interrupted)
      {
        std::cerr << "poundfe: bifurcation interrupted (" << directory
                  << "/summary.json says interrupted): " << points.size() << " of "
                  << b.sweep.values().size() << " values kept in bifurcation.csv\n";
        return interrupted_exit_status();
      }

    const auto n_failed = std::count_if(points.begin(), points.end(),
                                        [](const BifurcationPoint &p) { return !p.completed; });
    std::cout << "poundfe bifurcation: " << points.size() << " values of " << b.sweep.parameter
              << " in " << wall_time << " s\nresults in " << directory
              << "/ (bifurcation.csv, bifurcation_classification.csv, summary.json, "
                 "bifurcation.png)\n";
    if (n_failed > 0)
      {
        std::cerr << "poundfe: numerical failure at " << n_failed
                  << " values (completed = 0 in bifurcation_classification.csv)\n";
        return 2;
      }
    return 0;
  }
} // namespace poundfe
