// Event-driven adaptive Dormand–Prince 5(4) integration of
//   M u'' + C u' + K u + f(u, u') = p(t)
// as the first-order system y = (u, v), y' = (v, M^-1 (p - C v - K u - f)),
// for small models (oscillators, the spillway, shear buildings of some
// dozens of DOFs) whose nonlinear elements are contacts (gaps, barriers)
// and elastic springs.
//   Stages k_i = F(t + c_i h, y + h sum_j a_ij k_j), i = 1..7 (FSAL:
//   k_7 = F(t + h, y_1)); y_1 = y + h sum_i b_i k_i (order 5); the error
//   estimate h sum_i e_i k_i (e = b - b^, b^ of order 4);
//   err = sqrt(1/N sum_i (est_i / (atol + rtol max(|y_0,i|, |y_1,i|)))^2),
//   accepted when err <= 1, h_new = h min(5, max(0.2, 0.9 err^(-1/5))).
//   Dense output (the continuous extension of order 4, Hairer's dopri5):
//   y(t + theta h) = r1 + theta (r2 + (1-theta) (r3 + theta (r4 + (1-theta) r5))).
// Events: each gap's phase (open, in contact: g = 0 on the gap's
// penetration) and, in contact, the sign of the penetration rate (the kink
// of a damped law such as Jankowski's at the largest penetration), and each
// spring's branch. When an accepted step ends on another phase than it
// began, the first switch is located by bisection of the phase along the
// dense output to `Event resolution` (1e-12 of the time by default) and the
// step is redone to end there, so the next step starts on the new, smooth,
// branch: the order is kept across the non-smooth events.
// The energy terms (input int v.p dt, damping int v.C v dt, each element's
// work int F d' dt) are integrated with the state as extra components, at
// the method's order (not in the error norm).
// Sources: Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19;
// Hairer, Nørsett & Wanner, Solving ODEs I, 2nd ed., §II.4 (step size
// control, starting step), §II.5 (Table 5.2), §II.6 (dense output, eq. 6.12)
// and §II.6 (event location, "Discontinuous solutions"); Shampine &
// Reichelt, SIAM J. Sci. Comput. 18 (1997) 1 (ode45, the thesis's solver).
#ifndef poundfe_integration_dormand_prince_h
#define poundfe_integration_dormand_prince_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/integration/stepper_state.h>

#include <Eigen/Cholesky>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace poundfe
{
  struct DormandPrinceParameters
  {
    /// The analysis (output) time step: advance() ends exactly on its multiples.
    double       time_step          = 0.001;
    double       relative_tolerance = 1e-8;
    double       absolute_tolerance = 1e-10; // on u (m) and v (m/s)
    /// > 0: fixed steps of this size, no error control (for convergence studies).
    double       fixed_step         = 0;
    /// Events are located to this fraction of max(1 s, t).
    double       event_resolution   = 1e-12;
    /// The largest model (equations) the method takes.
    unsigned int max_equations      = 200;
    unsigned long max_steps_per_output = 1000000;
  };

  /// One Dormand–Prince 5(4) step of y' = F(t, y) and its dense output;
  /// the tableau of Hairer, Nørsett & Wanner, Table II.5.2.
  class DormandPrinceStep
  {
  public:
    using Rhs = std::function<void(double, const Vector &, Vector &)>;

    /// From (t, y) with k1 = F(t, y): y1, k7 = F(t + h, y1) and the error
    /// estimate, and the dense-output coefficients of the step.
    void take(const Rhs &rhs, double t, const Vector &y, const Vector &k1, double h);
    /// y at t + theta h, theta in [0, 1].
    void dense_output(double theta, Vector &out) const;
    /// The scaled RMS norm of the error estimate over the first n_controlled
    /// components.
    double error_norm(const Vector &y0, double rtol, double atol, unsigned int n_controlled) const;
    /// The next step after one of size h with error norm err (HNW §II.4):
    /// h min(5, max(0.2, 0.9 err^(-1/5))); a non-finite err gives h / 5.
    static double next_size(double h, double err);
    /// The smallest theta in (0, 1] where `unchanged(theta)` (evaluated on
    /// the dense output) turns false, bisected to `resolution` / h;
    /// unchanged(0) is true and unchanged(1) false.
    static double locate_change(double h, double resolution,
                                const std::function<bool(double)> &unchanged);

    Vector y1, k7, error;

  private:
    std::array<Vector, 7> k;
    Vector                stage, r1, r2, r3, r4, r5;
  };

  class DormandPrinceIntegrator : public TimeStepperState
  {
  public:
    /// Why the method cannot take this system and these elements (too
    /// many equations, an equation without mass, an element that is not a
    /// contact or an elastic spring); empty when it can.
    static std::string unsupported(const LinearSystem &system, const NonlinearElements *elements,
                                   unsigned int max_equations);

    /// `elements` may be null (a linear model); they are updated in place.
    DormandPrinceIntegrator(const LinearSystem &system, const DormandPrinceParameters &parameters,
                            NonlinearElements *elements = nullptr);

    void initialize(const Vector &load, const Vector &u0, const Vector &v0) override;
    void advance(const LoadFunction &load) override;
    /// Events located so far (switches of a gap's or a spring's phase).
    unsigned long n_events() const { return stats.event_refinements; }
    /// Right-hand-side evaluations so far.
    unsigned long n_evaluations() const { return evaluations; }

  private:
    /// y' = F(t, y) with the energy rates in the extra components.
    void   rhs(double t, const Vector &y, Vector &dy);
    /// Each event element's phase at state y (0 without elements).
    void   phases_at(double t, const Vector &y, std::vector<int> &out);
    /// Sets the elements' trial state to y's (u, v); the element that
    /// refused it, or -1.
    int    set_trial(const Vector &y);
    /// The same at time t; NumericalError naming the element that refused.
    void   set_trial_or_throw(double t, const Vector &y);
    /// The theta in (0, 1] just past the first phase switch of the step
    /// just taken from t0 (its dense output).
    double locate_event(double t0, double h);
    /// The elements committed at `state` (time t); with t0 >= 0 the step
    /// from t0 is recorded in the impact log first.
    void   commit_elements(double t, const Vector &state, double t0);
    /// The step just taken from t0 with size h becomes the state.
    void   accept(double t0, double h);
    double initial_step(double t, double t_end);
    /// From the current time to t_end (a multiple of the time step).
    void   integrate_to(double t_end);
    void   update_energy(const Vector &y);

    const LinearSystem     &system;
    DormandPrinceParameters parameters;
    NonlinearElements      *elements   = nullptr;
    unsigned int            n          = 0; // equations
    unsigned int            n_elements = 0;
    Eigen::LLT<Eigen::MatrixXd> mass_factor;
    std::vector<unsigned int>   gap_elements, event_elements;

    LoadFunction       load;
    DormandPrinceStep  step;
    Vector             y, k1, y_trial, load_vector, force, local_u, local_v;
    double             proposed_step = 0;
    unsigned long      evaluations   = 0;
    std::vector<int>   phases, trial_phases;
    std::vector<double> supplied, initial_stored, committed_force, committed_history, committed_rate;
  };
} // namespace poundfe

#endif
