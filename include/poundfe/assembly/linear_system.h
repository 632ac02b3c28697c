// The linear part of the equations of motion on the free DOFs (equations):
// M, K and C = sum_b (a0_b M_b + a1_b K_b) + storey dashpots. Assembled once.
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

  struct LinearSystem
  {
    SparseMatrix mass;
    SparseMatrix stiffness;
    SparseMatrix damping;
    /// Influence vector of a horizontal ground motion: 1 on every ux equation.
    Vector influence;
    /// Rayleigh coefficients (a0, a1) used for each building.
    std::vector<std::array<double, 2>> rayleigh;

    unsigned int n_equations() const { return stiffness.rows(); }
  };

  /// Assemble M and K (and the influence vector); C is left empty.
  LinearSystem assemble_mass_and_stiffness(const Model &model);

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
