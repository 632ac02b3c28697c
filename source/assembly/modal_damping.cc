#include <poundfe/assembly/low_rank_update.h>
#include <poundfe/assembly/modal_damping.h>

#include <deal.II/base/exceptions.h>

namespace poundfe
{
  namespace
  {
    /// A + s U D U^T: `base` holds A's factorisation, `woodbury` the columns
    /// of U and A^{-1} U, refreshed at every factorisation of A.
    class LowRankDampingSolver : public LinearSolver
    {
    public:
      LowRankDampingSolver(std::unique_ptr<LinearSolver> base_, const LowRankDamping &damping,
                           const double scale)
        : base(std::move(base_))
        , d(damping.weights.data(), damping.weights.data() + damping.weights.size())
      {
        for (double &x : d)
          x *= scale;
        const Eigen::MatrixXd &U = damping.factor;
        n_rows                   = U.rows();
        for (Eigen::Index c = 0; c < U.cols(); ++c)
          {
            SparseColumn column;
            for (Eigen::Index i = 0; i < U.rows(); ++i)
              if (U(i, c) != 0)
                {
                  column.rows.push_back(i);
                  column.values.push_back(U(i, c));
                }
            columns.push_back(std::move(column));
          }
      }

      void analyze(const SparseMatrix &matrix) override { base->analyze(matrix); }

      void
      factorize(const SparseMatrix &matrix) override
      {
        base->factorize(matrix);
        woodbury.initialize(*base, columns, n_rows); // A^{-1} U: m solves
      }

      void
      solve(const Vector &b, Vector &x) override
      {
        const bool solved = woodbury.solve(b, d, x);
        Assert(solved, dealii::ExcInternalError()); // every column of W is kept
        (void)solved;
      }

      bool
      reuse_analysis(const LinearSolver &analysed, const SparseMatrix &matrix) override
      {
        const auto *other = dynamic_cast<const LowRankDampingSolver *>(&analysed);
        return base->reuse_analysis(other ? *other->base : analysed, matrix);
      }

      std::string name() const override { return base->name(); }

      double
      agreed_seconds(const double seconds) const override
      {
        return base->agreed_seconds(seconds);
      }

    private:
      std::unique_ptr<LinearSolver> base;
      std::vector<double>           d; // scale * weights
      std::vector<SparseColumn>     columns;
      unsigned int                  n_rows = 0;
      LowRankUpdateSolver           woodbury;
    };
  } // namespace

  void
  add_modal_damping(LowRankDamping &damping, const unsigned int n,
                    const std::array<unsigned int, 2> range, const SparseMatrix &mass,
                    const Eigen::MatrixXd &shapes, const std::vector<double> &omega,
                    const std::vector<double> &ratios)
  {
    AssertDimension(mass.rows(), range[1] - range[0]);
    AssertThrow(shapes.cols() >= Eigen::Index(ratios.size()) && omega.size() >= ratios.size(),
                dealii::ExcMessage("modal damping needs a mode for every ratio"));
    unsigned int m = 0;
    for (const double ratio : ratios)
      m += ratio > 0;
    if (damping.factor.rows() == 0)
      damping.factor.resize(n, 0);
    const Eigen::Index first = damping.factor.cols();
    damping.factor.conservativeResize(n, first + m);
    damping.weights.conservativeResize(first + m);
    Eigen::Index c = first;
    for (unsigned int i = 0; i < ratios.size(); ++i)
      if (ratios[i] > 0)
        {
          damping.factor.col(c).setZero();
          damping.factor.col(c).segment(range[0], range[1] - range[0]) = mass * shapes.col(i);
          damping.weights[c] = 2 * ratios[i] * omega[i];
          ++c;
        }
  }

  void
  add_low_rank_damping_product(const LowRankDamping &damping, const Vector &v, Vector &out)
  {
    if (damping.empty())
      return;
    // D U^T v on the stack up to a few dozen modes: a Newmark step calls this
    // two or three times and allocates nothing. The same products as
    // weights.cwiseProduct(U^T v) into a heap temporary, so the same bits.
    constexpr int max_stack_modes = 32;
    if (damping.weights.size() <= max_stack_modes)
      {
        Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max_stack_modes, 1> modal(
          damping.weights.size());
        modal.noalias() = damping.factor.transpose() * v;
        modal.array() *= damping.weights.array();
        out.noalias() += damping.factor * modal;
        return;
      }
    const Vector modal = damping.weights.cwiseProduct(damping.factor.transpose() * v);
    out.noalias() += damping.factor * modal;
  }

  Vector
  damping_product(const LinearSystem &system, const Vector &v)
  {
    Vector product = system.damping * v;
    add_low_rank_damping_product(system.modal_damping, v, product);
    return product;
  }

  std::unique_ptr<LinearSolver>
  with_low_rank_damping(std::unique_ptr<LinearSolver> base, const LowRankDamping &damping,
                        const double scale)
  {
    if (damping.empty())
      return base;
    return std::make_unique<LowRankDampingSolver>(std::move(base), damping, scale);
  }
} // namespace poundfe
