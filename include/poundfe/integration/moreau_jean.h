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
// the constraint's Jacobian at the beginning of the step). A slab against a
// column (model/column_contact_geometry.h) is taken the same way, its gap a
// function of z = B^T u (the column point's Hermite displacement, the slab's
// motion) and its row B ∇g(z) at the step's start.
// A friction-contact problem the chosen fc2d solver leaves unsolved goes to
// a fallback (Lemke's pivoting after NSGS, NSGS after Lemke).
// Equations without mass (a frame's rotations under lumped masses) keep
// their rows of the scheme, which there read θ F+ + (1 - θ) F = 0: J's rows
// h θ (C + C_t) + (h θ)^2 (K + K_t) stay regular, and from the equilibrium
// F = 0 of the start (at rest) θ = 1/2 keeps F+ = 0 at every step, as
// Newmark's average acceleration (the same scheme on the smooth part) does.
// The contacts act on equations with mass only: an impulse needs inertia.
// J is dense on small models and sparse on large ones (W then from one solve
// with J's factor per active contact's row: integration/moreau_jean_matrix.h);
// the products with M, C and K are sparse.
#ifndef poundfe_integration_moreau_jean_h
#define poundfe_integration_moreau_jean_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/integration/lcp_solver.h>
#include <poundfe/integration/moreau_jean_matrix.h>
#include <poundfe/integration/moreau_jean_parameters.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/integration/stepper_state.h>
#include <poundfe/model/column_contact_geometry.h>
#include <poundfe/model/plan_contact_geometry.h>

