#include <poundfe/dynamics/modal.h>
#include <poundfe/base/exceptions.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace poundfe
{
  const char *const stiffness_not_positive_definite =
    "modal analysis: the stiffness matrix is singular or not positive definite (is the "
    "structure a mechanism? check the supports)";

  double
  Modes::frequency(const unsigned int i) const
  {
    return omega[i] / (2 * M_PI);
  }

  double
  Modes::period(const unsigned int i) const
  {
    return 2 * M_PI / omega[i];
  }

  unsigned int
  max_sparse_modes(const SparseMatrix &mass)
  {
    return (mass.diagonal().array() != 0).count();
  }

  unsigned int
  lanczos_mode_limit(const SparseMatrix &mass)
  {
    const Eigen::Index basis = std::min<Eigen::Index>(max_sparse_modes(mass), mass.rows() - 1);
    return basis >= 4 ? (basis - 2) / 2 : 0;
  }

  Eigensolver
  choose_eigensolver(const Eigensolver requested, const SparseMatrix &mass, const unsigned int n)
  {
    if (requested != Eigensolver::automatic)
      return requested;
    return mass.rows() > dense_eigensolver_limit && n <= lanczos_mode_limit(mass) ?
             Eigensolver::sparse :
             Eigensolver::dense;
  }

  void
  append_mode(Modes &modes, Eigen::VectorXd phi, const double omega, const SparseMatrix &mass,
              const Vector &influence)
  {
    phi /= std::sqrt(phi.dot(mass * phi));
    // A sign convention makes shapes comparable between runs and solvers.
    Eigen::Index largest;
    phi.cwiseAbs().maxCoeff(&largest);
    if (phi[largest] < 0)
      phi = -phi;
    const Eigen::Index column = modes.shapes.cols();
    modes.shapes.conservativeResize(phi.size(), column + 1);
    modes.shapes.col(column) = phi;
    modes.omega.push_back(omega);
    modes.participating_mass_ratio.push_back(participating_mass_ratio(phi, mass, influence));
  }

  double
  participating_mass_ratio(const Eigen::VectorXd &phi, const SparseMatrix &mass,
                           const Vector &influence)
  {
    const double total = influence.dot(mass * influence);
    const double gamma = phi.dot(mass * influence);
    return total > 0 ? gamma * gamma / total : 0;
  }

  void
  add_plan_participation(Modes &modes, const SparseMatrix &mass, const Vector &influence_y,
                         const Vector &influence_rz)
  {
    modes.participating_mass_ratio_y.clear();
    modes.participating_mass_ratio_rz.clear();
    for (unsigned int i = 0; i < modes.n_modes(); ++i)
      {
        const Eigen::VectorXd phi = modes.shapes.col(i);
        modes.participating_mass_ratio_y.push_back(participating_mass_ratio(phi, mass, influence_y));
        modes.participating_mass_ratio_rz.push_back(
          participating_mass_ratio(phi, mass, influence_rz));
      }
  }

  Modes
  compute_modes(const SparseMatrix &mass, const SparseMatrix &stiffness, const Vector &influence,
                const unsigned int n, const Eigensolver solver)
  {
    if (choose_eigensolver(solver, mass, n) == Eigensolver::sparse)
      return compute_modes_sparse(mass, stiffness, influence, n);
    return compute_modes_dense(mass, stiffness, influence, n);
  }

  Modes
  compute_modes_dense(const SparseMatrix &mass, const SparseMatrix &stiffness,
                      const Vector &influence, const unsigned int n)
  {
    const Eigen::MatrixXd m(mass), k(stiffness);
    Eigen::LLT<Eigen::MatrixXd> cholesky(k);
    if (cholesky.info() != Eigen::Success)
      throw NumericalError(stiffness_not_positive_definite);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      m, k, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
    if (solver.info() != Eigen::Success)
      throw NumericalError("modal analysis: the eigensolver did not converge");

    const Eigen::VectorXd &mu     = solver.eigenvalues(); // ascending
    const double           mu_max = mu.size() ? mu.maxCoeff() : 0;
    Modes                  modes;
    modes.shapes.resize(m.rows(), 0);
    for (int i = mu.size() - 1; i >= 0 && modes.n_modes() < n; --i)
      if (mu[i] > 1e-12 * mu_max)
        append_mode(modes, solver.eigenvectors().col(i), 1 / std::sqrt(mu[i]), mass, influence);
    return modes;
  }
} // namespace poundfe
