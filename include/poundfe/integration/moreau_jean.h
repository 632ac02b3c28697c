// Rigid (non-smooth) contact by Moreau–Jean's time-stepping scheme
// (Jean, Comput. Methods Appl. Mech. Engrg. 177 (1999) 235; Acary &
// Brogliato, Numerical Methods for Nonsmooth Dynamical Systems, Springer
// 2008, §10.1): velocities may jump, contact forces are impulses.
//   M (v+ - v) = h [theta F(t+, u+, v+) + (1 - theta) F(t, u, v)] + H^T P
//   u+ = u + h [theta v+ + (1 - theta) v]          theta in [1/2, 1]
// with F = p - C v - K u - f(u, v) the smooth forces (hinges, storeys,
// springs: Newton on them inside the step), and per unilateral contact a
// (gap g_a(u) = g0_a - d_a(u), d_a the closure, U_a = H_a v = dg_a/dt) that
// is closed or closing, g_a + h U_a <= 0 at the start of the step, Newton's
// impact law at the velocity level
//   0 <= U_a+ + e_a U_a  ⊥  P_a >= 0.
// Each Newton iteration k on the smooth part, with the iteration matrix
//   J = M + h theta (C + C_t) + (h theta)^2 (K + K_t),
// (factored anew only when the one in hand, of an earlier iteration or
// step, contracts the iteration by less than a factor 4: the iteration's
// fixed point is the step's equations whatever J, which sets only its pace)
// takes the free velocity v_free (the update without impulses) and the
// Delassus operator W = H J^-1 H^T, and solves the LCP
//   w = W P + (H v_free + e ∘ H v),  0 <= P ⊥ w >= 0
// with Siconos Numerics (integration/lcp_solver.h); then v+ = v_free +
// J^-1 H^T P. A linear model converges in one iteration.
// The energy an impulse dissipates is -P_a (U_a+ + U_a) / 2, which for one
// impact of two bodies is (1 - e^2) m_eff U_a^2 / 2; it is booked as the
// work on the contact's gap element (the balance's contact term). With
// theta = 1/2 the balance of a linear model is exact; theta > 1/2 damps
// numerically (the balance error shows it).
// The impact log takes a step with an impulse P as one with the mean force
// P / h: its impulse is P, its peak force P / h of the largest step's
// impulse, its approach and separation velocities the jumps' ends.
// A contact in plan (Model/Dimension = 3: a corner of one floor's slab
// against the edge of the other's, model/plan_contact_geometry.h) has a gap
// g_a(u) nonlinear in the floors' (ux, uy, θz): its row H_a = ∇g_a(u) is
// taken at the start of each step (the impulse acts along the normal through
// the contact point there, equal and opposite on the two floors, so that
// linear and angular momentum are kept), g_a(u) is evaluated exactly, and a
// contact whose edges do not overlap is open (Acary & Brogliato §10.1.7:
// the constraint's Jacobian at the beginning of the step).
// Equations without mass (a frame's rotations under lumped masses) keep
// their rows of the scheme, which there read θ F+ + (1 - θ) F = 0: J's rows
// h θ (C + C_t) + (h θ)^2 (K + K_t) stay regular, and from the equilibrium
// F = 0 of the start (at rest) θ = 1/2 keeps F+ = 0 at every step, as
// Newmark's average acceleration (the same scheme on the smooth part) does.
// The contacts act on equations with mass only: an impulse needs inertia.
#ifndef poundfe_integration_moreau_jean_h
#define poundfe_integration_moreau_jean_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/integration/lcp_solver.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/integration/stepper_state.h>
#include <poundfe/model/plan_contact_geometry.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <functional>
#include <string>
#include <vector>