#include <Eigen/SparseCholesky>

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
    /// A slab against a column between the column's floors (Model/Dimension
    /// = 3): g(u) from `column` on `equations`, the column's DOFs then the
    /// slab's floor's (ux, uy, θz) (coefficients and initial_gap unused).
    bool                  on_column = false;
    ColumnContactGeometry column;
    /// Coulomb's coefficient along the contact (in plan only: the tangent
    /// J n of the normal through the contact point); 0: frictionless.
    double friction = 0;
  };

  /// The unilateral contacts of `model`'s gap elements among `elements`
  /// (one per gap: between floors, against a barrier, in plan or a slab
  /// against a column), each with restitution e, into `contacts`; the
  /// reason when a gap is beyond them (bumpers), else empty.
  std::string unilateral_contacts(const Model &model, const NonlinearElements &elements,
                                  double restitution, std::vector<UnilateralContact> &contacts);

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
    /// Why the scheme cannot take this system and these elements (an
    /// element it does not take: fibre members, friction; beyond
    /// parameters.max_dense_equations, where J is sparse: modal damping, a
    /// linear solver on several processes, a nonsymmetric element tangent
    /// on a symmetric solver); empty when it can.
    static std::string unsupported(const LinearSystem &system, const NonlinearElements *elements,
                                   const MoreauJeanParameters &parameters);
    /// Why the scheme cannot take these contacts on this system (one acting
    /// on an equation without mass); empty when it can.
    static std::string unsupported(const LinearSystem &system,
                                   const std::vector<UnilateralContact> &contacts);

    /// `elements` may be null; gap elements are left alone (the contacts
    /// replace them). Throws NumericalError from advance() when Siconos
    /// fails or Newton does not converge.
    /// J is sparse beyond parameters.max_dense_equations; within it as
    /// `storage` asks (`automatic`: dense, or sparse where allowed and
    /// cheaper, integration/moreau_jean_matrix.h).
    MoreauJeanIntegrator(const LinearSystem &system, const MoreauJeanParameters &parameters,
                         std::vector<UnilateralContact> contacts,
                         NonlinearElements *elements = nullptr,
                         JacobianStorage storage = JacobianStorage::automatic);
    /// Whether J is kept dense.
    bool dense_jacobian() const { return jacobian->is_dense(); }

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
    /// Friction-contact problems the chosen solver left unsolved and the
    /// fallback solved.
    unsigned long      n_fallback_solves() const { return fallback_solves; }

  private:
    /// Why J cannot be sparse (modal damping, the linear solver, an element
    /// tangent); `beyond` closes each reason. Empty when it can.
    static std::string sparse_unsupported(const LinearSystem &system,
                                          const NonlinearElements *elements,
                                          const MoreauJeanParameters &parameters,
                                          const std::string &beyond);
    /// J's constant part M + h θ C + (h θ)^2 K, the elements' B_e, and J
    /// kept as `storage` asks (sparse beyond the Dense matrix limit).
    void make_jacobian(JacobianStorage storage);
    /// g_a(u) (exact, also in plan) and U_a(v) = H_a v.
    double gap(unsigned int a, const Vector &x) const;
    /// The geometry of contact in plan a at displacements x.
    PlanContactState plan_state(unsigned int a, const Vector &x) const;
    /// The geometry of slab-against-column contact a at displacements x
    /// (z = B_a^T u_a: the column's plan displacement at the slab, the slab's).
    ColumnContactState column_state(unsigned int a, const Vector &x) const;
    /// M^-1 x on the equations with mass, 0 on the others.
    Vector inverse_mass(const Vector &x) const;
    /// C x (the sparse part and the modal one) into y.
    void   damping_times(const Vector &x, Vector &y) const;
    /// H (and T) anew: the constant rows, and the rows of the contacts in
    /// plan at the current displacements.
    void   linearize_contacts();
    /// T_a of contact in plan a at the current displacements, `state` its geometry.
    Vector6 plan_tangent(unsigned int a, const PlanContactState &state) const;
    double normal_velocity(unsigned int a, const Vector &x) const;
    /// Sets the (non-gap) elements' trial state at (x, y); their force
    /// corrections added to `force`, and with `tangent` their tangents to J
    /// with weight (h theta)^2. NumericalError naming a refusal.
    void   evaluate_elements(double t, const Vector &x, const Vector &y, Vector &force,
                             bool tangent);
    /// C x + K y + element forces - p, the smooth forces' negative at (y, x),
    /// into `force`; with `tangent`, J assembled at (y, x) too.
    void   smooth_force(double t, const Vector &displacement, const Vector &velocity,
                        const Vector &load_vector, Vector &force, bool tangent);
    /// The impulses of the active contacts for free velocity v_free: P_a
    /// (normal) for each, and with friction P_T after them, in the order
    /// of `active` (the rows of `rows`: the active contacts' H, then T).
    Vector contact_impulses(const Vector &v_free);
    /// The same with friction: Siconos's fc2d on the normal and tangent rows,
    /// by the chosen solver and, when it leaves the problem unsolved, by
    /// the fallback (Lemke's, or NSGS when Lemke is the chosen one).
    Vector friction_impulses(const Vector &v_free);
    /// W of the active rows with J's factor in hand (kept while neither
    /// changes).
    const Eigen::MatrixXd &delassus();
    /// Whether a contact problem's solution meets the tolerance by the
    /// program's residual (Siconos's status aside).
    bool   is_solved(const LcpSolution &solution) const;
    /// Count a contact problem's solve; NumericalError naming the solver
    /// (and the fallback's, when one ran) when it failed.
    void   count_solve(const LcpSolution &solution, unsigned int n_contacts,
                       const char *problem, const LcpSolution *first_attempt = nullptr);
    /// The index set (contacts closed, or closing within the step) into
    /// `active`, their rows (H's, then T's with friction) into `rows`.
    void   find_active_contacts();
    /// Newton on the step's equations with the impulses: v_end, impulse,
    /// u_end and s_end (the smooth forces there) of the step to t1; returns
    /// its iterations. `full_newton`: J factored anew at every iteration.
    unsigned int solve_step(double t1, bool full_newton);
    /// One Newton iteration from v_end: the next iterate and its change.
    double newton_update(Vector &v_next);
    /// One step of h from the current state.
    void   step(const LoadFunction &load);
    /// The energy terms of the step, the elements' commit, the state moved to t1.
    void   accept_step(double t1);
    /// The step's impulses into the impulse and impact logs and the gaps' work.
    void   record_impulses(double t_end);
    void   update_energy();

    const LinearSystem            &system;
    MoreauJeanParameters           parameters;
    std::vector<UnilateralContact> contact_list;
    NonlinearElements             *elements   = nullptr;
    unsigned int                   n          = 0;
    unsigned int                   n_elements = 0;
    bool                           smooth_nonlinear = false;
    /// H_a = dg_a/du (U_a = H_a v < 0 while gap a closes) and the tangent
    /// rows (J n through the contact point) of contacts in plan.
    SparseRows                     H, T;
    bool                           has_friction = false;
    bool                           has_plan_contacts = false;
    /// B_a of each slab-against-column contact (its equations x 5), empty
    /// for the others.
    std::vector<Eigen::MatrixXd>   column_bases;
    std::unique_ptr<MoreauJeanMatrix> jacobian;
    /// Each element's B_e (constant), D_e and (h theta)^2 B_e D_e B_e^T.
    std::vector<Eigen::MatrixXd>   bases;
    Eigen::MatrixXd                element_d, element_local;
    /// Whether the next iteration factors J anew (the one in hand is
    /// renewed when an iteration's change exceeds max_contraction times
    /// the last one's).
    bool                           refactor        = true;
    static constexpr double        max_contraction = 0.25;
    /// W of `active` on J's factorisation `delassus_factorization`.
    Eigen::MatrixXd                W;
    std::vector<unsigned int>      delassus_active;
    unsigned long                  delassus_factorization = 0;
    bool                           delassus_valid         = false;
    /// The equations with mass and the factor of M on them.
    std::vector<unsigned int>      massive;
    Eigen::SimplicialLDLT<SparseMatrix> mass_factor;
    /// The step in hand: its index set and rows, the iterate, its impulses.
    std::vector<unsigned int>      active;
    SparseRows                     rows;
    Vector                         load_end, u_end, v_end, s_end, impulse;
    Vector                         residual, v_free, correction_velocity, product;
    Vector                         load_start, smooth_start, local_u, local_v, local_force;
    std::vector<double>            initial_stored;
    std::vector<ContactImpulse>    impulse_log;
    /// The energy lost at impacts of contacts without a gap element.
    double                         unattached_loss = 0;
    /// Each contact's normal and tangential impulse of the step in hand
    /// (sized once) and the normal ones of the step before.
    std::vector<double>            impulses_this_step, tangential_this_step, impulses_last_step;
    std::string                    solver_name, friction_solver_name;
    unsigned long                  fallback_solves = 0;
  };
} // namespace poundfe

#endif
