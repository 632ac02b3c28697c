// The analysis of an OpenSees script's domain, with OpenSees 3.8's
// algorithms so that a script gives its numbers: the integrators Newmark
// (displacement predictor, Newmark.cpp), HHT (HHT.cpp: Newmark's predictor
// with gamma = 3/2 - alpha, beta = (2 - alpha)^2/4; the elements, the
// damping and the loads at t + alpha dt, U_alpha = (1 - alpha) U_n + alpha
// U, V_alpha likewise, the inertia at t + dt; tangent alpha K + alpha c2 C
// + c3 M; the elements set at U_n+1 before the commit), LoadControl and DisplacementControl
// (DisplacementControl.cpp: newStep's predictor and update's correction of
// each iterate), the algorithms
// Linear, Newton and ModifiedNewton (NewtonRaphson.cpp: tangent, solve,
// update, new residual, test), NewtonLineSearch with the
// InitialInterpolated search (NewtonLineSearch.cpp,
// InitialInterpolatedLineSearch.cpp: s0 = -dU . R before the update; unless
// the test is met, s = -dU . R after it, and while |s/s0| > tol, eta *= s0 /
// (s0 - s) within [minEta, maxEta] (1 where |s/s0| grew), the state moved
// by (eta - eta_prev) dU and s = dU . R (OpenSees's sign); the test then sees
// eta dU), KrylovNewton as OpenSees 3.8's Tcl command makes it
// (AcceleratedNewton.cpp with KrylovAccelerator.cpp, Carlson and Miller's
// accelerated modified Newton: one tangent a step; each solution r_k of
// K dU = R is corrected by the least-squares fit of its difference to the
// earlier ones, v_k = r_k + sum c_j (v_j - (r_j - r_j+1)), c minimising
// |A c - r_k| with A's columns r_j - r_j+1; the state moves by v_k, the test
// sees r_k; after maxDim + 1 iterations a new tangent empties the
// subspace), BFGS (BFGS.cpp: each tangent solves and applies one Newton
// increment s_1, then up to -count quasi-Newton increments du_n = K^-1 R_n
// corrected by the BFGS product of the earlier s_i and z_i = K^-1 (R_i-1 -
// R_i), with s_i . (R_i-1 - R_i) and z_i . (R_i-1 - R_i); an inner copy of
// the test with -count iterations ends that sequence, the script's test then
// judges it once per tangent, with the last solution of the system, K^-1
// (R_n-1 - R_n), as its displacement increment, as OpenSees's does), the
// tests NormDispIncr (|dU|), NormUnbalance
// (|R| after the update) and EnergyIncr (|dU . R| / 2), a failed step
// reverted to the last commit and reported by the return value, as
// `analyze` does. No step is cut and no event located unless the script
// asks (poundfe::stepCutting, poundfe::locateEvents; off by default).
// poundfe::locateEvents applies `poundfe run`'s Event refinement
// (integration/newmark.h) to `analyze n dt` of a transient analysis: a
// converged step in which a gap's contact starts or ends is reverted and
// redone as its two halves, each of which is treated so again, down to
// dt/2^R, so that each event lies in a sub-step of dt/2^R and every other
// sub-step is as long as it can be; a step that fails meanwhile is halved
// the same way (it cannot tell whether a contact began in it).
// Equations (OpenSees's, with c2 = gamma/(beta dt), c3 = 1/(beta dt^2)):
//   R = P(t) - sum_e (f_e + C_e v_e) - M (a + r a_g(t)) - alpha_M M v,
//   K_eff = sum_e (K_e + c2 C_e) + (c3 + c2 alpha_M) M,
// C_e = beta_K K_e + beta_K0 K_e,0 + beta_Kc K_e,c for Rayleigh-damped
// elements and the materials' damping tangents for the others.
// K_eff is solved by LU with partial pivoting on a dense matrix up to
// dense_equation_limit equations (as OpenSees's BandGeneral, LAPACK's
// dgbsv), above by LAPACK's banded LU (a banded system) or UMFPACK, with the
// numbering or symbolic analysis kept while the equations stay; the work
// vectors keep their storage between iterations.
#ifndef poundfe_opensees_opensees_analysis_h
#define poundfe_opensees_opensees_analysis_h

