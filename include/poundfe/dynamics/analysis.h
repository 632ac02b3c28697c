// Everything a command needs before it starts: prm -> Model -> M, K ->
// per-building modes -> Rayleigh C. Built once; read-only afterwards.
#ifndef poundfe_dynamics_analysis_h
#define poundfe_dynamics_analysis_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/base/console.h>
#include <poundfe/base/input_file.h>
#include <poundfe/dynamics/modal.h>
#include <poundfe/dynamics/modal_parameters.h>
#include <poundfe/model/contact_parameters.h>
#include <poundfe/model/friction_parameters.h>
#include <poundfe/model/model.h>
#include <poundfe/model/parameters.h>
#include <poundfe/output/json_writer.h>

#include <string>
#include <vector>

namespace poundfe
{
  /// The state of Model/Gravity analysis = static (dynamics/gravity_state.cc):
  /// what every time history of the model starts from, the loads held.
  struct GravityState
  {
    bool active = false;
    /// The committed displacements of every load step (restore_static_state
    /// brings a fresh set of elements to the gravity state through them).
    std::vector<Vector> path;
    /// The load factor of each (the elements' own loads: self-weight).
    std::vector<double> path_factors;
    /// u_g, the last of them.
    Vector displacement;
    /// The gravity loads applied (total_gravity_loads).
    Vector applied;
    /// K u_g + f(u_g): the load held constant through the dynamics, equal to
    /// `applied` to the tolerance; the equations at t = 0 are in equilibrium
    /// to round-off with it.
    Vector held;
    /// The symmetric part of K + sum_e B_e D_e B_e^T at the gravity state
    /// (the modes' stiffness; the PDelta tangent is nonsymmetric).
    SparseMatrix tangent;
    /// The largest |u_g| of a translation, and its equation's name.
    double      peak_displacement = 0;
    std::string peak_where;
    /// Per building: the vertical load its structure carries to the base
    /// (the sum of the applied vertical loads on its free DOFs), N.
    std::vector<double> base_reactions;
    unsigned int steps = 0, iterations = 0, cuts = 0;
  };

  struct Analysis
  {
    Model              model;
    LinearSystem       system;
    /// Model/Gravity analysis = static: its state (inactive otherwise).
    GravityState       gravity;
    std::vector<Modes> building_modes; // for Rayleigh damping and reports
    Modes              modes;          // whole model
    /// Input that is valid but probably not what was meant (damping_warnings).
    std::vector<std::string> warnings;
  };

  /// The model of the input's sections (`input` names the file in messages
  /// and resolves mesh files), M and K, each building's modes (as many as
  /// Output/Number of modes = `n_modes` and its Rayleigh damping need, by
  /// `modal`'s eigensolver), C, and `n_modes` modes of the whole model.
  /// Throws InputError (bad input) or NumericalError (e.g. a mechanism).
  /// Says nothing: the warnings are in Analysis::warnings.
  Analysis prepare_analysis(const InputFile &input, const ModelParameters &model,
                            const ContactParameters &contact, const SpringParameters &springs,
                            const FrictionParameters &friction, const ModalParameters &modal,
                            unsigned int n_modes);

  /// One rank's Analysis of a model partitioned by building (doc/theory.md
  /// §3.5d): `model` (built whole: every rank has the topology) with M, K
  /// and C of the buildings [first, last) only, their rows and columns
  /// alone filled (assemble_mass_and_stiffness with those equations), the
  /// modes of those buildings (as many as their damping needs, at least
  /// `n_building_modes`), none of the others and none of the whole model.
  /// The checks and errors are those buildings'.
  Analysis prepare_analysis_of_buildings(const InputFile &input, Model model,
                                         const ModalParameters &modal,
                                         std::array<unsigned int, 2> buildings,
                                         unsigned int n_building_modes);

  /// Model/Gravity analysis = static: the load-controlled gravity analysis
  /// of the model on `analysis.system` (integration/static_analysis.h),
  /// into analysis.gravity; with P-Delta, K_G is then rebuilt from the
  /// members' axial forces at the gravity state and the state
  /// re-equilibrated on K_E + K_G. Nothing when the analysis is off.
  /// Throws NumericalError when a load step never converges.
  void set_gravity_state(Analysis &analysis);

  /// The stick spring and dashpot of each friction element from M and K:
  /// k_s = 1e4 K_ii when automatic (0 in the input), c_s = 2 sqrt(k_s M_ii)
  /// (i the element's ux equation). prepare_analysis sets them once; a
  /// realization whose M or K changes sets them again.
  void fit_stick_laws(const LinearSystem &system, Model &model);

  /// The suspicious damping choices of each building: Rayleigh damping
  /// fitted at a mode whose kinetic energy is mostly vertical (a beam or
  /// column mode of a frame, not a storey mode), mass-proportional damping
  /// alone (a1 = 0: the higher modes nearly undamped), given coefficients
  /// both 0 (no damping). (Entries of another Damping/Type: the model's
  /// warnings, model/entry_scope.h.)
  std::vector<std::string> damping_warnings(const Analysis &analysis);
} // namespace poundfe

#endif
