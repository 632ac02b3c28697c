// Bifurcation diagrams: Poincaré sections x_k = x(k T) of the steady
// response to a harmonic force of period T, their period, and the largest
// Lyapunov exponent by Benettin's two-trajectory method,
//   lambda = (1 / (K T)) sum_{k=1..K} ln(d_k / d0),
// the second trajectory put back at distance d0 along the separation after
// every period (Benettin, Galgani, Giorgilli & Strelcyn 1980, Meccanica
// 15:9-20; Wolf, Swift, Swinney & Vastano 1985, Physica D 16:285-317),
// both trajectories integrated through the discontinuities (cf. Müller
// 1995, Chaos Solitons Fractals 5:1671-1681, for the variational route).
// See dynamics/bifurcation.h and doc/theory.md §8.4. (Each value's input is
// read in input/bifurcation_input.h; the command is commands/bifurcation_command.cc.)
#include <poundfe/dynamics/bifurcation.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/base/choices.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
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
    if (!continuation) // continued, a value again goes on along the branch (up and back down)
      input.distinct("Bifurcation/Values", sweep.values()); // from rest: the same point twice
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
      LyapunovEstimator(const Analysis &analysis, const TimeIntegrationParameters &time_integration,
                        const Excitation &excitation, const unsigned long steps_per_period,
                        const unsigned int n_transient, const double period,
                        const double perturbation)
        : elements(make_nonlinear_elements(analysis.model))
        , shadow(analysis.system, time_integration.linear_solver, time_integration.newmark,
                 &elements)
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
        // A perturbation that vanishes within a period (both trajectories
        // stuck at the same point: a superstable orbit, exponent -inf) counts
        // as contracted to round-off, ln(eps) per period, so the estimate
        // is finite and an upper bound there.
        if (d0 > 0 && state.step() > first_step)
          sum += std::log(std::max(d, std::numeric_limits<double>::epsilon() * d0) / d0),
            ++n_periods;
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

  } // namespace

  double
  forcing_period(const BifurcationParameters &b, const NodalForceParameters &nodal_forces,
                 const InputFile &input)
  {
    if (b.forcing_period > 0)
      return b.forcing_period;
    for (const std::string &entry : nodal_forces.harmonic)
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

  BifurcationPoint
  bifurcation_point(const Analysis &analysis, const TimeHistoryParameters &parameters,
                    const BifurcationParameters &b, const double value, const double period,
                    const unsigned long steps_per_period, BifurcationState *state)
  {
    const InputFile   &input      = parameters.input;
    const unsigned long n         = steps_per_period;
    const Excitation   excitation = make_excitation(analysis, parameters);
    std::istringstream fields(b.response);
    const NodeDof dof = find_node_dof(input, analysis.model, fields, "Bifurcation/Response", b.response);
    const bool from_state = state && state->u.size() > 0;
    if (from_state && state->u.size() != analysis.system.n_equations())
      input.fail("Bifurcation/Continuation", "the model's equations change at " +
                                               format_value(value) + ": cannot continue");

    TimeHistory     history(analysis, parameters);
    PoincareSampler sampler(dof.equation, b.quantity == "velocity", n, b.transient_periods,
                            b.sampled_periods);
    Observers       observers{&sampler};
    std::optional<LyapunovEstimator> lyapunov;
    if (b.lyapunov_exponent)
      observers.push_back(&lyapunov.emplace(analysis, parameters.time_integration, excitation, n,
                                            b.transient_periods, period, b.perturbation));
    const RunStatus status = from_state ? history.run(state->u, state->v, excitation, observers) :
                                          history.run(excitation, observers);
    if (state) // after a failure the next value starts from rest
      *state = status.completed() ? BifurcationState{sampler.final_u, sampler.final_v} :
                                    BifurcationState{};
    BifurcationPoint point;
    point.value          = value;
    point.forcing_period = period;
    point.time_step      = parameters.time_integration.newmark.time_step;
    point.completed      = status.completed();
    point.samples        = sampler.samples;
    point.response_range = sampler.samples.empty() ? 0 : sampler.highest - sampler.lowest;
    point.period = point.completed ?
                     poincare_period(point.samples, b.period_tolerance * point.response_range) :
                     0;
    point.lyapunov_exponent = lyapunov ? lyapunov->exponent() : 0;
    return point;
  }
} // namespace poundfe
