// The stepper of a run partitioned by building over the ranks of a
// communicator (doc/theory.md §3.5d), which TimeHistory::run steps in the
// program's one time loop: each rank advances its own buildings in lockstep
// with the others (PartitionedHistory) and, after every accepted (sub)step,
// replays the nonlinear elements it observes through its own values and
// ghosts (integration/replayed_stepper.h); the observers see that replayed
// state of the whole model, in which only this rank's part moves. Their
// rows and field frames go to rank 0 summed by owner at each observation,
// their peaks, logs and work are merged there at the end (observation by
// rank: dynamics/ranks_of_run.h), so that rank 0 writes the files of a
// one-process run and the other ranks write nothing. A failure on one rank
// (a replay, or rank 0 that cannot write) stops every rank at the start of
// the next step.
#ifndef poundfe_dynamics_partitioned_stepper_h
#define poundfe_dynamics_partitioned_stepper_h

#include <poundfe/dynamics/partitioned_history.h>
#include <poundfe/dynamics/ranks_of_run.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/integration/replayed_stepper.h>
#include <poundfe/output/output_parameters.h>

#include <mpi.h>

#include <functional>
#include <memory>
#include <string>

namespace poundfe
{
  class PartitionedStepper final : public LockstepStepper
  {
  public:
    /// Collective. What a partitioned run refuses (friction surfaces,
    /// initial conditions; InputError alike on every rank), then the
    /// buildings' report (Rayleigh coefficients, modes, warnings) gathered
    /// to rank 0 in `analysis`, then this rank's part of the lockstep
    /// history (PartitionedHistory, which takes over `analysis`' system).
    /// `analysis` must outlive this object.
    PartitionedStepper(Analysis &analysis, const TimeHistoryParameters &parameters,
                       MPI_Comm communicator);

    const PartitionedHistory &history() const { return part; }
    /// The ground motion and nodal forces (alike on every rank).
    const Excitation &excitation() const { return part.excitation(); }
    /// Where the observers' rows go (recorders: RowSink), and whether this
    /// rank writes the files (rank 0).
    RowSink &rows() { return ranks; }
    bool     writes_files() const { return ranks.writes_files(); }
    /// The field output of the run, written from every rank's part: every
    /// rank's (HDF5 + XDMF, written together) or rank 0's (VTU) series in
    /// `directory`, a frame every `every`-th step and, with `impact_peaks`,
    /// at each impact's peak (the gaps' total force then summed over the
    /// ranks at every step). One per run.
    std::unique_ptr<StepObserver> field_recorder(const Model &model, const std::string &directory,
                                                 FieldFormat format, unsigned int every,
                                                 bool impact_peaks);

    const NonlinearElements &observed_elements() const override { return elements; }
    void set_observed(ResponseView &view) const override;
    bool agreed_stop(bool interruptible, RunStatus &status) override;
    void observe(Observation call, const Observers &observers, const ResponseView &view) override;
    bool merged(const Observers &observers, ResponseView &view, RunStatus &status) override;

    /// From rest (the load and state given are not read: the history has
    /// its own, and a partitioned run starts at rest).
    void initialize(const Vector &load, const Vector &u0, const Vector &v0) override;
    /// One step of the lockstep history (its own load), then the replay.
    void advance(const LoadFunction &load) override;
    void set_substep_callback(std::function<void()> callback) override;

    /// The replayed state, as the observers see it.
    double        time() const override { return replayed.time(); }
    /// The integrator's steps (alike on every rank).
    unsigned long steps() const override { return part.integrator().steps(); }
    const Vector &displacement() const override { return replayed.displacement(); }
    const Vector &velocity() const override { return replayed.velocity(); }
    const Vector &acceleration() const override { return replayed.acceleration(); }
    EnergyBalance energy() const override { return replayed.energy(); }
    double        max_energy_error() const override { return replayed.max_energy_error(); }
    double element_work(unsigned int h) const override { return replayed.element_work(h); }
    double element_supplied_work(unsigned int h) const override
    {
      return replayed.element_supplied_work(h);
    }
    const ImpactLog    &impact_log() const override { return replayed.impact_log(); }
    const StickSlipLog &stick_slip_log() const override { return replayed.stick_slip_log(); }
    const IterationStatistics &statistics() const override { return replayed.statistics(); }

  private:
    /// This rank's values and ghosts placed in the replayed state, its
    /// elements replayed to them at the history's time (or started,
    /// `first`), unless this rank stopped.
    void replay(bool first);
    /// `action`, an OutputError or NumericalError kept as the reason this
    /// rank stops (told to the others at the next agreed_stop).
    void keep_failure(const std::function<void()> &action);
    /// The gaps' total |force| of the replayed state (`gap_force`), from
    /// the ranks that observe them, when the field output asks for it.
    /// Collective: after every step's replay, whether or not it failed.
    void sum_gap_forces();

    const MPI_Comm         communicator;
    PartitionedHistory     part; // this rank's buildings, stepped with the other ranks
    NonlinearElements      elements; // the whole model's, replayed where observed
    RanksOfRun             ranks;
    ReplayedStepper        replayed;
    RankFieldRecorder     *field = nullptr; // of the observers, when there is a field output
    std::function<void()>  substep_callback;
    bool                   gap_forces_asked = false;
    double                 gap_force        = 0;
    std::vector<double>    gap_forces; // each element's |force| (zero but for observed gaps)
    // why this rank cannot go on (rank 0 could not write, or a replay
    // failed), told to the others at the start of the next step
    std::string stop_reason;
    bool        output_failed = false;
  };
} // namespace poundfe

#endif
