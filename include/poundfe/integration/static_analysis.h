// Static equilibrium of the model with its nonlinear elements,
//   R(u) = p - K u - sum_e (f_e(u_e, 0) - K_ref,e u_e) = 0,
// by Newton-Raphson on the tangent K + sum_e B_e D_e B_e^T (D_e at c = 0:
// the elements' static tangent; elements/nonlinear_element.h), velocities 0.
// Load control (OpenSees's LoadControl + Newton): p = lambda p_ref with
// lambda in equal steps to 1, and the elements' own loads (element loads:
// a member's self-weight) at the same factor; a step that does not converge
// is halved, down to a given number of cuts. Each accepted step commits the elements; the
// sequence of committed displacements (the path) restores the same state in
// a fresh set of elements (restore_static_state), which is how the gravity
// state is handed to each time history: the elements are path dependent,
// and replaying their committed path reproduces them exactly.
// Path following (pushover): the load p = p_c + lambda p_ref with p_c
// constant (the gravity loads held) and lambda an unknown, by displacement
// control (OpenSees's DisplacementControl: lambda is found in each
// iteration so that the control DOF moves by the prescribed increment,
// Batoz & Dhatt 1979) or by arc length (Crisfield's cylindrical constraint
// ||Delta u|| = Delta l; the root of the quadratic for delta lambda nearest
// the previous increment's direction), which passes limit points and
// snap-backs of the control displacement.
// Sources: Crisfield, Non-linear Finite Element Analysis of Solids and
// Structures, vol. 1 (1991), §9.1-9.2; McKenna, Fenves & Scott, OpenSees
// (LoadControl, loadConst).
#ifndef poundfe_integration_static_analysis_h
#define poundfe_integration_static_analysis_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/model/model.h>

#include <functional>
#include <string>
#include <vector>

namespace poundfe
{
  /// Newton on the static equations of one stiffness K and the elements.
  class StaticSolver
  {
  public:
    /// `elements` may be null (a linear model); they are updated in place.
    StaticSolver(const SparseMatrix &stiffness, NonlinearElements *elements);

    /// r = load - K u - f(u), the elements set to the trial u (v = 0);
    /// false when an element refuses the state (failure() says which).
    bool residual(const Vector &load, const Vector &u, Vector &r);
    /// The tangent K + sum_e B_e D_e B_e^T at the last trial state.
    SparseMatrix tangent() const;
    /// K u + f(u) at the last trial state: what the structure resists with.
    Vector resisting_force(const Vector &u) const;
    /// Newton from `u` (the committed state) to R(u) = 0 under `load`:
    /// ||R|| <= tolerance * max(||load||, scale). On success u is the
    /// converged state, the elements at it (trial, not committed).
    bool newton(const Vector &load, Vector &u, double tolerance, double scale,
                unsigned int max_iterations);
    const SparseMatrix &stiffness_matrix() const { return stiffness; }
    /// Newton iterations of the last newton().
    unsigned int iterations() const { return last_iterations; }

    /// The elements set to the trial u (v = 0), no residual formed; false
    /// when an element refuses it.
    bool set_state(const Vector &u);
    /// The factor of the elements' own loads (a member's self-weight) from
    /// the next trial on: load control's lambda (0 to 1).
    void set_load_factor(double lambda);
    void commit();
    void revert();
    /// Why the last residual or newton failed (an element, a singular
    /// tangent, the iterations spent).
    const std::string &failure() const { return why; }
    /// The element that is farthest beyond its yield deformation at the
    /// trial state ("" without elements): where a failed analysis points.
    std::string most_strained_element(const Vector &u) const;

  private:
    /// The elements' local vectors of global u (0 on ground DOFs).
    void gather(const Vector &u);

    const SparseMatrix &stiffness;
    NonlinearElements  *elements;
    std::vector<unsigned int> dof_start;
    Vector              local_u, local_v, correction;
    std::string         why;
    unsigned int        last_iterations = 0;
  };

  /// The state a load-controlled static analysis ends in.
  struct StaticState
  {
    /// The committed displacements after each accepted step, in order, and
    /// the load factor of each (the elements' own loads follow it).
    std::vector<Vector> path;
    std::vector<double> load_factors;
    /// The last of them (0 before any step).
    Vector displacement;
    unsigned int steps = 0, iterations = 0, cuts = 0;
  };

  struct LoadControlSettings
  {
    unsigned int n_steps        = 10;
    double       tolerance      = 1e-8;
    unsigned int max_iterations = 25;
    unsigned int max_step_cuts  = 8;
  };

  /// Load control from lambda0 to lambda1 of p_ref in n_steps equal steps
  /// (each halved on failure, max_step_cuts times), starting from and
  /// appending to `state` (the elements committed at its displacement).
  /// Throws NumericalError naming `what`, the load factor reached, why and
  /// the most strained element when a step fails at its smallest size.
  void load_control(StaticSolver &solver, const Vector &p_ref, double lambda0, double lambda1,
                    const LoadControlSettings &settings, const std::string &what,
                    StaticState &state);

  struct PathSettings
  {
    double       tolerance      = 1e-8;
    unsigned int max_iterations = 25;
  };

  /// The committed point of a path: displacements and load factor, and the
  /// increment that led to it (the arc length's direction).
  struct PathPoint
  {
    Vector u;
    double lambda = 0;
    Vector increment;
    double lambda_increment = 0;
  };

  /// One step of a path under p_c + lambda p_ref from `point` (the elements
  /// committed there). On success `point` is the new committed state.
  class PathFollower
  {
  public:
    PathFollower(StaticSolver &solver, const Vector &constant_load, const Vector &reference_load,
                 const PathSettings &settings);
    /// Displacement control: u[control] moves by `increment`.
    bool displacement_step(unsigned int control, double increment, PathPoint &point);
    /// Arc length: ||Delta u|| = length, continuing in the direction of
    /// point.increment (the first step: where u[control] grows with
    /// `direction`'s sign).
    bool arc_length_step(double length, unsigned int control, double direction,
                         PathPoint &point);
    unsigned int iterations() const { return last_iterations; }
    /// Why the last step failed.
    const std::string &failure() const { return why; }

  private:
    /// Newton's residual at (u, lambda); false when an element refuses it.
    bool residual_at(const Vector &u, double lambda, Vector &r, double &target);
    /// T^-1 p_ref and T^-1 r on the tangent at the last trial state.
    bool solve_both(const Vector &r, Vector &du_reference, Vector &du_residual);
    /// The converged step committed into `point`.
    void accept(const Vector &u, double lambda, PathPoint &point);

    StaticSolver &solver;
    const Vector &constant_load, &reference_load;
    PathSettings  settings;
    unsigned int  last_iterations = 0;
    std::string   why;
  };

  /// Bring fresh (reset) elements to the state of `path`: each committed
  /// displacement set as a trial at v = 0 at its load factor and
  /// committed, in order.
  void restore_static_state(const std::vector<Vector> &path,
                            const std::vector<double> &load_factors,
                            NonlinearElements         &elements);
} // namespace poundfe

#endif
