// What the time loop (dynamics/time_history.cc) and its observers need of a time
// integrator of M u'' + C u' + K u + f(u, u') = p(t): start from (u0, v0),
// advance one analysis time step, and read the state, the energy balance,
// the impact and stick-slip logs and the statistics. Two implement it:
// NewmarkIntegrator (integration/newmark.h, every model) and
// DormandPrinceIntegrator (integration/dormand_prince.h, small models with
// contact, event-driven and adaptive).
// The element dissipation of the energy balance (Belytschko, Liu & Moran,
// Nonlinear Finite Elements, §6.3) is shared by both: what each element
// dissipated is its work minus its stored energy plus what its drive
// supplied, booked by the element's kind.
#ifndef poundfe_integration_time_stepper_h
#define poundfe_integration_time_stepper_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/integration/impact_log.h>
#include <poundfe/integration/stick_slip_log.h>

#include <functional>
#include <vector>

namespace poundfe
{
  /// p(t) into the vector.
  using LoadFunction = std::function<void(double, Vector &)>;

  struct EnergyBalance;
  struct IterationStatistics;

  class TimeStepper
  {
  public:
    virtual ~TimeStepper() = default;

    /// Start at time 0 from (u0, v0) under load p0.
    virtual void initialize(const Vector &load, const Vector &u0, const Vector &v0) = 0;
    /// Advance one analysis time step; `load(t, p)` gives p at any time in it.
    /// Throws NumericalError when it cannot.
    virtual void advance(const LoadFunction &load) = 0;
    /// Called after every accepted sub-step inside an analysis time step.
    virtual void set_substep_callback(std::function<void()> callback) = 0;

    virtual double        time() const         = 0;
    virtual unsigned long steps() const        = 0;
    virtual const Vector &displacement() const = 0;
    virtual const Vector &velocity() const     = 0;
    virtual const Vector &acceleration() const = 0;

    virtual EnergyBalance energy() const           = 0;
    virtual double        max_energy_error() const = 0;
    /// Work done on element h so far, J.
    virtual double element_work(unsigned int h) const = 0;
    /// Work done on the structure by what drives element h (a belt), J.
    virtual double element_supplied_work(unsigned int h) const = 0;
    virtual const ImpactLog           &impact_log() const     = 0;
    virtual const StickSlipLog        &stick_slip_log() const = 0;
    virtual const IterationStatistics &statistics() const     = 0;
    /// Whether, at each accepted (sub)step it reports, the nonlinear
    /// elements hold the trial state at displacement() and velocity() as
    /// their last evaluation (the converged Newton iterate), so that an
    /// observer may read a uniaxial element's deformation from it instead
    /// of forming it again (UniaxialElement::trial_deformation_value).
    virtual bool elements_hold_state() const { return false; }
  };

  /// What one element dissipated: its work minus its stored energy plus
  /// what drives it (for an undamped contact law, the quadrature of its
  /// work over the steps that open or close a gap).
  double element_dissipation(const NonlinearElement &element, double work, double supplied);

  /// Sets balance's dissipation terms (hysteretic, contact, friction, links,
  /// foundation) from each element's work, stored energy and supplied work;
  /// `counted` (empty: all) leaves out the elements h with counted[h] == 0
  /// (another rank counts them).
  void set_element_dissipation(EnergyBalance &balance, const NonlinearElements &elements,
                               const std::vector<double> &work,
                               const std::vector<double> &supplied_work,
                               const std::vector<char>   &counted = {});
  /// The same with each element's stored energy given, stored[h] as
  /// elements[h].stored_energy() (noted once a step with the strain
  /// energy): the same sums, so the same bits, without a second call.
  void set_element_dissipation(EnergyBalance &balance, const NonlinearElements &elements,
                               const std::vector<double> &work,
                               const std::vector<double> &supplied_work,
                               const std::vector<double> &stored,
                               const std::vector<char>   &counted);

  /// max_error = max(max_error, |supplied - stored and dissipated| / scale),
  /// scale the running maximum of both (so the start of the motion, where
  /// both are tiny, is not divided by nearly zero).
  void update_balance_error(const EnergyBalance &balance, double &scale, double &max_error);
} // namespace poundfe

#endif
