// The equations owned by each rank, as the time integrator sees them: a
// model partitioned by building (assembly/partition.h) is stepped on every
// rank at once, each rank holding M, K, C and K_eff of its own equations
// only and evaluating only its nonlinear elements (those touching its
// equations: a gap between buildings on two ranks is evaluated on both).
// A rank's vectors hold its own equations, then its ghost equations: the
// equations of its elements that another rank owns, whose values the owner
// sends (update_ghosts) after every change of the iterate. Newton's
// residual is zero at the ghosts (zero_ghosts), so every norm and inner
// product is a sum over ranks of their own equations' terms (sum, taken in
// the same order on every rank). Decisions (convergence, a step cut, an
// event, a contact that needs a shorter step) then come out the same on
// every rank, or are agreed (any).
// Design after PETSc's ghosted vectors (VecCreateGhost, Balay et al., PETSc
// Users Manual §2.4) and deal.II's locally owned/relevant index sets
// (step-40), with the partition by connected structure of doc/theory.md §3.5d.
#ifndef poundfe_assembly_rank_ownership_h
#define poundfe_assembly_rank_ownership_h

#include <Eigen/Core>

#include <array>
#include <cmath>

namespace poundfe
{
  class RankOwnership
  {
  public:
    virtual ~RankOwnership() = default;

    /// [first, last): this rank's equations.
    virtual std::array<unsigned int, 2> owned_range() const = 0;
    virtual unsigned int                n_ranks() const       = 0;
    /// The sum over ranks of x[0..n) (in place; collective), the same bits
    /// on every rank.
    virtual void sum(double *x, unsigned int n) const = 0;
    double       sum(double x) const
    {
      sum(&x, 1);
      return x;
    }
    /// Whether any rank says true (collective).
    virtual bool any(bool x) const = 0;
    /// x[0..n) of every rank, rank after rank, into `all` (n x n_ranks).
    virtual void all_gather(const double *x, unsigned int n, double *all) const = 0;
    /// The owners' values of x at this rank's ghost equations (collective).
    virtual void update_ghosts(Eigen::VectorXd &x) const = 0;
    /// x = 0 at this rank's ghost equations.
    virtual void zero_ghosts(Eigen::VectorXd &x) const = 0;

    /// a . b over every rank's own equations (collective).
    double
    dot(const Eigen::VectorXd &a, const Eigen::VectorXd &b) const
    {
      const auto [first, last] = owned_range();
      return sum(a.segment(first, last - first).dot(b.segment(first, last - first)));
    }
    double norm(const Eigen::VectorXd &x) const { return std::sqrt(dot(x, x)); }
  };
} // namespace poundfe

#endif
