// The vector arithmetic of a Newmark–Newton step (integration/newmark.h),
// written once for any storage and run on two: the general one (sparse M,
// C, K, K_eff, vectors of run-time size, modal damping, a model over ranks)
// and, for models of at most FixedSizeStep::max_size equations, dense
// matrices and vectors whose size N is fixed at compile time (chosen once,
// when a step size's level is made).
//   r_0 = p - K u + M (c_v v + c_a a) + C (c_v' v + c_a' a)        (start residual)
//   floor = 1e-13 (|p| + |K u| + |M (...)| + |C (...)|)            (its round-off)
//   r = r_0 - K_eff du                        (Newton's residual before f(u + du))
//   a_{n+1} = c_u du - c_v v_n - c_a a_n,  v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1})
//   W_input += du . (p_n + p_{n+1}) / 2,  W_damping += du . C (v_n + v_{n+1}) / 2
//   T = v . M v / 2
// Sources: Chopra, Dynamics of Structures, 4th ed., §5.4, Table 5.7.2;
// Belytschko, Liu & Moran, Nonlinear Finite Elements, §6.3 (the work sums);
// doc/theory.md §3.3 (r_0 term by term).
// Why a fixed size: on a 1–12-equation model each operation on a vector of
// run-time size costs a few dozen instructions of set-up (sizes, alignment,
// a loop's head and tail) around a handful of flops; with N fixed the loops
// unroll. The dense products run column by column, j = 0 .. N-1, as Eigen's
// column-major sparse product does, so they give its bits (the zeros of the
// dense matrix add nothing); the norms and dot products are Eigen's of
// fixed size, whose order of summation differs from the run-time size's
// from 6 equations on (round-off: doc/verification.md).
// The solves of K_eff by eigen-ldlt run in fixed size too (with_fixed_size_solve):
//   x = P^-1 L^-T D^-1 L^-1 P b
// on a dense copy of the factors of Eigen's SimplicialLDLT of the same matrix
// (the same P, L, D), substituted in Eigen's order (L by columns, skipping a
// zero entry of the right-hand side, L^T by rows, each row's entries in
// ascending order), so that every solve gives the sparse solve's bits.
#ifndef poundfe_integration_fixed_size_step_h
#define poundfe_integration_fixed_size_step_h

#include <poundfe/assembly/linear_solver.h>
#include <poundfe/assembly/linear_system.h>

#include <memory>

namespace poundfe
{
  /// Newmark's coefficients of one step size dt (NewmarkIntegrator's levels):
  /// a_{n+1} = c_mass_u du - c_mass_v v - c_mass_a a, and the damping's.
  struct NewmarkCoefficients
  {
    double dt = 0, gamma = 0.5;
    double c_mass_u = 0, c_mass_v = 0, c_mass_a = 0;
    double c_damp_u = 0, c_damp_v = 0, c_damp_a = 0;
  };

  /// The formulas above on a storage S, which gives y = M x and y = C x
  /// (`mass_product`, `damping_product`), y -= K_eff x
  /// (`subtract_effective_product`) and `norm`.
  namespace newmark_formulas
  {
    /// r_0 into `r0`; returns its round-off floor.
    template <class S, class In, class Out, class Work>
    double
    start_residual(const S &s, const NewmarkCoefficients &c, const In &p, const In &stiffness_u,
                   const In &v, const In &a, Work &work, Work &product, Out &r0)
    {
      double floor = s.norm(p) + s.norm(stiffness_u);
      r0           = p - stiffness_u;
      work.noalias() = c.c_mass_v * v + c.c_mass_a * a;
      s.mass_product(work, product);
      floor += s.norm(product);
      r0 += product;
      work.noalias() = c.c_damp_v * v + c.c_damp_a * a;
      s.damping_product(work, product);
      floor += s.norm(product);
      r0 += product;
      // below this a residual is the round-off of its terms
      return floor * 1e-13;
    }

