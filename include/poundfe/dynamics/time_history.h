// The time loop: the time-history engine of one model and the excitation
// it runs under, the one loop over steps of the program (a run partitioned
// by building steps through it too, with a LockstepStepper). (A run with the
// standard outputs: report/run_outputs.h.)
#ifndef poundfe_dynamics_run_h
#define poundfe_dynamics_run_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/initial_conditions.h>
#include <poundfe/base/input_file.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/excitation/excitation_parameters.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/integration/time_integration_parameters.h>
#include <poundfe/output/observer.h>

#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class MoreauJeanIntegrator; // integration/moreau_jean.h

  /// What a time history of the model reads from the input: how to
  /// integrate, what loads it, and the file they came from (for messages).
  /// Each part is its module's own section.
  struct TimeHistoryParameters
  {
    InputFile                 input;
    TimeIntegrationParameters time_integration;
    GroundMotionParameters    ground_motion;
    NodalForceParameters      nodal_forces;
    /// The state at t = 0 (default: rest).
    InitialConditionParameters initial_conditions;
  };

  /// One observation of every observer: initialize, observe_step or observe_substep.
  using Observation = void (StepObserver::*)(const ResponseView &);

  /// A stepper that advances with the other ranks of a communicator in
  /// lockstep, each rank its own part of the model (a run partitioned by
  /// building: dynamics/partitioned_stepper.h). TimeHistory::run steps it
  /// in its one loop; at the loop's collective points (before each step
  /// and once after the last, each observation, the end) it lets the ranks
  /// agree through these calls, made in the same order on every rank.
  class LockstepStepper : public TimeStepper
  {
  public:
    /// The whole model's nonlinear elements, which the observers see.
    virtual const NonlinearElements &observed_elements() const = 0;
    /// What this rank observes of the model, into `view` (ResponseView::set_observed).
    virtual void set_observed(ResponseView &view) const = 0;
    /// Before each step and once after the last: false when every rank goes
    /// on, else true with `status` saying why all stop (a signal when
    /// `interruptible`, a rank whose replay or observers failed). Collective.
    virtual bool agreed_stop(bool interruptible, RunStatus &status) = 0;
    /// `call` of `observers` on `view`, unless this rank stopped (a failure
    /// is kept for agreed_stop, never thrown), then what they gave the
    /// other ranks exchanged. Collective.
    virtual void observe(Observation call, const Observers &observers, const ResponseView &view) = 0;
    /// At the end: the ranks' observations merged (collective; `status`
    /// takes the run's end and any failure of the ranks' share of
    /// finishing); true on the rank whose observers finish, reading the
    /// merged values through `view`.
    virtual bool merged(const Observers &observers, ResponseView &view, RunStatus &status) = 0;
  };

  /// The time-history engine of one model: the nonlinear elements and the
  /// integrator (with its factorisations) are set up once, and each run()
  /// starts again from the input's initial conditions (rest by default).
  /// Monte Carlo runs every realization through one.
  class TimeHistory
  {
  public:
    /// `linear_solver` empty: the input's (Time integration/Linear solver).
    TimeHistory(const Analysis &analysis, const TimeHistoryParameters &parameters,
                const std::string &linear_solver = "");
    /// The loop over `stepper`, made by the caller, which steps this rank's
    /// part of the model with the other ranks (it must outlive this object):
    /// no integrator of its own. The observers see the stepper's state of
    /// the whole model.
    TimeHistory(const Analysis &analysis, const TimeHistoryParameters &parameters,
                LockstepStepper &stepper);
    ~TimeHistory();
    TimeHistory(const TimeHistory &) = delete;
    TimeHistory &operator=(const TimeHistory &) = delete;

    /// From the initial conditions to the end time under `excitation`
    /// (initial_conditions.h); the observers see the
    /// initial state, every step and the end. A NumericalError ends the
    /// run with status failed; when `interruptible`, SIGINT/SIGTERM end it
    /// after the current step with status interrupted. (A realization of a
    /// probabilistic analysis is not interruptible: its driver stops
    /// between realizations, so no partial realization is ever recorded.)
    RunStatus run(const Excitation &excitation, const Observers &observers,
                  bool interruptible = false);
    /// The same from (u0, v0) at t = 0 instead of rest (e.g. a
    /// continuation from an earlier run's final state).
    RunStatus run(const Vector &u0, const Vector &v0, const Excitation &excitation,
                  const Observers &observers, bool interruptible = false);

    /// The view observers read; valid for the life of this object.
    const ResponseView &state() const { return view; }
    const NonlinearElements &nonlinear_elements() const { return view.elements; }
    /// The integrator's choices (not with a LockstepStepper: its own).
    std::string tangent_update() const;
    std::string linear_solver_name() const;

    /// Steps of the analysis time step to the end time.
    unsigned long n_steps(const Excitation &excitation) const;

    /// The nonlinear elements made again from `model`, a copy of the
    /// analysis' model whose nonlinear laws (not M, K, C, nor which DOFs an
    /// element joins) differ: the integrator keeps its factorisations, which
    /// depend on the elements' DOFs and tangent bases only.
    void replace_nonlinear_elements(const Model &model);

  private:
    /// Whether the run stops before step `step` of `n` (after the last:
    /// step > n); `status` then says why.
    bool stops_before(unsigned long step, unsigned long n, bool interruptible,
                      RunStatus &status) const;
    /// `call` of every observer (through the lockstep stepper, if any).
    void observe(Observation call, const Observers &observers);

    const Analysis   &analysis;
    const InputFile   input;            // for messages about the end time
    const TimeIntegrationParameters time_integration;
    const GroundMotionParameters ground_motion; // what sets the end without an End time
    NonlinearElements elements; // before the integrator, which points to them (empty: lockstep)
    std::unique_ptr<NewmarkIntegrator> integrator; // null with a lockstep stepper
    /// Time integration/Method = dopri: the integrator that runs (null: Newmark).
    std::unique_ptr<DormandPrinceIntegrator> dopri;
    /// Contact/Model = nonsmooth: Moreau-Jean's rigid contact (null: penalty).
    std::unique_ptr<MoreauJeanIntegrator> rigid;
    TimeStepper      &stepper; // *integrator, *dopri, *rigid or *lockstep
    LockstepStepper  *lockstep = nullptr;
    ResponseView      view;
    const InitialState initial; // checked against the model on construction
  };

  /// "A3 node 12 at (6, 3) rz" for each equation of `model` (the first DOF
  /// that maps to it): where Newton's messages point.
  std::vector<std::string> equation_names(const Model &model);
  /// The same for one equation (a search: for a message).
  std::string equation_name(const Model &model, unsigned int equation);

  /// Steps of the analysis time step from 0 to the end time (Time
  /// integration/End time, else the ground motion's duration); InputError
  /// naming what set the end when it is not positive or too many steps.
  unsigned long n_steps_of(const TimeHistoryParameters &parameters, const Excitation &excitation);

  /// Every observer's finish(), even when one cannot write its files: an
  /// OutputError makes `status` failed (output_failed) and is added to its
  /// message; the summary, last, then reports the file that failed.
  void finish_observers(const Observers &observers, const ResponseView &state, RunStatus &status);

  /// SIGINT/SIGTERM (base/interruption.h), agreed by every rank of
  /// `communicator` (mpirun may deliver it to the ranks at different steps;
  /// a rank that stopped alone would leave the others waiting). Collective.
  bool stop_requested(MPI_Comm communicator);

  /// The excitation the input describes: the ground motion and the nodal
  /// forces (with white-noise forces, the sample of Ground motion/Realization).
  Excitation make_excitation(const Analysis &analysis, const TimeHistoryParameters &parameters);
} // namespace poundfe

#endif
