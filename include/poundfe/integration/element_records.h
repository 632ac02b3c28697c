// What a time integrator keeps of its nonlinear elements from one accepted
// (sub)step to the next: each element's work W_h = sum over the steps of
// the trapezoidal increment (1/2)(f_n + f_n+1) . (d_n+1 - d_n) that the
// element itself reports (work_increment, doc/theory.md §3.6), what a drive
// supplied (a belt), the impact log of the gaps and the stick-slip log of
// the friction elements (integration/impact_log.h, stick_slip_log.h), and
// the committed force, history variable and rate that open the next step's
// entries in those logs. NewmarkIntegrator records its steps with it, and
// rank 0 of a run partitioned by building replays its ranks' steps with it
// (integration/replayed_stepper.h): both logs are made by the same code.
// Both call accept() with the elements at the step's trial state, their
// last evaluation: a uniaxial element's rate at v_next is read from it
// (UniaxialElement::trial_rate_value), the same bits as forming it again.
#ifndef poundfe_integration_element_records_h
#define poundfe_integration_element_records_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/integration/impact_log.h>
#include <poundfe/integration/stick_slip_log.h>

#include <vector>

namespace poundfe
{
  class UniaxialElement;

  class ElementRecords
  {
  public:
    /// Sorted from `elements` (nullptr: none): the gaps and the friction
    /// elements. `observed` (observation by rank): only the elements h with
    /// (*observed)[h] are recorded and committed, the others keep zero
    /// work and no impacts; nullptr: all.
    explicit ElementRecords(const NonlinearElements *elements,
                            const std::vector<char>  *observed = nullptr);

    /// The elements have just been committed at velocity `v` (the initial
    /// state, or a restart): their force, history variable and rate.
    void note_committed(const NonlinearElements &elements, const Vector &v);
    /// From the initial state: empty logs, nothing supplied, each
    /// element's work its stored energy there. Lists the elements' classes
    /// again (they may have been replaced since the last run).
    void start(const NonlinearElements &elements);
    /// The step [t0, t1], whose trial state (velocity `v_next`) the
    /// elements hold: log its impacts and stick-slip episodes, add each
    /// element's work, commit every element and note its committed values.
    /// Adds to `belt` what the drives supplied over the step, and to
    /// held_load_work() what the elements' own loads did, of the elements
    /// that `counted` marks (every element when nullptr).
    void accept(NonlinearElements &elements, double t0, double t1, const Vector &v_next,
                const std::vector<char> *counted, double &belt);

    /// A run partitioned over ranks: each element's work and the impacts
    /// from the rank that observes it, on rank 0 (base/rank_merge.h).
    /// Collective; for the run's end.
    void merge(const RankMerge &ranks);

    const std::vector<double> &work() const { return work_done; }
    const std::vector<double> &supplied_work() const { return work_supplied; }
    /// The work of the elements' own loads held constant (a member's
    /// self-weight after gravity) since start(), of the counted elements, J.
    double held_load_work() const { return held_work; }
    const ImpactLog           &impact_log() const { return impacts; }
    const StickSlipLog        &stick_slip_log() const { return stick_slip; }
    const std::vector<unsigned int> &gap_elements() const { return gaps; }
    const std::vector<unsigned int> &friction_elements() const { return frictions; }
    /// Element h's history variable and rate at the last accepted state.
    double committed_history(const unsigned int h) const { return history[h]; }
    double committed_rate(const unsigned int h) const { return rate[h]; }

  private:
    /// One kept element's work, supplied work and commit, and its
    /// committed force and history variable noted.
    template <typename Element>
    void accept_element(unsigned int h, Element &e, const std::vector<char> *counted,
                        double &belt);

    std::vector<unsigned int> kept, gaps, frictions;
    /// Element h as the UniaxialElement it is, else null (listed at start()):
    /// the per-step calls go through the final class, with no test of the
    /// class per element and step.
    std::vector<UniaxialElement *> typed;
    std::vector<double>       work_done, work_supplied, force, history, rate;
    double                    held_work = 0;
    ImpactLog                 impacts;
    StickSlipLog              stick_slip;
  };
} // namespace poundfe

#endif
