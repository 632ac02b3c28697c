// The state that the time steppers other than Newmark's keep alike
// (DormandPrinceIntegrator, MoreauJeanIntegrator, ReplayedStepper): the
// time and the steps taken, u, v and a, the energy balance and its largest
// error, the impact and stick-slip logs, the statistics, each element's
// work and the sub-step callback, with TimeStepper's accessors on them and
// the reset that starts a run. One copy here, so that a stepper adds only
// what its method needs. NewmarkIntegrator keeps its own (sub-steps,
// partitioned balances).
#ifndef poundfe_integration_stepper_state_h
#define poundfe_integration_stepper_state_h

#include <poundfe/integration/newmark.h>
#include <poundfe/integration/time_stepper.h>

#include <functional>
#include <vector>

namespace poundfe
{
  class TimeStepperState : public TimeStepper
  {
  public:
    void set_substep_callback(std::function<void()> callback) override
    {
      substep_callback = std::move(callback);
    }

    double        time() const override { return current_time; }
    unsigned long steps() const override { return step_count; }
    const Vector &displacement() const override { return u; }
    const Vector &velocity() const override { return v; }
    const Vector &acceleration() const override { return a; }

    EnergyBalance energy() const override { return balance; }
    double        max_energy_error() const override { return max_balance_error; }
    double element_work(unsigned int h) const override { return work[h]; }
    double element_supplied_work(unsigned int) const override { return 0; }
    const ImpactLog           &impact_log() const override { return impacts; }
    const StickSlipLog        &stick_slip_log() const override { return stick_slip; }
    const IterationStatistics &statistics() const override { return stats; }

  protected:
    /// Back to the start of a run: time 0, no steps, empty logs and zero
    /// work for n_elements elements, zero balance and error, statistics
    /// whose smallest step is `time_step` (none smaller taken yet).
    void reset_state(const unsigned int n_elements, const double time_step)
    {
      current_time = 0;
      step_count   = 0;
      stats        = IterationStatistics();
      stats.smallest_time_step = time_step;
      balance                  = EnergyBalance();
      energy_scale = max_balance_error = 0;
      impacts.reset(n_elements);
      stick_slip.reset(n_elements);
      work.assign(n_elements, 0.0);
    }

    Vector                u, v, a;
    double                current_time = 0;
    unsigned long         step_count   = 0;
    EnergyBalance         balance;
    double                energy_scale = 0, max_balance_error = 0;
    ImpactLog             impacts;
    StickSlipLog          stick_slip;
    IterationStatistics   stats;
    std::vector<double>   work; // per element, J
    std::function<void()> substep_callback;
  };
} // namespace poundfe

#endif
