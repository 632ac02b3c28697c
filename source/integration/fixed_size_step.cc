// The fixed-size storage of a Newmark step's arithmetic
// (integration/fixed_size_step.h: the formulas, their sources, and why
// the dense products give the sparse ones' bits).
#include <poundfe/integration/fixed_size_step.h>

#include <poundfe/base/exceptions.h>

#include <Eigen/SparseCholesky>

#include <array>
#include <utility>

namespace poundfe
{
  namespace
  {
    template <int N>
    using FixedVector = Eigen::Matrix<double, N, 1>;
    template <int N>
    using FixedMatrix = Eigen::Matrix<double, N, N>;
    template <int N>
    using View = Eigen::Map<FixedVector<N>>;
    template <int N>
    using ConstView = Eigen::Map<const FixedVector<N>>;

    /// y += alpha A x, column by column as Eigen's column-major sparse
    /// product: y_i += A_ij (alpha x_j), j = 0 .. N-1 (each column's update
    /// is element by element, so Eigen's unrolled packets keep the bits).
    template <int N, class In, class Out>
    inline void
    add_product(const FixedMatrix<N> &A, const double alpha, const In &x, Out &y)
    {
      for (int j = 0; j < N; ++j)
        y.noalias() += A.col(j) * (alpha * x[j]);
    }

    /// The storage of newmark_formulas: dense M, C, K and K_eff of N equations.
    template <int N>
    struct FixedStorage
    {
      FixedMatrix<N> mass, damping, stiffness, effective;

      template <class In, class Out>
      void mass_product(const In &x, Out &y) const
      {
        y.setZero();
        add_product<N>(mass, 1.0, x, y);
      }
      template <class In, class Out>
      void damping_product(const In &x, Out &y) const
      {
        y.setZero();
        add_product<N>(damping, 1.0, x, y);
      }
      template <class In, class Out>
      void subtract_effective_product(const In &x, Out &y) const
      {
        add_product<N>(effective, -1.0, x, y);
      }
      template <class In>
      double norm(const In &x) const
      {
        return x.norm();
      }
    };

    template <int N>
    class FixedSizeStepOf : public FixedSizeStep
    {
    public:
      FixedSizeStepOf(const LinearSystem &system, const SparseMatrix &effective)
      {
        storage.mass      = Eigen::MatrixXd(system.mass);
        storage.damping   = Eigen::MatrixXd(system.damping);
        storage.stiffness = Eigen::MatrixXd(system.stiffness);
        storage.effective = Eigen::MatrixXd(effective);
      }

      void stiffness_product(const Vector &u, Vector &stiffness_u) const override
      {
        View<N> y(stiffness_u.data());
        y.setZero();
        add_product<N>(storage.stiffness, 1.0, ConstView<N>(u.data()), y);
      }

      double start_residual(const NewmarkCoefficients &c, const Vector &p,
                            const Vector &stiffness_u, const Vector &v, const Vector &a,
                            Vector &r0) const override
      {
        FixedVector<N> work, product;
        View<N>        r(r0.data());
        return newmark_formulas::start_residual(storage, c, ConstView<N>(p.data()),
                                                ConstView<N>(stiffness_u.data()),
                                                ConstView<N>(v.data()), ConstView<N>(a.data()),
                                                work, product, r);
      }

      void kinematics(const NewmarkCoefficients &c, const Vector &du, const Vector &v,
                      const Vector &a, Vector &v_next, Vector &a_next) const override
      {
        View<N> v1(v_next.data()), a1(a_next.data());
        newmark_formulas::kinematics(c, ConstView<N>(du.data()), ConstView<N>(v.data()),
                                     ConstView<N>(a.data()), v1, a1);
      }

      void iterate(const Vector &u, const Vector &du, Vector &u_next) const override
      {
        View<N>(u_next.data()).noalias() = ConstView<N>(u.data()) + ConstView<N>(du.data());
      }

      void effective_residual(const Vector &r0, const Vector &du, Vector &r) const override
      {
        const ConstView<N> d(du.data());
        View<N>            y(r.data());
        if ((d.array() == 0.0).all())
          y = ConstView<N>(r0.data());
        else
          newmark_formulas::effective_residual(storage, ConstView<N>(r0.data()), d, y);
      }

      void add_step_work(const Vector &du, const Vector &p_start, const Vector &p_end,
                         const Vector &v, const Vector &v_next, double &input,
                         double &damping) const override
      {
        FixedVector<N> work, product;
        newmark_formulas::add_step_work(storage, ConstView<N>(du.data()),
                                        ConstView<N>(p_start.data()),
                                        ConstView<N>(p_end.data()), ConstView<N>(v.data()),
                                        ConstView<N>(v_next.data()), work, product, input,
                                        damping);
      }

      double kinetic_energy(const Vector &v) const override
      {
        FixedVector<N> product;
        return newmark_formulas::kinetic_energy(storage, ConstView<N>(v.data()), product);
      }