    /// a_{n+1} and v_{n+1} of the step's displacement du.
    template <class In, class Out>
    void
    kinematics(const NewmarkCoefficients &c, const In &du, const In &v, const In &a,
               Out &v_next, Out &a_next)
    {
      const double g = c.gamma;
      a_next.noalias() = c.c_mass_u * du - c.c_mass_v * v - c.c_mass_a * a;
      v_next.noalias() = v + c.dt * ((1 - g) * a + g * a_next);
    }

    /// r = r_0 - K_eff du (K_eff's part without a modal damping's).
    template <class S, class In, class Out>
    void
    effective_residual(const S &s, const In &r0, const In &du, Out &r)
    {
      r = r0;
      s.subtract_effective_product(du, r);
    }

    /// The trapezoidal input and damping work of an accepted step; `work`
    /// and `product` are scratch.
    template <class S, class In, class Work>
    void
    add_step_work(const S &s, const In &du, const In &p_start, const In &p_end, const In &v,
                  const In &v_next, Work &work, Work &product, double &input, double &damping)
    {
      input += 0.5 * du.dot(p_start + p_end);
      work = v + v_next;
      s.damping_product(work, product);
      damping += 0.5 * du.dot(product);
    }

    /// v . M v / 2; `product` is scratch.
    template <class S, class In, class Work>
    double
    kinetic_energy(const S &s, const In &v, Work &product)
    {
      s.mass_product(v, product);
      return 0.5 * v.dot(product);
    }
  } // namespace newmark_formulas

  /// The formulas above on the fixed-size storage of one step size: dense
  /// copies of M, C, K and K_eff, and the vectors of the integrator seen as
  /// vectors of N entries. One virtual call per phase of the step.
  class FixedSizeStep
  {
  public:
    /// The most equations held in fixed size: dense products of N^2
    /// multiply-adds stay below the sparse ones' bookkeeping up to here.
    static constexpr unsigned int max_size = 12;

    virtual ~FixedSizeStep() = default;

    virtual void   stiffness_product(const Vector &u, Vector &stiffness_u) const = 0;
    virtual double start_residual(const NewmarkCoefficients &c, const Vector &p,
                                  const Vector &stiffness_u, const Vector &v, const Vector &a,
                                  Vector &r0) const = 0;
    virtual void   kinematics(const NewmarkCoefficients &c, const Vector &du, const Vector &v,
                              const Vector &a, Vector &v_next, Vector &a_next) const = 0;
    /// u_next = u + du
    virtual void   iterate(const Vector &u, const Vector &du, Vector &u_next) const = 0;
    /// r = r_0 - K_eff du, or r = r_0 (the same bits) when du = 0.
    virtual void   effective_residual(const Vector &r0, const Vector &du, Vector &r) const = 0;
    virtual void   add_step_work(const Vector &du, const Vector &p_start, const Vector &p_end,
                                 const Vector &v, const Vector &v_next, double &input,
                                 double &damping) const = 0;
    virtual double kinetic_energy(const Vector &v) const = 0;
    virtual double norm(const Vector &x) const = 0;
    virtual double dot(const Vector &x, const Vector &y) const = 0;
  };

  /// The fixed-size step of `system` with the effective matrix `effective`
  /// (K_eff of one step size), or null where the general one serves: more
  /// than FixedSizeStep::max_size equations, or modal damping.
  std::unique_ptr<FixedSizeStep>
  make_fixed_size_step(const LinearSystem &system, const SparseMatrix &effective);

  /// `solver`, an eigen-ldlt solver of n equations (n <= FixedSizeStep::
  /// max_size), whose solves run in fixed size on a dense copy of the same
  /// factors (above); its analysis and factorisation, with their checks, are
  /// still `solver`'s. Any other solver or size: `solver` itself.
  std::unique_ptr<LinearSolver>
  with_fixed_size_solve(std::unique_ptr<LinearSolver> solver, unsigned int n);
} // namespace poundfe

#endif
