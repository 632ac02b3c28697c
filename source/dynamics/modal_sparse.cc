// The sparse modal solver (the theory is in include/poundfe/dynamics/modal.h
// and doc/theory.md §1.8). ARPACK's symmetric driver in shift-invert mode 3
// with shift 0 finds the largest nu of K^-1 M x = nu x in the M inner
// product, nu = 1/omega^2; M may be singular (ARPACK Users' Guide, mode
// 3 needs M positive semidefinite only). Its Lanczos vectors stay in the
// range of K^-1 M, which is where the eigenvectors with finite omega live,
// so the massless rotations come out statically condensed.
//
// deal.II's ArpackSolver checks ARPACK's error codes with Assert only (gone
// in Release builds) and returns the Ritz vectors before ARPACK's
// purification step, so the result is refined and checked here: one step
// of subspace iteration Y = K^-1 M X (which also removes any component in
// the null space of M), a Rayleigh-Ritz projection onto Y, and the residual
// of every pair (Bathe, Finite Element Procedures, §11.6).
#include <poundfe/dynamics/modal.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>

#include <deal.II/lac/arpack_solver.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/vector.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <string>

namespace poundfe
{
  namespace
  {
    using DealVector = dealii::Vector<double>;

    Eigen::Map<const Eigen::VectorXd>
    view(const DealVector &v)
    {
      return {v.begin(), static_cast<Eigen::Index>(v.size())};
    }

    Eigen::Map<Eigen::VectorXd>
    view(DealVector &v)
    {
      return {v.begin(), static_cast<Eigen::Index>(v.size())};
    }

    /// The M of ARPACK's inner product (only vmult is used).
    struct MassOperator
    {
      const SparseMatrix &mass;
      void
      vmult(DealVector &dst, const DealVector &src) const
      {
        view(dst).noalias() = mass * view(src);
      }
    };

    /// (K - sigma M)^-1 with sigma = 0, by the Cholesky factor of K.
    struct InverseOperator
    {
      const Eigen::SimplicialLLT<SparseMatrix> &cholesky;
      void
      vmult(DealVector &dst, const DealVector &src) const
      {
        view(dst) = cholesky.solve(view(src));
      }
    };

    /// The Lanczos basis: at least 2 nev + 2 vectors (deal.II's requirement),
    /// some more for fast convergence, at most the massive DOFs (the rank of
    /// K^-1 M, beyond which the Krylov space cannot grow).
    unsigned int
    lanczos_basis_size(const SparseMatrix &mass, const unsigned int nev)
    {
      const unsigned int limit = 2 * lanczos_mode_limit(mass) + 2;
      return std::min(limit, std::max(2 * nev + 2, nev + 20));
    }

    /// ARPACK's approximate eigenvectors of the nev lowest modes, as columns.
    Eigen::MatrixXd
    lanczos_vectors(const SparseMatrix &mass, const Eigen::SimplicialLLT<SparseMatrix> &cholesky,
                    const unsigned int nev)
    {
      const unsigned int n = mass.rows();
      // A random start (fixed seed: runs repeat) excites every mode; a
      // constant vector would miss those orthogonal to it in symmetric frames.
      DealVector                             start(n);
      std::mt19937                           random(12345);
      std::uniform_real_distribution<double> uniform(-1, 1);
      for (double &x : start)
        x = uniform(random);

      dealii::SolverControl control(1000, 1e-12);
      const dealii::ArpackSolver::AdditionalData data(lanczos_basis_size(mass, nev),
                                                      dealii::ArpackSolver::largest_magnitude,
                                                      true);
      dealii::ArpackSolver solver(control, data);
      solver.set_initial_vector(start);
      std::vector<std::complex<double>> eigenvalues(nev);
      std::vector<DealVector>           eigenvectors(nev, DealVector(n));
      const MassOperator                m{mass};
      solver.solve(m, m, InverseOperator{cholesky}, eigenvalues, eigenvectors);

      Eigen::MatrixXd x(n, nev);
      for (unsigned int j = 0; j < nev; ++j)
        x.col(j) = view(eigenvectors[j]);
      return x;
    }

    /// A unit vector on every DOF that carries mass: K^-1 M of them spans
    /// the whole range of K^-1 M, so the Rayleigh-Ritz step below is exact
    /// (static condensation onto the massive DOFs). For models too small
    /// for a Lanczos basis (a one-storey building, an oscillator).
    Eigen::MatrixXd
    massive_unit_vectors(const SparseMatrix &mass)
    {
      Eigen::MatrixXd x = Eigen::MatrixXd::Zero(mass.rows(), max_sparse_modes(mass));
      Eigen::Index    column = 0;
      for (Eigen::Index i = 0; i < mass.rows(); ++i)
        if (mass.coeff(i, i) != 0)
          x(i, column++) = 1;
      return x;
    }
  } // namespace

  Modes
  compute_modes_sparse(const SparseMatrix &mass, const SparseMatrix &stiffness,
                       const Vector &influence, unsigned int n)
  {
    n = std::min(n, max_sparse_modes(mass)); // the finite modes
    Modes modes;
    modes.shapes.resize(mass.rows(), 0);
    if (n == 0)
      return modes;
    const Eigen::SimplicialLLT<SparseMatrix> cholesky(stiffness);
    if (cholesky.info() != Eigen::Success)
      throw NumericalError(stiffness_not_positive_definite);

    // Subspace iteration step and Rayleigh-Ritz: K_r z = omega^2 M_r z.
    const Eigen::MatrixXd x = n <= lanczos_mode_limit(mass) ? lanczos_vectors(mass, cholesky, n) :
                                                              massive_unit_vectors(mass);
    const Eigen::MatrixXd y = cholesky.solve(Eigen::MatrixXd(mass * x));
    const Eigen::MatrixXd k_r = y.transpose() * (stiffness * y);
    const Eigen::MatrixXd m_r = y.transpose() * (mass * y);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> projected(
      0.5 * (k_r + k_r.transpose()), 0.5 * (m_r + m_r.transpose()));
    if (projected.info() != Eigen::Success)
      throw NumericalError("modal analysis: the sparse eigensolver found dependent vectors "
                           "(set Modal analysis/Eigensolver = dense)");

    for (unsigned int j = 0; j < n; ++j)
      {
        const double          lambda = projected.eigenvalues()[j]; // ascending
        const Eigen::VectorXd phi    = y * projected.eigenvectors().col(j);
        // The residual of K^-1 M phi = phi / lambda, the operator ARPACK
        // works with (K phi - lambda M phi itself is all round-off for the
        // lowest modes: its terms cancel to 1e-12 of K's entries). Building
        // models give ~1e-13; a finely meshed single member, whose K has a
        // condition number growing as n^4, up to ~1e-5 (1000 elements) with
        // eigenvalues as good as the dense solver's. 1e-3 only catches an
        // ARPACK failure, which Release builds of deal.II do not report.
        const double residual =
          (phi - lambda * cholesky.solve(mass * phi)).norm() / phi.norm();
        if (!(lambda > 0) || !(residual < 1e-3))
          throw NumericalError("modal analysis: the sparse eigensolver did not converge (mode " +
                               std::to_string(j + 1) + ", residual " +
                               number_text(residual) +
                               "; set Modal analysis/Eigensolver = dense)");
        append_mode(modes, phi, std::sqrt(lambda), mass, influence);
      }
    return modes;
  }
} // namespace poundfe
