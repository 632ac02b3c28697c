// A rank's replay of a partitioned run (integration/replayed_stepper.h).
#include <poundfe/integration/replayed_stepper.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>

#include <deal.II/base/exceptions.h>

namespace poundfe
{
  ReplayedStepper::ReplayedStepper(NonlinearElements &elements, const unsigned int n_equations,
                                   const std::vector<char> observed)
    : elements(elements)
    , records(&elements, observed.empty() ? nullptr : &observed)
  {
    AssertThrow(observed.empty() || observed.size() == elements.size(),
                dealii::ExcDimensionMismatch(observed.size(), elements.size()));
    for (unsigned int h = 0; h < elements.size(); ++h)
      if (observed.empty() || observed[h])
        replayed.push_back(h);
    dof_start.assign(1, 0);
    for (const unsigned int h : replayed) // the DOFs of the observed elements only
      dof_start.push_back(dof_start.back() + elements[h].n_dofs());
    local_u.setZero(dof_start.back());
    local_v.setZero(dof_start.back());
    for (Vector *x : {&u, &v, &a})
      x->setZero(n_equations);
  }

  void
  ReplayedStepper::set_trial_states()
  {
    for (std::size_t i = 0; i < replayed.size(); ++i)
      {
        NonlinearElement       &e         = elements[replayed[i]];
        const std::vector<int> &equations = e.equations();
        const unsigned int      s = dof_start[i], k = equations.size();
        for (unsigned int q = 0; q < k; ++q)
          {
            local_u[s + q] = equations[q] >= 0 ? u[equations[q]] : 0.0;
            local_v[s + q] = equations[q] >= 0 ? v[equations[q]] : 0.0;
          }
        if (!e.set_trial(local_u.segment(s, k), local_v.segment(s, k)))
          throw NumericalError("the replay of the state at t = " + number_text(current_time) +
                               " s: " + e.label + ": " + e.failure());
      }
  }

  void
  ReplayedStepper::start()
  {
    reset_state(0, 0); // its logs and work are the records'
    accepted = 0;
    for (NonlinearElement &e : elements)
      e.reset();
    set_trial_states();
    for (const unsigned int h : replayed)
      elements[h].commit();
    records.note_committed(elements, v);
    records.start(elements);
  }

  void
  ReplayedStepper::replay(const double t, const double h, const unsigned long n_accepted)
  {
    if (n_accepted == accepted)
      {
        // the step's last sub-step, seen again as the step: the integrator
        // then restarts its clock at n Δt, which t0 + h of the sub-step may
        // miss by an ulp, and so does the replay
        current_time = t;
        return;
      }
    const double t0 = current_time;
    current_time    = t;
    accepted        = n_accepted;
    for (const unsigned int h : replayed)
      elements[h].set_trial_time(t);
    set_trial_states();
    double belt = 0; // the integrator's balance has it
    records.accept(elements, t0, t0 + h, v, nullptr, belt);
  }

  void
  ReplayedStepper::set_integrator_state(const EnergyBalance &energy, const double max_energy_error,
                                        const IterationStatistics &statistics,
                                        const unsigned long steps)
  {
    balance    = energy;
    max_balance_error = max_energy_error;
    stats      = statistics;
    step_count = steps;
  }

  void
  ReplayedStepper::merge(const RankMerge &ranks)
  {
    records.merge(ranks);
    stored.assign(elements.size(), 0.0);
    for (const unsigned int h : replayed)
      stored[h] = elements[h].stored_energy();
    ranks.owned(Owner::element, stored);
  }

  void
  ReplayedStepper::initialize(const Vector &, const Vector &, const Vector &)
  {
    AssertThrow(false, dealii::ExcMessage("a replayed run is started by start()"));
  }

  void
  ReplayedStepper::advance(const LoadFunction &)
  {
    AssertThrow(false, dealii::ExcMessage("a replayed run does not integrate: replay()"));
  }
} // namespace poundfe
