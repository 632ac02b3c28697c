// Gravity first (OpenSees: a load-controlled static analysis of the gravity
// pattern, then loadConst): the state every time history of the model starts
// from. With P-Delta the gravity analysis runs on K_E; the members' axial
// forces at its state give K_G (the linearised P-Delta of
// assembly/linear_system.h, now of the gravity state), and the state is
// re-equilibrated on K_E + K_G at the full load. The load held through the
// dynamics is the resisting force K u_g + f(u_g) of the end state, so that a
// run without excitation stays at u_g to round-off.
// The modes of the gravity state are those of the symmetric part of its
// tangent, K_s = (K_t + K_t^T)/2. K_t is nonsymmetric where a PDelta member's
// axial force varies on a drifted chord ((delta/L) g (dN/du)^T,
// elements/crd_transformation.h), and the symmetric eigensolvers read one
// triangle of what they are given, which would make the frequencies depend
// on the numbering. For K_t = K_s + A with A antisymmetric, phi^T A phi = 0:
// the eigenvalues of K_s are those of the linearised equations of motion
// M du'' + K_t du = 0 to second order in A (a 2-storey frame with self-weight:
// 3e-10 apart; OpenSees's eigen, which drops the term, 2.5e-7; doc/verification.md).
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/integration/static_analysis.h>
#include <poundfe/output/recorders.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    LoadControlSettings
    load_control_of(const GravityAnalysisSettings &g)
    {
      LoadControlSettings settings;
      settings.n_steps        = g.n_steps;
      settings.tolerance      = g.tolerance;
      settings.max_iterations = g.max_iterations;
      settings.max_step_cuts  = g.max_step_cuts;
      return settings;
    }

    /// (K + K^T)/2.
    SparseMatrix
    symmetric_part(const SparseMatrix &k)
    {
      SparseMatrix s = 0.5 * (k + SparseMatrix(k.transpose()));
      s.makeCompressed();
      return s;
    }

    /// P-Delta: K_G of the axial forces at u_g in K (and the structure's
    /// stiffness of compliant foundations), in place of the one of the
    /// linear gravity analysis.
    void
    rebuild_geometric_stiffness(const Model &model, const Vector &u_g, LinearSystem &system)
    {
      const SparseMatrix geometric = geometric_stiffness(
        model, member_axial_forces_at(model, u_g), storey_gravity_loads(model));
      system.stiffness = SparseMatrix(system.stiffness - system.geometric_stiffness) + geometric;
      system.stiffness.makeCompressed();
      if (system.structure_stiffness.rows() > 0)
        system.structure_stiffness =
          SparseMatrix(system.structure_stiffness - system.geometric_stiffness) + geometric;
      system.geometric_stiffness = geometric;
    }

    /// The peak translation of u_g and the vertical loads carried by each
    /// building's structure: the applied loads on its vertical translations,
    /// uy in 2D, a 3D frame joint's (or basemat's) uz in 3D (z is up there;
    /// a 3D shear building has none). The loads of the rigid floors' maps are
    /// already on their equations (gravity_loads), so the sum is the weight
    /// of every mass on a free DOF (and of the fibre members' self-weight,
    /// by its consistent nodal loads).
    void
    describe_gravity_state(const Model &model, GravityState &gravity)
    {
      const std::string vertical = model.dimension == 2 ? "uy" : "uz";
      gravity.base_reactions.assign(model.buildings.size(), 0.0);
      // the fibre members' self-weight is in their elements, not in `applied`
      const Vector carried = gravity.applied + member_element_loads(model);
      std::vector<char> seen(model.n_equations(), 0); // a hinge's two nodes share ux, uy
      int               peak = -1; // named once, after the search (a name scans the model)
      for (unsigned int dof = 0; dof < model.n_dofs(); ++dof)
        {
          const int eq = model.equation(dof);
          if (eq < 0 || seen[eq])
            continue;
          seen[eq] = 1;
          const unsigned int node      = dof / n_dofs_per_node;
          const std::string  component = node_components(model, node)[dof % n_dofs_per_node];
          if (!is_rotation(component) &&
              std::abs(gravity.displacement[eq]) > gravity.peak_displacement)
            {
              gravity.peak_displacement = std::abs(gravity.displacement[eq]);
              peak                      = eq;
            }
          if (component == vertical)
            gravity.base_reactions[model.nodes[node].building] -= carried[eq];
        }
      if (peak >= 0)
        gravity.peak_where = equation_name(model, peak);
    }
  } // namespace

  void
  set_gravity_state(Analysis &analysis)
  {
    const Model &model = analysis.model;
    if (!model.gravity_analysis.enabled)
      return;
    LinearSystem       &system   = analysis.system;
    GravityState       &gravity  = analysis.gravity;
    const bool          p_delta  = model.geometric_nonlinearity == GeometricNonlinearity::p_delta;
    const LoadControlSettings settings = load_control_of(model.gravity_analysis);
    gravity          = GravityState();
    gravity.active   = true;
    gravity.applied  = total_gravity_loads(model);
    NonlinearElements elements = make_nonlinear_elements(model);
    const SparseMatrix elastic =
      p_delta ? SparseMatrix(system.stiffness - system.geometric_stiffness) : system.stiffness;
    StaticState state;
    {
      StaticSolver solver(elastic, &elements);
      load_control(solver, gravity.applied, 0, 1, settings, "gravity analysis", state);
    }
    if (p_delta)
      {
        rebuild_geometric_stiffness(model, state.displacement, system);
        StaticSolver solver(system.stiffness, &elements);
        load_control(solver, gravity.applied, 1, 1, settings,
                     "gravity analysis (P-Delta of the gravity state)", state);
      }
    StaticSolver solver(system.stiffness, &elements);
    AssertThrow(solver.set_state(state.displacement),
                dealii::ExcMessage("an element refuses its committed state"));
    gravity.path         = std::move(state.path);
    gravity.path_factors = std::move(state.load_factors);
    gravity.displacement = state.displacement;
    gravity.held         = solver.resisting_force(gravity.displacement);
    gravity.tangent      = symmetric_part(solver.tangent());
    gravity.steps        = state.steps;
    gravity.iterations   = state.iterations;
    gravity.cuts         = state.cuts;
    describe_gravity_state(model, gravity);
  }
} // namespace poundfe