namespace poundfe
{
  /// A unilateral constraint g = initial_gap - d(u) >= 0 with closure
  /// d = sum_i coefficients[i] u[equations[i]] (equations < 0: the ground).
  struct UnilateralContact
  {
    std::string         label;
    std::vector<int>    equations;
    std::vector<double> coefficients;
    double              initial_gap = 0;
    double              restitution = 0;
    /// The gap element of this contact among the nonlinear elements (its
    /// work carries the energy lost at impacts); -1: none.
    int element = -1;
    /// A contact in plan: g(u) from `plan` on `equations`, the (ux, uy, θz)
    /// of its two floors (coefficients and initial_gap unused).
    bool                in_plan = false;
    PlanContactGeometry plan;
    /// Coulomb's coefficient along the contact (in plan only: the tangent
    /// J n of the normal through the contact point); 0: frictionless.
    double friction = 0;
  };

  /// The unilateral contacts of `model`'s gap elements among `elements`
  /// (one per gap: between floors, against a barrier or in plan), each with
  /// restitution e, into `contacts`; the reason when a gap is beyond them
  /// (a slab against a column, bumpers), else empty.
  std::string unilateral_contacts(const Model &model, const NonlinearElements &elements,
                                  double restitution, std::vector<UnilateralContact> &contacts);

  struct MoreauJeanParameters
  {
    double       time_step = 0.001;
    double       theta     = 0.5;
    LcpOptions   lcp;
    /// Coulomb's coefficient of the contacts in plan (Contact/Friction
    /// coefficient; copied to each contact), and with it the solver of the
    /// friction-contact problem.
    double                 friction_coefficient = 0;
    FrictionContactOptions friction;
    /// Newton on the smooth part: |dv| <= tolerance (|v+| + velocity_scale).
    double       newton_tolerance  = 1e-10;
    double       velocity_scale    = 1e-6; // m/s
    unsigned int newton_iterations = 50;
    /// The largest model (equations) it takes: J is dense.
    unsigned int max_equations = 500;
  };

  /// One impulse of one contact in one step.
  struct ContactImpulse
  {
    double       time    = 0; // the end of the step
    unsigned int contact = 0;
    double       impulse = 0;                     // N s, along the normal
    double       tangential_impulse = 0;          // N s, along J n (friction)
    double       velocity_before = 0, velocity_after = 0; // U_a, U_a+ (m/s; < 0 closing)
    double       energy_lost = 0; // -P (U+ + U) / 2 - P_T (U_T+ + U_T) / 2, J
  };

  class MoreauJeanIntegrator : public TimeStepperState
  {
  public:
    /// Why the scheme cannot take this system and these elements (too many
    /// equations, an equation without mass, an element it does not take:
    /// fibre members, friction, elements of rank > 1); empty when it can.
    static std::string unsupported(const LinearSystem &system, const NonlinearElements *elements,
                                   unsigned int max_equations);
    /// Why the scheme cannot take these contacts on this system (one acting
    /// on an equation without mass); empty when it can.
    static std::string unsupported(const LinearSystem &system,
                                   const std::vector<UnilateralContact> &contacts);

    /// `elements` may be null; gap elements are left alone (the contacts
    /// replace them). Throws NumericalError from advance() when Siconos
    /// fails or Newton does not converge.
    MoreauJeanIntegrator(const LinearSystem &system, const MoreauJeanParameters &parameters,
                         std::vector<UnilateralContact> contacts,
                         NonlinearElements *elements = nullptr);

    void initialize(const Vector &load, const Vector &u0, const Vector &v0) override;
    void advance(const LoadFunction &load) override;
    /// TimeStepperState::acceleration() is the smooth part of the
    /// acceleration, (v+ - v - M^-1 H^T P) / h: the impulses are Dirac
    /// measures, reported as impulses.

    const std::vector<UnilateralContact> &contacts() const { return contact_list; }
    /// Every nonzero impulse so far, in the order of the steps.
    const std::vector<ContactImpulse> &impulses() const { return impulse_log; }
    /// The gap of each contact at the current state (m, < 0 penetrated).
    std::vector<double> gaps() const;
    /// Siconos's solver name, LCPs solved, their largest iterations and residual.
    const std::string &lcp_solver() const { return solver_name; }
    /// Siconos's name of the friction-contact solver ("" without friction).
    const std::string &friction_solver() const { return friction_solver_name; }
    unsigned long      n_lcps() const { return stats.contact.solves; }
    int                max_lcp_iterations() const { return stats.contact.max_iterations; }
    double             max_lcp_residual() const { return stats.contact.max_residual; }

