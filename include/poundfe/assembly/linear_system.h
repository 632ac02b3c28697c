// The linear part of the equations of motion on the free DOFs (equations):
// M, K and C = sum_b (a0_b M_b + a1_b K_b) + storey dashpots. Assembled once.
// With P-Delta (Model::geometric_nonlinearity) K = K_E + K_G: the geometric
// stiffness of the gravity loads f_g = -g M r_y (r_y = 1 on every uy: the
// floor weights, and the members' self-weight as M distributes it), linearised
// about the undeformed shape. Members: the consistent k_G of their axial
// force N under f_g in a linear static analysis K_E u = f_g (statics, not
// tributary areas: beams shed load to the columns as the frame deforms).
// Shear-building storeys: -P/h [1 -1; -1 1] on the two floors' ux, P the
// weight of the floors above the storey (the overturning P Delta balanced by
// a storey shear P Delta / h).
// Dimension 3: each resisting plane adds k a a^T (a its PlaneLink
// coefficients) and each floor its polar moment on θz (doc/theory.md §1.12).
// Sources: Przemieniecki (1968) (geometric stiffness); McGuire, Gallagher & Ziemian, Matrix
// Structural Analysis, 2nd ed. (2000), §9.3; Wilson & Habibullah, Earthquake
// Spectra 3 (1987) 289-298 (the linearised P-Delta of buildings).
#ifndef poundfe_assembly_linear_system_h
#define poundfe_assembly_linear_system_h

