// UMFPACK (Davis 2004, ACM TOMS 30(2):196-199) on the effective matrix
// through its C interface: the symbolic analysis (column ordering and
// elimination tree) once per pattern in analyze(), a numeric factorisation
// in each factorize() that reuses it. That is what the refactorising
// tangent updates need: a model with thousands of nonlinear elements
// refactorises in every Newton iteration, always with the same pattern.
// (deal.II's SparseDirectUMFPACK redoes the symbolic analysis each time.)
// The symbolic object is read-only in umfpack_di_numeric, so solvers of
// matrices with one pattern (the effective matrices of every step size,
// the tangent of the hybrid update) share one analysis (reuse_analysis).
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>

#include <suitesparse/umfpack.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace poundfe
{
  namespace
  {
    class UmfpackSolver : public LinearSolver
    {
    public:
      UmfpackSolver() { umfpack_di_defaults(control); }
      ~UmfpackSolver() override { release(); }

      void
      analyze(const SparseMatrix &matrix) override
      {
        release();
        // Eigen's compressed column storage is UMFPACK's: sorted rows per column.
        const int n = matrix.rows();
        column_start.assign(matrix.outerIndexPtr(), matrix.outerIndexPtr() + n + 1);
        row.assign(matrix.innerIndexPtr(), matrix.innerIndexPtr() + matrix.nonZeros());
        value.assign(matrix.valuePtr(), matrix.valuePtr() + matrix.nonZeros());
        void *analysis = nullptr;
        if (umfpack_di_symbolic(n, n, column_start.data(), row.data(), value.data(), &analysis,
                                control, nullptr) != UMFPACK_OK)
          throw NumericalError("UMFPACK: the symbolic analysis of the effective matrix failed");
        symbolic.reset(analysis, [](void *p) { umfpack_di_free_symbolic(&p); });
      }
      bool
      reuse_analysis(const LinearSolver &analysed, const SparseMatrix &matrix) override
      {
        const auto *other = dynamic_cast<const UmfpackSolver *>(&analysed);
        if (!other || !other->symbolic ||
            other->column_start.size() != static_cast<std::size_t>(matrix.cols()) + 1 ||
            other->row.size() != static_cast<std::size_t>(matrix.nonZeros()) ||
            !std::equal(other->column_start.begin(), other->column_start.end(),
                        matrix.outerIndexPtr()) ||
            !std::equal(other->row.begin(), other->row.end(), matrix.innerIndexPtr()))
          return false;
        release();
        column_start = other->column_start;
        row          = other->row;
        symbolic     = other->symbolic;
        return true;
      }
      void
      factorize(const SparseMatrix &matrix) override
      {
        value.assign(matrix.valuePtr(), matrix.valuePtr() + matrix.nonZeros());
        if (numeric)
          umfpack_di_free_numeric(&numeric);
        const int status = umfpack_di_numeric(column_start.data(), row.data(), value.data(),
                                              symbolic.get(), &numeric, control, nullptr);
        if (status != UMFPACK_OK)
          throw NumericalError(status == UMFPACK_WARNING_singular_matrix ?
                                 "UMFPACK: the effective matrix is singular" :
                                 "UMFPACK: the numeric factorisation failed");
      }
      void
      solve(const Vector &b, Vector &x) override
      {
        x.resize(b.size());
        umfpack_di_solve(UMFPACK_A, column_start.data(), row.data(), value.data(), x.data(),
                         b.data(), numeric, control, nullptr);
      }
      std::string
      name() const override
      {
        return "umfpack";
      }

    private:
      void
      release()
      {
        if (numeric)
          umfpack_di_free_numeric(&numeric);
        numeric = nullptr;
        symbolic.reset();
      }

      double           control[UMFPACK_CONTROL];
      std::vector<int> column_start, row;
      std::vector<double> value; // the factorised values (iterative refinement uses them)
      std::shared_ptr<void> symbolic; // shared by the solvers of one pattern
      void            *numeric  = nullptr;
    };
  } // namespace

  std::unique_ptr<LinearSolver>
  create_umfpack_solver()
  {
    return std::make_unique<UmfpackSolver>();
  }
} // namespace poundfe