  private:
    /// g_a(u) (exact, also in plan) and U_a(v) = H_a v.
    double gap(unsigned int a, const Vector &x) const;
    /// The geometry of contact in plan a at displacements x.
    PlanContactState plan_state(unsigned int a, const Vector &x) const;
    /// M^-1 x on the equations with mass, 0 on the others.
    Vector inverse_mass(const Vector &x) const;
    /// H_a and T_a of the contacts in plan at the current displacements.
    void   linearize_plan_contacts();
    /// T_a of contact in plan a at the current displacements, `state` its geometry.
    Vector6 plan_tangent(unsigned int a, const PlanContactState &state) const;
    double normal_velocity(unsigned int a, const Vector &x) const;
    /// Sets the (non-gap) elements' trial state at (x, y); their force
    /// corrections added to `force`, their tangent to `jacobian` (if not
    /// null) with weight (h theta)^2. NumericalError naming a refusal.
    void   evaluate_elements(double t, const Vector &x, const Vector &y, Vector &force,
                             Eigen::MatrixXd *jacobian);
    /// C x + K y + element forces - p: the smooth forces' negative at (y, x).
    Vector smooth_force(double t, const Vector &displacement, const Vector &velocity,
                        const Vector &load_vector, Eigen::MatrixXd *jacobian);
    /// The impulses of the active contacts for free velocity v_free: P_a
    /// (normal) for each, and with friction P_T after them, in the order
    /// of `active` (the columns of the active contacts' H, then T).
    Vector contact_impulses(const std::vector<unsigned int> &active, const Vector &v_free);
    /// The same with friction: Siconos's fc2d on the normal and tangent rows.
    Vector friction_impulses(const std::vector<unsigned int> &active, const Vector &v_free);
    /// Count a contact problem's solve; NumericalError when it failed.
    void   count_solve(const LcpSolution &solution, unsigned int n_contacts,
                       const char *problem);
    /// The rows of the active contacts: H's, then T's of those with friction.
    Eigen::MatrixXd active_rows(const std::vector<unsigned int> &active) const;
    /// Factor J at the end-of-step state (u_end, v_end) into jacobian_factor.
    void   factor_jacobian(double t, const Vector &u_end, const Vector &v_end,
                           const Vector &load_end);
    /// One step of h from the current state; returns the impulses.
    void   step(const LoadFunction &load);
    void   record_impulses(const std::vector<unsigned int> &active, const Vector &impulse,
                           const Vector &v_end, double t_end);
    void   update_energy();

    const LinearSystem            &system;
    MoreauJeanParameters           parameters;
    std::vector<UnilateralContact> contact_list;
    NonlinearElements             *elements   = nullptr;
    unsigned int                   n          = 0;
    unsigned int                   n_elements = 0;
    Eigen::MatrixXd                mass, damping, stiffness, base_jacobian, H;
    /// The tangent rows (J n through the contact point) of contacts in plan.
    Eigen::MatrixXd                T;
    bool                           has_friction = false;
    Eigen::PartialPivLU<Eigen::MatrixXd> jacobian_factor;
    /// Whether the next iteration factors J anew (the one in hand is
    /// renewed when an iteration's change exceeds max_contraction times
    /// the last one's).
    bool                           refactor        = true;
    static constexpr double        max_contraction = 0.25;
    /// The equations with mass and the Cholesky factor of M on them.
    std::vector<unsigned int>    massive;
    Eigen::LLT<Eigen::MatrixXd>  mass_factor;
    Vector                         load_start, smooth_start, local_u, local_v;
    std::vector<double>            initial_stored;
    std::vector<ContactImpulse>    impulse_log;
    /// The energy lost at impacts of contacts without a gap element.
    double                         unattached_loss = 0;
    std::vector<double>            impulses_last_step;
    std::string                    solver_name, friction_solver_name;
  };
} // namespace poundfe

#endif
