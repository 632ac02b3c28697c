// The stick-slip log: the stick and slip episodes of each friction element,
// fed with every accepted (sub-)step. A step in which an element switches is
// one the integrator has already cut around the switch (Event refinement),
// so the switch lies in a sub-step of dt / 2^r. Slip ends where the slip
// velocity r' = x' - v0 crosses zero: located by linear interpolation of r'
// in that sub-step when it changes sign there, otherwise (and for the
// break-away from stick, where r' = 0 on both sides to within the stick
// spring) at the sub-step's midpoint, within dt / 2^(r+1).
#ifndef poundfe_integration_stick_slip_log_h
#define poundfe_integration_stick_slip_log_h

#include <vector>

namespace poundfe
{
  struct FrictionEpisode
  {
    unsigned int element  = 0; // index among the nonlinear elements
    bool         slipping = false;
    double       start    = 0;
    double       end      = -1; // < 0: still under way at the end of the run
  };

  class StickSlipLog
  {
  public:
    /// State of a friction element at one end of a step.
    struct SlipState
    {
      bool   slipping      = false;
      double slip_velocity = 0;
    };

    /// `elements`: how many nonlinear elements there are (indices h).
    void reset(unsigned int n_elements);
    /// An accepted step of element h from t0 to t1.
    void record(unsigned int h, double t0, double t1, const SlipState &start, const SlipState &end);

    const std::vector<FrictionEpisode> &episodes() const { return log; }

  private:
    std::vector<FrictionEpisode> log;
    std::vector<int>             open; // per element: its current episode, or -1
  };

  /// Stick and slip statistics of one friction element over [0, end_time]
  /// (an episode under way at the end counts to end_time in the fractions,
  /// not among the durations). A stick between two slips shorter than
  /// `shortest_stick` is a velocity reversal passing through the stick
  /// spring (half its period, pi sqrt(m/k_s), for the elastic-plastic
  /// model), not a stick of Coulomb's law: it is counted as a reversal and
  /// the slips on either side as one.
  struct StickSlipStatistics
  {
    unsigned int        n_sticks = 0, n_slips = 0; // episodes begun
    unsigned int        n_reversals = 0;           // through the stick spring
    std::vector<double> stick_durations, slip_durations; // completed episodes, s
    double              time_stuck = 0, time_slipping = 0;
    double fraction_stuck() const
    {
      const double total = time_stuck + time_slipping;
      return total > 0 ? time_stuck / total : 0.0;
    }
  };

  StickSlipStatistics stick_slip_statistics(const StickSlipLog &log, unsigned int element,
                                            double end_time, double shortest_stick = 0);
} // namespace poundfe

#endif
