// Newmark time stepping of M u'' + C u' + K u + f(u, u') = p(t) (Newmark 1959)
// with Newton-Raphson on the nonlinear elements f = sum_e (f_e - K_ref,e u_e)
// (elements/nonlinear_element.h).
//   a_{n+1} = (u_{n+1} - u_n)/(beta dt^2) - v_n/(beta dt) - (1/(2 beta) - 1) a_n
//   v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1})
//   K_eff = K + gamma/(beta dt) C + 1/(beta dt^2) M  (factorised once)
//   tangent = K_eff + sum_e B_e D_e B_e^T,
//   B_e D_e B_e^T = K_t,e - K_ref,e + gamma/(beta dt) C_t,e  (rank r_e, D_e dense)
// The tangent is solved by the Woodbury identity on the one factorisation
// of K_eff (assembly/low_rank_update.h, total rank sum_e r_e) or by adding
// the B_e D_e B_e^T into K_eff and refactorising. A step that does not
// converge is halved and retried down to dt / 2^max_cuts. Without nonlinear
// elements a step is one solve. Average acceleration (gamma = 1/2,
// beta = 1/4) conserves the energy of undamped free vibration exactly, and
// the trapezoidal work sums below then balance to the Newton tolerance.
// C may carry a low-rank modal part U D U^T (assembly/modal_damping.h): its
// products are taken as such, and every factorisation of K_eff (or of a
// tangent) is wrapped by the Woodbury identity for it.
// The initial acceleration solves M a_0 = p_0 - C v_0 - K u_0 - f_0 on the
// equations that carry mass; massless equations (rotations under lumped
// mass) are static and get a_0 = 0.
// Sources: Chopra, Dynamics of Structures, 4th ed., §5.4, Table 5.7.2;
// Belytschko, Liu & Moran, Nonlinear Finite Elements, §6.3 (energy balance).
#ifndef poundfe_integration_newmark_h
#define poundfe_integration_newmark_h

