// Event-driven adaptive Dormand–Prince 5(4): the tableau, the step, its
// dense output and the structural right-hand side; equations and sources
// in integration/dormand_prince.h.
#include <poundfe/assembly/modal_damping.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/integration/dormand_prince.h>
#include <poundfe/integration/element_kind_text.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    // Hairer, Nørsett & Wanner, Table II.5.2 (c_i, a_ij, b_i = a_7j) and
    // the error coefficients e_i = b_i - b^_i.
    constexpr double c2 = 1. / 5, c3 = 3. / 10, c4 = 4. / 5, c5 = 8. / 9;
    constexpr double a21 = 1. / 5;
    constexpr double a31 = 3. / 40, a32 = 9. / 40;
    constexpr double a41 = 44. / 45, a42 = -56. / 15, a43 = 32. / 9;
    constexpr double a51 = 19372. / 6561, a52 = -25360. / 2187, a53 = 64448. / 6561,
                     a54 = -212. / 729;
    constexpr double a61 = 9017. / 3168, a62 = -355. / 33, a63 = 46732. / 5247, a64 = 49. / 176,
                     a65 = -5103. / 18656;
    constexpr double b1 = 35. / 384, b3 = 500. / 1113, b4 = 125. / 192, b5 = -2187. / 6784,
                     b6 = 11. / 84;
    constexpr double e1 = 71. / 57600, e3 = -71. / 16695, e4 = 71. / 1920, e5 = -17253. / 339200,
                     e6 = 22. / 525, e7 = -1. / 40;
    // The dense output's fifth coefficient (Hairer's dopri5, after Shampine 1986).
    constexpr double d1 = -12715105075. / 11282082432., d3 = 87487479700. / 32700410799.,
                     d4 = -10690763975. / 1880347072., d5 = 701980252875. / 199316789632.,
                     d6 = -1453857185. / 822651844., d7 = 69997945. / 29380423.;

    /// The extra components after (u, v): input, damping, then each element's work.
    constexpr unsigned int n_energy_terms = 2;
  } // namespace

  void
  DormandPrinceStep::take(const Rhs &F, const double t, const Vector &y, const Vector &k_1,
                          const double h)
  {
    k[0] = k_1;
    stage = y + h * a21 * k[0];
    F(t + c2 * h, stage, k[1]);
    stage = y + h * (a31 * k[0] + a32 * k[1]);
    F(t + c3 * h, stage, k[2]);
    stage = y + h * (a41 * k[0] + a42 * k[1] + a43 * k[2]);
    F(t + c4 * h, stage, k[3]);
    stage = y + h * (a51 * k[0] + a52 * k[1] + a53 * k[2] + a54 * k[3]);
    F(t + c5 * h, stage, k[4]);
    stage = y + h * (a61 * k[0] + a62 * k[1] + a63 * k[2] + a64 * k[3] + a65 * k[4]);
    F(t + h, stage, k[5]);
    y1 = y + h * (b1 * k[0] + b3 * k[2] + b4 * k[3] + b5 * k[4] + b6 * k[5]);
    F(t + h, y1, k[6]);
    k7    = k[6];
    error = h * (e1 * k[0] + e3 * k[2] + e4 * k[3] + e5 * k[4] + e6 * k[5] + e7 * k[6]);
    r1 = y;
    r2 = y1 - y;
    r3 = h * k[0] - r2;
    r4 = r2 - h * k[6] - r3;
    r5 = h * (d1 * k[0] + d3 * k[2] + d4 * k[3] + d5 * k[4] + d6 * k[5] + d7 * k[6]);
  }

  void
  DormandPrinceStep::dense_output(const double theta, Vector &out) const
  {
    const double s = 1 - theta;
    out = r1 + theta * (r2 + s * (r3 + theta * (r4 + s * r5)));
  }

  double
  DormandPrinceStep::error_norm(const Vector &y0, const double rtol, const double atol,
                                const unsigned int n_controlled) const
  {
    double sum = 0;
    for (unsigned int i = 0; i < n_controlled; ++i)
      {
        const double scale = atol + rtol * std::max(std::abs(y0[i]), std::abs(y1[i]));
        sum += (error[i] / scale) * (error[i] / scale);
      }
    return std::sqrt(sum / std::max(1u, n_controlled));
  }

  double
  DormandPrinceStep::next_size(const double h, const double err)
  {
    if (!std::isfinite(err))
      return 0.2 * h;
    return h * std::min(5.0, std::max(0.2, 0.9 * std::pow(std::max(err, 1e-10), -0.2)));
  }

  double
  DormandPrinceStep::locate_change(const double h, const double resolution,
                                   const std::function<bool(double)> &unchanged)
  {
    double lo = 0, hi = 1;
    while ((hi - lo) * h > resolution)
      {
        const double mid = 0.5 * (lo + hi);
        (unchanged(mid) ? lo : hi) = mid;
      }
    return hi;
  }

  std::string
  element_kind_text(const NonlinearElement &e)
  {
    switch (e.kind)
      {
        case ElementKind::hinge:
          return "a plastic hinge";
        case ElementKind::storey:
          return "a hysteretic storey";
        case ElementKind::friction:
          return "a friction element";
        case ElementKind::link:
          return "a link between buildings";
        case ElementKind::foundation:
          return "a foundation spring";
        case ElementKind::member:
          return "a fibre member";
        default:
          return "a contact in plan (rank " + std::to_string(e.rank()) + ")";
      }
  }

  std::string
  DormandPrinceIntegrator::unsupported(const LinearSystem &system,
                                       const NonlinearElements *elements,
                                       const unsigned int max_equations)
  {
    const unsigned int n = system.n_equations();
    if (n > max_equations)
      return "takes models of up to " + std::to_string(max_equations) + " equations; this one has " +
             std::to_string(n) + " (use newmark)";
    const Eigen::MatrixXd mass(system.mass);
    for (unsigned int i = 0; i < n; ++i)
      if (!(mass(i, i) > 0))
        return "needs mass on every equation; equation " + std::to_string(i) +
               " has none (a rotation of a frame under lumped mass: use newmark)";
    if (elements)
      for (const NonlinearElement &e : *elements)
        if (!((e.kind == ElementKind::gap || e.kind == ElementKind::spring) && e.rank() == 1))
          return "integrates contacts and elastic springs only; " + e.label + " is " +
                 element_kind_text(e) + " (use newmark)";
    return {};
  }

  DormandPrinceIntegrator::DormandPrinceIntegrator(const LinearSystem &system_,
                                                   const DormandPrinceParameters &parameters_,
                                                   NonlinearElements *elements_)
    : system(system_)
    , parameters(parameters_)
    , elements(elements_)
    , n(system_.n_equations())
    , n_elements(elements_ ? elements_->size() : 0)
  {
    Assert(unsupported(system, elements, parameters.max_equations).empty(),
           dealii::ExcMessage(unsupported(system, elements, parameters.max_equations)));
    mass_factor.compute(Eigen::MatrixXd(system.mass));
    AssertThrow(mass_factor.info() == Eigen::Success,
                dealii::ExcMessage("Dormand-Prince: the mass matrix is not positive definite"));
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        if ((*elements)[h].kind == ElementKind::gap)
          gap_elements.push_back(h);
        event_elements.push_back(h);
      }
    work.assign(n_elements, 0.0);
    for (auto *x : {&supplied, &initial_stored, &committed_force, &committed_history,
                    &committed_rate})
      x->assign(n_elements, 0.0);
    load_vector.setZero(n);
  }

  int
  DormandPrinceIntegrator::set_trial(const Vector &state)
  {
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        NonlinearElement       &e         = (*elements)[h];
        const std::vector<int> &equations = e.equations();
        local_u.resize(e.n_dofs());
        local_v.resize(e.n_dofs());
        for (unsigned int i = 0; i < e.n_dofs(); ++i)
          {
            local_u[i] = equations[i] < 0 ? 0.0 : state[equations[i]];
            local_v[i] = equations[i] < 0 ? 0.0 : state[n + equations[i]];
          }
        if (!e.set_trial(local_u, local_v))
          return h;
      }
    return -1;
  }

  void
  DormandPrinceIntegrator::set_trial_or_throw(const double t, const Vector &state)
  {
    for (unsigned int h = 0; h < n_elements; ++h)
      (*elements)[h].set_trial_time(t);
    if (const int h = set_trial(state); h >= 0)
      throw NumericalError("t = " + number_text(t) + " s: " + (*elements)[h].label + ": " +
                           (*elements)[h].failure());
  }

  void
  DormandPrinceIntegrator::rhs(const double t, const Vector &state, Vector &dy)
  {
    ++evaluations;
    dy.resize(state.size());
    load(t, load_vector);
    const Vector velocity = state.segment(n, n);
    const Vector damping  = damping_product(system, velocity);
    force = load_vector - damping - system.stiffness * state.head(n);
    set_trial_or_throw(t, state);
    Vector correction;
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        NonlinearElement &e = (*elements)[h];
        correction.resize(e.n_dofs());
        e.force_correction(correction);
        for (unsigned int i = 0; i < e.n_dofs(); ++i)
          if (e.equations()[i] >= 0)
            force[e.equations()[i]] -= correction[i];
        dy[2 * n + n_energy_terms + h] = e.force() * e.deformation(velocity);
        e.revert();
      }
    dy.head(n)      = velocity;
    dy.segment(n, n) = mass_factor.solve(force);
    dy[2 * n]       = velocity.dot(load_vector);
    dy[2 * n + 1]   = velocity.dot(damping);
  }

  void
  DormandPrinceIntegrator::phases_at(const double t, const Vector &state, std::vector<int> &out)
  {
    out.assign(event_elements.size(), 0);
    for (unsigned int h = 0; h < n_elements; ++h)
      (*elements)[h].set_trial_time(t);
    if (set_trial(state) >= 0)
      return; // the step's evaluation reports it
    for (unsigned int i = 0; i < event_elements.size(); ++i)
      {
        NonlinearElement &e = (*elements)[event_elements[i]];
        // in contact, the sign of the penetration rate: the damped laws' kink
        const bool closing = e.kind == ElementKind::gap && e.is_active() &&
                             e.deformation(state.segment(n, n)) > 0;
        out[i] = 2 * e.phase() + closing;
      }
    for (unsigned int h = 0; h < n_elements; ++h)
      (*elements)[h].revert();
  }

  void
  DormandPrinceIntegrator::commit_elements(const double t, const Vector &state, const double t0)
  {
    set_trial_or_throw(t, state);
    const Vector velocity = state.segment(n, n);
    if (t0 >= 0)
      for (const unsigned int h : gap_elements)
        {
          const NonlinearElement &e = (*elements)[h];
          impacts.record(h, t0, t, {committed_history[h], committed_rate[h], committed_force[h]},
                         {e.history_variable(), e.deformation(velocity), e.force(),
                          e.contact_point(), e.phase()});
        }
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        NonlinearElement &e = (*elements)[h];
        e.commit();
        committed_force[h]   = e.force();
        committed_history[h] = e.history_variable();
        committed_rate[h]    = e.deformation(velocity);
      }
    phases_at(t, state, phases);
  }

  void
  DormandPrinceIntegrator::initialize(const Vector &load_0, const Vector &u0, const Vector &v0)
  {
    Assert(u0.size() == n && v0.size() == n, dealii::ExcDimensionMismatch(u0.size(), n));
    reset_state(n_elements, parameters.time_step);
    proposed_step = 0;
    y.setZero(2 * n + n_energy_terms + n_elements);
    y.head(n)       = u0;
    y.segment(n, n) = v0;
    load            = [load_0](double, Vector &p) { p = load_0; };
    for (unsigned int h = 0; h < n_elements; ++h)
      (*elements)[h].reset();
    commit_elements(0, y, -1);
    rhs(0, y, k1);
    u = u0;
    v = v0;
    a = k1.segment(n, n);
    for (unsigned int h = 0; h < n_elements; ++h)
      initial_stored[h] = (*elements)[h].stored_energy();
    update_energy(y);
    balance.initial = balance.kinetic + balance.strain;
    energy_scale = max_balance_error = 0;
    update_balance_error(balance, energy_scale, max_balance_error);
  }

  void
  DormandPrinceIntegrator::update_energy(const Vector &state)
  {
    const Vector velocity = state.segment(n, n), displacement = state.head(n);
    balance.kinetic = 0.5 * velocity.dot(system.mass * velocity);
    balance.strain  = 0.5 * displacement.dot(system.stiffness * displacement);
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const NonlinearElement &e = (*elements)[h];
        balance.strain += e.stored_energy() - e.reference_energy();
        work[h] = initial_stored[h] + state[2 * n + n_energy_terms + h];
      }
    balance.input   = state[2 * n];
    balance.damping = state[2 * n + 1];
    if (elements)
      set_element_dissipation(balance, *elements, work, supplied);
  }

  double
  DormandPrinceIntegrator::initial_step(const double t, const double t_end)
  {
    // Hairer, Nørsett & Wanner §II.4, "Starting step size"
    const double rtol = parameters.relative_tolerance, atol = parameters.absolute_tolerance;
    double       d0 = 0, d1 = 0;
    for (unsigned int i = 0; i < 2 * n; ++i)
      {
        const double scale = atol + rtol * std::abs(y[i]);
        d0 += (y[i] / scale) * (y[i] / scale);
        d1 += (k1[i] / scale) * (k1[i] / scale);
      }
    d0 = std::sqrt(d0 / (2 * n));
    d1 = std::sqrt(d1 / (2 * n));
    double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
    h0        = std::min(h0, t_end - t);
    y_trial   = y + h0 * k1;
    Vector f1;
    rhs(t + h0, y_trial, f1);
    double d2 = 0;
    for (unsigned int i = 0; i < 2 * n; ++i)
      {
        const double scale = atol + rtol * std::abs(y[i]);
        d2 += ((f1[i] - k1[i]) / scale) * ((f1[i] - k1[i]) / scale);
      }
    d2              = std::sqrt(d2 / (2 * n)) / h0;
    const double dm = std::max(d1, d2);
    const double h1 = dm <= 1e-15 ? std::max(1e-6, 1e-3 * h0) : std::pow(0.01 / dm, 0.2);
    return std::min(100 * h0, h1);
  }

  double
  DormandPrinceIntegrator::locate_event(const double t0, const double h)
  {
    const double resolution = parameters.event_resolution * std::max(1.0, std::abs(t0));
    return DormandPrinceStep::locate_change(h, resolution, [&](const double theta) {
      step.dense_output(theta, y_trial);
      phases_at(t0 + theta * h, y_trial, trial_phases);
      return trial_phases == phases;
    });
  }

  void
  DormandPrinceIntegrator::integrate_to(const double t_end)
  {
    const DormandPrinceStep::Rhs F = [this](double t, const Vector &s, Vector &dy) {
      rhs(t, s, dy);
    };
    const double  rtol = parameters.relative_tolerance, atol = parameters.absolute_tolerance;
    const bool    fixed = parameters.fixed_step > 0;
    double        t     = current_time;
    unsigned long tries = 0;
    rhs(t, y, k1);
    if (proposed_step <= 0)
      proposed_step = fixed ? parameters.fixed_step : initial_step(t, t_end);
    while (t_end - t > 1e-14 * std::max(1.0, std::abs(t_end)))
      {
        if (++tries > parameters.max_steps_per_output)
          throw NumericalError("t = " + number_text(t) + " s: Dormand-Prince took more than " +
                               std::to_string(parameters.max_steps_per_output) +
                               " steps in one time step (events accumulating?)");
        double     h       = fixed ? parameters.fixed_step : proposed_step;
        const bool clipped = t + 1.01 * h >= t_end;
        if (clipped)
          h = t_end - t;
        step.take(F, t, y, k1, h);
        const double err = fixed ? 0 : step.error_norm(y, rtol, atol, 2 * n);
        if (!(err <= 1))
          {
            ++stats.step_cuts;
            proposed_step = std::min(h, DormandPrinceStep::next_size(h, err));
            if (proposed_step < 1e-14 * std::max(1.0, std::abs(t)))
              throw NumericalError("t = " + number_text(t) + " s: the Dormand-Prince step fell to " +
                                   number_text(proposed_step) + " s");
            continue;
          }
        const double h_next = DormandPrinceStep::next_size(h, err);
        phases_at(t + h, step.y1, trial_phases);
        bool event = false;
        if (trial_phases != phases)
          {
            const double theta = locate_event(t, h);
            event              = theta < 1;
            if (event)
              {
                h *= theta;
                step.take(F, t, y, k1, h);
              }
            ++stats.event_refinements;
          }
        accept(t, h);
        t = (clipped && !event) ? t_end : t + h;
        current_time = t;
        if (!fixed && (!clipped || h_next < proposed_step))
          proposed_step = h_next;
        if (t < t_end && substep_callback)
          substep_callback();
      }
  }

  void
  DormandPrinceIntegrator::accept(const double t0, const double h)
  {
    commit_elements(t0 + h, step.y1, t0);
    y  = step.y1;
    k1 = step.k7;
    u  = y.head(n);
    v  = y.segment(n, n);
    a  = k1.segment(n, n);
    ++stats.steps;
    stats.smallest_time_step = std::min(stats.smallest_time_step, h);
    update_energy(y);
    update_balance_error(balance, energy_scale, max_balance_error);
  }

  void
  DormandPrinceIntegrator::advance(const LoadFunction &load_function)
  {
    load = load_function;
    integrate_to((step_count + 1) * parameters.time_step);
    ++step_count;
    current_time = step_count * parameters.time_step;
  }
} // namespace poundfe
