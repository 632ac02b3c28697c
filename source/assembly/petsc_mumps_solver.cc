// The distributed direct solver "petsc-mumps": the effective matrix as a
// PETSc MPI AIJ matrix split by contiguous blocks of rows over the ranks of
// MPI_COMM_WORLD, factorised by MUMPS (Amestoy et al. 2001, SIAM J. Matrix
// Anal. Appl. 23(1):15-41) through PETSc's MatGetFactor interface (Balay et
// al., PETSc Users Manual, "Using External Linear Solvers").
//
// Every rank holds the whole Eigen matrix and vectors (the integrator's state
// is replicated); each rank copies only its own rows into PETSc (the
// distributed assembly of K_eff and of every refactorised tangent), MUMPS's
// analysis (ordering, symbolic factorisation) runs once in analyze() and each
// factorize() is a numeric factorisation on that analysis. A solve scatters
// nothing in (each rank takes its rows of b from its own copy) and gathers
// the solution to every rank (VecScatterCreateToAll). On one rank it is
// sequential MUMPS. Every call is collective: all ranks must make the same
// calls in the same order, which the replicated time stepping guarantees.
//
// A symmetric matrix (K_eff = K + a0 M + a1 C with symmetric element
// tangents: every model without friction or a nonsymmetric contact
// tangent) is factorised as L D L^T (MUMPS SYM = 2, PETSc's
// MAT_FACTOR_CHOLESKY on the upper triangle; 2x2 pivots keep it stable for
// an indefinite tangent): half the factor entries of L U, so about half the
// memory, factorisation and solve time (MUMPS users' guide, ICNTL and SYM;
// Amestoy et al. 2001 §2). Symmetry is checked on the values at every
// factorisation (every rank holds the same matrix, so all decide alike); a
// matrix that is not symmetric gets L U, analysed again if the last analysis
// was symmetric.
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/base/exceptions.h>

#include <petscmat.h>

#include <Eigen/Core>

#include "csr_copy.h"

