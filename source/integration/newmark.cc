#include <poundfe/base/exceptions.h>
#include <poundfe/integration/newmark.h>

#include <Eigen/SparseCholesky>

#include <cmath>
#include <sstream>

namespace poundfe
{
  NewmarkIntegrator::NewmarkIntegrator(const LinearSystem &system, LinearSolver &solver,
                                       const NewmarkParameters &parameters)
    : system(system)
    , solver(solver)
    , parameters(parameters)
  {
    const double dt = parameters.time_step, g = parameters.gamma, b = parameters.beta;
    c_mass_u = 1 / (b * dt * dt);
    c_mass_v = 1 / (b * dt);
    c_mass_a = 1 / (2 * b) - 1;
    c_damp_u = g / (b * dt);
    c_damp_v = g / b - 1;
    c_damp_a = dt * (g / (2 * b) - 1);
    effective = system.stiffness + c_damp_u * system.damping + c_mass_u * system.mass;
    effective.makeCompressed();
    solver.analyze_and_factorize(effective);
    const unsigned int n = system.n_equations();
    for (Vector *x : {&u, &v, &a, &u_next, &rhs, &work})
      x->setZero(n);
  }

  void
  NewmarkIntegrator::initialize(const Vector &load)
  {
    const Vector zero = Vector::Zero(system.n_equations());
    initialize(load, zero, zero);
  }

  void
  NewmarkIntegrator::initialize(const Vector &load, const Vector &u0, const Vector &v0)
  {
    u          = u0;
    v          = v0;
    step_count = 0;
    const Vector residual = load - system.damping * v0 - system.stiffness * u0;

    // Equations that carry mass: any nonzero in their row of M.
    const unsigned int n = system.n_equations();
    std::vector<int>   reduced(n, -1);
    unsigned int       n_massive = 0;
    for (int column = 0; column < system.mass.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(system.mass, column); it; ++it)
        if (it.value() != 0 && reduced[it.row()] < 0)
          reduced[it.row()] = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (reduced[i] == 0)
        reduced[i] = n_massive++;

    std::vector<Eigen::Triplet<double>> triplets;
    for (int column = 0; column < system.mass.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(system.mass, column); it; ++it)
        if (reduced[it.row()] >= 0 && reduced[it.col()] >= 0)
          triplets.emplace_back(reduced[it.row()], reduced[it.col()], it.value());
    SparseMatrix mass(n_massive, n_massive);
    mass.setFromTriplets(triplets.begin(), triplets.end());
    Vector r(n_massive);
    for (unsigned int i = 0; i < n; ++i)
      if (reduced[i] >= 0)
        r[reduced[i]] = residual[i];
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(mass);
    if (ldlt.info() != Eigen::Success)
      throw NumericalError("Newmark: the mass matrix of the massive DOFs is singular");
    const Vector a_massive = ldlt.solve(r);
    a.setZero(n);
    for (unsigned int i = 0; i < n; ++i)
      if (reduced[i] >= 0)
        a[i] = a_massive[reduced[i]];
  }

  void
  NewmarkIntegrator::advance(const Vector &load)
  {
    const double dt = parameters.time_step;
    rhs             = load;
    work.noalias()  = c_mass_u * u + c_mass_v * v + c_mass_a * a;
    rhs.noalias() += system.mass * work;
    work.noalias() = c_damp_u * u + c_damp_v * v + c_damp_a * a;
    rhs.noalias() += system.damping * work;
    solver.solve(rhs, u_next);

    // a_{n+1} and v_{n+1} from the Newmark relations, in place.
    work.noalias() = c_mass_u * (u_next - u) - c_mass_v * v - c_mass_a * a; // a_{n+1}
    v += dt * ((1 - parameters.gamma) * a + parameters.gamma * work);
    a.swap(work);
    u.swap(u_next);
    ++step_count;
    if (!std::isfinite(u.squaredNorm()))
      {
        std::ostringstream message;
        message << "Newmark: the displacement became non-finite at t = " << time() << " s";
        throw NumericalError(message.str());
      }
  }

  double
  NewmarkIntegrator::kinetic_energy() const
  {
    return 0.5 * v.dot(system.mass * v);
  }

  double
  NewmarkIntegrator::strain_energy() const
  {
    return 0.5 * u.dot(system.stiffness * u);
  }
} // namespace poundfe