#include <poundfe/model/model.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace poundfe
{
  using SparseMatrix = Eigen::SparseMatrix<double>;
  using Vector       = Eigen::VectorXd;

  /// The modal part of C, U diag(weights) U^T (assembly/modal_damping.h):
  /// U = M Phi (n x m, dense; zero outside each damped building's rows),
  /// weights 2 zeta_i omega_i. Empty without modal damping.
  struct LowRankDamping
  {
    Eigen::MatrixXd factor;
    Vector          weights;

    bool empty() const { return weights.size() == 0; }
  };

  struct LinearSystem
  {
    SparseMatrix mass;
    SparseMatrix stiffness; // K_E, plus K_G with P-Delta
    /// K_G, the P-Delta part of `stiffness` (0 x 0 without P-Delta).
    SparseMatrix geometric_stiffness;
    SparseMatrix damping; // Rayleigh and storey dashpots
    /// With compliant foundations (empty without): M and K without the
    /// foundations' terms, the superstructure's, for its Rayleigh damping.
    SparseMatrix structure_mass, structure_stiffness;
    /// Modal damping (Damping/Type = modal or bands): C = damping + this.
    LowRankDamping modal_damping;
    /// Influence vector of a horizontal ground motion: 1 on every ux equation.
    Vector influence;
    /// Dimension 3 (empty in 2D): 1 on every uy (plan) equation, and 1 on
    /// every θz equation (the rotation about Z, for effective modal masses).
    Vector influence_y, influence_rz;
    /// Influence vector of a vertical ground motion: 1 on every vertical
    /// translation, uz of each 3D frame joint (Model/Dimension = 3) or uy
    /// of each node (2D); 0 on a shear building's floors, which have none.
    Vector influence_z;
    /// Rayleigh coefficients (a0, a1) used for each building.
    std::vector<std::array<double, 2>> rayleigh;

    unsigned int n_equations() const { return stiffness.rows(); }
  };

  /// The equations [first, last).
  using EquationRange = std::array<unsigned int, 2>;

  /// Assemble M and K (and the influence vector); C is left empty. With
  /// P-Delta, K includes K_G. Throws NumericalError if the gravity analysis
  /// meets a singular K_E (a mechanism).
  LinearSystem assemble_mass_and_stiffness(const Model &model);

  /// The same, with only the entries whose row and column are in `kept`:
  /// a rank's part of a model partitioned by building (doc/theory.md
  /// §3.5d), its buildings' M and K (P-Delta from their own gravity
  /// analysis), the other rows and columns empty; still n x n, the
  /// influence vectors whole. An entry joining `kept` to another equation
  /// (a coupling the partition missed) is a programming error.
  LinearSystem assemble_mass_and_stiffness(const Model &model, EquationRange kept);

  /// The building of each equation (the buildings' equations are
  /// consecutive and cover the model).
  std::vector<unsigned int> building_of_equations(const Model &model);

  /// Each pair of buildings (a < b, sorted) that an entry of M, K (with
  /// the foundations' and P-Delta's terms) or C joins, from the model's
  /// elements, without assembling: what a partition by building must keep
  /// on one rank. (C's Rayleigh terms and storey dashpots lie on M's and
  /// K's entries.)
  std::vector<std::array<unsigned int, 2>> coupled_buildings(const Model &model);

  /// The gravity loads -g M r_y on the equations (g = model.gravity), from
  /// every mass: nodal weights, and the members' self-weight as their mass
  /// matrix distributes it (lumped: mL/2 per end; consistent: also the end
  /// moments mL/12 of a beam); a member with a distributed self-weight
  /// (Member::weight_per_length) instead its consistent nodal loads when it
  /// is elastic, nothing when it is a fibre member (its element carries it). Dimension 3 (z up, r_z): the joints' vertical
  /// masses (DofMass) and the 3D members' self-weight through T_eᵀ.
  Vector gravity_loads(const Model &model);

  /// The consistent nodal loads of the fibre members' self-weight
  /// (Member::weight_per_length), which their elements carry as element
  /// loads and gravity_loads leaves out: what a report adds to the loads
  /// the structure carries.
  Vector member_element_loads(const Model &model);

  /// The Floor::gravity_load of every floor of a 2D frame, -q / n on uy
  /// of each of its n nodes (shear buildings have no vertical DOF: their
  /// floor loads act through storey_gravity_loads alone).
  Vector floor_loads(const Model &model);

  /// What the gravity analysis and P-Delta load the structure with:
  /// gravity_loads, plus floor_loads when a floor has one.
  Vector total_gravity_loads(const Model &model);

  /// Axial force (tension positive) of every member (Model::members, then
  /// Model::members_3d) at the displacements u.
  std::vector<double> member_axial_forces_at(const Model &model, const Vector &u);

  /// Axial force (tension positive) of every member (Model::members, then
  /// Model::members_3d) under `loads`, from the
  /// linear static analysis `stiffness` u = loads. Throws NumericalError if
  /// `stiffness` is not positive definite.
  std::vector<double> member_axial_forces(const Model &model, const SparseMatrix &stiffness,
                                          const Vector &loads);

  /// Compression P of every storey link: g times the nodal masses of its
  /// building at and above the link's top node, plus the floor loads there.
  std::vector<double> storey_gravity_loads(const Model &model);

  /// K_G of the members under `axial_forces` (tension positive) and of the
  /// storey links under `storey_compressions`.
  SparseMatrix geometric_stiffness(const Model &model, const std::vector<double> &axial_forces,
                                   const std::vector<double> &storey_compressions);

  /// Whether a symmetric matrix has a Cholesky factor.
  bool is_positive_definite(const SparseMatrix &matrix);

  /// a0 = 2 zeta w_i w_j / (w_i + w_j), a1 = 2 zeta / (w_i + w_j)
  /// (Chopra, Dynamics of Structures, eq. 11.4.9).
  std::array<double, 2> rayleigh_coefficients(double damping_ratio, double omega_i,
                                              double omega_j);

  /// C = sum over buildings of a0_b M_b + a1_b K_b, plus storey dashpots.
  /// `coefficients[b]` are building b's (a0, a1).
  void assemble_damping(const Model &model, const std::vector<std::array<double, 2>> &coefficients,
                        LinearSystem &system);

  /// The rows and columns [first, last) of a matrix (one building's block).
  SparseMatrix block(const SparseMatrix &matrix, std::array<unsigned int, 2> range);
} // namespace poundfe

#endif
