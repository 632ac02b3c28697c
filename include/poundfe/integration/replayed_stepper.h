// One rank's view of a run partitioned by building (dynamics/partitioned_history.h)
// for the observers that write the run's outputs (report/run_outputs.h,
// observation by rank, theory §3.5d): u, v and a in the model's numbering,
// filled with the rank's own values and ghosts after each accepted
// (sub)step, and the nonlinear elements this rank observes replayed through
// the same accepted states (the others stay at rest). A law's trial state
// is a function of its committed state and of the trial displacements and
// velocities alone (the uniaxial-material interface of OpenSees: McKenna,
// Scott & Fenves 2010; doc/theory.md §2.1), so setting each element's trial
// state at the accepted state and committing it gives the integrator's
// history; the impact and stick-slip logs and each element's work are
// recorded from it by the code NewmarkIntegrator records them with
// (ElementRecords), and merged on rank 0 at the end. The energy balance and
// the Newton statistics are the partitioned integrator's (summed over the
// ranks, and alike on every rank). It does not integrate: initialize() and
// advance() are not for it.
#ifndef poundfe_integration_replayed_stepper_h
#define poundfe_integration_replayed_stepper_h

#include <poundfe/integration/element_records.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/integration/stepper_state.h>

#include <array>

namespace poundfe
{
  class ReplayedStepper final : public TimeStepperState
  {
  public:
    /// `elements`: the whole model's, numbered as the model; it must
    /// outlive this object. `observed[h]`: whether element h is replayed
    /// here (empty: every element).
    ReplayedStepper(NonlinearElements &elements, unsigned int n_equations,
                    std::vector<char> observed = {});

    /// u, v and a of the whole model, to be filled in place (each rank's own
    /// values and ghosts) before start() and each replay(): nothing allocated
    /// per state.
    std::array<Vector *, 3> state_to_fill() { return {{&u, &v, &a}}; }
    /// The initial state (t = 0) is in state_to_fill().
    void start();
    /// The state in state_to_fill() was accepted at time `t` after a
    /// (sub)step of length `h` (NewmarkIntegrator::last_step_length), the
    /// integrator's `n_accepted`-th accepted (sub)step: the elements are
    /// replayed to it once (a step's last sub-step is seen twice: as a
    /// sub-step and as the step, whose time is then taken). The logs span
    /// [t_previous, t_previous + h], as the integrator's do.
    void replay(double t, double h, unsigned long n_accepted);
    /// The partitioned integrator's balance, statistics and steps taken.
    void set_integrator_state(const EnergyBalance &energy, double max_energy_error,
                              const IterationStatistics &statistics, unsigned long steps);
    /// Observation by rank, at the run's end: each element's work, its
    /// stored energy at the last state and the impacts from the rank that
    /// observes it, on rank 0. Collective.
    void merge(const RankMerge &ranks);
    /// Each element's stored energy at the last state, after merge() on
    /// rank 0 (ResponseView::set_stored_energies).
    const std::vector<double> &stored_energies() const { return stored; }

    void initialize(const Vector &load, const Vector &u0, const Vector &v0) override;
    void advance(const LoadFunction &load) override;

    // time, state, balance and statistics: TimeStepperState's; the work and
    // the logs are the replay's records
    double element_work(unsigned int h) const override { return records.work()[h]; }
    double element_supplied_work(unsigned int h) const override
    {
      return records.supplied_work()[h];
    }
    const ImpactLog           &impact_log() const override { return records.impact_log(); }
    const StickSlipLog        &stick_slip_log() const override { return records.stick_slip_log(); }

  private:
    /// Every element's trial state at (u, v); NumericalError if one refuses
    /// it (it was accepted by its owner: a bug, not an input).
    void set_trial_states();

    NonlinearElements  &elements;
    ElementRecords      records;
    std::vector<unsigned int> replayed; // the elements observed here
    std::vector<double> stored;         // after merge()
    // the DOFs of element replayed[i] are [dof_start[i], dof_start[i + 1]) of
    // local_u, local_v (a rank's own elements: its share of the model)
    std::vector<unsigned int> dof_start;
    Vector              local_u, local_v;
    unsigned long       accepted = 0;
  };
} // namespace poundfe

#endif
