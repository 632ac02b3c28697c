// The impact log: one record per contact episode of each gap element, fed
// with every accepted (sub-)step. Onset and release are located inside the
// step by linear interpolation of the penetration to zero (the integrator
// has already cut the step around the event, see Event refinement), the
// velocities at those instants by interpolating the rate. The maximum
// penetration and its time are those of the cubic Hermite interpolant of
// the penetration (values and rates at both ends) where the interpolated
// rate vanishes. The impulse is the trapezoidal integral of the contact
// force, the tangential impulse that of the tangential (friction) force.
#ifndef poundfe_integration_impact_log_h
#define poundfe_integration_impact_log_h

#include <poundfe/base/rank_merge.h>

#include <array>
#include <cmath>
#include <vector>

namespace poundfe
{
  struct Impact
  {
    unsigned int element              = 0; // index among the nonlinear elements
    double       start_time           = 0;
    double       max_penetration_time = 0;
    double       end_time             = -1; // < 0: still in contact at the end
    double       approach_velocity    = 0;
    double       separation_velocity  = 0;
    double       max_penetration      = 0;
    double       peak_force           = 0;
    double       impulse              = 0;
    /// Along the contact's tangent (friction of rigid contact in plan,
    /// integration/moreau_jean.h: signed along J n); 0 without friction.
    double       tangential_impulse   = 0;
    /// Where the peak force acted in plan (3D plan contact; NaN otherwise).
    std::array<double, 2> point{{std::nan(""), std::nan("")}};
    /// What was touched: a gap's bumper, the structure (laws/bumper.h's
    /// ContactPhase at the ends of the impact's steps).
    bool bumper = false, structure = false;
    /// The start of the accepted (sub)step in which it began: the log is in
    /// the order of these, then of the elements (what merges the logs of
    /// the ranks of a partitioned run into the one-process order).
    double step_start = 0;
  };

  class ImpactLog
  {
  public:
    /// State of a gap at one end of a step.
    struct GapState
    {
      double penetration = 0, rate = 0, force = 0;
      std::array<double, 2> point{{std::nan(""), std::nan("")}};
      /// The element's phase (laws/bumper.h: 1 structure, 2 bumper only).
      int phase = 0;
      /// The force along the contact's tangent (friction), N.
      double tangential_force = 0;
    };

    void reset(unsigned int n_elements);
    /// An accepted step of element h from t0 to t1.
    void record(unsigned int h, double t0, double t1, const GapState &start, const GapState &end);

    const std::vector<Impact> &impacts() const { return log; }

    /// A run partitioned over ranks: every rank's log (of the gaps it
    /// observes) merged on rank 0 in the order of one process's log.
    /// Collective. The open impacts are forgotten: for the run's end only.
    void merge(const RankMerge &ranks);

  private:
    std::vector<Impact> log;
    std::vector<int>    open; // per element: index of its open impact, or -1
  };
} // namespace poundfe

#endif
