// Newmark time stepping of M u'' + C u' + K u = p(t) (Newmark 1959).
//   a_{n+1} = (u_{n+1} - u_n)/(beta dt^2) - v_n/(beta dt) - (1/(2 beta) - 1) a_n
//   v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1})
//   K_eff = K + gamma/(beta dt) C + 1/(beta dt^2) M, factorised once.
// Average acceleration (gamma = 1/2, beta = 1/4) conserves the energy of
// undamped free vibration exactly. The initial acceleration solves
// M a_0 = p_0 - C v_0 - K u_0 on the equations that carry mass; massless
// equations (rotations under lumped mass) are static and get a_0 = 0.
// Source: Chopra, Dynamics of Structures, 4th ed., §5.4 and Table 5.4.2.
#ifndef poundfe_integration_newmark_h
#define poundfe_integration_newmark_h

#include <poundfe/assembly/linear_solver.h>
#include <poundfe/assembly/linear_system.h>

namespace poundfe
{
  struct NewmarkParameters
  {
    double time_step = 0.01;
    double gamma     = 0.5;
    double beta      = 0.25;
  };

  class NewmarkIntegrator
  {
  public:
    NewmarkIntegrator(const LinearSystem &system, LinearSolver &solver,
                      const NewmarkParameters &parameters);

    /// Start at time 0 from (u0, v0) under load p0.
    void initialize(const Vector &load, const Vector &u0, const Vector &v0);
    /// Start from rest.
    void initialize(const Vector &load);

    /// Advance one step; `load` is p(t_{n+1}). Throws NumericalError if the
    /// solution stops being finite.
    void advance(const Vector &load);

    double time() const { return step_count * parameters.time_step; }
    unsigned long steps() const { return step_count; }
    const Vector &displacement() const { return u; }
    const Vector &velocity() const { return v; }
    const Vector &acceleration() const { return a; }

    double kinetic_energy() const;
    double strain_energy() const;

  private:
    const LinearSystem &system;
    LinearSolver       &solver;
    NewmarkParameters   parameters;
    double              c_mass_u, c_mass_v, c_mass_a; // M (c_u u + c_v v + c_a a)
    double              c_damp_u, c_damp_v, c_damp_a; // C (...)
    SparseMatrix        effective;
    Vector              u, v, a, u_next, rhs, work;
    unsigned long       step_count = 0;
  };
} // namespace poundfe

#endif