#include <algorithm>
#include <cmath>

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace poundfe
{
  namespace
  {
    DistributedSolverProfile profile;

    /// PETSc calls that fail are programming or installation errors: the
    /// caller (main) aborts all ranks.
    void
    check(const PetscErrorCode code, const char *call)
    {
      if (code != 0)
        throw std::runtime_error(std::string("PETSc: ") + call + " failed (error " +
                                 std::to_string(code) + ")");
    }

    /// Whether `matrix` equals its transpose to round-off: each off-diagonal
    /// entry and its mirror (0 where it is not stored) within 1e-13 of the
    /// larger of their two diagonal entries. The assembly adds k_ij and k_ji
    /// in different orders, so exact equality would be too strict; a
    /// difference at that level changes the solution far less than the
    /// pivot order does.
    bool
    is_symmetric(const SparseMatrix &matrix)
    {
      if (matrix.rows() != matrix.cols())
        return false;
      for (Eigen::Index column = 0; column < matrix.outerSize(); ++column)
        for (SparseMatrix::InnerIterator entry(matrix, column); entry; ++entry)
          {
            const Eigen::Index row = entry.row();
            if (row == column)
              continue;
            const double scale = std::max(std::abs(matrix.coeff(row, row)),
                                          std::abs(matrix.coeff(column, column)));
            if (std::abs(entry.value() - matrix.coeff(column, row)) > 1e-13 * scale)
              return false;
          }
      return true;
    }

    /// Seconds since `start`, added to `total`.
    class ScopedTime
    {
    public:
      explicit ScopedTime(double &total)
        : total(total)
        , start(std::chrono::steady_clock::now())
      {}
      ~ScopedTime()
      {
        total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }

    private:
      double                               &total;
      std::chrono::steady_clock::time_point start;
    };

    class PetscMumpsSolver : public LinearSolver
    {
    public:
      PetscMumpsSolver()
        : communicator(MPI_COMM_WORLD)
      {}
      ~PetscMumpsSolver() override { destroy(); }

      void
      analyze(const SparseMatrix &matrix) override
      {
        ScopedTime time(profile.analysis_time);
        destroy();
        symmetric = is_symmetric(matrix);
        copy_local_rows(matrix);
        if (symmetric)
          check(MatCholeskyFactorSymbolic(factor, petsc_matrix, nullptr, &info),
                "MatCholeskyFactorSymbolic");
        else
          check(MatLUFactorSymbolic(factor, petsc_matrix, nullptr, nullptr, &info),
                "MatLUFactorSymbolic");
        throw_if_failed("analysis");
        ++profile.analyses;
      }

      void
      factorize(const SparseMatrix &matrix) override
      {
        ScopedTime time(profile.factorization_time);
        Assert(petsc_matrix != nullptr, dealii::ExcMessage("analyze() first"));
        AssertDimension(matrix.nonZeros(), csr.n_nonzeros);
        if (symmetric && !is_symmetric(matrix)) // e.g. a friction tangent: L U
          analyze(matrix);
        set_values(matrix);
        if (symmetric)
          check(MatCholeskyFactorNumeric(factor, petsc_matrix, &info), "MatCholeskyFactorNumeric");
        else
          check(MatLUFactorNumeric(factor, petsc_matrix, &info), "MatLUFactorNumeric");
        throw_if_failed("factorisation");
        record_memory();
        ++profile.factorizations;
        if (symmetric)
          ++profile.symmetric_factorizations;
      }

      void
      solve(const Vector &b, Vector &x) override
      {
        ScopedTime time(profile.solve_time);
        PetscScalar *local = nullptr;
        check(VecGetArray(rhs, &local), "VecGetArray");
        for (PetscInt i = first_row; i < end_row; ++i)
          local[i - first_row] = b[i];
        check(VecRestoreArray(rhs, &local), "VecRestoreArray");
        check(MatSolve(factor, rhs, solution), "MatSolve");
        check(VecScatterBegin(to_all, solution, gathered, INSERT_VALUES, SCATTER_FORWARD),
              "VecScatterBegin");
        check(VecScatterEnd(to_all, solution, gathered, INSERT_VALUES, SCATTER_FORWARD),
              "VecScatterEnd");
        const PetscScalar *all = nullptr;
        check(VecGetArrayRead(gathered, &all), "VecGetArrayRead");
        x = Eigen::Map<const Vector>(all, b.size());
        check(VecRestoreArrayRead(gathered, &all), "VecRestoreArrayRead");
        ++profile.solves;
      }

      std::string
      name() const override
      {
        return "petsc-mumps";
      }

      double
      agreed_seconds(const double seconds) const override
      {
        double largest = seconds;
        MPI_Allreduce(&seconds, &largest, 1, MPI_DOUBLE, MPI_MAX, communicator);
        return largest;
      }

    private:
      /// This rank's block of rows [first_row, end_row): contiguous, about
      /// n / P rows each, as PETSc would split them.
      void
      split_rows(const PetscInt n)
      {
        PetscInt n_local = PETSC_DECIDE, n_global = n;
        check(PetscSplitOwnership(communicator, &n_local, &n_global), "PetscSplitOwnership");
        first_row = 0;
        MPI_Exscan(&n_local, &first_row, 1, MPIU_INT, MPI_SUM, communicator);
        int rank = 0;
        MPI_Comm_rank(communicator, &rank);
        if (rank == 0)
          first_row = 0; // MPI_Exscan leaves rank 0's result undefined
        end_row = first_row + n_local;
      }

      /// The PETSc matrix of this rank's rows with `matrix`'s pattern and
      /// values, the vectors, the gather to all ranks and the MUMPS factor.
      void
      copy_local_rows(const SparseMatrix &matrix)
      {
        const PetscInt n = matrix.rows();
        split_rows(n);
        csr.build(matrix, first_row, end_row);
        const PetscInt n_local = end_row - first_row;
        check(MatCreate(communicator, &petsc_matrix), "MatCreate");
        check(MatSetSizes(petsc_matrix, n_local, n_local, n, n), "MatSetSizes");
        check(MatSetType(petsc_matrix, MATAIJ), "MatSetType");
        // one of the two applies: sequential AIJ on one rank, MPI AIJ on more
        check(MatSeqAIJSetPreallocationCSR(petsc_matrix, csr.row_start.data(), csr.columns.data(),
                                           csr.values.data()),
              "MatSeqAIJSetPreallocationCSR");
        check(MatMPIAIJSetPreallocationCSR(petsc_matrix, csr.row_start.data(), csr.columns.data(),
                                           csr.values.data()),
              "MatMPIAIJSetPreallocationCSR");
        check(MatSetOption(petsc_matrix, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE),
              "MatSetOption");
        check(MatCreateVecs(petsc_matrix, &solution, &rhs), "MatCreateVecs");
        check(VecScatterCreateToAll(solution, &to_all, &gathered), "VecScatterCreateToAll");
        if (symmetric) // PETSc then hands MUMPS the upper triangle only
          check(MatSetOption(petsc_matrix, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
        check(MatGetFactor(petsc_matrix, MATSOLVERMUMPS,
                           symmetric ? MAT_FACTOR_CHOLESKY : MAT_FACTOR_LU, &factor),
              "MatGetFactor (is PETSc built with MUMPS?)");
        check(MatFactorInfoInitialize(&info), "MatFactorInfoInitialize");
      }

      /// The new values of this rank's rows (same pattern) into PETSc.
      void
      set_values(const SparseMatrix &matrix)
      {
        csr.gather(matrix);
        for (PetscInt i = 0; i < end_row - first_row; ++i)
          {
            const PetscInt row = first_row + i;
            check(MatSetValues(petsc_matrix, 1, &row, csr.row_start[i + 1] - csr.row_start[i],
                               csr.columns.data() + csr.row_start[i],
                               csr.values.data() + csr.row_start[i],
                               INSERT_VALUES),
                  "MatSetValues");
          }
        check(MatAssemblyBegin(petsc_matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
        check(MatAssemblyEnd(petsc_matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
      }

      /// MUMPS's global status INFOG(1) (the same on every rank): negative
      /// is a failure; -10 a numerically singular matrix.
      void
      throw_if_failed(const char *phase) const
      {
        PetscInt status = 0;
        check(MatMumpsGetInfog(factor, 1, &status), "MatMumpsGetInfog");
        if (status == -10 || status == -6)
          throw NumericalError("MUMPS: the effective matrix is singular");
        if (status < 0)
          throw NumericalError(std::string("MUMPS ") + phase + " failed (INFOG(1) = " +
                               std::to_string(status) + ")");
      }

      /// INFOG(21), INFOG(22): MB of the factorisation on the largest rank
      /// and on all ranks; INFOG(29): entries in the factors (negative:
      /// millions).
      void
      record_memory() const
      {
        PetscInt largest = 0, total = 0, entries = 0;
        check(MatMumpsGetInfog(factor, 21, &largest), "MatMumpsGetInfog");
        check(MatMumpsGetInfog(factor, 22, &total), "MatMumpsGetInfog");
        check(MatMumpsGetInfog(factor, 29, &entries), "MatMumpsGetInfog");
        profile.factor_megabytes_per_rank = std::max<double>(profile.factor_megabytes_per_rank, largest);
        profile.factor_megabytes_total    = std::max<double>(profile.factor_megabytes_total, total);
        profile.factor_entries = std::max<double>(profile.factor_entries,
                                                  entries < 0 ? -1e6 * entries : double(entries));
      }

      void
      destroy()
      {
        MatDestroy(&factor);
        VecScatterDestroy(&to_all);
        VecDestroy(&gathered);
        VecDestroy(&solution);
        VecDestroy(&rhs);
        MatDestroy(&petsc_matrix);
      }

      const MPI_Comm        communicator;
      PetscInt              first_row = 0, end_row = 0;
      CsrCopy<PetscInt>     csr; // this rank's rows
      bool                  symmetric    = false; // of the last analysis: L D L^T
      Mat                   petsc_matrix = nullptr, factor = nullptr;
      Vec                   rhs = nullptr, solution = nullptr, gathered = nullptr;
      VecScatter            to_all = nullptr;
      MatFactorInfo         info;
    };
  } // namespace

  const DistributedSolverProfile &
  distributed_solver_profile()
  {
    return profile;
  }

  std::unique_ptr<LinearSolver>
  create_petsc_mumps_solver()
  {
    return std::make_unique<PetscMumpsSolver>();
  }
} // namespace poundfe
