// What watches a time history: observers of the accepted steps.
//
// The time loop (TimeHistory::run, dynamics/time_history.cc) advances the integrator
// one step at a time and, after each step, hands every observer the same
// read-only ResponseView of the state: time, u, v, a (relative to the
// ground), the ground acceleration, the nonlinear elements, and the
// integrator's running energy balance, impact log and Newton statistics.
// An observer never changes the state and never reaches into the
// integrator; peaks, recorders, VTU frames, the summary and the console
// progress are all observers. The pattern follows deal.II's step-23/26
// (set up, step, output) with the output split into independent parts.
#ifndef poundfe_output_observer_h
#define poundfe_output_observer_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/base/rank_merge.h>
#include <poundfe/model/model.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  /// How a time history ended.
  struct RunStatus
  {
    enum class Kind
    {
      completed,
      failed,     // a numerical failure or an output error: results up to end_time are kept
      interrupted // SIGINT/SIGTERM: stopped at the end of a step
    };
    Kind          kind      = Kind::completed;
    std::string   message;       // the failure, when failed
    /// failed because a results file could not be written (OutputError:
    /// disk full, ...), not numerically; `message` says which and why
    bool          output_failed = false;
    unsigned long steps     = 0; // steps of the analysis time step reached
    double        end_time  = 0; // s
    double        wall_time = 0; // s, the stepping loop with its observers

    bool completed() const { return kind == Kind::completed; }
    /// "completed", "failed" or "interrupted" (summary.json's status).
    const char *name() const;
  };

  /// The state after an accepted step, read-only.
  class ResponseView
  {
  public:
    ResponseView(const Model &model, const LinearSystem &system,
                 const NonlinearElements &elements, const TimeStepper &integrator);

    /// Called by the time loop once per step, before the observers, with
    /// the ground acceleration (a_x, a_y, a_z) (a_y = 0 without a horizontal
    /// pair, a_z = 0 without a vertical component).
    void set_step(unsigned long step, const std::array<double, 3> &ground_acceleration);
    /// Whether the run has a vertical ground motion (Components = 3): set
    /// once, before the observers are made.
    void set_vertical_ground_motion(bool vertical) { vertical_ground = vertical; }
    bool has_vertical_ground_motion() const { return vertical_ground; }

    unsigned long step() const { return step_index; }
    double        time() const { return integrator.time(); }
    double        ground_acceleration() const { return ground[0]; }
    /// a_y: a 3D model's ground acceleration along y (0 in 2D).
    double        ground_acceleration_y() const { return ground[1]; }
    /// a_z: the vertical ground acceleration, upward (0 without one).
    double        ground_acceleration_z() const { return ground[2]; }
    const Vector &displacement() const { return integrator.displacement(); }
    const Vector &velocity() const { return integrator.velocity(); }
    const Vector &acceleration() const { return integrator.acceleration(); }

    const Model            &model;
    const LinearSystem     &system;
    const NonlinearElements &elements;

    EnergyBalance              energy() const { return integrator.energy(); }
    double                     max_energy_error() const { return integrator.max_energy_error(); }
    /// Work done on nonlinear element h so far, J.
    double                     element_work(unsigned int h) const { return integrator.element_work(h); }
    /// Energy element h has dissipated so far: its work minus its stored
    /// energy plus what its drive (a belt) supplied, J.
    double                     dissipated_energy(unsigned int h) const;
    /// Each element's stored energy at the end of a run whose elements
    /// this view does not all hold at their last state (observation by
    /// rank: ReplayedStepper::stored_energies); nullptr: the elements'.
    void set_stored_energies(const std::vector<double> *energies) { stored_energies = energies; }
    /// Observation by rank: the elements and buildings this rank observes
    /// (masks over the whole model's; nullptr: all). The others are at rest
    /// here and their values dropped when merged, so that observers may
    /// skip them.
    void set_observed(const std::vector<char> *elements, const std::vector<char> *buildings)
    {
      observed_elements  = elements;
      observed_buildings = buildings;
    }
    bool observes_element(const unsigned int h) const
    {
      return !observed_elements || (*observed_elements)[h];
    }
    bool observes_building(const unsigned int b) const
    {
      return !observed_buildings || (*observed_buildings)[b];
    }
    const ImpactLog           &impact_log() const { return integrator.impact_log(); }
    const StickSlipLog        &stick_slip_log() const { return integrator.stick_slip_log(); }
    const IterationStatistics &statistics() const { return integrator.statistics(); }
    /// At observe_step and observe_substep: whether the elements' last
    /// trial state is this state (TimeStepper::elements_hold_state).
    bool elements_hold_state() const { return integrator.elements_hold_state(); }

  private:
    const TimeStepper &integrator;
    unsigned long            step_index = 0;
    std::array<double, 3>    ground{{0, 0, 0}};
    bool                     vertical_ground = false;
    const std::vector<double> *stored_energies = nullptr;
    const std::vector<char>   *observed_elements = nullptr, *observed_buildings = nullptr;
  };

  /// Watches a time history: initialize() sees the initial state (step 0),
  /// observe_step() every accepted step, finish() the final state and how
  /// the run ended (also after a failure or an interruption).
  class StepObserver
  {
  public:
    virtual ~StepObserver() = default;
    virtual void initialize(const ResponseView &state) { observe_step(state); }
    virtual void observe_step(const ResponseView &state) = 0;
    /// The end of a sub-step inside a step that was cut (a contact resolved
    /// in time, an event located, a step halved to converge): for what
    /// must not miss a peak between steps. Recorders keep to the steps.
    virtual void observe_substep(const ResponseView &) {}
    /// Observation by rank (a run partitioned by building): what this rank
    /// observed of its own part, merged on rank 0 after the last step and
    /// before finish(). Collective, in the order of the observers, alike on
    /// every rank; nothing for an observer that merges nothing.
    virtual void merge(const RankMerge &) {}
    virtual void finish(const ResponseView &, const RunStatus &) {}
  };

  using Observers = std::vector<StepObserver *>;

  /// An observer that writes (a row, a frame) at the steps 0, every,
  /// 2 every, ...: found by a comparison, not a division, per step.
  class PeriodicObserver : public StepObserver
  {
  public:
    explicit PeriodicObserver(const unsigned int every)
      : every(every)
    {}
    void
    initialize(const ResponseView &state) override
    {
      next = 0;
      observe_step(state);
    }
    void
    observe_step(const ResponseView &state) override
    {
      if (state.step() != next)
        return;
      next += every;
      write(state);
    }

  protected:
    /// What it does at each of its steps.
    virtual void write(const ResponseView &state) = 0;

  private:
    const unsigned int every;
    unsigned long      next = 0;
  };
} // namespace poundfe

#endif
