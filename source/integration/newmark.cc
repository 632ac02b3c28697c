#include <poundfe/assembly/linear_solver.h>
#include <poundfe/assembly/low_rank_update.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/integration/newmark.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace poundfe
{
  /// Everything that depends on the step size: Newmark coefficients, the
  /// effective matrix and its factorisation. Level c has dt / 2^c.
  struct NewmarkIntegrator::Level
  {
    double                        dt = 0;
    double                        c_mass_u, c_mass_v, c_mass_a; // a_{n+1} = c_u du - c_v v - c_a a
    double                        c_damp_u, c_damp_v, c_damp_a;
    SparseMatrix                  effective;
    std::vector<double>           base_values;
    std::unique_ptr<LinearSolver> solver;
    LowRankUpdateSolver           woodbury;
    // refactorize: positions of each element's entries in effective's values
    std::vector<std::array<int, 4>> entry_index;
  };

  NewmarkIntegrator::NewmarkIntegrator(const LinearSystem &system,
                                       const std::string  &linear_solver,
                                       const NewmarkParameters &parameters,
                                       UniaxialElements        *elements)
    : system(system)
    , solver_name(linear_solver)
    , parameters(parameters)
    , elements(elements)
    , n_elements(elements ? elements->size() : 0)
  {
    const std::string &mode = parameters.newton.tangent_update;
    use_woodbury = mode == "woodbury" || (mode == "auto" && n_elements <= 100);
    const unsigned int n = system.n_equations();
    for (Vector *x : {&u, &v, &a, &load_now, &u_next, &v_next, &a_next, &rhs, &residual,
                      &increment, &work_vector, &load_next})
      x->setZero(n);
    for (auto *x : {&correction, &tangent_change, &committed_deformation, &committed_force,
                    &committed_history, &committed_rate, &work})
      x->assign(n_elements, 0.0);
    for (unsigned int h = 0; h < n_elements; ++h)
      if ((*elements)[h].kind == ElementKind::gap)
        gap_elements.push_back(h);
    level(0);
  }

  NewmarkIntegrator::~NewmarkIntegrator() = default;

  std::string
  NewmarkIntegrator::linear_solver_name() const
  {
    return levels[0]->solver->name();
  }

  NewmarkIntegrator::Level &
  NewmarkIntegrator::level(const unsigned int cuts)
  {
    if (levels.size() > cuts && levels[cuts])
      return *levels[cuts];
    if (levels.size() <= cuts)
      levels.resize(cuts + 1);
    auto L = std::make_unique<Level>();
    const double dt = parameters.time_step / std::ldexp(1.0, cuts);
    const double g = parameters.gamma, b = parameters.beta;
    L->dt       = dt;
    L->c_mass_u = 1 / (b * dt * dt);
    L->c_mass_v = 1 / (b * dt);
    L->c_mass_a = 1 / (2 * b) - 1;
    L->c_damp_u = g / (b * dt);
    L->c_damp_v = g / b - 1;
    L->c_damp_a = dt * (g / (2 * b) - 1);
    L->effective = system.stiffness + L->c_damp_u * system.damping + L->c_mass_u * system.mass;
    if (!use_woodbury)
      {
        // Every coupling of a nonlinear element must be in the pattern.
        for (unsigned int h = 0; h < n_elements; ++h)
          for (const int i : (*elements)[h].equations)
            for (const int j : (*elements)[h].equations)
              if (i >= 0 && j >= 0)
                L->effective.coeffRef(i, j) += 0.0;
      }
    L->effective.makeCompressed();
    L->solver = create_linear_solver(solver_name);
    L->solver->analyze_and_factorize(L->effective);
    if (n_elements > 0 && use_woodbury)
      {
        std::vector<SparseColumn> columns(n_elements);
        for (unsigned int h = 0; h < n_elements; ++h)
          {
            columns[h].rows   = (*elements)[h].equations;
            columns[h].values = (*elements)[h].signs;
          }
        L->woodbury.initialize(*L->solver, columns, system.n_equations());
      }
    else if (n_elements > 0)
      {
        L->base_values.assign(L->effective.valuePtr(),
                              L->effective.valuePtr() + L->effective.nonZeros());
        L->entry_index.resize(n_elements);
        for (unsigned int h = 0; h < n_elements; ++h)
          {
            const auto &eq = (*elements)[h].equations;
            for (unsigned int i = 0; i < 2; ++i)
              for (unsigned int j = 0; j < 2; ++j)
                L->entry_index[h][2 * i + j] =
                  (eq[i] >= 0 && eq[j] >= 0) ?
                    &L->effective.coeffRef(eq[i], eq[j]) - L->effective.valuePtr() :
                    -1;
          }
      }
    levels[cuts] = std::move(L);
    return *levels[cuts];
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
    u            = u0;
    v            = v0;
    load_now     = load;
    step_count   = 0;
    current_time = 0;
    stats        = IterationStatistics();
    stats.smallest_time_step = parameters.time_step;
    balance           = EnergyBalance();
    impacts.reset(n_elements);
    energy_scale      = 0;
    max_balance_error = 0;
    Vector r = load - system.damping * v0 - system.stiffness * u0;
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        UniaxialElement &e = (*elements)[h];
        e.law->reset();
        const double d = e.deformation(u0);
        if (!e.law->set_trial(d, e.deformation(v0)))
          throw NumericalError("initial state: " + e.label + ": " + e.law->failure());
        e.law->commit();
        committed_deformation[h] = d;
        committed_force[h]       = e.law->force();
        committed_history[h]     = e.law->history_variable();
        committed_rate[h]        = e.deformation(v0);
        work[h]                  = e.law->stored_energy();
        const double f           = e.law->force() - e.reference_stiffness * d;
        for (unsigned int i = 0; i < 2; ++i)
          if (e.equations[i] >= 0)
            r[e.equations[i]] -= e.signs[i] * f;
      }

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
    Vector rr(n_massive);
    for (unsigned int i = 0; i < n; ++i)
      if (reduced[i] >= 0)
        rr[reduced[i]] = r[i];
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(mass);
    if (ldlt.info() != Eigen::Success)
      throw NumericalError("Newmark: the mass matrix of the massive DOFs is singular");
    const Vector a_massive = ldlt.solve(rr);
    a.setZero(n);
    for (unsigned int i = 0; i < n; ++i)
      if (reduced[i] >= 0)
        a[i] = a_massive[reduced[i]];
    balance.strain  = strain_energy();
    balance.kinetic = kinetic_energy();
    balance.initial = balance.strain + balance.kinetic;
  }

  bool
  NewmarkIntegrator::evaluate_elements(const Vector &u_trial, const Vector &v_trial,
                                       const Level &L)
  {
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        UniaxialElement &e = (*elements)[h];
        const double     d = e.deformation(u_trial);
        if (!e.law->set_trial(d, e.deformation(v_trial)))
          {
            failure = e.label + ": " + e.law->failure();
            return false;
          }
        correction[h] = e.law->force() - e.reference_stiffness * d;
        tangent_change[h] =
          e.law->tangent() - e.reference_stiffness + L.c_damp_u * e.law->damping_tangent();
      }
    return true;
  }

  void
  NewmarkIntegrator::subtract_element_forces(Vector &r) const
  {
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const UniaxialElement &e = (*elements)[h];
        for (unsigned int i = 0; i < 2; ++i)
          if (e.equations[i] >= 0)
            r[e.equations[i]] -= e.signs[i] * correction[h];
      }
  }

  bool
  NewmarkIntegrator::try_step(Level &L, const Vector &p)
  {
    const double g = parameters.gamma, dt = L.dt;
    // rhs = p + M (c_u u + c_v v + c_a a) + C (c_u' u + c_v' v + c_a' a)
    rhs                   = p;
    work_vector.noalias() = L.c_mass_u * u + L.c_mass_v * v + L.c_mass_a * a;
    rhs.noalias() += system.mass * work_vector;
    work_vector.noalias() = L.c_damp_u * u + L.c_damp_v * v + L.c_damp_a * a;
    rhs.noalias() += system.damping * work_vector;

    auto kinematics = [&]() {
      a_next.noalias() = L.c_mass_u * (u_next - u) - L.c_mass_v * v - L.c_mass_a * a;
      v_next.noalias() = v + dt * ((1 - g) * a + g * a_next);
    };

    if (n_elements == 0)
      {
        L.solver->solve(rhs, u_next);
        kinematics();
        ++stats.iterations;
        stats.max_iterations = std::max(stats.max_iterations, 1u);
        if (!std::isfinite(u_next.squaredNorm()))
          {
            failure = "the displacement became non-finite";
            return false;
          }
        return true;
      }

    const NewtonParameters &newton = parameters.newton;
    u_next                         = u; // predictor
    double first_residual = 0, first_energy = 0;
    for (unsigned int it = 0;; ++it)
      {
        kinematics();
        if (!evaluate_elements(u_next, v_next, L))
          return false;
        if (!use_woodbury) // L.effective holds the last tangent: restore K_eff
          std::copy(L.base_values.begin(), L.base_values.end(), L.effective.valuePtr());
        residual.noalias() = rhs - L.effective * u_next;
        subtract_element_forces(residual);
        const double norm = residual.norm();
        if (!std::isfinite(norm))
          {
            failure = "the residual became non-finite";
            return false;
          }
        if (it == 0)
          first_residual = norm;
        const double floor = 1e-13 * rhs.norm();
        const bool   small = norm <= std::max(newton.residual_tolerance * first_residual, floor);
        if (it > 0 && small &&
            (std::abs(increment.dot(residual)) <= newton.energy_tolerance * first_energy ||
             norm <= floor))
          {
            stats.iterations += it;
            stats.max_iterations = std::max(stats.max_iterations, it);
            return true;
          }
        if (it == 0 && norm <= floor)
          return true;
        if (it == newton.max_iterations)
          {
            // Where the equations are most out of balance, for the message.
            Eigen::Index worst = 0;
            residual.cwiseAbs().maxCoeff(&worst);
            std::ostringstream message;
            message << "Newton did not converge in " << it << " iterations (residual "
                    << norm << ", " << norm / std::max(first_residual, 1e-300)
                    << " of the first; largest at equation " << worst;
            if (static_cast<std::size_t>(worst) < equation_names.size())
              message << ", " << equation_names[worst];
            message << ")";
            failure = message.str();
            return false;
          }

        if (use_woodbury)
          L.woodbury.solve(residual, tangent_change, increment);
        else
          {
            double *values = L.effective.valuePtr();
            for (unsigned int h = 0; h < n_elements; ++h)
              {
                const auto &s = (*elements)[h].signs;
                for (unsigned int i = 0; i < 2; ++i)
                  for (unsigned int j = 0; j < 2; ++j)
                    if (L.entry_index[h][2 * i + j] >= 0)
                      values[L.entry_index[h][2 * i + j]] += tangent_change[h] * s[i] * s[j];
              }
            L.solver->factorize(L.effective);
            L.solver->solve(residual, increment);
          }
        if (it == 0)
          first_energy = std::abs(increment.dot(residual));
        u_next += increment;
      }
  }

  void
  NewmarkIntegrator::residual_and_tangent(const Vector &load, const Vector &u_trial,
                                          Vector &residual_out, Eigen::MatrixXd &tangent_out)
  {
    Level       &L  = level(0);
    const double g  = parameters.gamma;
    Vector       an = L.c_mass_u * (u_trial - u) - L.c_mass_v * v - L.c_mass_a * a;
    Vector       vn = v + L.dt * ((1 - g) * a + g * an);
    if (!evaluate_elements(u_trial, vn, L))
      throw NumericalError(failure);
    if (!use_woodbury)
      std::copy(L.base_values.begin(), L.base_values.end(), L.effective.valuePtr());
    residual_out = load - system.mass * an - system.damping * vn - system.stiffness * u_trial;
    subtract_element_forces(residual_out);
    tangent_out = Eigen::MatrixXd(L.effective);
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const UniaxialElement &e = (*elements)[h];
        for (unsigned int i = 0; i < 2; ++i)
          if (e.equations[i] >= 0)
            {
              for (unsigned int j = 0; j < 2; ++j)
                if (e.equations[j] >= 0)
                  tangent_out(e.equations[i], e.equations[j]) +=
                    tangent_change[h] * e.signs[i] * e.signs[j];
            }
      }
    for (unsigned int h = 0; h < n_elements; ++h)
      (*elements)[h].law->revert();
  }

  void
  NewmarkIntegrator::accept(const Level &L, const Vector &p)
  {
    for (const unsigned int h : gap_elements)
      {
        const UniaxialElement &e = (*elements)[h];
        impacts.record(h, current_time, current_time + L.dt,
                       {committed_history[h], committed_rate[h], committed_force[h]},
                       {e.law->history_variable(), e.deformation(v_next), e.law->force()});
      }
    // Trapezoidal work of the step; exact for the average-acceleration rule.
    work_vector = u_next - u;
    balance.input += 0.5 * work_vector.dot(load_now + p);
    balance.damping += 0.5 * work_vector.dot(system.damping * (v + v_next));
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        UniaxialElement &e = (*elements)[h];
        const double     d = e.deformation(u_next);
        work[h] += 0.5 * (committed_force[h] + e.law->force()) * (d - committed_deformation[h]);
        e.law->commit();
        committed_deformation[h] = d;
        committed_force[h]       = e.law->force();
        committed_history[h]     = e.law->history_variable();
        committed_rate[h]        = e.deformation(v_next);
      }
    u.swap(u_next);
    v.swap(v_next);
    a.swap(a_next);
    load_now = p;
    ++stats.steps;
    stats.smallest_time_step = std::min(stats.smallest_time_step, L.dt);
  }

  void
  NewmarkIntegrator::advance_from(const unsigned int cuts, const double t0,
                                  const LoadFunction &load)
  {
    Level       &L  = level(cuts);
    const double t1 = (cuts == 0) ? (step_count + 1) * parameters.time_step : t0 + L.dt;
    load(t1, load_next);
    const Vector p = load_next; // load_next is reused by the sub-steps
    const bool converged = try_step(L, p);
    bool       event     = false;
    if (converged && cuts < parameters.newton.event_refinement)
      for (const unsigned int h : gap_elements)
        event = event || (*elements)[h].law->is_active() != (*elements)[h].law->was_active();
    if (converged && !event)
      {
        accept(L, p);
        current_time = t1;
        return;
      }
    for (unsigned int h = 0; h < n_elements; ++h)
      (*elements)[h].law->revert();
    if (event)
      {
        ++stats.event_refinements;
        advance_from(cuts + 1, t0, load);
        advance_from(cuts + 1, t0 + 0.5 * L.dt, load);
        return;
      }
    if (cuts >= parameters.newton.max_step_cuts)
      {
        std::ostringstream message;
        message << "the step from t = " << t0 << " s failed even at dt = " << L.dt << " s ("
                << cuts << " step cuts): " << failure;
        throw NumericalError(message.str());
      }
    ++stats.step_cuts;
    advance_from(cuts + 1, t0, load);
    advance_from(cuts + 1, t0 + 0.5 * L.dt, load);
  }

  void
  NewmarkIntegrator::advance(const LoadFunction &load)
  {
    advance_from(0, current_time, load);
    ++step_count;
    current_time = step_count * parameters.time_step;
    update_energy_error();
  }

  void
  NewmarkIntegrator::advance(const Vector &load)
  {
    advance([&load](double, Vector &p) { p = load; });
  }

  void
  NewmarkIntegrator::update_energy_error()
  {
    balance.kinetic = kinetic_energy();
    balance.strain  = strain_energy();
    double dissipated_hysteretic = 0, dissipated_contact = 0;
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const UniaxialElement &e         = (*elements)[h];
        const double           dissipated = work[h] - e.law->stored_energy();
        (e.kind == ElementKind::gap ? dissipated_contact : dissipated_hysteretic) += dissipated;
      }
    balance.hysteretic = dissipated_hysteretic;
    balance.contact    = dissipated_contact;
    const double sum   = balance.stored_and_dissipated();
    const double supplied = balance.initial + balance.input;
    energy_scale          = std::max({energy_scale, std::abs(supplied), sum});
    if (energy_scale > 0)
      max_balance_error = std::max(max_balance_error, std::abs(supplied - sum) / energy_scale);
  }

  EnergyBalance
  NewmarkIntegrator::energy() const
  {
    return balance;
  }

  double
  NewmarkIntegrator::kinetic_energy() const
  {
    return 0.5 * v.dot(system.mass * v);
  }

  double
  NewmarkIntegrator::strain_energy() const
  {
    double energy = 0.5 * u.dot(system.stiffness * u);
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const UniaxialElement &e = (*elements)[h];
        const double           d = e.deformation(u);
        energy += e.law->stored_energy() - 0.5 * e.reference_stiffness * d * d;
      }
    return energy;
  }
} // namespace poundfe