#include <poundfe/assembly/small_lu.h>
#include <poundfe/opensees/opensees_domain.h>

#include <Eigen/LU>
#include <Eigen/SparseCore>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace poundfe
{
  class LinearSolver;

  namespace opensees
  {
    struct ConvergenceTest
    {
      enum class Kind
      {
        norm_disp_incr,
        norm_unbalance,
        energy_incr,
        /// |dx| over the step's first |dx| (CTestRelativeNormDispIncr)
        relative_norm_disp_incr
      } kind                     = Kind::norm_unbalance;
      double       tolerance      = 1e-6; // OpenSees's default test
      unsigned int max_iterations = 25;
      int          print_flag     = 0; // 0, 1 (print each iteration), 2 (convergence), 5 (go on)
    };

    struct AnalysisOptions
    {
      enum class Algorithm
      {
        linear,
        newton,
        modified_newton,
        newton_line_search,
        krylov_newton,
        bfgs
      } algorithm = Algorithm::newton;
      /// BFGS's -count: the quasi-Newton increments on one tangent.
      unsigned int bfgs_count = 10;
      /// KrylovNewton's -maxDim: the iterations accelerated by one tangent.
      unsigned int krylov_dimension = 3;
      ConvergenceTest test;
      /// NewtonLineSearch's InitialInterpolated search: -tol, -maxIter,
      /// -minEta, -maxEta, and -pFlag 0 (print each search iteration).
      struct LineSearch
      {
        double       tolerance = 0.8, min_eta = 0.1, max_eta = 10;
        unsigned int max_iterations = 10;
        bool         print          = false;
      } line_search;
      bool            transient = false;
      /// analysis VariableTransient (OpenSees's
      /// VariableTimeStepDirectIntegrationAnalysis): `analyze n dt dtMin
      /// dtMax Jd` varies the step.
      bool            variable_time_step = false;
      double          gamma = 0.5, beta = 0.25;       // Newmark
      double          alpha = 1; // HHT's (OpenSees's convention: 1 is Newmark)
      /// HHT (any alpha): modal damping takes the velocity at t + dt and
      /// stays out of the tangent (OpenSees 3.8's HHT::getVel, no getCFactor).
      bool hht = false;
      double          d_lambda = 1, lambda_min = 1, lambda_max = 1; // LoadControl
      double          lambda_iterations = 1;
      /// DisplacementControl (DisplacementControl.cpp) in place of
      /// LoadControl: node, DOF (0-based), increment, Jd, min, max. Each
      /// step predicts with the reference load phat = R(lambda + 1) at the
      /// state where the integrator first analyses (the unbalance of the
      /// patterns at unit factor), then corrects each Newton iterate by
      /// dU = dUbar + dlambda dUhat with dlambda = -dUbar_c / dUhat_c, so
      /// that the controlled DOF moves by exactly the increment.
      bool            displacement_control = false;
      int             control_node = 0;
      unsigned int    control_dof = 0;
      double          d_u = 0, d_u_min = 0, d_u_max = 0, d_u_iterations = 1;
      /// ArcLength s alpha (ArcLength.cpp) in place of LoadControl.
      bool            arc_length = false;
      double          arc_s = 0, arc_alpha = 1;
      /// Counts the script's `integrator` commands: a new one starts a
      /// fresh integrator (its increment, its reference load).
      unsigned int    integrator_serial = 0;
      /// constraints Transformation: an sp command imposes its value;
      /// Plain (OpenSees's PlainHandler) holds the DOF at zero, with a warning.
      bool            transformation = false;
      /// constraints Penalty alphaSP alphaMP (PenaltyConstraintHandler):
      /// every DOF an equation, each fix and sp a spring alphaSP to its
      /// value, each equalDOF, rigidLink bar and rigidDiaphragm row c . u = 0
      /// the stiffness alphaMP c c^T (opensees_penalty.cc).
      bool            penalty = false;
      double          alpha_sp = 0, alpha_mp = 0;
      /// constraints Lagrange: Transformation's displacements; ArcLength and
      /// an adaptive DisplacementControl are refused with it (OpenSees's
      /// multipliers enter their norms).
      bool            lagrange = false;
      /// system BandGeneral, BandSPD or ProfileSPD: LAPACK's banded LU after
      /// a Cuthill-McKee numbering (assembly/band_lu_solver.h); any other
      /// system: UMFPACK. Either above dense_equation_limit equations only.
      bool            banded_system = false;
    };

    /// What the analyses of a script have done (poundfe::report).
    struct AnalysisCounts
    {
      unsigned long steps = 0, iterations = 0, factorizations = 0, failed_steps = 0;
    };

    class UniaxialLinks;
    class ContactEvents;

    class Analysis
    {
    public:
      /// The largest system solved dense: at a few dozen equations LU on a
      /// dense matrix costs less than a sparse factorisation's bookkeeping.
      static constexpr unsigned int dense_equation_limit = 32;
      /// The equation of a rigid tie's first combination (see combinations).
      static constexpr int first_combination = -1000000;

      Analysis(Domain &domain, AnalysisOptions options);
      ~Analysis();

      /// `analyze n <dt>`: 0 when every step converged; otherwise the
      /// domain is back at the last committed step and the result is < 0
      /// (OpenSees: -3), after `warn` was told why. `after_step` runs after
      /// each committed step (the recorders).
      int analyze(unsigned int n_steps, double dt, const std::function<void()> &after_step,
                  const std::function<void(const std::string &)> &warn);
      /// poundfe::stepCutting: a step of `analyze n dt` that fails is
      /// tried again from where it failed in sub-steps of dt/2, dt/4, ...
      /// dt/2^max_cuts (each committed and recorded as it converges), before
      /// analyze gives up; 0 (OpenSees's behaviour) by default.
      unsigned int max_cuts = 0;
      /// poundfe::locateEvents: the most halvings R of a transient step of
      /// `analyze n dt` with a contact event, and the gaps watched (null
      /// and 0, OpenSees's behaviour, by default; null while R is 0).
      unsigned int   event_levels = 0;
      ContactEvents *events       = nullptr;

      /// `analyze n dt dtMin dtMax Jd` of a VariableTransient analysis
      /// (VariableTimeStepDirectIntegrationAnalysis::analyze): steps until
      /// their sum reaches n dt, each next one the last times Jd over the
      /// test's iterations (determineDt), within [dtMin, dtMax]; a failed
      /// step is reverted and tried again shorter, and ends the analysis
      /// (-3) when it was not longer than dtMin.
      struct VariableSteps
      {
        unsigned int n_steps = 0;
        double       dt = 0, dt_min = 0, dt_max = 0;
        int          jd = 1;
      };
      int analyze_variable(const VariableSteps &steps, const std::function<void()> &after_step,
                           const std::function<void(const std::string &)> &warn);

      /// The lowest n eigenvalues omega^2 of K_t phi = omega^2 M phi.
      std::vector<double> eigenvalues(unsigned int n);

      const AnalysisOptions &options() const { return opts; }
      /// The script changed the test, algorithm or integrator of this analysis.
      void configure(const AnalysisOptions &options);
      AnalysisCounts         counts;
      /// The script's test at the last step that ran it (testIter,
      /// testNorm: CTest's currentIter and norms, maxIter of them, those
      /// not reached 0).
      unsigned int        test_iterations = 0;
      std::vector<double> test_norms;
      /// RelativeNormDispIncr's first norm of the step, of the script's test
      /// and of BFGS's inner copy.
      std::array<double, 2> first_norms{{0, 0}};

    private:
      void   number();
      void   gather();
      void   scatter();
      bool   set_trial(std::string &why);
      /// R at the trial state, in `unbalance` (valid until the next call).
      const Vector &residual();
      /// r -= the elements' forces (with their Rayleigh damping's C_e v_e).
      void   subtract_element_forces(Vector &r, const Vector &v);
      void   assemble_tangent(double c_k, double c_c, double c_m);
      /// K_eff's entries into the dense matrix or the triplets.
      void   add_element_tangents(double c_k, double c_c);
      /// x = K_eff^-1 b with the last factorisation.
      void   solve(const Vector &b, Vector &x);
      bool   dense() const { return n_equations > 0 && n_equations <= dense_equation_limit; }
      /// Up to SmallLU::max_size equations the dense LU is SmallLU's:
      /// Eigen's arithmetic in fixed storage.
      bool   small() const { return n_equations <= SmallLU::max_size; }
      /// The elements in the domain's order with their Rayleigh factors
      /// and whether a diaphragm's combination is among their equations,
      /// and the typed loops of a small model, after number(); at every
      /// analyze the Rayleigh factors alone (`rayleigh` may have changed).
      void   list_elements(bool renumbered);
      bool   step(double dt, std::string &why);
      /// The checks and settings every `analyze` starts with.
      void   begin_analysis(const std::function<void(const std::string &)> &warn);
      /// One step of dt from the committed state, committed; false (why
      /// said, the elements reverted) when it failed, or (`event` given
      /// and set) when it converged with a contact event.
      bool   advance(double dt, std::string &why, bool *event = nullptr);
      /// The two halves, at `depth` halvings of the script's step, of a
      /// step of dt that had an event or failed (poundfe::locateEvents):
      /// each committed and recorded, or while depth < event_levels halved
      /// again when it too has an event or fails, at event_levels cut
      /// when it fails (max_cuts); false, with why, when that failed.
      bool   advance_in_halves(double dt, unsigned int depth,
                               const std::function<void()> &after_step, std::string &why);
      /// The rest of a failed step of dt in ever halved sub-steps
      /// (max_cuts); false, with why, when the finest fails.
      bool   cut_step(double dt, const std::function<void()> &after_step, std::string &why);
      /// DisplacementControl's predictor (newStep).
      bool   displacement_step(std::string &why);
      /// DisplacementControl's corrector of a Newton iterate dx (update).
      bool   correct_displacement(Vector &dx, std::string &why);
      /// A static predictor's dUhat = K^-1 phat, K at the committed state.
      bool   reference_displacement(Vector &dx_hat, std::string &why);
      /// The predictor's load increment and displacements, then the iterations.
      bool   predict_and_iterate(double d_lambda, const Vector &dx, std::string &why);
      /// ArcLength's predictor (newStep) and corrector (update), in
      /// opensees_arc_length.cc.
      bool   arc_length_step(std::string &why);
      bool   correct_arc_length(Vector &dx, std::string &why);
      /// phat = R at the committed state and the factor lambda + 1.
      void   reference_load();
      int    iterate(std::string &why);
      /// BFGS's iterations of a step (BFGS::solveCurrentStep).
      int    iterate_bfgs(std::string &why);
      /// The test's verdict on an iterate, with at most max_iterations: the
      /// iteration when it converged (or goes on past the limit, print flag
      /// 5), 0 to iterate again, -1 (with why) when it failed.
      int    judge(unsigned int iteration, unsigned int max_iterations, const Vector &dx,
                   const Vector &r, std::string &why, bool script_test = true);
      /// U += dx with V, A (Newmark's or HHT's update) and the elements at
      /// the evaluation point.
      bool   apply_increment(const Vector &dx, std::string &why);
      /// InitialInterpolatedLineSearch::search; dx becomes eta dx, r the
      /// residual there.
      bool   line_search(double s0, Vector &dx, Vector &r, std::string &why);
      /// HHT: U_alpha, V_alpha from U_n, V_n and the trial U, V.
      void   update_alpha_point();
      double test_norm(const Vector &dx, const Vector &r) const;
      /// Whether NewtonLineSearch's own copy of the test (its theOtherTest,
      /// started afresh at every iteration) is met by the Newton step.
      bool   fresh_test_met(const Vector &dx, const Vector &r) const;
      /// The test's line of print flag 1 (each iteration) or 2 (convergence).
      void   print_iteration(unsigned int iteration, double norm) const;
      void   commit();
      /// After a failed step: the elements reverted and updated at the
      /// committed displacements (OpenSees's Domain::revertToLastCommit).
      void   revert_to_last_commit();

      Domain         &domain;
      AnalysisOptions opts;
      unsigned int    n_equations = 0;
      Vector          U, V, A;             // trial response by equation
      Vector          U_n, V_n;            // HHT: the step's start
      Vector          U_alpha, V_alpha;    // HHT: where elements are evaluated
      bool            at_alpha = false;    // HHT's iterations: elements at U_alpha
      double          step_dt  = 0;
      Vector          mass_of_equation;    // lumped nodal masses
      /// alpha_M M by equation, when alpha_M differs between masses
      /// (Domain::uniform_mass_damping false; else domain.rayleigh's times M).
      Vector          mass_damping_of_equation;
      bool            uniform_mass_damping = true;
      /// A node's mass on an equation, along its DOF (the ground
      /// acceleration's component), in the nodes' order.
      struct InertiaTerm
      {
        int          equation;
        unsigned int dof;
        double       mass;
      };
      std::vector<InertiaTerm> inertia_terms;
      /// The second ground-motion load of the masses that take it twice
      /// (Domain::LumpedMass::ground_load_twice), after the inertia terms.
      std::vector<InertiaTerm> second_ground_terms;
      /// Whether an element takes beam loads (the residual applies them).
      bool            beam_loads_taken = false;
      /// The ground acceleration at ground_time (per DOF), the residual's
      /// iterations at one time sharing it.
      std::vector<double> ground;
      double              ground_time  = 0;
      bool                ground_known = false;
      /// The residual's, the iterations' and the step's vectors, their
      /// storage kept.
      Vector          unbalance, iteration_residual, iteration_increment, step_velocity;
      /// The DOFs the sp commands impose (node, 0-based DOF) and their
      /// values at the trial time.
      std::vector<std::pair<int, unsigned int>> imposed_dofs;
      /// A DOF a rigid tie constrains (or an equalDOF ties to one) has the
      /// equation first_combination - j: the j-th combination, sum c_k x[e_k].
      std::vector<std::vector<std::pair<int, double>>> combinations;
      /// The equalDOFs' constrained DOFs and their retained DOFs.
      using DofMap = std::map<std::pair<int, unsigned int>, std::pair<int, unsigned int>>;
      /// The constrained DOFs of the equalDOFs and rigid ties (in number()),
      /// in dependency order.
      void number_ties(const DofMap &retained_by);
      /// One rigid tie's combinations, its retained DOFs numbered.
      void number_tie(const RigidTie &tie);
      /// Penalty's rows (in number(), every DOF an equation): a fix, an sp
      /// (its value by its node and DOF) or a row of a multi-point constraint.
      struct PenaltyRow
      {
        std::vector<std::pair<int, double>> terms; // equation, coefficient
        double                              alpha = 0;
        std::pair<int, unsigned int>        imposed{0, 0};
        bool                                is_imposed = false;
      };
      std::vector<PenaltyRow> penalty_rows;
      void number_penalty();
      /// r += alpha c (g(t) - c . u) for each row, u at the elements' point.
      void add_penalty_forces(Vector &r);
      /// alpha c c^T into K_eff (OpenSees's Penalty FE: unscaled by c_k).
      void add_penalty_tangent();
      /// mass_of_equation, inertia_terms and second_ground_terms (in number()).
      void number_inertia();
      /// mass_damping_of_equation and uniform_mass_damping (in number()).
      void number_mass_damping();
      /// The consistent masses by equation (-1: fixed), their alpha_M (0
      /// unless the element is Rayleigh-damped) and matrices (in number()).
      struct CoupledMass
      {
        std::vector<int>          equations;
        std::vector<unsigned int> dofs; // each row's DOF at its node
        const Matrix             *matrix = nullptr;
        double                    alpha_m = 0;
        double                    n_ground_loads = 1; // ConsistentMass::ground_load_twice: 2
      };
      std::vector<CoupledMass> coupled_masses;
      Vector                   coupled_work; // the residual's local storage
      void                     number_coupled_masses();
      /// r -= M_e (A + alpha_M v + n r a_g) of the consistent masses.
      void subtract_coupled_inertia(Vector &r, const Vector &v);
      /// (c_m + c_c alpha_M) M_e of the consistent masses into the tangent.
      void add_coupled_masses(double c_m, double c_c);
      /// M x with the consistent masses (the modes' M).
      Vector mass_times(const Vector &x) const;
      /// OpenSees 3.8's modal damping (IncrementalIntegrator::
      /// addModalDampingForce, addModalDampingMatrix): C = W diag(c) W^T,
      /// W's columns M phi_i, c_i = 2 zeta_i omega_i; renewed from the
      /// domain's modes when they or the equations change.
      Matrix       modal_mass_shapes;
      Vector       modal_coefficients;
      unsigned int modal_stamp_seen = 0;
      bool         modal_numbered   = false;
      /// The nodes' equations when M phi was formed: a renumbering that
      /// keeps them keeps M phi (OpenSees forms it anew only on new modes).
      std::vector<int> modal_equations;
      /// Whether modal damping acts (its vectors renewed first).
      bool modal_damping_active();
      /// Whether c_c times the modal damping matrix joins the tangent
      /// (modalDamping, not Q; not HHT, whose getCFactor is OpenSees's 0).
      bool modal_damping_in_tangent(double c_c);
      /// The domain's M-normalised modes from the solution of `eigen`.
      void keep_modes(const Matrix &shapes, const std::vector<double> &eigenvalues);
      /// r[e] += c value for the equation's terms (none where fixed or imposed).
      void add_to(Vector &r, int eq, double value) const;
      /// An equation's terms: itself, or a diaphragm's combination.
      std::vector<std::pair<int, double>> terms(int eq) const;
      Vector                                    imposed_u;
      double          trial_time = 0, lambda_step = 0, last_iterations = 1;
      double          c_c = 0, c_m = 0;    // the step's update coefficients
      double          k_k = 1, k_c = 0;    // the tangent's K and C factors (HHT: alpha, alpha c_c)
      Eigen::SparseMatrix<double>   tangent_matrix;
      std::vector<Eigen::Triplet<double>> tangent_entries; // its storage kept
      Matrix                        dense_tangent;       // K_eff of a small system
      Eigen::PartialPivLU<Matrix>   dense_factors;
      SmallLU                       small_factors;       // up to SmallLU::max_size
      struct ListedElement
      {
        Element               *element;
        const RayleighFactors *rayleigh;
        bool                   combined; // some equation a diaphragm's combination
      };
      std::vector<ListedElement> element_list;
      /// Whether set_trial evaluates the elements over deal.II's threads
      /// (list_elements decides: more than one thread and at least 8
      /// costly elements).
      bool elements_on_threads = false;
      /// A small model's elements, all UniaxialRows without Rayleigh
      /// damping, in typed loops (null otherwise; list_elements decides).
      std::unique_ptr<UniaxialLinks> links;
      /// Whether a pattern has nodal loads (else the residual takes none).
      bool nodal_loads_given = true;
      const std::map<int, std::vector<double>> no_nodal_loads;
      /// Each element's local displacements and velocities (set_trial's
      /// arguments), by the elements' order, and its tangent and damping.
      std::vector<std::pair<Vector, Vector>> element_state;
      Matrix element_matrix, element_damping_matrix, element_work_matrix;
      Vector                        element_force, element_velocity;
      std::unique_ptr<LinearSolver> solver;
      std::function<void(const std::string &)> print; // analyze's `warn`
      bool                          analysed = false; // the solver saw the pattern
      bool                          numbered = false; // this analysis numbered the domain
      Vector                        phat;                // DisplacementControl's reference load
      double                        d_u_step = 0;       // its current increment
      int                           control_equation = -1;
      bool                          fresh_integrator = true;
      /// ArcLength's step so far: Delta U and Delta lambda (its sign the
      /// next predictor's).
      Vector                        arc_u_step;
      double                        arc_lambda_step = 0;
    };
  } // namespace opensees
} // namespace poundfe

#endif
