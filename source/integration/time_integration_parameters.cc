#include <poundfe/assembly/iterative_solver.h>
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/numbers.h>
#include <poundfe/integration/time_integration_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <utility>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  const NameTable<HysteresisIntegration> &
  hysteresis_integration_names()
  {
    static const NameTable<HysteresisIntegration> table(
      {{HysteresisIntegration::trapezoidal, "trapezoidal"},
       {HysteresisIntegration::backward_euler, "backward-euler"}});
    return table;
  }

  const NameTable<TimeIntegrationMethod> &
  time_integration_method_names()
  {
    static const NameTable<TimeIntegrationMethod> table(
      {{TimeIntegrationMethod::newmark, "newmark"}, {TimeIntegrationMethod::dopri, "dopri"}});
    return table;
  }

  const NameTable<ContactModel> &
  contact_model_names()
  {
    static const NameTable<ContactModel> table(
      {{ContactModel::penalty, "penalty"}, {ContactModel::nonsmooth, "nonsmooth"}});
    return table;
  }

  MoreauJeanParameters
  TimeIntegrationParameters::moreau_jean_parameters() const
  {
    MoreauJeanParameters p = moreau_jean;
    p.time_step            = newmark.time_step;
    p.linear_solver        = linear_solver;
    p.friction.tolerance      = moreau_jean.lcp.tolerance;
    p.friction.max_iterations = moreau_jean.lcp.max_iterations;
    return p;
  }

  const NameTable<RunPartition> &
  run_partition_names()
  {
    static const NameTable<RunPartition> table(
      {{RunPartition::none, "none"}, {RunPartition::buildings, "buildings"}});
    return table;
  }

  DormandPrinceParameters
  TimeIntegrationParameters::dormand_prince() const
  {
    DormandPrinceParameters p = dopri;
    p.time_step               = newmark.time_step;
    return p;
  }

  double
  TimeIntegrationParameters::hysteresis_theta() const
  {
    return hysteresis_integration == HysteresisIntegration::trapezoidal ? 0.5 : 1.0;
  }

  namespace
  {
    /// The entries of the Newton iteration (convergence, step cuts, tangent
    /// update, nonlinear solver, line search), in the order of the listing.
    void
    declare_newton_entries(dealii::ParameterHandler &prm, NewtonParameters &newton)
    {
      prm.add_parameter("Newton residual tolerance", newton.residual_tolerance,
                        "A nonlinear step has converged when the residual norm is below this "
                        "times the norm of the effective load ... Unit: dimensionless.");
      prm.add_parameter("Newton energy tolerance", newton.energy_tolerance,
                        "... and the work of the residual on the last correction is below "
                        "this times that of the first iteration (theory §3.4). Unit: dimensionless.");
      prm.add_parameter("Newton maximum iterations", newton.max_iterations,
                        "Iterations before the step is cut. Unit: count.",
                        Patterns::Integer(1, 1000));
      prm.add_parameter("Maximum step cuts", newton.max_step_cuts,
                        "A step that fails is halved and retried, down to Time step / "
                        "2^cuts; then the run stops (exit 2). Unit: count.",
                        Patterns::Integer(0, 40));
      add_choice(prm, "Tangent update", newton.tangent_update,
                 "How the tangent of nonlinear elements enters the solve: woodbury "
                 "keeps the one factorisation of the linear part and adds a dense "
                 "correction whose rank is the total tangent rank of the nonlinear "
                 "elements (one per uniaxial element); refactorize adds the tangents "
                 "into the matrix and refactorises every iteration (the symbolic "
                 "analysis done once); hybrid uses woodbury while the elements whose "
                 "tangent differs from their initial one (the active rank) fit in "
                 "Woodbury columns, and refactorises when they do not; auto picks "
                 "woodbury up to a total rank of Woodbury columns, else hybrid. Unit: -.",
                 tangent_update_names());
      prm.add_parameter("Woodbury columns", newton.woodbury_columns,
                        "The most columns of A^-1 B the Woodbury update keeps (a dense "
                        "equations x columns block, 8 bytes each): the limit of auto and "
                        "hybrid. Unit: count.", Patterns::Integer(1, 100000));
      add_choice(prm, "Nonlinear solver", newton.nonlinear_solver,
                 "How a Newton iteration finds its correction (theory §3.4b): newton forms "
                 "and factorises the tangent at every iterate (quadratic convergence); "
                 "modified-newton reuses one factorised tangent K_0; krylov-newton "
                 "accelerates the modified-Newton correction in the subspace of the step's "
                 "last corrections (Carlson and Miller 1998, OpenSees's KrylovNewton); bfgs "
                 "updates the inverse of K_0 by BFGS (Matthies and Strang 1979); auto is "
                 "newton when no sparse factorisation is needed (Woodbury), else "
                 "krylov-newton re-forming K_0 when the measured cost of continuing exceeds "
                 "that of a factorisation. Every method but newton redoes a step it fails by "
                 "full Newton before the step is cut. Unit: -.",
                 nonlinear_solver_names());
      prm.add_parameter("Keep tangent across steps", newton.keep_tangent,
                        "Every Nonlinear solver but newton: keep the factorised tangent K_0 "
                        "from step to step (false: form it at each step's first iteration). "
                        "Unit: -.");
      prm.add_parameter("Refactorisation ratio", newton.refactorization_ratio,
                        "modified-newton, krylov-newton and bfgs: re-form and refactorise K_0 at "
                        "the current iterate when an iteration reduces the residual norm by less "
                        "than this factor (>= 1: only when the residual grows). Unit: "
                        "dimensionless.");
      prm.add_parameter("Subspace dimension", newton.subspace_dimension,
                        "krylov-newton: the most earlier corrections spanning the subspace; "
                        "bfgs: the most update pairs kept. Unit: count.",
                        Patterns::Integer(1, 100));
      prm.add_parameter("Line search", newton.line_search,
                        "Scale each correction d by the secant line search on the work "
                        "G(s) = d . R(u + s d), until |G(s)| <= Line search tolerance |G(0)| "
                        "(s in [0.1, 10], at most 10 evaluations; Crisfield 1991 §9.3). "
                        "Unit: -.");
      prm.add_parameter("Line search tolerance", newton.line_search_parameters.tolerance,
                        "eta of Line search. Unit: dimensionless.",
                        Patterns::Double(0.01, 0.99));
    }

    /// The integrator: Newmark's or Dormand-Prince's and their constants.
    void
    declare_method_entries(dealii::ParameterHandler &prm, TimeIntegrationParameters &p)
    {
      add_choice(prm, "Method", p.method,
                 "newmark: Newmark-Newton with event refinement, every model; dopri: adaptive "
                 "Dormand-Prince 5(4) with dense output and event location (each contact's "
                 "g = 0 and, in contact, its penetration rate = 0), for models of up to "
                 "200 equations, all with mass, whose nonlinear elements are contacts and "
                 "elastic springs (theory §3.9a); Time step is then the output step. Unit: -.",
                 time_integration_method_names());
      prm.add_parameter("Relative tolerance", p.dopri.relative_tolerance,
                        "dopri: the relative tolerance of each step's local error estimate "
                        "(on every displacement and velocity). Unit: dimensionless.");
      prm.add_parameter("Absolute tolerance", p.dopri.absolute_tolerance,
                        "dopri: the absolute tolerance of the local error estimate (m on "
                        "displacements, m/s on velocities). Unit: m or m/s (displacements, velocities).");
      prm.add_parameter("Newmark gamma", p.newmark.gamma,
                        "gamma >= 1/2 (1/2: no numerical damping). Unit: dimensionless.");
      prm.add_parameter("Newmark beta", p.newmark.beta,
                        "beta >= (1/2 + gamma)^2 / 4 (1/4 with gamma = 1/2: average "
                        "acceleration). Unit: dimensionless.");
    }

    /// The linear solver and how a run is spread over its ranks.
    void
    declare_solver_entries(dealii::ParameterHandler &prm, TimeIntegrationParameters &p)
    {
      add_choice(prm, "Linear solver", p.linear_solver,
                 "Solver of the effective matrix: direct (factorised once) or conjugate "
                 "gradients with algebraic multigrid; band-lu is LAPACK's banded LU after a "
                 "Cuthill-McKee numbering, for a refactorised nonsymmetric tangent of a few "
                 "hundred equations (fibre frames on PDelta columns); petsc and trilinos need MPI; "
                 "petsc-mumps (MUMPS through PETSc) splits the matrix and its factorisation "
                 "over the ranks of mpirun -np P poundfe run (each rank keeps the whole "
                 "state; rank 0 writes); petsc-cg-boomeramg (PETSc CG, hypre BoomerAMG) and "
                 "trilinos-cg-ml (AztecOO CG, Trilinos ML) solve to a fraction of the Newton "
                 "tolerance and keep their preconditioner across iterations and steps "
                 "(Iterative solver; theory §3.5c); on P ranks each rank runs the whole "
                 "analysis. Not given: eigen-ldlt, or umfpack when a nonsymmetric element "
                 "tangent (3D plan contact) must be refactorised. Unit: -.",
                 linear_solver_names());
      add_choice(prm, "Partition", p.partition,
                 "How mpirun -np P poundfe run spreads one run over its ranks: none (every "
                 "rank runs the whole analysis; with petsc-mumps the matrix and its "
                 "factorisation are split) or buildings (each rank sets up, factorises and "
                 "steps only its own run of buildings, with its nonlinear elements and "
                 "their history; the ranks exchange the far ends of the elements between "
                 "them; every rank observes its own buildings and rank 0 writes every "
                 "output, merged from the ranks; theory §3.5d). buildings needs Method = newmark, a one-process Linear "
                 "solver (eigen-ldlt or umfpack) for each rank's block, a Nonlinear solver "
                 "that reuses its factorisation (krylov-newton, modified-newton, bfgs, or auto, "
                 "then krylov-newton; not the default newton), Tangent "
                 "update = refactorize or auto (then refactorize), no friction "
                 "surfaces and no initial conditions, and at least as many separable "
                 "buildings as ranks; other commands than run refuse it. Unit: -.",
                 run_partition_names());
    }
  } // namespace

  void
  TimeIntegrationParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    prm.add_parameter("Time step", newmark.time_step, "Analysis time step. Unit: s.");
    prm.add_parameter("Steps per shortest period", newmark.steps_per_period,
                      "newmark: integrate every step in 2^c equal sub-steps, c the smallest "
                      "level with at least this many sub-steps per period of the highest mode "
                      "(its Gershgorin bound from K and the diagonal of M), so that Newmark's "
                      "period error (omega h)^2 / 12 stays below pi^2 / (3 N^2) for every "
                      "mode (theory §3.7b); outputs keep to Time step, peaks see every "
                      "sub-step; Event refinement, Steps per contact and Maximum step cuts "
                      "count their levels from c. 0: off. Unit: count.",
                      Patterns::Integer(0, 100000));
    prm.add_parameter("Contact onset from acceleration",
                      newmark.newton.contact_onset_from_acceleration,
                      "newmark: Contact/Steps per contact also splits a step from which an "
                      "open gap closes within two steps on the parabola of its committed rate "
                      "and relative acceleration (not only within the step at the constant "
                      "rate), with the approach velocity at the crossing, and a step from a gap "
                      "penetrated without force; so that a contact the floors accelerate into "
                      "is resolved before it is tried rather than cut after Newton fails. "
                      "Inside a contact episode Newton then starts from u + h v + h^2 a / 2 "
                      "(its tolerances still relative to the step from u), and a correction "
                      "that would open again a gap closing in the step lands it at a sixteenth "
                      "of its penetration instead, once per step (theory §3.7a); the start "
                      "and correction are skipped with friction or a partitioned run; no "
                      "effect with dopri or Contact/Model = nonsmooth. false: the constant "
                      "rate alone, Newton from u. Unit: -.");
    prm.add_parameter("End time", end_time,
                      "s; 0: the length of the ground motion. Unit: s.");
    prm.add_parameter("Maximum number of steps", max_steps,
                      "A run whose End time / Time step (or ground-motion duration / Time "
                      "step) exceeds this is refused before it starts (a guard against "
                      "End time = 1e308 or a record's DT typed in ms); raise it for a "
                      "genuinely long run. Unit: count.",
                      Patterns::Integer(1));
    declare_method_entries(prm, *this);
    declare_solver_entries(prm, *this);
    declare_newton_entries(prm, newmark.newton);
    newmark.iterative.declare(prm);
    add_choice(prm, "Hysteresis integration", hysteresis_integration,
               "Bouc-Wen z over a step: trapezoidal (second order) or "
               "backward-euler (first order, most robust). Unit: -.",
               hysteresis_integration_names());
    prm.add_parameter("Law tolerance", law_tolerance,
                      "Tolerance of the local Newton iteration of a law (on z). "
                      "Unit: dimensionless.");
    prm.add_parameter("Law maximum iterations", law_max_iterations,
                      "Local iterations before the law reports failure. Unit: count.",
                      Patterns::Integer(1, 1000));
    prm.leave_subsection();
  }

  void
  TimeIntegrationParameters::declare_event_refinement(dealii::ParameterHandler &prm)
  {
    add_choice(prm, "Model", contact_model,
               "penalty: each gap is its Law's force, stepped by Time integration/Method; "
               "nonsmooth: rigid unilateral contact at velocity level (a closing gap stops "
               "closing; its penetration stays of the order of the step times the approach "
               "velocity) with "
               "Newton's impact law (Coefficient of restitution e in [0, 1]), stepped by "
               "Moreau-Jean's theta-scheme with each step's impulses from an LCP solved by "
               "Siconos Numerics (theory §3.9d); needs a Law other than none (its force "
               "parameters are then unused), gaps between floors, at barriers, in plan "
               "or a slab against a column (3D; a column with mass: Mass matrix = "
               "consistent), no bumpers, friction surfaces or fibre "
               "members, no gravity analysis (large models: Dense matrix limit); the "
               "commands run, stationary-pdf, "
               "montecarlo, subset, fragility, ida, msa, sweep, separation (its free "
               "responses have no contact: Newmark) and mitigation (no bumper cases), and "
               "Python's run; a build without Siconos offers penalty only (poundfe --version lists "
               "the contact models). Unit: -.",
               contact_model_names());
    prm.add_parameter("Theta", moreau_jean.theta,
                      "Model = nonsmooth: theta of Moreau-Jean's scheme, in [1/2, 1] (1/2: "
                      "no numerical damping of the smooth motion; 1: implicit Euler). "
                      "Unit: dimensionless.");
    add_choice(prm, "LCP solver", moreau_jean.lcp.solver,
               "Model = nonsmooth: Siconos Numerics' solver of each step's contact LCP: "
               "lemke (pivoting, exact), nsgs (projected Gauss-Seidel), enum "
               "(enumeration, a few contacts), newton-fb (semismooth Newton on "
               "Fischer-Burmeister). Unit: -.",
               lcp_solver_names());
    prm.add_parameter("LCP tolerance", moreau_jean.lcp.tolerance,
                      "Model = nonsmooth: the LCP solver's tolerance on Siconos's relative "
                      "complementarity error (lcp_compute_error); a step whose LCP is not "
                      "solved to it stops the run (exit 2, the results so far kept, the step "
                      "and the residual named). Unit: dimensionless.");
    prm.add_parameter("LCP iterations", moreau_jean.lcp.max_iterations,
                      "Model = nonsmooth: the LCP solver's iteration limit (Lemke: pivots; "
                      "nsgs: sweeps; newton-fb: Newton iterations). Unit: count.",
                      Patterns::Integer(1, 100000000));
    prm.add_parameter("Friction coefficient", moreau_jean.friction_coefficient,
                      "Model = nonsmooth: Coulomb's coefficient mu along the contacts in plan "
                      "(Model/Dimension = 3: the slabs slide along the edge they touch); each "
                      "step's contact problem is then a friction-contact problem (tangential "
                      "impulse at most mu times the normal one). 0: frictionless. Unit: "
                      "dimensionless.");
    add_choice(prm, "Friction solver", moreau_jean.friction.solver,
               "Model = nonsmooth with a Friction coefficient: Siconos Numerics' fc2d solver "
               "of each step's friction-contact problem: nsgs (Gauss-Seidel over the "
               "contacts, each solved exactly), lemke (Lemke on its LCP), enum (enumeration, a "
               "few contacts); its tolerance and iteration limit are the LCP's. A problem it "
               "leaves unsolved goes to a fallback, lemke (nsgs when lemke is chosen); the "
               "run stops (exit 2) only when both fail. Unit: -.",
               friction_solver_names());
    prm.add_parameter("Dense matrix limit", moreau_jean.max_dense_equations,
                      "Model = nonsmooth: Moreau-Jean's iteration matrix is sparse on models "
                      "of more than this many equations, factored by Time integration/Linear "
                      "solver (eigen-ldlt, or umfpack), without modal damping; up to it, "
                      "sparse where Linear solver = eigen-ldlt and its solves are estimated "
                      "cheaper than a dense LU's (from the factor's entries), else dense "
                      "(LU; so with modal damping or another Linear solver); each step's "
                      "Delassus operator by one solve per contact of its index set either way "
                      "(theory §3.9d). Unit: count.",
                      Patterns::Integer(0, 1000000000));
    prm.add_parameter("Event refinement", newmark.newton.event_refinement,
                      "A step in which a contact starts or ends is redone in 2^r "
                      "sub-steps around the event, which is then located inside the "
                      "sub-step by interpolation. Unit: count.", Patterns::Integer(0, 12));
    prm.add_parameter("Steps per contact", newmark.newton.steps_per_contact,
                      "While a gap is closed, or about to close, the step is halved until "
                      "the impact's duration spans at least this many steps (the duration "
                      "of an elastic impact of the effective mass: pi sqrt(m_e / k) for the "
                      "linear laws, 2.94 delta_max / v0 for the Hertz laws and Jankowski's, "
                      "at the approach velocity v0); at most Time integration/Maximum step "
                      "cuts halvings. 0: off. Unit: count.", Patterns::Integer(0, 10000));
  }

  unsigned long
  TimeIntegrationParameters::n_steps_to(const double end, const InputFile &input,
                                        const std::string &end_path) const
  {
    const double n = end / newmark.time_step;
    if (!(n >= 1)) // 1e200 s ran no step at all, with exit 0
      input.fail("Time integration/Time step",
                 "must not exceed the length of the run, " + number_text(end) + " s (" +
                   end_path + "), got " + number_text(newmark.time_step) + " s");
    if (!(n <= max_steps))
      input.fail(end_path, "needs " + count_text(n) +
                             " steps of " +
                             number_text(newmark.time_step) + " s to reach " + number_text(end) +
                             " s, more than Time integration/Maximum number of steps = " +
                             std::to_string(max_steps) + " (raise it if the run is meant)");
    return static_cast<unsigned long>(std::llround(n));
  }

  void
  TimeIntegrationParameters::check(const InputFile &input) const
  {
    input.positive("Time integration/Time step", newmark.time_step);
    input.non_negative("Time integration/End time", end_time);
    if (end_time > 0)
      n_steps_to(end_time, input, "Time integration/End time");
    if (!(newmark.gamma >= 0.5))
      input.fail("Time integration/Newmark gamma", "must be >= 1/2 for stability");
    if (!(newmark.beta >= 0.25 * (0.5 + newmark.gamma) * (0.5 + newmark.gamma) - 1e-12))
      input.fail("Time integration/Newmark beta",
             "must be >= (1/2 + gamma)^2 / 4 for unconditional stability");
    // fractions (of the effective load's norm, of the first iteration's
    // work): 1 or more accepts an iterate far from equilibrium (1e200 ran to
    // its end on the first iterates)
    for (const auto &[entry, tolerance] :
         {std::pair{"Time integration/Newton residual tolerance", newmark.newton.residual_tolerance},
          {"Time integration/Newton energy tolerance", newmark.newton.energy_tolerance}})
      {
        input.positive(entry, tolerance);
        if (!(tolerance < 1))
          input.fail(entry, "must be below 1, a fraction (got " + number_text(tolerance) +
                              "): 1 or more accepts an iterate far from equilibrium");
      }
    input.positive("Time integration/Law tolerance", law_tolerance);
    input.positive("Time integration/Relative tolerance", dopri.relative_tolerance);
    input.positive("Time integration/Absolute tolerance", dopri.absolute_tolerance);
    input.positive("Time integration/Refactorisation ratio", newmark.newton.refactorization_ratio);
    if (const std::string why = linear_solver_unavailable(linear_solver); !why.empty())
      input.fail("Time integration/Linear solver", linear_solver + " is not available: " + why);
    newmark.iterative.check(input);
    check_contact_model(input);
    if (partition == RunPartition::buildings)
      {
        if (method != TimeIntegrationMethod::newmark)
          input.fail("Time integration/Partition",
                     "buildings steps the ranks' blocks with Newmark-Newton: not with Method = " +
                       time_integration_method_names().name(method));
        if (newmark.newton.tangent_update == TangentUpdate::woodbury ||
            newmark.newton.tangent_update == TangentUpdate::hybrid)
          input.fail("Time integration/Tangent update",
                     tangent_update_names().name(newmark.newton.tangent_update) +
                       " would couple the ranks' blocks densely: with Partition = buildings "
                       "the tangent is assembled (refactorize, or auto)");
        if (linear_solver != "eigen-ldlt" && linear_solver != "umfpack")
          input.fail("Time integration/Linear solver",
                     "with Partition = buildings each rank factorises its own block with "
                     "eigen-ldlt or umfpack only, not " + linear_solver);
      }
  }

  void
  TimeIntegrationParameters::check_contact_model(const InputFile &input) const
  {
    if (!(moreau_jean.theta >= 0.5 && moreau_jean.theta <= 1))
      input.fail("Contact/Theta", "must lie in [1/2, 1], got " + number_text(moreau_jean.theta));
    if (!(moreau_jean.lcp.tolerance > 0 && moreau_jean.lcp.tolerance < 1))
      input.fail("Contact/LCP tolerance",
                 "must lie in (0, 1), got " + number_text(moreau_jean.lcp.tolerance));
    if (!(moreau_jean.friction_coefficient >= 0 && moreau_jean.friction_coefficient <= 10))
      input.fail("Contact/Friction coefficient",
                 "must lie in [0, 10], got " + number_text(moreau_jean.friction_coefficient));
    if (contact_model != ContactModel::nonsmooth && moreau_jean.friction_coefficient > 0)
      input.fail("Contact/Friction coefficient",
                 "acts along a rigid contact (Model = nonsmooth): with Model = penalty there "
                 "is no normal contact impulse to bound the friction by");
    if (contact_model != ContactModel::nonsmooth)
      return;
    if (!lcp_solver_available())
      input.fail("Contact/Model", "nonsmooth is not available in this build: " +
                                    lcp_solver_description());
    if (method != TimeIntegrationMethod::newmark)
      input.fail("Contact/Model", "nonsmooth is stepped by Moreau-Jean's scheme: not with Time "
                                  "integration/Method = " +
                                    time_integration_method_names().name(method));
    if (partition != RunPartition::none)
      input.fail("Contact/Model", "nonsmooth does not take Time integration/Partition = " +
                                    run_partition_names().name(partition) + " yet");
  }
} // namespace poundfe