      double norm(const Vector &x) const override { return ConstView<N>(x.data()).norm(); }

      double dot(const Vector &x, const Vector &y) const override
      {
        return ConstView<N>(x.data()).dot(ConstView<N>(y.data()));
      }

    private:
      FixedStorage<N> storage;
    };

    /// eigen-ldlt's solve on a dense copy of its factors (fixed_size_step.h).
    template <int N>
    class FixedSizeLdltSolver : public LinearSolver
    {
    public:
      explicit FixedSizeLdltSolver(std::unique_ptr<LinearSolver> base)
        : base(std::move(base))
      {}

      /// Our own analysis only: the base is never factorised (its solve is
      /// not used), so a refactorised tangent costs one factorisation. No
      /// reuse_analysis (LinearSolver's false): a reused analysis would skip
      /// this, and our own ldlt would be factorised unanalysed.
      void analyze(const SparseMatrix &matrix) override { ldlt.analyzePattern(matrix); }

      /// eigen-ldlt's factors (and its singularity checks) of our own
      /// analysis, copied into fixed size.
      void factorize(const SparseMatrix &matrix) override
      {
        ldlt.factorize(matrix);
        if (ldlt.info() != Eigen::Success || (ldlt.vectorD().array() == 0).any())
          throw NumericalError("Eigen LDLT: the effective matrix is singular");
        // L's stored entries (strictly lower; its unit diagonal is implied)
        lower.setZero();
        const SparseMatrix &factor = ldlt.matrixL().nestedExpression();
        for (int j = 0; j < N; ++j)
          for (SparseMatrix::InnerIterator entry(factor, j); entry; ++entry)
            if (entry.row() > j)
              lower(entry.row(), j) = entry.value();
        // what Eigen's D^-1 multiplies by (eigen-ldlt's solve)
        inverse_d             = ldlt.vectorD().cwiseInverse();
        const auto &p         = ldlt.permutationP().indices();
        const auto &p_inverse = ldlt.permutationPinv().indices();
        for (int i = 0; i < N; ++i)
          {
            permutation[i]         = p.size() > 0 ? p[i] : i;
            inverse_permutation[i] = p_inverse.size() > 0 ? p_inverse[i] : i;
          }
      }

      void solve(const Vector &b, Vector &x) override
      {
        FixedVector<N> y;
        for (int i = 0; i < N; ++i)
          y[permutation[i]] = b[i];
        for (int i = 0; i < N; ++i) // L y' = y by columns, as Eigen's sparse L
          if (const double yi = y[i]; yi != 0.0)
            for (int j = i + 1; j < N; ++j)
              y[j] -= yi * lower(j, i);
        y.array() *= inverse_d.array();
        for (int i = N - 1; i >= 0; --i) // L^T y' = y by rows, as Eigen's L^T
          {
            double sum = y[i];
            for (int j = i + 1; j < N; ++j)
              sum -= lower(j, i) * y[j];
            y[i] = sum;
          }
        x.resize(N);
        for (int j = 0; j < N; ++j)
          x[inverse_permutation[j]] = y[j];
      }

      std::string name() const override { return base->name(); }

      double agreed_seconds(const double seconds) const override
      {
        return base->agreed_seconds(seconds);
      }

    private:
      std::unique_ptr<LinearSolver>                      base;
      Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
      FixedMatrix<N>                                     lower;
      FixedVector<N>                                     inverse_d;
      std::array<int, N>                                 permutation, inverse_permutation;
    };

    /// Made<n>(arguments...) for the n of the model (1 <= n <= N_max).
    template <template <int> class Made, class Base, int... N, class... Arguments>
    std::unique_ptr<Base>
    make_of_size(const unsigned int n, std::integer_sequence<int, N...>,
                 Arguments &&...arguments)
    {
      std::unique_ptr<Base> made;
      ((n == N + 1 ?
          (made = std::make_unique<Made<N + 1>>(std::forward<Arguments>(arguments)...), 0) :
          0),
       ...);
      return made;
    }

    using Sizes = std::make_integer_sequence<int, FixedSizeStep::max_size>;
  } // namespace

  std::unique_ptr<FixedSizeStep>
  make_fixed_size_step(const LinearSystem &system, const SparseMatrix &effective)
  {
    const unsigned int n = system.n_equations();
    if (n == 0 || n > FixedSizeStep::max_size || !system.modal_damping.empty())
      return nullptr;
    return make_of_size<FixedSizeStepOf, FixedSizeStep>(n, Sizes{}, system, effective);
  }

  std::unique_ptr<LinearSolver>
  with_fixed_size_solve(std::unique_ptr<LinearSolver> solver, const unsigned int n)
  {
    if (n == 0 || n > FixedSizeStep::max_size || solver->name() != "eigen-ldlt")
      return solver;
    return make_of_size<FixedSizeLdltSolver, LinearSolver>(n, Sizes{}, std::move(solver));
  }
} // namespace poundfe
