#include <poundfe/assembly/band_lu_solver.h>
#include <poundfe/assembly/iterative_solver.h>
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>

#include <Eigen/SparseCholesky>

#include <mpi.h>

#include <stdexcept>

namespace poundfe
{
  namespace
  {
    class EigenLdltSolver : public LinearSolver
    {
    public:
      void
      analyze(const SparseMatrix &matrix) override
      {
        ldlt.analyzePattern(matrix);
      }
      void
      factorize(const SparseMatrix &matrix) override
      {
        ldlt.factorize(matrix);
        if (ldlt.info() != Eigen::Success)
          throw NumericalError("Eigen LDLT: the effective matrix is singular");
        const auto d = ldlt.vectorD();
        if ((d.array() == 0).any())
          throw NumericalError("Eigen LDLT: the effective matrix is singular");
        inverse_d = d.cwiseInverse(); // what Eigen's D^-1 multiplies by
      }
      /// Eigen's own solve() permutes in place, which allocates a mask on
      /// every call; the same steps (x = P^-1 L^-T D^-1 L^-1 P b) through a
      /// kept buffer allocate nothing and give the same numbers.
      /// The permutations are copies by index (buffer[P(i)] = b[i], x[P^-1(j)]
      /// = buffer[j], as Eigen's permutation products), without the
      /// products' expression machinery: the same numbers, a few hundred
      /// instructions less per solve of a small model.
      void
      solve(const Vector &b, Vector &x) override
      {
        const Eigen::Index n = b.size();
        buffer.resize(n);
        const auto &p = ldlt.permutationP().indices();
        if (p.size() > 0)
          for (Eigen::Index i = 0; i < n; ++i)
            buffer[p[i]] = b[i];
        else
          buffer = b;
        ldlt.matrixL().solveInPlace(buffer);
        buffer.array() *= inverse_d.array();
        ldlt.matrixU().solveInPlace(buffer);
        x.resize(n);
        const auto &p_inverse = ldlt.permutationPinv().indices();
        if (p_inverse.size() > 0)
          for (Eigen::Index j = 0; j < n; ++j)
            x[p_inverse[j]] = buffer[j];
        else
          x = buffer;
      }
      std::string
      name() const override
      {
        return "eigen-ldlt";
      }

    private:
      Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
      Vector                                            buffer, inverse_d;
    };
  } // namespace

  std::unique_ptr<LinearSolver>
  create_eigen_ldlt_solver()
  {
    return std::make_unique<EigenLdltSolver>();
  }

  std::vector<std::string>
  linear_solver_names()
  {
    return {"eigen-ldlt", "umfpack", "band-lu", "petsc", "trilinos", "petsc-mumps",
            "petsc-cg-boomeramg", "trilinos-cg-ml"};
  }

  bool
  linear_solver_needs_mpi(const std::string &name)
  {
    return name == "petsc" || name == "trilinos" || linear_solver_is_distributed(name) ||
           linear_solver_is_iterative(name);
  }

  bool
  linear_solver_is_distributed(const std::string &name)
  {
    return name == "petsc-mumps";
  }

  std::unique_ptr<LinearSolver>
  create_linear_solver(const std::string &name, const IterativeSolverSetup &setup)
  {
    int initialized = 0;
    if (linear_solver_needs_mpi(name) && (MPI_Initialized(&initialized), !initialized))
      throw std::logic_error("the " + name + " solver needs MPI initialised (MPI_InitFinalize)");
    if (name == "eigen-ldlt")
      return create_eigen_ldlt_solver();
    if (name == "umfpack")
      return create_umfpack_solver();
    if (name == "band-lu")
      return create_band_lu_solver("set Linear solver = umfpack");
    if (name == "petsc")
      return create_petsc_solver();
    if (name == "trilinos")
      return create_trilinos_solver();
    if (name == "petsc-mumps")
      return create_petsc_mumps_solver();
    if (name == "petsc-cg-boomeramg")
      return create_petsc_boomeramg_solver(setup);
    if (name == "trilinos-cg-ml")
      return create_trilinos_ml_solver(setup);
    throw InputError("", 0, "Time integration/Linear solver", "unknown solver '" + name + "'");
  }

  namespace
  {
    /// A solver on one diagonal block: the matrices it is given are the
    /// model's, zero outside the block but for the couplings of elements to
    /// other ranks' equations (ghosts), which this rank's block leaves out.
    class BlockRestrictedSolver : public LinearSolver
    {
    public:
      BlockRestrictedSolver(std::unique_ptr<LinearSolver> inner, const std::array<unsigned int, 2> range)
        : inner(std::move(inner))
        , first(range[0])
        , n_block(range[1] - range[0])
        , b_block(n_block)
        , x_block(n_block)
      {}

      void analyze(const SparseMatrix &matrix) override { inner->analyze(cut(matrix)); }
      void factorize(const SparseMatrix &matrix) override { inner->factorize(cut(matrix)); }
      void
      solve(const Vector &b, Vector &x) override
      {
        b_block = b.segment(first, n_block);
        inner->solve(b_block, x_block);
        x.setZero(b.size());
        x.segment(first, n_block) = x_block;
      }
      bool
      reuse_analysis(const LinearSolver &analysed, const SparseMatrix &matrix) override
      {
        const auto *other = dynamic_cast<const BlockRestrictedSolver *>(&analysed);
        return other && inner->reuse_analysis(*other->inner, cut(matrix));
      }
      std::string name() const override { return inner->name(); }

    private:
      SparseMatrix
      cut(const SparseMatrix &matrix) const
      {
        return block(matrix, {{first, first + n_block}});
      }

      std::unique_ptr<LinearSolver> inner;
      const unsigned int            first, n_block;
      Vector                        b_block, x_block;
    };
  } // namespace

  std::unique_ptr<LinearSolver>
  restrict_to_block(std::unique_ptr<LinearSolver> inner, const std::array<unsigned int, 2> range)
  {
    return std::make_unique<BlockRestrictedSolver>(std::move(inner), range);
  }

  std::unique_ptr<LinearSolver>
  create_linear_solver(const std::string &name)
  {
    return create_linear_solver(name, IterativeSolverSetup());
  }
} // namespace poundfe