#include <poundfe/assembly/iterative_solver.h>
#include <poundfe/assembly/linear_system.h>
#include <poundfe/base/choices.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/assembly/rank_ownership.h>
#include <poundfe/integration/impact_log.h>
#include <poundfe/integration/newton_acceleration.h>
#include <poundfe/integration/element_records.h>
#include <poundfe/integration/stick_slip_log.h>
#include <poundfe/integration/time_stepper.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  /// How the tangent of the nonlinear elements enters the solve.
  enum class TangentUpdate
  {
    automatic,   // woodbury up to a total tangent rank of Woodbury columns, else hybrid
    woodbury,    // one factorisation of K_eff and a dense low-rank correction
    refactorize, // add the element tangents to K_eff and refactorise
    hybrid       // woodbury while the active rank fits Woodbury columns, else refactorise
  };

  const NameTable<TangentUpdate> &tangent_update_names();

  struct NewtonParameters
  {
    double       residual_tolerance = 1e-8;
    double       energy_tolerance   = 1e-12;
    unsigned int max_iterations     = 20;
    unsigned int max_step_cuts      = 10;
    TangentUpdate tangent_update    = TangentUpdate::automatic;
    /// The most columns of A^-1 B the Woodbury update keeps (n x this,
    /// dense): the limit of `automatic` and `hybrid`.
    unsigned int woodbury_columns   = 100;
    /// How each iteration's correction is found (newton_acceleration.h).
    NonlinearSolver nonlinear_solver = NonlinearSolver::newton;
    /// Every method but newton: the factorised tangent K_0 is kept from
    /// step to step (false: formed at each step's first iteration).
    bool         keep_tangent       = true;
    /// ... and re-formed at the current iterate when an iteration reduces
    /// the residual norm by less than this factor (auto: by measured cost).
    double       refactorization_ratio = 0.5;
    /// krylov-newton: subspace dimension; bfgs: pairs kept.
    unsigned int subspace_dimension = 10;
    bool                 line_search = false;
    LineSearchParameters line_search_parameters;
    /// A step in which a gap opens or closes is redone as 2^r sub-steps
    /// around the event.
    unsigned int event_refinement   = 4;
    /// While a gap is closed, or about to close within the step, the step
    /// is halved until the impact's duration (NonlinearElement::
    /// contact_duration) spans at least this many steps; 0: off.
    unsigned int steps_per_contact  = 20;
    /// Steps per contact's prediction that an open gap closes within the
    /// step: false, at the committed closing rate (delta + rate h > 0);
    /// true, also with the committed relative acceleration
    /// (predicted_closing_rate), which then gives the approach velocity.
    bool         contact_onset_from_acceleration = false;
  };

  /// The rate (> 0, m/s) at which a gap of penetration `delta` (< 0: open),
  /// closing rate `rate` and relative acceleration `acceleration` (> 0:
  /// closing) closes within a step `h` on the parabola delta + rate t +
  /// acceleration t^2 / 2 (0 < t <= h); 0 when it does not close.
  double
  predicted_closing_rate(double delta, double rate, double acceleration, double h);

  struct NewmarkParameters
  {
    double           time_step = 0.01;
    double           gamma     = 0.5;
    double           beta      = 0.25;
    NewtonParameters newton;
    /// The CG + AMG linear solvers' options (Time integration/Iterative solver).
    IterativeSolverParameters iterative;
    /// Every step in 2^c equal sub-steps, c the smallest level giving this
    /// many sub-steps per period of the highest mode (its Gershgorin bound,
    /// integration/accuracy_substeps.h); 0: off. Event refinement, Steps
    /// per contact and step cuts count their levels from c.
    unsigned int     steps_per_period = 0;
    /// The input left Linear solver at its default (eigen-ldlt): a
    /// nonsymmetric element tangent that must be refactorised (3D plan
    /// contact with many hinges) then uses umfpack instead of being refused.
    bool             lu_when_nonsymmetric = false;
  };

  /// Work and energy terms of the relative-coordinate energy balance, J:
  /// initial + input + belt + constant_load = kinetic + damping + strain +
  /// hysteretic + contact + friction + links + foundation. With a gravity
  /// analysis first the strain and initial terms are measured from the
  /// gravity state, and the work of the gravity loads held through the
  /// dynamics is constant_load, not input (doc/theory.md §3.9).
  struct EnergyBalance
  {
    double initial    = 0; // kinetic + strain at t = 0
    double input      = 0; // int u'^T p dt (p includes -M r a_g; not the held loads)
    double belt       = 0; // done on the structure by moving belts under friction
    double constant_load = 0; // done by the gravity loads held constant (loadConst)
    double kinetic    = 0;
    double damping    = 0; // int u'^T C u' dt
    double strain     = 0; // recoverable: elastic structure and laws
    double hysteretic = 0; // dissipated by hinges, storeys and members
    double contact    = 0; // dissipated by gaps
    double friction   = 0; // dissipated by friction, int F (x' - v0) dt
    double links      = 0; // dissipated by links between buildings (dampers)
    double foundation = 0; // dissipated by the foundations' dashpots (soil radiation)

    double supplied() const { return initial + input + belt + constant_load; }
    double stored_and_dissipated() const
    {
      return kinetic + damping + strain + hysteretic + contact + friction + links + foundation;
    }
  };

  /// The one-step contact problems of rigid contact (Moreau-Jean's LCPs, or
  /// friction-contact problems with friction), solved by Siconos Numerics.
  struct ContactProblemCounts
  {
    unsigned long solves         = 0;
    unsigned long iterations     = 0; // the solver's, over all solves (Lemke: pivots)
    unsigned int  max_iterations = 0; // of one solve
    double        max_residual   = 0; // Siconos's error, the largest of one solve
  };

  struct IterationStatistics
  {
    unsigned long steps      = 0; // accepted steps and sub-steps
    unsigned long iterations = 0; // Newton iterations (solves) in them
    unsigned int  max_iterations = 0;
    unsigned long step_cuts  = 0;
    unsigned long event_refinements = 0; // steps cut to locate a contact or stick-slip event
    unsigned long contact_refinements = 0; // steps halved to resolve a contact in time
    unsigned long accuracy_refinements = 0; // steps halved for Steps per shortest period
    unsigned long woodbury_solves  = 0; // Newton iterations solved by the Woodbury update
    unsigned long refactorizations = 0; // numeric factorisations of the tangent
    unsigned long full_newton_retries = 0; // steps redone by full Newton after a cheaper method failed
    unsigned long line_searches = 0;    // iterations whose step the line search shortened or stretched
    unsigned long shared_analyses = 0;  // symbolic analyses taken over from another step size's solver
    double        smallest_time_step = 0;
    /// CG + AMG solves and preconditioner builds, over the integrator's
    /// life (the preconditioners outlive initialize()).
    IterativeSolveCounts linear;
    /// Rigid contact's contact problems (Contact/Model = nonsmooth).
    ContactProblemCounts contact;
  };

  class NewmarkIntegrator : public TimeStepper
  {
  public:
    /// `elements` may be null (a linear model); they are updated in place.
    /// Refactorising a nonsymmetric element tangent needs an LU backend
    /// (not eigen-ldlt): InputError otherwise.
    /// `distribution` (null: one process) steps this rank's part of a
    /// model partitioned by building (assembly/rank_ownership.h): `system`
    /// and `elements` are this rank's (assembly/partition.h), every rank
    /// constructs and advances its integrator in step, and each factorises
    /// its own block of the frozen tangent. The nonlinear solver must then
    /// reuse a factorisation (modified-newton, krylov-newton or bfgs) with
    /// Tangent update = refactorize; InputError otherwise.
    NewmarkIntegrator(const LinearSystem &system, const std::string &linear_solver,
                      const NewmarkParameters &parameters,
                      NonlinearElements       *elements     = nullptr,
                      const RankOwnership      *distribution = nullptr);
    ~NewmarkIntegrator() override;

    /// Start at time 0 from (u0, v0) under load p0.
    void initialize(const Vector &load, const Vector &u0, const Vector &v0) override;
    /// Called by initialize() right after the elements are reset, before
    /// they are set to u0: brings them to an earlier state (the gravity
    /// state, replayed: integration/static_analysis.h). Null: none.
    void set_element_preload(std::function<void(NonlinearElements &)> preload)
    {
      element_preload = std::move(preload);
    }
    /// The gravity state the run starts from (u_g) and the load held
    /// constant through it (p_g, OpenSees's loadConst; a part of every
    /// load(t) the integrator is given): the strain energy is measured from
    /// the state at u_g (the elements' after the preload), and p_g's work,
    /// with that of the elements' own held loads, is the balance's
    /// constant_load instead of input. Before initialize(); not distributed.
    void hold_gravity_state(const Vector &held_load, const Vector &gravity_displacement);
    /// Whether initialize() brings the massless equations into equilibrium
    /// with the massive ones first (set when the run is given initial
    /// conditions): u_0 on them from p - C v - K u - f(u, v) = 0, and v_0
    /// from the static tangent, -K_00^-1 K_0m v_m (doc/theory.md §3.8a).
    /// A massless equation has no state of its own, and one out of
    /// equilibrium at t = 0 does work in the first step that no energy term
    /// holds. Not distributed.
    void equilibrate_massless_start(const bool on) { equilibrate_massless = on; }
    /// Start from rest.
    void initialize(const Vector &load);
    /// Continue from (u_new, v_new) at the current time under p = load
    /// (e.g. a perturbed trajectory renormalised for a Lyapunov exponent):
    /// time, statistics, energy terms and each element's history are kept,
    /// the elements are set to the new state and committed, and a is the
    /// consistent acceleration, as initialize() computes a_0.
    void restart(const Vector &load, const Vector &u_new, const Vector &v_new);

    /// Advance one step to t + dt, cutting it if Newton fails; `load(t, p)`
    /// gives p at any time in the step. Throws NumericalError (with the
    /// time, the step size reached and where) if even the smallest step fails.
    void advance(const LoadFunction &load) override;
    /// Called after every accepted sub-step of a step that was cut (to
    /// resolve a contact, locate an event or converge), the state being
    /// that sub-step's end; peaks between the steps come from there.
    void set_substep_callback(std::function<void()> callback) override
    {
      substep_callback = std::move(callback);
    }
    /// Advance one step under p(t_{n+1}) = load (constant over a cut step).
    void advance(const Vector &load);

    double        time() const override { return current_time; }
    unsigned long steps() const override { return step_count; }
    /// The length of the last accepted (sub)step: the impact log's, and a
    /// replay's (replayed_stepper.h), time increment.
    double last_step_length() const { return last_step; }
    const Vector &displacement() const override { return u; }
    const Vector &velocity() const override { return v; }
    const Vector &acceleration() const override { return a; }

    double kinetic_energy() const;
    /// Recoverable strain energy: elastic structure plus the laws' stored
    /// energy, less their sum at the gravity state (hold_gravity_state).
    double strain_energy() const;
    /// The energy terms at the current time.
    EnergyBalance energy() const override;
    /// max over the run so far of |input - sum| / max(|input|, sum) with the
    /// denominator's running maximum (so the start of the motion, where
    /// both are tiny, is not divided by nearly zero).
    double max_energy_error() const override { return max_balance_error; }

    const IterationStatistics &statistics() const override { return stats; }
    /// Work done on element h so far (trapezoidal), J.
    double element_work(unsigned int h) const override { return records.work()[h]; }
    /// Work done on the structure by what drives element h (a belt) so far, J.
    double element_supplied_work(unsigned int h) const override
    {
      return records.supplied_work()[h];
    }
    /// The residual R(u_trial) of the next step under p(t_{n+1}) = load, and
    /// the dense tangent -dR/du that Newton uses (for checks and
    /// diagnostics; the laws are reverted afterwards).
    void residual_and_tangent(const Vector &load, const Vector &u_trial, Vector &residual_out,
                              Eigen::MatrixXd &tangent_out);

    /// Names of the equations, used in failure messages ("A3 (6, 3) ux").
    void set_equation_names(std::vector<std::string> names) { equation_names = std::move(names); }
    /// Or name an equation only when a message needs it (a partitioned
    /// rank: its equations in the model's terms, without a list of them).
    void set_equation_namer(std::function<std::string(unsigned int)> namer)
    {
      equation_namer = std::move(namer);
    }
    /// Every contact episode of the gap elements so far.
    const ImpactLog &impact_log() const override { return records.impact_log(); }
    /// Every stick and slip episode of the friction elements so far.
    const StickSlipLog &stick_slip_log() const override { return records.stick_slip_log(); }
    /// Every step ends on the converged iterate, the elements evaluated at
    /// it (try_step returns right after the evaluation that met the test),
    /// and accept() commits that state.
    bool elements_hold_state() const override { return true; }
    /// The update in use (never automatic).
    TangentUpdate tangent_update() const
    {
      return use_woodbury ? TangentUpdate::woodbury :
                            (use_hybrid ? TangentUpdate::hybrid : TangentUpdate::refactorize);
    }
    std::string linear_solver_name() const;

  private:
    struct Level;
    Level &level(unsigned int cuts);
    // level()'s phases: Newmark's coefficients for dt, K_eff with the
    // elements' couplings in its pattern, a solver (this rank's block when
    // distributed, wrapped for modal damping), the Woodbury update's
    // columns, the assembled tangent's positions in K_eff
    void   set_coefficients(Level &L, double dt) const;
    void   assemble_effective_matrix(Level &L) const;
    std::unique_ptr<LinearSolver> new_linear_solver(const Level &L);
    void   set_up_woodbury(Level &L) const;
    void   set_up_assembled_tangent(Level &L);
    bool   try_step(Level &L, const Vector &load_next);
    // try_step's start: the step's effective load less K_eff u, formed term
    // by term (r_0 below)
    void   set_start_residual(const Level &L, const Vector &load_next);
    /// K u, formed once after each change of u.
    const Vector &stiffness_times_u() const;
    /// u_next = u + step_displacement
    void   set_iterate();
    void   update_kinematics(const Level &L);
    bool   solve_linear_step(const Level &L);
    bool   newton_residual(Level &L, unsigned int it, double &norm);
    bool   newton_increment(Level &L, unsigned int it);
    void   accept(const Level &L, const Vector &load_next);
    void   advance_from(unsigned int cuts, double t0, const LoadFunction &load);
    /// Whether a step of L.dt from the committed state would not resolve a
    /// contact under way, or one predicted to begin in it, by Steps per
    /// contact steps.
    bool   contact_needs_shorter_step(const Level &L) const;
    bool   evaluate_elements(const Vector &u_trial, const Vector &v_trial, const Level &L);
    void   update_energy_error();
    /// total_balance = the sum of every rank's balance (collective).
    void   sum_balance_over_ranks();
    /// a from M a = p - C v - K u - f(u, v) at the current u, v (the
    /// elements set to them and committed); massless equations get a = 0.
    void   set_consistent_acceleration(const Vector &load);
    /// Its local part (distributed: agreed and the ghosts updated after).
    void   solve_consistent_acceleration(const Vector &load);
    /// The massive equations' numbers among themselves (-1: massless), and
    /// how many there are.
    std::vector<int> massive_numbering(unsigned int &n_massive) const;
    /// equilibrate_massless_start's state at t = 0 (massless_start.cc).
    void   equilibrate_massless_dofs(const Vector &load);
    /// Newton on the massless equations of u at fixed v, the elements left
    /// at the last (converged) evaluation.
    void   relax_massless_displacements(const Vector &load, const std::vector<int> &massless);
    /// r = load - C v - K u - f(u, v) with the elements set to (u, v) and
    /// committed, or not committed and their static tangent changes (D_e at
    /// damping factor 0) in tangent_change; NumericalError if an element
    /// refuses the state.
    void   evaluate_start(const Vector &load, Vector &r, bool commit);
    /// Rows `massless` of the static tangent K + sum_e B_e D_e B_e^T at
    /// the last evaluation: the massless columns in `square`, all in `rows`.
    void   massless_tangent(const std::vector<int> &massless, SparseMatrix &square,
                            SparseMatrix &rows) const;
    /// local_u, local_v: the elements' local vectors (0 on ground DOFs).
    void   gather(const Vector &u_global, const Vector &v_global);
    /// r -= sum_e (f_e - K_ref,e u_e) at the last evaluated trial state.
    void   subtract_element_forces(Vector &r) const;
    /// Entry (i, j) of element h's B_e D_e B_e^T at the last evaluation.
    /// Entry (i, j) of element h's B_e D_e B_e^T, D from `d` (laid out as
    /// tangent_change).
    double tangent_change_entry(const std::vector<double> &d, unsigned int h, unsigned int i,
                                unsigned int j) const;
    /// Solve the Newton correction with the assembled tangent D = `d`:
    /// add it into K_eff and factorise (unless `reuse`), then solve.
    void   solve_with_assembled_tangent(Level &L, const std::vector<double> &d, bool reuse,
                                        const Vector &b, Vector &x);
    /// The method of this iteration: newton for auto when no sparse
    /// refactorisation is ever needed (Woodbury), and in a retry.
    NonlinearSolver active_method() const;
    /// The increment on the level's frozen tangent K_0 (every method but
    /// newton), re-formed when the iteration that led to ||R_it|| = `norm`
    /// contracted too little; `target` is the converged residual norm.
    bool   quasi_newton_increment(Level &L, unsigned int it, double norm, double previous_norm,
                                  double target);
    /// Whether auto should re-form K_0: continuing at the contraction
    /// norm / previous_norm to `target` costs more than a factorisation.
    bool   reform_pays(const Level &L, double norm, double previous_norm, double target) const;
    /// x = K_0^{-1} b (Woodbury, or the assembled K_0 factorised once).
    void   solve_frozen(Level &L, const Vector &b, Vector &x);
    /// Scale the increment by the secant line search (Crisfield §9.3).
    void   search_line(Level &L, unsigned int it);
    /// The constructor's part for a partitioned model: the checks, the
    /// quasi-Newton updates' sums, which elements count here.
    void   set_up_distribution();
    /// Refuse what a partitioned model cannot yet do (InputError).
    void   check_distributable() const;
    /// The bound on the highest natural frequency (accuracy_substeps.h)
    /// of the model: over ranks, the largest of their blocks'.
    double highest_frequency() const;
    /// Norm and inner product over every rank's own equations.
    double norm_of(const Vector &x) const;
    double dot_of(const Vector &a, const Vector &b) const;
    /// x^T K x / 2 plus the elements' stored energy less their part in K,
    /// at their trial state (this rank's elements).
    double strain_energy_at(const Vector &x) const;
    /// strain_energy(), each counted element's stored energy written to
    /// (*noted)[h] on the way (not null: the step's dissipation reads them).
    double strain_energy(std::vector<double> *noted) const;
    /// `ok` on every rank; else false, with `failure` set where it was not
    /// already (the cause is on another rank). Collective when distributed.
    bool   agreed(bool ok, const char *elsewhere);

    const LinearSystem &system;
    std::string         solver_name;
    NewmarkParameters   parameters;
    NonlinearElements  *elements   = nullptr;
    unsigned int        n_elements = 0;
    const RankOwnership *distribution = nullptr;
    /// Distributed: whether element h's energy counts on this rank (an
    /// element between two ranks' buildings is evaluated on both and
    /// counted by the owner of its first equation).
    std::vector<char>   counted_here;
    /// Distributed: the energy terms summed over the ranks.
    EnergyBalance       total_balance;
    bool                equilibrate_massless = false;
    bool                use_woodbury = true;
    bool                use_hybrid   = false;
    // Element h's local DOFs are [dof_start[h], dof_start[h + 1]) of the
    // local vectors, its D_e is at tangent_change[d_start[h]] (column-major),
    // its B_e is basis[h]; local DOF q has the equation local_equation[q].
    std::vector<unsigned int>    dof_start, d_start;
    std::vector<int>             local_equation;
    std::vector<Eigen::MatrixXd> basis;
    std::vector<std::unique_ptr<Level>> levels;

    Vector u, v, a, load_now;
    Vector u_next, v_next, a_next, residual, increment, work_vector, velocity_sum;
    /// Newton's unknown is the step's displacement increment du = u_next - u,
    /// and its residual r_0 - K_eff du - f(u + du), with r_0 = rhs - K_eff u
    /// formed term by term (set_start_residual): rhs and K_eff u are both
    /// about M u / (beta dt^2), and their difference loses that many digits
    /// at the short sub-steps of an impact, where the accelerations
    /// c_u du amplify the lost digits (doc/theory.md §3.3).
    Vector step_displacement, start_residual;
    /// The residual's round-off scale for this step (set_start_residual).
    double residual_floor = 0;
    /// Sparse products of the energy terms, so a step allocates nothing.
    mutable Vector product;
    /// K u of the current u: the strain energy at a step's end and the next
    /// step's start residual need the same product (stiffness_times_u); u
    /// changes only in initialize, restart and accept, which mark it stale.
    mutable Vector stiffness_product;
    mutable bool   stiffness_product_is_current = false;
    // Local vectors of every element: displacement, velocity, force correction.
    Vector local_u, local_v, correction;
    std::vector<double> tangent_change;
    // The quasi-Newton corrections on the frozen tangent of a level.
    KrylovAcceleration krylov;
    BfgsUpdate         bfgs;
    /// advance_from's retry of a failed step with full Newton.
    bool full_newton_now = false;
    /// auto: wall time of the last iteration without a factorisation (s).
    double iteration_seconds = 0;
    std::chrono::steady_clock::time_point last_increment_end;
    // Gaps, friction and discontinuous springs: a change of is_active()
    // within a step is an event.
    std::vector<unsigned int> event_elements;
    /// Per element: work, the impact and stick-slip logs.
    ElementRecords records;
    /// Element h's stored energy at the last accepted step (update_energy_error).
    std::vector<double> element_energies;
    double         last_step = 0; // of the last accepted (sub)step
    std::string failure;
    std::function<void()> substep_callback;
    std::function<void(NonlinearElements &)> element_preload;
    std::vector<std::string> equation_names;
    std::function<std::string(unsigned int)> equation_namer;
    /// "equation i, NAME" (the name from equation_names or equation_namer).
    std::string equation_text(Eigen::Index i) const;
    double      current_time = 0;
    unsigned long step_count = 0;
    /// The level of every step's sub-steps (Steps per shortest period; 0:
    /// steps of Time step), from which the other refinements count.
    unsigned int base_level = 0;
    IterationStatistics stats;
    EnergyBalance       balance;
    /// hold_gravity_state: p_g and u_g (empty: no gravity state), the
    /// displacements at t = 0, the strain energy at u_g, and the input's
    /// trapezoidal sums with p_g's work in them.
    Vector              held_load, gravity_displacement, start_displacement;
    double              gravity_strain = 0;
    double              input_with_held = 0;
    double              energy_scale      = 0;
    double              max_balance_error = 0;
  };
} // namespace poundfe

#endif
