// Moreau–Jean's theta-scheme with Newton's impact law, the impulses of each
// step from Siconos Numerics' LCP solvers. The equations are those of
// integration/moreau_jean.h:
//   M (v+ - v) = h [theta F+ + (1 - theta) F] + H^T P,  u+ = u + h (theta v+ + (1 - theta) v),
//   0 <= H_a v+ + e_a H_a v  ⊥  P_a >= 0   for g_a + h H_a v <= 0,
// the smooth forces by Newton with J = M + h theta (C + C_t) + (h theta)^2 (K + K_t)
// and the LCP w = H J^-1 H^T P + H v_free + e ∘ H v in every iteration.
// Sources: Jean, CMAME 177 (1999) 235, §3-4; Acary & Brogliato, Numerical
// Methods for Nonsmooth Dynamical Systems (2008), §10.1 (the scheme) and
// §10.1.6 (Newton's law at the velocity level, the index set by prediction);
// contacts in plan: the gap of model/plan_contact_geometry.h, its gradient
// at the step's start as H_a (§10.1.7).
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/integration/moreau_jean.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace poundfe
{
  namespace
  {
    /// Whether any element but the gaps (which the contacts replace) is
    /// nonlinear: else the step's equations are linear, one iteration.
    bool
    has_smooth_nonlinearity(const NonlinearElements &elements)
    {
      return std::any_of(elements.begin(), elements.end(),
                         [](const NonlinearElement &e) { return e.kind != ElementKind::gap; });
    }
  } // namespace

  std::string
  unilateral_contacts(const Model &model, const NonlinearElements &elements,
                      const double restitution, std::vector<UnilateralContact> &contacts)
  {
    contacts.clear();
    if (model.bumper.law != BumperLaw::none)
      return "does not take bumpers yet";
    for (unsigned int h = 0; h < elements.size(); ++h)
      {
        const NonlinearElement &e = elements[h];
        if (e.kind != ElementKind::gap)
          continue;
        const auto gap = std::find_if(model.gaps.begin(), model.gaps.end(),
                                      [&](const Gap &g) { return g.label == e.label; });
        Assert(gap != model.gaps.end(), dealii::ExcMessage("a gap element without its gap"));
        Assert(gap->in_plan || gap->on_column || e.rank() == 1,
               dealii::ExcMessage("a gap between floors with a closure of rank > 1"));
        UnilateralContact contact;
        contact.label       = e.label;
        contact.equations   = e.equations();
        contact.restitution = restitution;
        contact.element     = h;
        contact.in_plan     = gap->in_plan;
        contact.on_column   = gap->on_column;
        if (gap->in_plan)
          contact.plan = gap->plan;
        else if (gap->on_column)
          contact.column = gap->column;
        else
          {
            const Eigen::MatrixXd B = e.tangent_basis(); // the closure's coefficients
            contact.coefficients.assign(B.data(), B.data() + B.rows());
            contact.initial_gap = gap->initial_gap;
          }
        contacts.push_back(contact);
      }
    return {};
  }

  std::string
  MoreauJeanIntegrator::unsupported(const LinearSystem &system, const NonlinearElements *elements,
                                    const MoreauJeanParameters &parameters)
  {
    if (elements)
      for (const NonlinearElement &e : *elements)
        if (e.kind == ElementKind::member || e.kind == ElementKind::friction)
          return "does not take " +
                 std::string(e.kind == ElementKind::member ? "fibre members" : "friction") +
                 " yet (" + e.label + ")";
    if (system.n_equations() <= parameters.max_dense_equations)
      return {};
    return sparse_unsupported(system, elements, parameters,
                              " on models of more than " +
                                std::to_string(parameters.max_dense_equations) +
                                " equations (Contact/Dense matrix limit; this one has " +
                                std::to_string(system.n_equations()) + ")");
  }

  std::string
  MoreauJeanIntegrator::sparse_unsupported(const LinearSystem         &system,
                                           const NonlinearElements    *elements,
                                           const MoreauJeanParameters &parameters,
                                           const std::string          &beyond)
  {
    if (!system.modal_damping.empty())
      return "does not take modal damping" + beyond;
    if (parameters.linear_solver != "eigen-ldlt" && parameters.linear_solver != "umfpack")
      return "factors its sparse iteration matrix with Time integration/Linear solver = "
             "eigen-ldlt or umfpack" + beyond + ", not " + parameters.linear_solver;
    if (elements && parameters.linear_solver == "eigen-ldlt")
      for (const NonlinearElement &e : *elements)
        if (e.kind != ElementKind::gap && !e.has_symmetric_tangent())
          return "needs Time integration/Linear solver = umfpack (an LU) for an element with a "
                 "nonsymmetric tangent (" + e.label + ")" + beyond;
    return {};
  }

  namespace
  {
    /// B of a slab against a column (its equations x 5): z = B^T u is the
    /// column point's plan displacement w = W u_column (W row-major,
    /// 2 x n_column) and the slab's (ux, uy, θz).
    Eigen::MatrixXd
    column_basis(const UnilateralContact &contact)
    {
      const unsigned int n_column = contact.equations.size() - 3;
      Assert(contact.column.weights.size() == 2 * n_column, dealii::ExcMessage("column weights"));
      Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n_column + 3, 5);
      for (unsigned int r = 0; r < 2; ++r)
        for (unsigned int j = 0; j < n_column; ++j)
          B(j, r) = contact.column.weights[r * n_column + j];
      B.bottomRightCorner<3, 3>().setIdentity();
      return B;
    }

    /// The rows and columns `kept` of `matrix`.
    SparseMatrix
    submatrix(const SparseMatrix &matrix, const std::vector<unsigned int> &kept)
    {
      std::vector<int> position(matrix.rows(), -1);
      for (unsigned int k = 0; k < kept.size(); ++k)
        position[kept[k]] = k;
      std::vector<Eigen::Triplet<double>> entries;
      for (Eigen::Index j = 0; j < matrix.outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(matrix, j); it; ++it)
          if (position[it.row()] >= 0 && position[it.col()] >= 0)
            entries.emplace_back(position[it.row()], position[it.col()], it.value());
      SparseMatrix result(kept.size(), kept.size());
      result.setFromTriplets(entries.begin(), entries.end());
      return result;
    }

    /// The smallest ratio, below which a slab against a column is refused,
    /// of the column point's effective mass in plan to the slab's floor's
    /// mass. An impact changes the slab's velocity by at most (1 + e) times
    /// this ratio of the approach velocity, so below 1e-6 rigid contact
    /// transmits nothing (the column passes through the slab). The point's
    /// effective mass is of the order of the column's mass per length times
    /// a metre (1.3 m on a 3 m column struck 2/3 up), so a real column, tens
    /// of kg/m or more against a floor of tens of tonnes, is above 1e-4.
    constexpr double min_column_mass_ratio = 1e-6;

    /// What gives a column's end rotations mass (a contact on a column acts
    /// on them; lumped masses leave them none).
    const char *const column_mass_hint =
      " (a contact on a column acts on its end rotations, which have mass only with "
      "Model/Mass matrix = consistent and a Column mass per length above 0)";

    /// Why slab-against-column contact `contact` is too light to act (the
    /// column point's effective mass 1 / λ_max(W M^-1 W^T), in its lightest
    /// plan direction, below min_column_mass_ratio of the floor's mass
    /// M(ux, ux)); empty else. `mass_factor` factors M on `position`'s
    /// equations (-1: without mass, where W is 0).
    std::string
    column_too_light(const UnilateralContact &contact, const LinearSystem &system,
                     const Eigen::SimplicialLDLT<SparseMatrix> &mass_factor,
                     const std::vector<int> &position)
    {
      const unsigned int n_column = contact.equations.size() - 3;
      const int          slab_ux  = contact.equations[n_column];
      if (slab_ux < 0)
        return {};
      Eigen::MatrixXd W = Eigen::MatrixXd::Zero(mass_factor.rows(), 2);
      for (unsigned int r = 0; r < 2; ++r)
        for (unsigned int j = 0; j < n_column; ++j)
          if (contact.equations[j] >= 0 && position[contact.equations[j]] >= 0)
            W(position[contact.equations[j]], r) = contact.column.weights[r * n_column + j];
      const Eigen::Matrix2d G = W.transpose() * mass_factor.solve(W);
      const double effective  = 1 / Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(G)
                                     .eigenvalues()
                                     .maxCoeff();
      const double floor = system.mass.coeff(slab_ux, slab_ux);
      if (!(effective < min_column_mass_ratio * floor))
        return {};
      return "needs a column with inertia against the slab it strikes: gap " + contact.label +
             "'s column point has an effective mass of " + rounded(effective) +
             " kg, less than " + number_text(min_column_mass_ratio) + " of the floor's " +
             rounded(floor) + " kg, so rigid contact would transmit nothing; raise the "
             "Column mass per length of the building of column " + contact.column.column;
    }
  } // namespace

  std::string
  MoreauJeanIntegrator::unsupported(const LinearSystem                   &system,
                                    const std::vector<UnilateralContact> &contacts)
  {
    for (const UnilateralContact &contact : contacts)
      for (unsigned int i = 0; i < contact.equations.size(); ++i)
        {
          const int          equation = contact.equations[i];
          const unsigned int n_column = contact.equations.size() - 3;
          // a column's DOF acts where its Hermite weight at the slab is nonzero
          const bool acts =
            contact.in_plan ||
            (contact.on_column ? i >= n_column || contact.column.weights[i] != 0 ||
                                   contact.column.weights[n_column + i] != 0 :
                                 contact.coefficients[i] != 0);
          if (equation >= 0 && acts && !(system.mass.coeff(equation, equation) > 0))
            return "needs mass on the equations a contact acts on (an impulse needs inertia): "
                   "gap " + contact.label + " acts on an equation without mass" +
                   (contact.in_plan ? std::string() : column_mass_hint);
        }
    if (std::none_of(contacts.begin(), contacts.end(),
                     [](const UnilateralContact &c) { return c.on_column; }))
      return {};
    std::vector<unsigned int> massive;
    std::vector<int>          position(system.n_equations(), -1);
    for (unsigned int i = 0; i < system.n_equations(); ++i)
      if (system.mass.coeff(i, i) > 0)
        {
          position[i] = massive.size();
          massive.push_back(i);
        }
    const Eigen::SimplicialLDLT<SparseMatrix> mass_factor(submatrix(system.mass, massive));
    for (const UnilateralContact &contact : contacts)
      if (contact.on_column)
        if (const std::string why = column_too_light(contact, system, mass_factor, position);
            !why.empty())
          return why;
    return {};
  }

  MoreauJeanIntegrator::MoreauJeanIntegrator(const LinearSystem &system_,
                                             const MoreauJeanParameters &parameters_,
                                             std::vector<UnilateralContact> contacts_,
                                             NonlinearElements *elements_,
                                             const JacobianStorage storage)
    : system(system_)
    , parameters(parameters_)
    , contact_list(std::move(contacts_))
    , elements(elements_)
    , n(system_.n_equations())
    , n_elements(elements_ ? elements_->size() : 0)
  {
    Assert(unsupported(system, elements, parameters).empty(),
           dealii::ExcMessage(unsupported(system, elements, parameters)));
    Assert(parameters.theta >= 0.5 && parameters.theta <= 1, dealii::ExcMessage("theta"));
    Assert(unsupported(system, contact_list).empty(),
           dealii::ExcMessage(unsupported(system, contact_list)));
    for (unsigned int i = 0; i < n; ++i)
      if (system.mass.coeff(i, i) > 0)
        massive.push_back(i);
    mass_factor.compute(submatrix(system.mass, massive));
    smooth_nonlinear = elements && has_smooth_nonlinearity(*elements);
    make_jacobian(storage);
    column_bases.resize(contact_list.size());
    for (unsigned int a = 0; a < contact_list.size(); ++a)
      if (contact_list[a].on_column)
        column_bases[a] = column_basis(contact_list[a]);
    for (const UnilateralContact &c : contact_list)
      {
        Assert(!c.in_plan || c.equations.size() == 6,
               dealii::ExcMessage("a contact in plan joins (ux, uy, θz) of two floors"));
        Assert(c.friction == 0 || c.in_plan,
               dealii::ExcMessage("friction on a contact without a tangent (not in plan)"));
        has_friction      = has_friction || c.friction > 0;
        has_plan_contacts = has_plan_contacts || c.in_plan || c.on_column;
      }
    if (!lcp_solver_available())
      return;
    solver_name = solve_lcp(Eigen::MatrixXd(), Vector(), parameters.lcp).solver;
    if (has_friction)
      friction_solver_name =
        solve_friction_contact(Eigen::MatrixXd(), Vector(), Vector(), parameters.friction).solver;
  }

  void
  MoreauJeanIntegrator::make_jacobian(const JacobianStorage storage)
  {
    // J's constant part M + h theta C + (h theta)^2 K; the elements' B_e
    const double ht = parameters.time_step * parameters.theta;
    SparseMatrix base = system.mass + ht * ht * system.stiffness;
    if (system.damping.size() > 0)
      base += ht * system.damping;
    Eigen::MatrixXd modal;
    if (!system.modal_damping.empty())
      modal = ht * system.modal_damping.factor * system.modal_damping.weights.asDiagonal() *
              system.modal_damping.factor.transpose();
    std::vector<const std::vector<int> *> element_equations;
    bases.resize(n_elements);
    for (unsigned int h = 0; h < n_elements; ++h)
      if ((*elements)[h].kind != ElementKind::gap)
        {
          element_equations.push_back(&(*elements)[h].equations());
          bases[h] = (*elements)[h].tangent_basis();
        }
    // beyond the limit sparse; within it dense where sparse by eigen-ldlt
    // (the solver the cost model measured) is refused, else the cheaper
    // (moreau_jean_matrix.h), unless the caller chose. The one place that
    // decides: MoreauJeanMatrix only applies the cost model when asked.
    const bool sparse_by_ldlt_allowed = parameters.linear_solver == "eigen-ldlt" &&
                                        sparse_unsupported(system, elements, parameters, "").empty();
    const JacobianStorage chosen =
      n > parameters.max_dense_equations    ? JacobianStorage::sparse :
      storage != JacobianStorage::automatic ? storage :
      sparse_by_ldlt_allowed                ? JacobianStorage::automatic :
                                              JacobianStorage::dense;
    jacobian = std::make_unique<MoreauJeanMatrix>(base, modal, element_equations, chosen,
                                                  parameters.linear_solver);
  }

  PlanContactState
  MoreauJeanIntegrator::plan_state(const unsigned int a, const Vector &x) const
  {
    const std::vector<int> &equations = contact_list[a].equations;
    Vector6                 q;
    for (unsigned int i = 0; i < 6; ++i)
      q[i] = equations[i] < 0 ? 0.0 : x[equations[i]];
    return plan_contact_state(contact_list[a].plan, q);
  }

  ColumnContactState
  MoreauJeanIntegrator::column_state(const unsigned int a, const Vector &x) const
  {
    const std::vector<int> &equations = contact_list[a].equations;
    Vector5                 z         = Vector5::Zero();
    for (unsigned int i = 0; i < equations.size(); ++i)
      if (equations[i] >= 0)
        z += x[equations[i]] * column_bases[a].row(i).transpose();
    return column_contact_state(contact_list[a].column, z);
  }

  double
  MoreauJeanIntegrator::gap(const unsigned int a, const Vector &x) const
  {
    const UnilateralContact &contact = contact_list[a];
    if (!contact.in_plan && !contact.on_column)
      return contact.initial_gap + H.row(a).dot(x);
    // a point beyond the edge's ends cannot touch: open however far it crosses
    const auto open = [](const auto &state) {
      return state.defined ? state.gap : std::numeric_limits<double>::infinity();
    };
    return contact.in_plan ? open(plan_state(a, x)) : open(column_state(a, x));
  }

  void
  MoreauJeanIntegrator::linearize_contacts()
  {
    // H_a = dg_a/du = -dd_a/du: U_a = H_a v < 0 while the gap closes
    std::vector<Eigen::Triplet<double>> normal, tangential;
    for (unsigned int a = 0; a < contact_list.size(); ++a)
      {
        const UnilateralContact &contact = contact_list[a];
        if (contact.on_column)
          {
            // dg/du = B dg/dz at the step's start (no tangent: frictionless)
            const ColumnContactState state = column_state(a, u);
            if (!state.defined)
              continue;
            const Eigen::VectorXd gradient = column_bases[a] * state.gradient;
            for (unsigned int i = 0; i < contact.equations.size(); ++i)
              if (contact.equations[i] >= 0 && gradient[i] != 0)
                normal.emplace_back(a, contact.equations[i], gradient[i]);
            continue;
          }
        if (!contact.in_plan)
          {
            for (unsigned int i = 0; i < contact.equations.size(); ++i)
              if (contact.equations[i] >= 0)
                normal.emplace_back(a, contact.equations[i], -contact.coefficients[i]);
            continue;
          }
        const PlanContactState state = plan_state(a, u);
        if (!state.defined)
          continue;
        const Vector6 tangent = plan_tangent(a, state);
        for (unsigned int i = 0; i < 6; ++i)
          if (contact.equations[i] >= 0)
            {
              normal.emplace_back(a, contact.equations[i], state.gradient[i]);
              tangential.emplace_back(a, contact.equations[i], tangent[i]);
            }
      }
    H.resize(contact_list.size(), n);
    H.setFromTriplets(normal.begin(), normal.end());
    T.resize(contact_list.size(), n);
    T.setFromTriplets(tangential.begin(), tangential.end());
    delassus_valid = false;
  }
  Vector6
  MoreauJeanIntegrator::plan_tangent(const unsigned int a, const PlanContactState &state) const
  {
    // floor k's block of the gradient is (s_k n, s_k (x_c - c_k) × n),
    // s_k = ±1: its block of the tangent's, (s_k J n, s_k (x_c - c_k) × J n),
    // is the relative velocity of the contact point along J n
    const std::vector<int> &equations = contact_list[a].equations;
    Vector6                 tangent;
    for (unsigned int k = 0; k < 2; ++k)
      {
        const Point2  &centre = contact_list[a].plan.centres[k];
        const double   ux = equations[3 * k] < 0 ? 0.0 : u[equations[3 * k]];
        const double   uy = equations[3 * k + 1] < 0 ? 0.0 : u[equations[3 * k + 1]];
        const double   rx = state.point.x - centre.x - ux, ry = state.point.y - centre.y - uy;
        const double   tx = -state.gradient[3 * k + 1], ty = state.gradient[3 * k]; // J (s_k n)
        tangent[3 * k]     = tx;
        tangent[3 * k + 1] = ty;
        tangent[3 * k + 2] = rx * ty - ry * tx;
      }
    return tangent;
  }

  Vector
  MoreauJeanIntegrator::inverse_mass(const Vector &x) const
  {
    const Vector reduced = mass_factor.solve(Vector(x(massive)));
    Vector       result  = Vector::Zero(n);
    result(massive)      = reduced;
    return result;
  }

  void
  MoreauJeanIntegrator::damping_times(const Vector &x, Vector &y) const
  {
    if (system.damping.size() > 0)
      y.noalias() = system.damping * x;
    else
      y.setZero(n);
    const LowRankDamping &modal = system.modal_damping;
    if (!modal.empty())
      y.noalias() += modal.factor * modal.weights.cwiseProduct(modal.factor.transpose() * x);
  }

  double
  MoreauJeanIntegrator::normal_velocity(const unsigned int a, const Vector &x) const
  {
    return H.row(a).dot(x);
  }

  std::vector<double>
  MoreauJeanIntegrator::gaps() const
  {
    std::vector<double> g(contact_list.size());
    for (unsigned int a = 0; a < g.size(); ++a)
      g[a] = gap(a, u);
    return g;
  }

  void
  MoreauJeanIntegrator::evaluate_elements(const double t, const Vector &x, const Vector &y,
                                          Vector &force, const bool tangent)
  {
    const double ht = parameters.time_step * parameters.theta;
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        NonlinearElement &e = (*elements)[h];
        if (e.kind == ElementKind::gap)
          continue; // replaced by the unilateral contacts
        const std::vector<int> &equations = e.equations();
        const unsigned int      n_dofs    = e.n_dofs();
        if (local_u.size() < n_dofs) // grown once to the largest element
          {
            local_u.resize(n_dofs);
            local_v.resize(n_dofs);
            local_force.resize(n_dofs);
          }
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            local_u[i] = equations[i] < 0 ? 0.0 : x[equations[i]];
            local_v[i] = equations[i] < 0 ? 0.0 : y[equations[i]];
          }
        e.set_trial_time(t);
        if (!e.set_trial(local_u.head(n_dofs), local_v.head(n_dofs)))
          throw NumericalError("t = " + number_text(t) + " s: " + e.label + ": " + e.failure());
        e.force_correction(local_force.head(n_dofs));
        for (unsigned int i = 0; i < n_dofs; ++i)
          if (equations[i] >= 0)
            force[equations[i]] += local_force[i];
        if (!tangent)
          continue;
        const Eigen::MatrixXd &B = bases[h];
        element_d.resize(e.rank(), e.rank());
        e.tangent_change(1 / ht, element_d);
        element_local.noalias() = (ht * ht) * B * element_d * B.transpose();
        jacobian->add(equations, element_local);
      }
  }

  void
  MoreauJeanIntegrator::smooth_force(const double t, const Vector &displacement,
                                     const Vector &velocity, const Vector &load_vector,
                                     Vector &force, const bool tangent)
  {
    damping_times(velocity, force);
    force.noalias() += system.stiffness * displacement;
    force -= load_vector;
    if (tangent)
      jacobian->start();
    evaluate_elements(t, displacement, velocity, force, tangent);
  }

  void
  MoreauJeanIntegrator::initialize(const Vector &load_0, const Vector &u0, const Vector &v0)
  {
    Assert(u0.size() == n && v0.size() == n, dealii::ExcDimensionMismatch(u0.size(), n));
    reset_state(n_elements, parameters.time_step);
    impulse_log.clear();
    fallback_solves = 0;
    unattached_loss = 0;
    refactor        = true;
    impulses_last_step.assign(contact_list.size(), 0.0);
    impulses_this_step.assign(contact_list.size(), 0.0);
    tangential_this_step.assign(contact_list.size(), 0.0);
    initial_stored.assign(n_elements, 0.0);
    u          = u0;
    v          = v0;
    load_start = load_0;
    linearize_contacts();
    for (unsigned int h = 0; h < n_elements; ++h)
      (*elements)[h].reset();
    smooth_force(0, u, v, load_start, smooth_start, false);
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        (*elements)[h].commit();
        initial_stored[h] = (*elements)[h].stored_energy();
        work[h]           = initial_stored[h];
      }
    a = inverse_mass(-smooth_start);
    update_energy();
    balance.initial = balance.kinetic + balance.strain;
    energy_scale = max_balance_error = 0;
    update_balance_error(balance, energy_scale, max_balance_error);
  }

  void
  MoreauJeanIntegrator::find_active_contacts()
  {
    const double h = parameters.time_step;
    active.clear();
    for (unsigned int c = 0; c < contact_list.size(); ++c)
      if (gap(c, u) + h * normal_velocity(c, v) <= 0)
        active.push_back(c);
    const unsigned int per_contact = has_friction ? 2 : 1;
    std::vector<Eigen::Triplet<double>> entries;
    for (unsigned int k = 0; k < active.size(); ++k)
      {
        for (SparseRows::InnerIterator it(H, active[k]); it; ++it)
          entries.emplace_back(per_contact * k, it.col(), it.value());
        if (has_friction)
          for (SparseRows::InnerIterator it(T, active[k]); it; ++it)
            entries.emplace_back(2 * k + 1, it.col(), it.value());
      }
    rows.resize(per_contact * active.size(), n);
    rows.setFromTriplets(entries.begin(), entries.end());
  }

  const Eigen::MatrixXd &
  MoreauJeanIntegrator::delassus()
  {
    if (!delassus_valid || delassus_active != active ||
        delassus_factorization != jacobian->n_factorizations())
      {
        jacobian->delassus(rows, W);
        delassus_active        = active;
        delassus_factorization = jacobian->n_factorizations();
        delassus_valid         = true;
      }
    return W;
  }

  bool
  MoreauJeanIntegrator::is_solved(const LcpSolution &solution) const
  {
    // Success is judged by the program's own residual (the same measure for
    // every solver), not by Siconos's status: Lemke on the friction problem
    // reports success on unsolved problems, NSGS failure on solved ones.
    const double tolerance =
      has_friction ? parameters.friction.tolerance : parameters.lcp.tolerance;
    return solution.residual <= tolerance && solution.z.allFinite();
  }

  namespace
  {
    /// "Siconos's S ... residual r above the tolerance t after k iterations
    /// (Siconos status i)" of one solver's attempt.
    std::string
    attempt_text(const LcpSolution &solution, const std::string &what, const double tolerance)
    {
      return "Siconos's " + solution.solver + what + ": residual " +
             number_text(solution.residual) + " above the tolerance " + number_text(tolerance) +
             " after " + std::to_string(solution.iterations) + " iterations (Siconos status " +
             std::to_string(solution.info) + ")";
    }
  } // namespace

  void
  MoreauJeanIntegrator::count_solve(const LcpSolution &solution, const unsigned int n_contacts,
                                    const char *problem, const LcpSolution *first_attempt)
  {
    ContactProblemCounts &counts = stats.contact;
    ++counts.solves;
    // a solve's iterations count both attempts, as a step's Newton iterations do
    int iterations = 0;
    for (const LcpSolution *attempt : {first_attempt, &solution})
      if (attempt)
        iterations += std::max(attempt->iterations, 0);
    counts.iterations += iterations;
    counts.max_iterations = std::max<unsigned int>(counts.max_iterations, iterations);
    counts.max_residual = std::max(counts.max_residual, solution.residual);
    if (is_solved(solution))
      {
        fallback_solves += first_attempt ? 1 : 0;
        return;
      }
    const double tolerance =
      has_friction ? parameters.friction.tolerance : parameters.lcp.tolerance;
    const std::string what = " did not solve the " + std::string(problem) + " of " +
                             std::to_string(n_contacts) + " contacts";
    throw NumericalError("step " + std::to_string(step_count + 1) + " (t = " +
                         number_text(current_time + parameters.time_step) + " s): " +
                         (first_attempt ? attempt_text(*first_attempt, what, tolerance) +
                                            "; nor did the fallback, " +
                                            attempt_text(solution, "", tolerance)
                                        : attempt_text(solution, what, tolerance)));
  }

  Vector
  MoreauJeanIntegrator::contact_impulses(const Vector &v_free)
  {
    if (has_friction)
      return friction_impulses(v_free);
    const unsigned int m = active.size();
    Vector             q(m);
    for (unsigned int k = 0; k < m; ++k)
      {
        const unsigned int c = active[k];
        q[k] = normal_velocity(c, v_free) + contact_list[c].restitution * normal_velocity(c, v);
      }
    const LcpSolution solution = solve_lcp(delassus(), q, parameters.lcp);
    count_solve(solution, m, "contact LCP");
    return solution.z;
  }

  Vector
  MoreauJeanIntegrator::friction_impulses(const Vector &v_free)
  {
    // per contact (U_N, U_T) = W (P_N, P_T) + q, Newton's law on the normal:
    // q_N = H v_free + e H v (Siconos's Moreau-Jean does the same)
    const unsigned int m = active.size();
    Vector             q(2 * m), mu(m);
    for (unsigned int k = 0; k < m; ++k)
      {
        const unsigned int c = active[k];
        q[2 * k] = normal_velocity(c, v_free) + contact_list[c].restitution * normal_velocity(c, v);
        q[2 * k + 1] = T.row(c).dot(v_free);
        mu[k]        = contact_list[c].friction;
      }
    const LcpSolution solution = solve_friction_contact(delassus(), q, mu, parameters.friction);
    if (is_solved(solution))
      {
        count_solve(solution, m, "friction-contact problem");
        return solution.z;
      }
    // NSGS can stall short of the tolerance where Lemke's pivots solve the
    // problem exactly, and Lemke can stop on an unsolved sticking contact
    // where NSGS converges: the same problem by the other method
    FrictionContactOptions fallback = parameters.friction;
    fallback.solver = parameters.friction.solver == FrictionSolverKind::lemke ?
                        FrictionSolverKind::nsgs :
                        FrictionSolverKind::lemke;
    const LcpSolution second = solve_friction_contact(delassus(), q, mu, fallback);
    count_solve(second, m, "friction-contact problem", &solution);
    return second.z;
  }

  double
  MoreauJeanIntegrator::newton_update(Vector &v_next)
  {
    // from the smooth residual r at the iterate v_end, the free velocity
    // v_free = v_end - J^-1 r, then the impulses and v_next = v_free + J^-1 R^T P
    const double h = parameters.time_step, theta = parameters.theta;
    residual.noalias() = system.mass * (v_end - v);
    residual += h * (theta * s_end + (1 - theta) * smooth_start);
    if (refactor)
      {
        jacobian->factorize();
        ++stats.refactorizations;
        refactor = false;
      }
    jacobian->solve(residual, correction_velocity);
    v_free = v_end - correction_velocity;
    v_next = v_free;
    if (active.empty())
      impulse.setZero(0);
    else
      {
        impulse            = contact_impulses(v_free);
        product.noalias()  = rows.transpose() * impulse;
        jacobian->solve(product, correction_velocity);
        v_next += correction_velocity;
      }
    ++stats.iterations;
    return (v_next - v_end).norm();
  }

  unsigned int
  MoreauJeanIntegrator::solve_step(const double t1, const bool full_newton)
  {
    const double h = parameters.time_step, theta = parameters.theta;
    v_end = v;
    Vector       v_next(n);
    double       last_change = std::numeric_limits<double>::infinity();
    for (unsigned int k = 0;; ++k)
      {
        if (k == parameters.newton_iterations)
          throw NumericalError("t = " + number_text(t1) + " s: Moreau-Jean's Newton did not " +
                               "converge in " + std::to_string(k) + " iterations");
        u_end = u + h * ((1 - theta) * v + theta * v_end);
        smooth_force(t1, u_end, v_end, load_end, s_end, refactor);
        // converged at the last iterate: the elements' trial state and s_end
        // are those of v_end, which the impulses of the last LCP took
        if (k > 0 && last_change <= parameters.newton_tolerance *
                                       (v_end.norm() + parameters.velocity_scale))
          return k;
        const double change = newton_update(v_next);
        std::swap(v_end, v_next);
        if (!smooth_nonlinear)
          {
            // linear: one iteration solves the step; s_end at its velocity
            u_end = u + h * ((1 - theta) * v + theta * v_end);
            smooth_force(t1, u_end, v_end, load_end, s_end, false);
            return 1;
          }
        // an older tangent that contracts the iteration too slowly is renewed
        refactor    = full_newton || change > max_contraction * last_change;
        last_change = change;
      }
  }

  void
  MoreauJeanIntegrator::step(const LoadFunction &load)
  {
    const double t1 = current_time + parameters.time_step;
    load_end.resize(n);
    load(t1, load_end);
    find_active_contacts();
    // the step's iterations count both attempts, as stats.iterations does
    const unsigned long iterations_before = stats.iterations;
    try
      {
        solve_step(t1, false);
      }
    catch (const NumericalError &)
      {
        // a kept tangent can leave the impulses and the hinges' branches
        // cycling: the step again with J at every iterate, as full Newton
        ++stats.full_newton_retries;
        refactor = true;
        solve_step(t1, true);
      }
    stats.max_iterations = std::max<unsigned int>(stats.max_iterations,
                                                   stats.iterations - iterations_before);
    accept_step(t1);
  }

  void
  MoreauJeanIntegrator::accept_step(const double t1)
  {
    const double h = parameters.time_step, theta = parameters.theta;
    const Vector v_theta = (1 - theta) * v + theta * v_end;
    balance.input += h * v_theta.dot((1 - theta) * load_start + theta * load_end);
    damping_times(v_theta, product);
    balance.damping += h * v_theta.dot(product);
    for (unsigned int e = 0; e < n_elements; ++e)
      if ((*elements)[e].kind != ElementKind::gap)
        {
          work[e] += (*elements)[e].work_increment();
          (*elements)[e].commit();
        }
    record_impulses(t1);
    // the smooth part of the acceleration: the impulses' jumps taken out
    a = (v_end - v) / h;
    if (impulse.size() > 0 && impulse.cwiseAbs().maxCoeff() > 0)
      a -= inverse_mass(rows.transpose() * impulse) / h;
    std::swap(u, u_end);
    std::swap(v, v_end);
    std::swap(load_start, load_end);
    std::swap(smooth_start, s_end);
    current_time = t1;
    ++step_count;
    ++stats.steps;
    if (has_plan_contacts)
      linearize_contacts();
    update_energy();
  }

  void
  MoreauJeanIntegrator::record_impulses(const double t_end)
  {
    std::vector<double> &this_step = impulses_this_step, &tangential = tangential_this_step;
    std::fill(this_step.begin(), this_step.end(), 0.0);
    std::fill(tangential.begin(), tangential.end(), 0.0);
    const unsigned int per_contact = has_friction ? 2 : 1;
    for (unsigned int j = 0; j < active.size(); ++j)
      if (impulse[per_contact * j] > 0)
        {
          const unsigned int c = active[j];
          ContactImpulse     record;
          record.time            = t_end;
          record.contact         = c;
          record.impulse         = impulse[per_contact * j];
          record.velocity_before = normal_velocity(c, v);
          record.velocity_after  = normal_velocity(c, v_end);
          record.energy_lost =
            -0.5 * record.impulse * (record.velocity_before + record.velocity_after);
          if (has_friction)
            {
              record.tangential_impulse = impulse[2 * j + 1];
              record.energy_lost -= 0.5 * record.tangential_impulse *
                                    (T.row(c).dot(v) + T.row(c).dot(v_end));
            }
          impulse_log.push_back(record);
          this_step[c]  = record.impulse;
          tangential[c] = record.tangential_impulse;
          if (contact_list[c].element >= 0)
            work[contact_list[c].element] += record.energy_lost;
          else
            unattached_loss += record.energy_lost;
        }
    // The impact log sees a step with an impulse as one carrying the mean
    // force P / h at both ends (so its impulse is P and its peak force the
    // mean force of the step), and the first step without one as its release.
    // Its start is taken as touching (no penetration < 0): the log then puts
    // the impact at the step's start with the velocity before the jump, and
    // the release at the next step's start with the velocity after it.
    // A contact in plan acts at the contact point of the step's start, where
    // its rows H_a and T_a were taken.
    const double h = parameters.time_step;
    for (unsigned int c = 0; c < contact_list.size(); ++c)
      if (contact_list[c].element >= 0 && (this_step[c] > 0 || impulses_last_step[c] > 0))
        {
          const double force = this_step[c] / h, tangential_force = tangential[c] / h;
          const double end_gap = gap(c, u_end); // infinite: a plan contact out of reach
          std::array<double, 2> point{{std::nan(""), std::nan("")}};
          if (contact_list[c].in_plan)
            if (const PlanContactState state = plan_state(c, u); state.defined)
              point = {{state.point.x, state.point.y}};
          if (contact_list[c].on_column)
            if (const ColumnContactState state = column_state(c, u); state.defined)
              point = {{state.point.x, state.point.y}};
          impacts.record(contact_list[c].element, current_time, t_end,
                         {std::max(-gap(c, u), 0.0), -normal_velocity(c, v), force, point, 0,
                          tangential_force},
                         {std::isfinite(end_gap) ? -end_gap : 0.0, -normal_velocity(c, v_end),
                          force, point, 0, tangential_force});
        }
    std::swap(impulses_last_step, impulses_this_step);
  }

  void
  MoreauJeanIntegrator::update_energy()
  {
    product.noalias() = system.mass * v;
    balance.kinetic   = 0.5 * v.dot(product);
    product.noalias() = system.stiffness * u;
    balance.strain    = 0.5 * u.dot(product);
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const NonlinearElement &e = (*elements)[h];
        if (e.kind != ElementKind::gap)
          balance.strain += e.stored_energy() - e.reference_energy();
      }
    if (elements)
      set_element_dissipation(balance, *elements, work, std::vector<double>(n_elements, 0.0));
    else
      balance.contact = 0;
    balance.contact += unattached_loss;
    update_balance_error(balance, energy_scale, max_balance_error);
  }

  void
  MoreauJeanIntegrator::advance(const LoadFunction &load)
  {
    step(load);
    if (substep_callback)
      substep_callback();
  }
} // namespace poundfe
