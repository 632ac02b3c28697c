#include <poundfe/analysis/modal.h>
#include <poundfe/base/exceptions.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numeric>

namespace poundfe
{
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

  Modes
  compute_modes(const SparseMatrix &mass, const SparseMatrix &stiffness, const Vector &influence,
                const unsigned int n)
  {
    const Eigen::MatrixXd m(mass), k(stiffness);
    Eigen::LLT<Eigen::MatrixXd> cholesky(k);
    if (cholesky.info() != Eigen::Success)
      throw NumericalError("modal analysis: the stiffness matrix is singular or not positive "
                           "definite (is the structure a mechanism? check the supports)");
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      m, k, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
    if (solver.info() != Eigen::Success)
      throw NumericalError("modal analysis: the eigensolver did not converge");

    const Eigen::VectorXd &mu       = solver.eigenvalues(); // ascending
    const double           mu_max   = mu.size() ? mu.maxCoeff() : 0;
    const double           total    = influence.dot(m * influence);
    Modes                  modes;
    std::vector<int>       kept;
    for (int i = mu.size() - 1; i >= 0 && kept.size() < n; --i)
      if (mu[i] > 1e-12 * mu_max)
        kept.push_back(i);
    modes.shapes.resize(m.rows(), kept.size());
    for (unsigned int j = 0; j < kept.size(); ++j)
      {
        Eigen::VectorXd phi = solver.eigenvectors().col(kept[j]);
        phi /= std::sqrt(phi.dot(m * phi));
        // A sign convention makes shapes comparable between runs.
        Eigen::Index largest;
        phi.cwiseAbs().maxCoeff(&largest);
        if (phi[largest] < 0)
          phi = -phi;
        modes.shapes.col(j) = phi;
        modes.omega.push_back(1 / std::sqrt(mu[kept[j]]));
        const double gamma = phi.dot(m * influence);
        modes.participating_mass_ratio.push_back(total > 0 ? gamma * gamma / total : 0);
      }
    return modes;
  }
} // namespace poundfe
