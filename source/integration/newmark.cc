#include <poundfe/assembly/linear_solver.h>
#include <poundfe/assembly/low_rank_update.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/parallel_refusal.h>
#include <poundfe/elements/uniaxial_element.h>
#include <poundfe/integration/accuracy_substeps.h>
#include <poundfe/integration/fixed_size_step.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/assembly/modal_damping.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// Steps per shortest period splits a step into at most 2^20 sub-steps.
    constexpr unsigned int max_accuracy_level = 20;

    /// The convergence criteria at Newton iterate i >= 1 (theory §3.4).
    struct NewtonCheck
    {
      double residual;       // ||R_i||
      double residual_ratio; // ||R_i|| / ||R_0||
      double energy;         // |du_i . R_i|, the work of the residual on the last correction
      double energy_ratio;   // |du_i . R_i| / |du_1 . R_0|
      bool   residual_met;   // ratio <= residual tolerance, or ||R_i|| at round-off
      bool   energy_met;     // ratio <= energy tolerance, or ||R_i|| at round-off

      bool converged() const { return residual_met && energy_met; }

      /// Each criterion's value against its tolerance, for a failure message.
      std::string
      describe(const NewtonParameters &newton) const
      {
        std::ostringstream s;
        s.precision(3);
        s << "residual norm " << residual << " = " << residual_ratio
          << " of the first (Newton residual tolerance " << newton.residual_tolerance << ": "
          << (residual_met ? "met" : "not met") << "); work of the residual on the last "
          << "correction " << energy << " J = " << energy_ratio
          << " of the first iteration's (Newton energy tolerance " << newton.energy_tolerance
          << ": " << (energy_met ? "met" : "not met") << ")";
        return s.str();
      }
    };

    /// Whether the element loop pays on more threads than one: when there
    /// are, and at least 8 elements other than the uniaxial ones (those
    /// whose pointer is null: fibre members, a section state per
    /// integration point, microseconds each; a uniaxial element's tens of
    /// nanoseconds do not pay for a thread's start).
    bool
    worth_threads(const std::vector<UniaxialElement *> &uniaxial)
    {
      constexpr long heavy_elements = 8;
      return dealii::MultithreadInfo::n_threads() > 1 &&
             std::count(uniaxial.begin(), uniaxial.end(), nullptr) >= heavy_elements;
    }

    /// local_u[q], local_v[q] = u[i], v[i] of the local DOFs q in [first,
    /// end), i = local_equation[q]; 0 on the ground (i < 0).
    void
    gather_dofs(const unsigned int first, const unsigned int end,
                const std::vector<int> &local_equation, const Vector &u, const Vector &v,
                Vector &local_u, Vector &local_v)
    {
      for (unsigned int q = first; q < end; ++q)
        if (const int i = local_equation[q]; i >= 0)
          {
            local_u[q] = u[i];
            local_v[q] = v[i];
          }
        else
          local_u[q] = local_v[q] = 0.0;
    }

    /// Why `element` refused its trial state, for a failure message.
    std::string
    refusal_text(const NonlinearElement &element)
    {
      const std::string why = element.failure();
      return element.label + ": " +
             (why.empty() ? "the element refused its trial state (it gave no reason)" : why);
    }

    /// "equation 12, A3 (6, 3) ux" for a message.
    /// The first equation whose entry of `x` is not finite, -1 if none.
    Eigen::Index
    first_non_finite(const Vector &x)
    {
      for (Eigen::Index i = 0; i < x.size(); ++i)
        if (!std::isfinite(x[i]))
          return i;
      return -1;
    }

    /// Element h of `elements` as the concrete UniaxialElement it is, else
    /// null. Listed again at every initialize(): the elements may have been
    /// replaced between runs (TimeHistory::replace_nonlinear_elements), so a
    /// list kept from an earlier run would point to freed elements.
    /// Returns whether every element is one.
    bool
    list_uniaxial(NonlinearElements *const elements, const unsigned int n_elements,
                  std::vector<UniaxialElement *> &uniaxial)
    {
      uniaxial.assign(n_elements, nullptr);
      for (unsigned int h = 0; h < n_elements; ++h)
        uniaxial[h] = as_uniaxial((*elements)[h]);
      return std::count(uniaxial.begin(), uniaxial.end(), nullptr) == 0;
    }

    /// f(element h): as the UniaxialElement it is when `uniaxial` lists it,
    /// so that f's calls go through the final class with no virtual call of
    /// the element's own (only its law's), else as a NonlinearElement. The
    /// same functions either way, so the same bits.
    template <typename Elements, typename F>
    decltype(auto)
    on_element(Elements &elements, const std::vector<UniaxialElement *> &uniaxial,
               const unsigned int h, F &&f)
    {
      if (UniaxialElement *const typed = uniaxial[h])
        return f(*typed);
      return f(elements[h]);
    }

    /// `start` plus the elements' stored energies above their reference
    /// (this rank's counted elements), added one by one onto `start`: the
    /// order of the sum, and so its last bits, is that of a run without a
    /// gravity state.
    /// `uniaxial`: the elements listed by list_uniaxial since they were
    /// last replaced (the energies read through the final class), or null.
    /// `noted` (not null): each counted element's stored energy, at [h].
    double
    add_element_energies(double start, const NonlinearElements *const elements,
                         const std::vector<UniaxialElement *> *const uniaxial,
                         const unsigned int n_elements, const RankOwnership *const distribution,
                         const std::vector<char> &counted_here,
                         std::vector<double> *const noted = nullptr)
    {
      if (noted)
        noted->resize(n_elements);
      for (unsigned int h = 0; h < n_elements; ++h)
        if (!distribution || counted_here[h])
          {
            const auto energy = [&](const auto &e) {
              const double stored = e.stored_energy();
              if (noted)
                (*noted)[h] = stored;
              return stored - e.reference_energy();
            };
            start += uniaxial ? on_element(*elements, *uniaxial, h, energy) : energy((*elements)[h]);
          }
      return start;
    }
  } // namespace

  namespace
  {
    /// |x| over every rank's own equations (distribution null: one process).
    double
    norm_over_ranks(const RankOwnership *distribution, const Vector &x)
    {
      return distribution ? distribution->norm(x) : x.norm();
    }

    /// The general storage of the step's formulas (fixed_size_step.h): the
    /// sparse matrices, modal damping's low-rank part, norms over ranks.
    struct GeneralStorage
    {
      const LinearSystem  &system;
      const SparseMatrix  &effective;
      const RankOwnership *distribution;

      void mass_product(const Vector &x, Vector &y) const { y.noalias() = system.mass * x; }
      void damping_product(const Vector &x, Vector &y) const
      {
        y.noalias() = system.damping * x;
        add_low_rank_damping_product(system.modal_damping, x, y);
      }
      void subtract_effective_product(const Vector &x, Vector &y) const
      {
        y.noalias() -= effective * x;
      }
      double norm(const Vector &x) const { return norm_over_ranks(distribution, x); }
    };
  } // namespace

  /// Everything that depends on the step size: Newmark coefficients, the
  /// effective matrix and its factorisation. Level c has dt / 2^c.
  struct NewmarkIntegrator::Level : NewmarkCoefficients
  {
    SparseMatrix                  effective;
    /// The step's arithmetic in fixed size (fixed_size_step.h), or null:
    /// the general storage.
    std::unique_ptr<FixedSizeStep> fixed;
    std::vector<double>           base_values;
    std::unique_ptr<LinearSolver> solver;
    /// hybrid: the assembled tangent's factorisation (same pattern).
    std::unique_ptr<LinearSolver> tangent_solver;
    LowRankUpdateSolver           woodbury;
    // refactorize: position of entry (i, j) of each element in effective's
    // values at [i n_dofs + j], -1 for the ground
    std::vector<std::vector<int>> entry_index;
    /// `effective` holds an assembled tangent, not K_eff (refactorize, hybrid).
    bool holds_tangent = false;
    /// p at the end of a step of this size; the sub-steps of a cut step
    /// use their own level's, so it stays valid across them.
    Vector load_end;
    /// Element h as the concrete UniaxialElement it is, else null: the
    /// element loop evaluates these through UniaxialElement::evaluate, with
    /// no virtual call of the element's own (the same elements at every
    /// level; listed when the level is made and again at every initialize,
    /// since the elements may be replaced between runs).
    std::vector<UniaxialElement *> uniaxial;
    /// Whether every element is listed in `uniaxial`: then the element loop
    /// is one plain loop over them.
    bool all_uniaxial = false;
    /// The frozen tangent K_0 = K_eff + sum_e B_e D_0,e B_e^T of every
    /// method but newton: D_0 (laid out as tangent_change), whether it is
    /// set, whether the assembled K_0 is the factorisation held (the
    /// Woodbury path needs none), and that factorisation's wall time (auto).
    std::vector<double> frozen_d;
    bool                frozen_set = false, frozen_factorised = false;
    double              factorization_seconds = 0;
  };

  NewmarkIntegrator::NewmarkIntegrator(const LinearSystem &system,
                                       const std::string  &linear_solver,
                                       const NewmarkParameters &parameters,
                                       NonlinearElements       *elements,
                                       const RankOwnership      *distribution)
    : system(system)
    , solver_name(linear_solver)
    , parameters(parameters)
    , elements(elements)
    , n_elements(elements ? elements->size() : 0)
    , distribution(distribution)
    , krylov(std::max(parameters.newton.subspace_dimension, 1u))
    , bfgs(std::max(parameters.newton.subspace_dimension, 1u))
    , records(elements)
  {
    dof_start.assign(1, 0);
    d_start.assign(1, 0);
    unsigned int total_rank = 0;
    bool         symmetric  = true;
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const NonlinearElement &e = (*elements)[h];
        basis.push_back(e.tangent_basis());
        AssertThrow(e.rank() > 0 && basis[h].rows() == e.n_dofs() && basis[h].cols() == e.rank(),
                    dealii::ExcMessage(e.label + ": B_e must be n_dofs x rank, rank > 0"));
        dof_start.push_back(dof_start.back() + e.n_dofs());
        local_equation.insert(local_equation.end(), e.equations().begin(), e.equations().end());
        d_start.push_back(d_start.back() + e.rank() * e.rank());
        total_rank += e.rank();
        symmetric = symmetric && e.has_symmetric_tangent();
        if (e.kind == ElementKind::gap || e.kind == ElementKind::friction ||
            e.kind == ElementKind::spring)
          event_elements.push_back(h);
      }
    // auto: Woodbury while its dense capacitance matrix, of size the total
    // rank (one per uniaxial element), stays small.
    const TangentUpdate mode = parameters.newton.tangent_update;
    use_woodbury             = mode == TangentUpdate::woodbury ||
                   (mode == TangentUpdate::automatic &&
                    total_rank <= parameters.newton.woodbury_columns);
    use_hybrid = n_elements > 0 && !use_woodbury &&
                 (mode == TangentUpdate::hybrid || mode == TangentUpdate::automatic);
    if (!use_woodbury && !symmetric && solver_name == "eigen-ldlt" &&
        parameters.lu_when_nonsymmetric)
      solver_name = "umfpack"; // summary.json and the log name the solver used
    if (!use_woodbury && !symmetric && solver_name == "eigen-ldlt")
      throw InputError("", 0, "Time integration/Linear solver",
                       "refactorising a nonsymmetric element tangent needs an LU solver "
                       "(umfpack, petsc or trilinos), not eigen-ldlt");
    if (!use_woodbury && !symmetric && linear_solver_is_iterative(solver_name))
      throw InputError("", 0, "Time integration/Linear solver",
                       "conjugate gradients needs a symmetric tangent, and a nonlinear "
                       "element's is not: use a direct solver or Tangent update = woodbury");
    const unsigned int n = system.n_equations();
    for (Vector *x : {&u, &v, &a, &load_now, &u_next, &v_next, &a_next, &residual,
                      &increment, &work_vector, &velocity_sum, &product, &step_displacement,
                      &start_residual, &stiffness_product})
      x->setZero(n);
    for (Vector *x : {&local_u, &local_v, &correction})
      x->setZero(dof_start.back());
    tangent_change.assign(d_start.back(), 0.0);
    if (distribution)
      set_up_distribution();
    if (parameters.steps_per_period > 0)
      base_level = accuracy_level(parameters.time_step, highest_frequency(),
                                  parameters.steps_per_period, max_accuracy_level);
    level(0);
  }

  NewmarkIntegrator::~NewmarkIntegrator() = default;

  std::string
  NewmarkIntegrator::equation_text(const Eigen::Index i) const
  {
    std::string text = "equation " + std::to_string(i);
    if (i >= 0 && static_cast<std::size_t>(i) < equation_names.size())
      text += ", " + equation_names[i];
    else if (i >= 0 && equation_namer)
      text += ", " + equation_namer(i);
    return text;
  }

  void
  NewmarkIntegrator::set_up_distribution()
  {
    check_distributable();
    krylov.set_distribution(distribution);
    bfgs.set_distribution(distribution);
    // an element between two ranks counts on the owner of its first equation
    const auto [first, last] = distribution->owned_range();
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const std::vector<int> &equations = (*elements)[h].equations();
        const auto counted = std::find_if(equations.begin(), equations.end(),
                                          [](const int i) { return i >= 0; });
        counted_here.push_back(counted != equations.end() && *counted >= int(first) &&
                               *counted < int(last));
      }
  }

  void
  NewmarkIntegrator::check_distributable() const
  {
    const NewtonParameters &newton = parameters.newton;
    const std::string       method = nonlinear_solver_names().name(newton.nonlinear_solver);
    if (newton.nonlinear_solver == NonlinearSolver::newton ||
        newton.nonlinear_solver == NonlinearSolver::automatic)
      throw InputError("", 0, "Time integration/Nonlinear solver",
                       "a model partitioned over ranks steps with one factorisation of each "
                       "rank's block, reused: modified-newton, krylov-newton or bfgs, not " +
                         method);
    if (n_elements > 0 && (use_woodbury || use_hybrid))
      throw InputError("", 0, "Time integration/Tangent update",
                       "a model partitioned over ranks needs Tangent update = refactorize (the "
                       "Woodbury update would couple the ranks' blocks densely)");
  }

  double
  NewmarkIntegrator::highest_frequency() const
  {
    // the bound is a largest row ratio: over ranks, the largest of the
    // ranks' (their blocks' rows are the model's; ghost rows are empty)
    const double here = highest_frequency_bound(system.stiffness, system.mass);
    if (!distribution)
      return here;
    std::vector<double> all(distribution->n_ranks());
    distribution->all_gather(&here, 1, all.data());
    return *std::max_element(all.begin(), all.end());
  }

  double
  NewmarkIntegrator::norm_of(const Vector &x) const
  {
    // the fixed-size arithmetic of M, K and the norms is every level's: level 0's
    if (const FixedSizeStep *const fixed = levels[0]->fixed.get())
      return fixed->norm(x);
    return norm_over_ranks(distribution, x);
  }

  double
  NewmarkIntegrator::dot_of(const Vector &x, const Vector &y) const
  {
    if (const FixedSizeStep *const fixed = levels[0]->fixed.get())
      return fixed->dot(x, y);
    return distribution ? distribution->dot(x, y) : x.dot(y);
  }

  bool
  NewmarkIntegrator::agreed(const bool ok, const char *elsewhere)
  {
    if (!distribution || !distribution->any(!ok))
      return ok;
    if (ok)
      failure = elsewhere;
    return false;
  }

  const NameTable<TangentUpdate> &
  tangent_update_names()
  {
    static const NameTable<TangentUpdate> table({{TangentUpdate::automatic, "auto"},
                                                 {TangentUpdate::woodbury, "woodbury"},
                                                 {TangentUpdate::refactorize, "refactorize"},
                                                 {TangentUpdate::hybrid, "hybrid"}});
    return table;
  }

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
    set_coefficients(*L, parameters.time_step / std::ldexp(1.0, cuts));
    assemble_effective_matrix(*L);
    if (!distribution)
      L->fixed = make_fixed_size_step(system, L->effective);
    L->solver = new_linear_solver(*L);
    L->all_uniaxial = list_uniaxial(elements, n_elements, L->uniaxial);
    // every step size has K_eff's pattern: one symbolic analysis where the
    // backend can share it (UMFPACK)
    stats.shared_analyses +=
      L->solver->analyze_or_reuse(cuts > 0 ? levels[0]->solver.get() : nullptr, L->effective);
    L->solver->factorize(L->effective);
    if (n_elements > 0 && (use_woodbury || use_hybrid))
      set_up_woodbury(*L);
    if (n_elements > 0 && !use_woodbury)
      set_up_assembled_tangent(*L);
    levels[cuts] = std::move(L);
    return *levels[cuts];
  }

  void
  NewmarkIntegrator::set_coefficients(Level &L, const double dt) const
  {
    const double g = parameters.gamma, b = parameters.beta;
    L.dt       = dt;
    L.gamma    = g;
    L.load_end.setZero(system.n_equations());
    L.c_mass_u = 1 / (b * dt * dt);
    L.c_mass_v = 1 / (b * dt);
    L.c_mass_a = 1 / (2 * b) - 1;
    L.c_damp_u = g / (b * dt);
    L.c_damp_v = g / b - 1;
    L.c_damp_a = dt * (g / (2 * b) - 1);
  }

  void
  NewmarkIntegrator::assemble_effective_matrix(Level &L) const
  {
    L.effective = system.stiffness + L.c_damp_u * system.damping + L.c_mass_u * system.mass;
    if (!use_woodbury)
      {
        // Every coupling of a nonlinear element must be in the pattern: add
        // them as explicit zeros in one sparse sum (a union of patterns,
        // O(nnz)). Inserting them one by one with coeffRef moved the
        // matrix's tail at every new entry, quadratic in the model: minutes
        // of set-up at two million equations.
        std::vector<Eigen::Triplet<double>> couplings;
        for (unsigned int h = 0; h < n_elements; ++h)
          for (const int i : (*elements)[h].equations())
            for (const int j : (*elements)[h].equations())
              if (i >= 0 && j >= 0)
                couplings.emplace_back(i, j, 0.0);
        SparseMatrix pattern(system.n_equations(), system.n_equations());
        pattern.setFromTriplets(couplings.begin(), couplings.end());
        L.effective = L.effective + pattern;
      }
    L.effective.makeCompressed();
  }

  std::unique_ptr<LinearSolver>
  NewmarkIntegrator::new_linear_solver(const Level &L)
  {
    // CG + AMG: eta = factor x Newton residual tolerance (iterative_solver.h)
    const IterativeSolverSetup iterative{
      parameters.iterative,
      parameters.iterative.tolerance_factor * parameters.newton.residual_tolerance,
      "Linear tolerance factor x Newton residual tolerance", &stats.linear};
    std::unique_ptr<LinearSolver> solver = create_linear_solver(solver_name, iterative);
    if (distribution) // this rank's block
      solver = restrict_to_block(std::move(solver), distribution->owned_range());
    else // eigen-ldlt's solves of a small model in fixed size
      solver = with_fixed_size_solve(std::move(solver), system.n_equations());
    // modal damping: K_eff + c U D U^T by the Woodbury identity (assembly/modal_damping.h)
    return with_low_rank_damping(std::move(solver), system.modal_damping, L.c_damp_u);
  }

  void
  NewmarkIntegrator::set_up_woodbury(Level &L) const
  {
    // B: the columns of every B_e on the element's equations
    std::vector<SparseColumn> columns;
    std::vector<unsigned int> ranks;
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const std::vector<int> &equations = (*elements)[h].equations();
        for (unsigned int c = 0; c < basis[h].cols(); ++c)
          {
            SparseColumn column;
            for (unsigned int i = 0; i < equations.size(); ++i)
              if (equations[i] >= 0 && basis[h](i, c) != 0)
                {
                  column.rows.push_back(equations[i]);
                  column.values.push_back(basis[h](i, c));
                }
            columns.push_back(std::move(column));
          }
        ranks.push_back(basis[h].cols());
      }
    L.woodbury.initialize(*L.solver, columns, system.n_equations(), ranks,
                          use_hybrid ? parameters.newton.woodbury_columns : 0);
  }

  void
  NewmarkIntegrator::set_up_assembled_tangent(Level &L)
  {
    if (use_hybrid) // the tangent gets its own factorisation; K_eff's stays
      {
        L.tangent_solver = new_linear_solver(L);
        stats.shared_analyses += L.tangent_solver->analyze_or_reuse(L.solver.get(), L.effective);
      }
    L.base_values.assign(L.effective.valuePtr(), L.effective.valuePtr() + L.effective.nonZeros());
    L.entry_index.resize(n_elements);
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const std::vector<int> &eq = (*elements)[h].equations();
        for (const int i : eq)
          for (const int j : eq)
            L.entry_index[h].push_back(
              (i >= 0 && j >= 0) ? &L.effective.coeffRef(i, j) - L.effective.valuePtr() : -1);
      }
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
    stiffness_product_is_current = false;
    if (distribution) // the owners' initial state at the ghosts
      {
        distribution->update_ghosts(u);
        distribution->update_ghosts(v);
      }
    load_now     = load;
    step_count   = 0;
    current_time = 0;
    const IterativeSolveCounts linear = stats.linear; // the solvers outlive a run
    stats        = IterationStatistics();
    stats.linear = linear;
    stats.smallest_time_step = parameters.time_step;
    balance           = EnergyBalance();
    energy_scale      = 0;
    max_balance_error = 0;
    for (unsigned int h = 0; h < n_elements; ++h)
      (*elements)[h].reset();
    for (const std::unique_ptr<Level> &L : levels)
      if (L)
        L->all_uniaxial = list_uniaxial(elements, n_elements, L->uniaxial);
    if (element_preload && elements)
      element_preload(*elements);
    gravity_strain  = 0;
    input_with_held = 0;
    if (held_load.size() > 0) // the elements are at the gravity state now
      gravity_strain = strain_energy_at(gravity_displacement);
    if (equilibrate_massless)
      equilibrate_massless_dofs(load);
    if (held_load.size() > 0)
      start_displacement = u;
    set_consistent_acceleration(load);
    if (elements)
      records.start(*elements);
    balance.strain  = strain_energy();
    balance.kinetic = kinetic_energy();
    balance.initial = balance.strain + balance.kinetic;
    // the strain term from the gravity state is a difference of energies of
    // this size, to their round-off: the error's scale is at least it
    energy_scale = std::abs(gravity_strain);
    if (distribution)
      sum_balance_over_ranks();
  }

  void
  NewmarkIntegrator::hold_gravity_state(const Vector &held, const Vector &displacement)
  {
    AssertThrow(!distribution, dealii::ExcMessage("a gravity state is not distributed"));
    AssertDimension(held.size(), displacement.size());
    held_load            = held;
    gravity_displacement = displacement;
  }

  void
  NewmarkIntegrator::restart(const Vector &load, const Vector &u_new, const Vector &v_new)
  {
    AssertThrow(!distribution, dealii::ExcMessage("a restart is not distributed"));
    u        = u_new;
    v        = v_new;
    stiffness_product_is_current = false;
    load_now = load;
    set_consistent_acceleration(load);
  }

  void
  NewmarkIntegrator::set_consistent_acceleration(const Vector &load)
  {
    if (!distribution)
      {
        solve_consistent_acceleration(load);
        return;
      }
    // an element that refuses the initial state on one rank stops every rank
    std::string why;
    try
      {
        solve_consistent_acceleration(load);
      }
    catch (const NumericalError &e)
      {
        why = e.what();
      }
    if (distribution->any(!why.empty()))
      throw NumericalError(why.empty() ? "the initial state failed on another rank" : why);
    distribution->update_ghosts(a); // a ghost equation carries no mass here
  }

  void
  NewmarkIntegrator::evaluate_start(const Vector &load, Vector &r, const bool commit)
  {
    r = load - damping_product(system, v) - system.stiffness * u;
    gather(u, v);
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        NonlinearElement  &e = (*elements)[h];
        const unsigned int s = dof_start[h], k = e.n_dofs(), rank = basis[h].cols();
        if (!e.set_trial(local_u.segment(s, k), local_v.segment(s, k)))
          throw NumericalError("state at t = " + number_text(current_time) + " s: " + e.label +
                               ": " + e.failure());
        if (commit)
          e.commit();
        else // the static tangent, for the massless equations' Newton
          e.tangent_change(0, Eigen::Map<Eigen::MatrixXd>(tangent_change.data() + d_start[h],
                                                           rank, rank));
        e.force_correction(correction.segment(s, k));
      }
    subtract_element_forces(r);
  }

  std::vector<int>
  NewmarkIntegrator::massive_numbering(unsigned int &n_massive) const
  {
    // Equations that carry mass: any nonzero in their row of M.
    const unsigned int n = system.n_equations();
    std::vector<int>   reduced(n, -1);
    n_massive = 0;
    for (int column = 0; column < system.mass.outerSize(); ++column)
      for (SparseMatrix::InnerIterator it(system.mass, column); it; ++it)
        if (it.value() != 0 && reduced[it.row()] < 0)
          reduced[it.row()] = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (reduced[i] == 0)
        reduced[i] = n_massive++;
    return reduced;
  }

  void
  NewmarkIntegrator::solve_consistent_acceleration(const Vector &load)
  {
    Vector r;
    evaluate_start(load, r, true);
    if (elements)
      records.note_committed(*elements, v);

    const unsigned int n = system.n_equations();
    unsigned int       n_massive = 0;
    const std::vector<int> reduced = massive_numbering(n_massive);

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
  }

  void
  NewmarkIntegrator::gather(const Vector &u_global, const Vector &v_global)
  {
    gather_dofs(0, local_equation.size(), local_equation, u_global, v_global, local_u, local_v);
  }

  bool
  NewmarkIntegrator::evaluate_elements(const Vector &u_trial, const Vector &v_trial,
                                       const Level &L)
  {
    // one element's trial state, force correction and tangent change, each
    // in its own slices of local_u, local_v, correction and tangent_change:
    // the elements are independent, so their order (or thread) does not
    // change a number
    const auto evaluate_uniaxial = [&](const unsigned int h) { // no gather, no virtual call
      const unsigned int s = dof_start[h];
      return L.uniaxial[h]->evaluate(local_equation.data() + s, u_trial, v_trial, L.c_damp_u,
                                     correction.data() + s, tangent_change[d_start[h]]);
    };
    const auto evaluate = [&](const unsigned int h) {
      const unsigned int s = dof_start[h], k = dof_start[h + 1] - s, r = basis[h].cols();
      if (L.uniaxial[h])
        return evaluate_uniaxial(h);
      NonlinearElement &e = (*elements)[h];
      gather_dofs(s, s + k, local_equation, u_trial, v_trial, local_u, local_v);
      if (!e.set_trial(local_u.segment(s, k), local_v.segment(s, k)))
        return false;
      e.force_correction(correction.segment(s, k));
      e.tangent_change(L.c_damp_u,
                       Eigen::Map<Eigen::MatrixXd>(tangent_change.data() + d_start[h], r, r));
      return true;
    };
    // A line search tries trial states without a revert in between, from
    // which a force-based element iterates on: there the elements past a
    // refusal stay untouched, as in order. Elsewhere a refusal cuts the
    // step, which reverts every element. Uniaxial elements alone: one plain
    // loop in order (never worth threads), without the general branch.
    const unsigned int refused =
      L.all_uniaxial ? first_refusal(n_elements, evaluate_uniaxial, false) :
                       first_refusal(n_elements, evaluate,
                                     !parameters.newton.line_search && worth_threads(L.uniaxial));
    if (refused == n_elements)
      return true;
    failure = refusal_text((*elements)[refused]);
    return false;
  }

  void
  NewmarkIntegrator::subtract_element_forces(Vector &r) const
  {
    for (unsigned int q = 0; q < local_equation.size(); ++q)
      if (local_equation[q] >= 0)
        r[local_equation[q]] -= correction[q];
  }

  double
  NewmarkIntegrator::tangent_change_entry(const std::vector<double> &d, const unsigned int h,
                                          const unsigned int i, const unsigned int j) const
  {
    const Eigen::MatrixXd &B = basis[h];
    const unsigned int     r = B.cols();
    const double          *D = d.data() + d_start[h]; // D(a, b) = D[a + b r]
    // from the first term, so that a rank-one element adds exactly d b_i b_j
    double value = D[0] * B(i, 0) * B(j, 0);
    for (unsigned int b = 0; b < r; ++b)
      for (unsigned int a = (b == 0 ? 1 : 0); a < r; ++a)
        value += D[a + b * r] * B(i, a) * B(j, b);
    return value;
  }

  void
  NewmarkIntegrator::set_start_residual(const Level &L, const Vector &p)
  {
    // r_0 = rhs - K_eff u = p - K u + M (c_v v + c_a a) + C (c_v' v + c_a' a),
    // each term of the size of the forces, not of M u / (beta dt^2)
    const Vector &stiffness_u = stiffness_times_u();
    residual_floor =
      L.fixed ? L.fixed->start_residual(L, p, stiffness_u, v, a, start_residual) :
                newmark_formulas::start_residual(GeneralStorage{system, L.effective, distribution},
                                                 L, p, stiffness_u, v, a, work_vector, product,
                                                 start_residual);
  }

  void
  NewmarkIntegrator::set_iterate()
  {
    if (const FixedSizeStep *const fixed = levels[0]->fixed.get())
      fixed->iterate(u, step_displacement, u_next);
    else
      u_next.noalias() = u + step_displacement;
  }

  void
  NewmarkIntegrator::update_kinematics(const Level &L)
  {
    if (L.fixed)
      L.fixed->kinematics(L, step_displacement, v, a, v_next, a_next);
    else
      newmark_formulas::kinematics(L, step_displacement, v, a, v_next, a_next);
  }

  bool
  NewmarkIntegrator::solve_linear_step(const Level &L)
  {
    // Without elements the equations are linear: one solve, K_eff du = r_0
    // on the factorisation of K_eff kept for the step size, u_{n+1} = u_n +
    // du. It is Newton's first correction from u_n to the bit (r_0 from
    // set_start_residual, each term of the size of the forces, solved by
    // the same factorisation), and the residual Newton would form next,
    // r_0 - K_eff du, is that solve's round-off (a backward-stable LDL^T:
    // of the order of eps cond(K_eff) |r_0|), far below any tolerance that
    // could reject it: it is not formed. (Solved for u_{n+1} from the whole
    // rhs = K_eff u_n + r_0 instead, the step keeps fewer digits at short
    // steps, where rhs is M u_n / (beta dt^2) and the forces are its last
    // digits: doc/theory.md §3.3.)
    try
      {
        L.solver->solve(start_residual, step_displacement);
        set_iterate();
      }
    catch (const NumericalError &e) // an iterative solve that failed: cut the step
      {
        failure = e.what();
        return false;
      }
    update_kinematics(L);
    ++stats.iterations;
    stats.max_iterations = std::max(stats.max_iterations, 1u);
    if (const Eigen::Index i = first_non_finite(u_next); i >= 0)
      {
        failure = "the displacement became non-finite (" + number_text(u_next[i]) + " at " +
                  equation_text(i) + ")";
        return false;
      }
    return true;
  }

  bool
  NewmarkIntegrator::newton_residual(Level &L, const unsigned int it, double &norm)
  {
    if (L.holds_tangent) // restore K_eff
      {
        std::copy(L.base_values.begin(), L.base_values.end(), L.effective.valuePtr());
        L.holds_tangent = false;
      }
    // A step's first iterate from u_n (no friction) has du = 0: r = r_0 to
    // the bit, without the sparse products.
    const bool from_start = !L.fixed && (step_displacement.array() == 0.0).all();
    if (L.fixed)
      L.fixed->effective_residual(start_residual, step_displacement, residual);
    else if (from_start)
      residual = start_residual;
    else
      newmark_formulas::effective_residual(GeneralStorage{system, L.effective, distribution},
                                           start_residual, step_displacement, residual);
    if (!from_start && !system.modal_damping.empty()) // the modal part of K_eff: c U D U^T
      {
        product.setZero();
        add_low_rank_damping_product(system.modal_damping, step_displacement, product);
        residual.noalias() -= L.c_damp_u * product;
      }
    subtract_element_forces(residual);
    if (distribution) // the owners balance the ghost equations
      distribution->zero_ghosts(residual);
    norm = norm_of(residual);
    if (!std::isfinite(norm))
      {
        const Eigen::Index i = first_non_finite(residual);
        if (i >= 0)
          failure = "Newton iteration " + std::to_string(it) +
                    ": the residual became non-finite (" + number_text(residual[i]) + " at " +
                    equation_text(i) + ")";
        if (!agreed(i < 0, "the residual became non-finite on another rank"))
          return false;
        // finite entries whose squares overflow
        norm = distribution ? std::numeric_limits<double>::infinity() : residual.stableNorm();
      }
    return true;
  }

  bool
  NewmarkIntegrator::newton_increment(Level &L, const unsigned int it)
  {
    bool solved = false;
    if (use_woodbury || use_hybrid)
      {
        solved = L.woodbury.solve(residual, tangent_change, increment);
        stats.woodbury_solves += solved;
      }
    if (!solved)
      try
        {
          solve_with_assembled_tangent(L, tangent_change, false, residual, increment);
        }
      catch (const NumericalError &e) // a singular tangent at this iterate: cut the step
        {
          L.holds_tangent = true; // the values hold a partial tangent: restore them
          failure = "Newton iteration " + std::to_string(it) + ": " + e.what();
          return false;
        }
    return true;
  }

  NonlinearSolver
  NewmarkIntegrator::active_method() const
  {
    const NonlinearSolver method = parameters.newton.nonlinear_solver;
    if (full_newton_now || (method == NonlinearSolver::automatic && use_woodbury))
      return NonlinearSolver::newton;
    return method;
  }

  bool
  NewmarkIntegrator::reform_pays(const Level &L, const double norm, const double previous_norm,
                                 const double target) const
  {
    const double contraction = norm / std::max(previous_norm, 1e-300);
    if (!(contraction < 1)) // not contracting: only a new tangent can help
      return true;
    if (norm <= target)
      return false;
    // iterations still needed at this rate, against a factorisation and
    // the two iterations full Newton would take from here
    const double remaining = std::log(target / norm) / std::log(contraction);
    return remaining * iteration_seconds > L.factorization_seconds + 2 * iteration_seconds;
  }

  void
  NewmarkIntegrator::solve_frozen(Level &L, const Vector &b, Vector &x)
  {
    if (distribution) // a singular block on one rank cuts the step on all
      {
        std::string why;
        try
          {
            solve_with_assembled_tangent(L, L.frozen_d, L.frozen_factorised, b, x);
            L.frozen_factorised = true;
          }
        catch (const NumericalError &e)
          {
            why = e.what();
          }
        if (distribution->any(!why.empty()))
          throw NumericalError(why.empty() ? "another rank's block of the tangent is singular" :
                                             why);
        return;
      }
    if ((use_woodbury || use_hybrid) && L.woodbury.solve(b, L.frozen_d, x))
      {
        ++stats.woodbury_solves;
        return;
      }
    const bool reuse   = L.frozen_factorised;
    const auto started = std::chrono::steady_clock::now();
    solve_with_assembled_tangent(L, L.frozen_d, reuse, b, x);
    L.frozen_factorised = true;
    if (!reuse) // one number on every rank (LinearSolver::agreed_seconds)
      L.factorization_seconds = L.solver->agreed_seconds(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  }

  bool
  NewmarkIntegrator::quasi_newton_increment(Level &L, const unsigned int it, const double norm,
                                            const double previous_norm, const double target)
  {
    const NewtonParameters &newton = parameters.newton;
    const NonlinearSolver   method = active_method();
    bool reform = !L.frozen_set || (it == 0 && !newton.keep_tangent);
    if (!reform && it > 0)
      reform = method == NonlinearSolver::automatic ?
                 reform_pays(L, norm, previous_norm, target) :
                 norm > newton.refactorization_ratio * previous_norm;
    if (reform) // K_0 from the tangent at this iterate: a Newton iteration
      {
        L.frozen_d          = tangent_change;
        L.frozen_set        = true;
        L.frozen_factorised = false;
      }
    if (reform || it == 0)
      {
        krylov.reset();
        bfgs.reset();
      }
    const unsigned long factorizations = stats.refactorizations;
    try
      {
        const InverseOperator h0 = [this, &L](const Vector &b, Vector &x) { solve_frozen(L, b, x); };
        if (method == NonlinearSolver::modified_newton)
          solve_frozen(L, residual, increment);
        else if (method == NonlinearSolver::bfgs)
          bfgs.direction(residual, h0, increment);
        else // krylov-newton, auto
          krylov.direction(residual, h0, increment);
      }
    catch (const NumericalError &e) // a singular K_0: cut the step
      {
        L.holds_tangent = true;
        L.frozen_set = L.frozen_factorised = false;
        failure = "Newton iteration " + std::to_string(it) + ": " + e.what();
        return false;
      }
    // auto's cost of an iteration on K_0: evaluation and residual since the
    // last increment, and this solve
    const auto end = std::chrono::steady_clock::now();
    if (it > 0 && stats.refactorizations == factorizations)
      iteration_seconds =
        L.solver->agreed_seconds(std::chrono::duration<double>(end - last_increment_end).count());
    last_increment_end = end;
    return true;
  }

  void
  NewmarkIntegrator::search_line(Level &L, const unsigned int it)
  {
    const Vector start = step_displacement;
    const double g0    = dot_of(increment, residual);
    // G(s) = d . R(u + s d), NaN when the elements refuse the state; over
    // ranks the sums and refusals are agreed, so every rank searches alike
    const auto g = [&](const double s) {
      step_displacement = start + s * increment;
      set_iterate();
      update_kinematics(L);
      double norm = 0;
      if (!agreed(evaluate_elements(u_next, v_next, L),
                  "an element on another rank refused its trial state") ||
          !newton_residual(L, it, norm))
        return std::numeric_limits<double>::quiet_NaN();
      return dot_of(increment, residual);
    };
    const double s = line_search(g0, g(1.0), g, parameters.newton.line_search_parameters);
    step_displacement = start;
    set_iterate();
    if (s != 1.0)
      {
        increment *= s;
        ++stats.line_searches;
      }
  }

  namespace
  {
    /// episode_duration of gap element e, whose committed penetration (its
    /// history variable, negative while open) is delta and rate is `rate`.
    template <typename E>
    double
    episode_duration_of(const E &e, const double delta, const double rate, const Vector &a,
                        const double h, const bool onset_from_acceleration)
    {
      if (e.was_active())
        return e.contact_duration(0);
      if (onset_from_acceleration && delta >= 0)
        // penetrated without force (a damped law's restitution, its force
        // clipped at zero): still inside the contact episode, on the law's
        // time scale at the present rate
        return e.contact_duration(std::abs(rate));
      if (delta + rate * h > 0) // closing within the step at the committed rate
        return e.contact_duration(rate);
      if (!onset_from_acceleration)
        return 0;
      // A gap that a constant rate would not close but the floors'
      // acceleration does: missed, it would close deep inside a step too
      // long for its impact, which Newton then fails (a step cut). Over two
      // steps, since the acceleration changes within one.
      const double closing = predicted_closing_rate(delta, rate, e.deformation(a), 2 * h);
      return closing > 0 ? e.contact_duration(closing) : 0;
    }

    /// The duration of the contact episode gap `gap` is in, or enters within
    /// a step of h from the committed state (penetration, its rate and the
    /// accelerations a), by Contact/Steps per contact's prediction; 0 when it
    /// neither is in nor enters one (theory §3.7a).
    double
    episode_duration(const ElementRecords &records, const NonlinearElements &elements,
                     const std::vector<UniaxialElement *> &uniaxial, const unsigned int gap,
                     const Vector &a, const double h, const bool onset_from_acceleration)
    {
      return on_element(elements, uniaxial, gap, [&](const auto &e) {
        return episode_duration_of(e, records.committed_history(gap),
                                   records.committed_rate(gap), a, h, onset_from_acceleration);
      });
    }
  } // namespace

  namespace
  {
    /// Inside a contact episode (a gap closed, penetrated or closing within
    /// the step h: episode_duration), Newton's start from u_n + h v_n + h^2
    /// a_n / 2 (Newmark's with a_{n+1} = a_n) in `step`: a gap closing in the
    /// step then starts closed, with its tangent, rather than open, from
    /// where the first correction is the free flight that overshoots into
    /// it. The convergence tests stay relative to the step from u_n: the
    /// residual to ||r_0|| (`start_residual`, Delta u = 0 without the
    /// elements' forces) and the work to |step . r_0| (the first correction
    /// from u_n is about the whole step), or a better start would tighten
    /// them. False (nothing set) outside an episode (theory §3.7a).
    bool
    start_from_extrapolation(const ElementRecords &records, const NonlinearElements &elements,
                             const std::vector<UniaxialElement *> &uniaxial, const double h,
                             const Vector &v, const Vector &a, const Vector &start_residual,
                             Vector &step, double &first_residual, double &first_energy)
    {
      bool in_episode = false;
      for (const unsigned int gap : records.gap_elements())
        in_episode =
          in_episode || episode_duration(records, elements, uniaxial, gap, a, h, true) > 0;
      if (!in_episode)
        return false;
      step.noalias()  = h * v + (0.5 * h * h) * a;
      first_residual = start_residual.norm();
      first_energy   = std::abs(step.dot(start_residual));
      return true;
    }

    /// The length s <= 1 of a Newton correction `increment` from the step
    /// displacement `step` such that no gap open at the step's start and
    /// closed at this iterate is opened again by it: such a gap lands at a
    /// sixteenth of its penetration instead. A law whose force rises with a
    /// power below 1/2 of the penetration at onset (Jankowski's damping,
    /// c(delta) ~ delta^(1/4)) makes Newton overshoot a root near touch to
    /// the open side, from where the open tangent brings it back: a cycle
    /// that no step cut but the one moving the touch away from the step's
    /// end breaks. From below the root the concave force converges
    /// monotonically (theory §3.7a).
    double
    onset_correction_length(const ElementRecords &records, const NonlinearElements &elements,
                            const Vector &step, const Vector &increment)
    {
      double length = 1;
      for (const unsigned int gap : records.gap_elements())
        {
          const NonlinearElement &e = elements[gap];
          if (e.was_active())
            continue;
          // the penetration is linear in u: its committed value plus the step's
          const double delta = records.committed_history(gap) + e.deformation(step);
          const double change = e.deformation(increment);
          if (delta > 0 && delta + change < 0)
            length = std::min(length, (15.0 / 16.0) * delta / -change);
        }
      return length;
    }

    /// The scale of Newton's tests that is not finite, empty if none: a floor,
    /// first residual or first work that overflowed (|x|^2 beyond 1e308 at
    /// forces of ~1e154) would accept any iterate, the zero correction too.
    /// A non-finite correction needs no test of its own: at the next iterate
    /// an element refuses it (naming itself) or the residual is non-finite.
    std::string
    non_finite_scale(const double floor, const double first_residual, const double first_energy)
    {
      const auto text = [](const char *what, const double x) {
        return std::string(what) + " is not finite (" + number_text(x) + ")";
      };
      if (!std::isfinite(floor))
        return text("the residual floor (the size of the step's forces)", floor);
      if (!std::isfinite(first_residual))
        return text("the first residual norm", first_residual);
      if (!std::isfinite(first_energy))
        return text("the first correction's work", first_energy);
      return {};
    }
  } // namespace

  bool
  NewmarkIntegrator::try_step(Level &L, const Vector &p)
  {
    // distributed: the Newton path on every rank, so that a rank whose
    // buildings have no nonlinear element takes part in the others' sums
    if (n_elements == 0 && !distribution)
      {
        set_start_residual(L, p);
        return solve_linear_step(L);
      }

    const NewtonParameters &newton = parameters.newton;
    // Predictor: the last displacement; with friction, the last velocity
    // carried over the step, so a mass stuck to a moving belt starts its
    // iteration stuck (from u_n its stick spring would see the belt's whole
    // step, v0 dt, and the first iterate would break away; with static >
    // kinetic friction the slip it starts can be a converged discrete
    // solution too, and the mass would break away early); inside a contact
    // episode, the extrapolation (start_from_extrapolation; not on a model
    // partitioned by building, whose ranks would each decide on their own
    // gaps and disagree at the ghost equations).
    set_start_residual(L, p);
    double first_residual = 0, first_energy = 0, previous_norm = 0;
    bool   onset_corrected = false;
    const bool extrapolated = records.friction_elements().empty() && !distribution &&
                              newton.contact_onset_from_acceleration &&
                              start_from_extrapolation(records, *elements, L.uniaxial, L.dt, v, a,
                                                       start_residual, step_displacement,
                                                       first_residual, first_energy);
    if (!records.friction_elements().empty())
      step_displacement.noalias() = L.dt * v;
    else if (!extrapolated)
      step_displacement.setZero();
    set_iterate();
    const NonlinearSolver method = active_method();
    for (unsigned int it = 0;; ++it)
      {
        update_kinematics(L);
        if (!agreed(evaluate_elements(u_next, v_next, L),
                    "an element on another rank refused its trial state"))
          return false;
        double norm = 0;
        if (!newton_residual(L, it, norm))
          return false;
        if (it == 0 && !extrapolated)
          first_residual = norm;
        const double floor = residual_floor;
        // the same on every rank (norms and dots over ranks): no agreement
        if (!std::isfinite(floor) || !std::isfinite(first_residual) ||
            !std::isfinite(first_energy))
          {
            failure = "Newton iteration " + std::to_string(it) + ": " +
                      non_finite_scale(floor, first_residual, first_energy);
            return false;
          }
        if (it == 0 && norm <= floor)
          return true;
        NewtonCheck check{};
        if (it > 0)
          {
            check.residual       = norm;
            check.residual_ratio = norm / std::max(first_residual, 1e-300);
            check.energy         = std::abs(dot_of(increment, residual));
            check.energy_ratio   = check.energy / std::max(first_energy, 1e-300);
            check.residual_met =
              norm <= std::max(newton.residual_tolerance * first_residual, floor);
            check.energy_met =
              check.energy <= newton.energy_tolerance * first_energy || norm <= floor;
            if (check.converged())
              {
                stats.iterations += it;
                stats.max_iterations = std::max(stats.max_iterations, it);
                return true;
              }
          }
        if (it == newton.max_iterations)
          {
            // Which criterion failed, and where the equations are most out
            // of balance, for the message.
            Eigen::Index worst = 0;
            residual.cwiseAbs().maxCoeff(&worst);
            failure = "Newton did not converge in " + std::to_string(it) +
                      (it == 1 ? " iteration: " : " iterations: ") + check.describe(newton) +
                      "; the largest residual is at " + equation_text(worst);
            return false;
          }
        if (!agreed(method == NonlinearSolver::newton ?
                      newton_increment(L, it) :
                      quasi_newton_increment(L, it, norm, previous_norm,
                                             newton.residual_tolerance * first_residual),
                    "another rank's tangent is singular"))
          return false;
        if (distribution) // the owners' increments at the ghost equations
          distribution->update_ghosts(increment);
        if (it == 0 && !extrapolated)
          first_energy = std::abs(dot_of(increment, residual));
        if (newton.line_search)
          search_line(L, it);
        // a gap closing in the step not reopened, once per step: repeated, a
        // step whose gap really ends open would approach it by sixteenths
        // (theory §3.7a)
        if (extrapolated && !onset_corrected)
          {
            const double length =
              onset_correction_length(records, *elements, step_displacement, increment);
            onset_corrected = length < 1;
            increment *= length;
          }
        if (method == NonlinearSolver::krylov_newton || method == NonlinearSolver::automatic)
          krylov.record_step(increment);
        if (method == NonlinearSolver::bfgs)
          bfgs.record_step(increment);
        step_displacement += increment;
        set_iterate();
        previous_norm = norm;
      }
  }

  void
  NewmarkIntegrator::solve_with_assembled_tangent(Level &L, const std::vector<double> &d,
                                                  const bool reuse, const Vector &b, Vector &x)
  {
    LinearSolver &solver = use_hybrid ? *L.tangent_solver : *L.solver;
    if (!reuse)
      {
        double *values = L.effective.valuePtr();
        for (unsigned int h = 0; h < n_elements; ++h)
          {
            const unsigned int k = (*elements)[h].n_dofs();
            // B_e = I (a member of full rank): B D B^T is D itself, bit for
            // bit (the sum's other terms are signed zeros), without the k^2 r^2
            // products of tangent_change_entry
            const bool   identity = basis[h].cols() == k && basis[h].isIdentity(0.0);
            const double *D       = d.data() + d_start[h];
            for (unsigned int i = 0; i < k; ++i)
              for (unsigned int j = 0; j < k; ++j)
                if (const int index = L.entry_index[h][i * k + j]; index >= 0)
                  values[index] += identity ? D[i + j * k] : tangent_change_entry(d, h, i, j);
          }
        L.holds_tangent = true;
        L.frozen_factorised = false; // the factorisation held is this one
        solver.factorize(L.effective);
        ++stats.refactorizations;
      }
    solver.solve(b, x);
  }

  void
  NewmarkIntegrator::residual_and_tangent(const Vector &load, const Vector &u_trial,
                                          Vector &residual_out, Eigen::MatrixXd &tangent_out)
  {
    AssertThrow(!distribution,
                dealii::ExcMessage("the dense tangent is of one process's model"));
    Level &L = level(0);
    Vector an(u.size()), vn(u.size());
    newmark_formulas::kinematics(L, Vector(u_trial - u), v, a, vn, an);
    if (!evaluate_elements(u_trial, vn, L))
      throw NumericalError(failure);
    if (L.holds_tangent)
      {
        std::copy(L.base_values.begin(), L.base_values.end(), L.effective.valuePtr());
        L.holds_tangent = false;
      }
    residual_out = load - system.mass * an - damping_product(system, vn) - system.stiffness * u_trial;
    subtract_element_forces(residual_out);
    tangent_out = Eigen::MatrixXd(L.effective);
    if (const LowRankDamping &modal = system.modal_damping; !modal.empty())
      tangent_out += L.c_damp_u * modal.factor * modal.weights.asDiagonal() * modal.factor.transpose();
    for (unsigned int h = 0; h < n_elements; ++h)
      {
        const std::vector<int> &equations = (*elements)[h].equations();
        for (unsigned int i = 0; i < equations.size(); ++i)
          for (unsigned int j = 0; j < equations.size(); ++j)
            if (equations[i] >= 0 && equations[j] >= 0)
              tangent_out(equations[i], equations[j]) += tangent_change_entry(tangent_change, h, i, j);
      }
    for (unsigned int h = 0; h < n_elements; ++h)
      (*elements)[h].revert();
  }

  void
  NewmarkIntegrator::accept(const Level &L, const Vector &p)
  {
    // Trapezoidal work of the step; exact for the average-acceleration rule.
    // with a gravity state p holds p_g: its work is split off the input by
    // update_energy_error
    double &input = held_load.size() > 0 ? input_with_held : balance.input;
    if (L.fixed)
      L.fixed->add_step_work(step_displacement, load_now, p, v, v_next, input, balance.damping);
    else
      newmark_formulas::add_step_work(GeneralStorage{system, L.effective, distribution},
                                      step_displacement, load_now, p, v, v_next, velocity_sum,
                                      product, input, balance.damping);
    if (n_elements > 0) // no call per step without elements
      records.accept(*elements, current_time, current_time + L.dt, v_next,
                     distribution ? &counted_here : nullptr, balance.belt);
    u.swap(u_next);
    stiffness_product_is_current = false;
    v.swap(v_next);
    a.swap(a_next);
    load_now = p;
    ++stats.steps;
    stats.smallest_time_step = std::min(stats.smallest_time_step, L.dt);
    last_step = L.dt;
  }

  double
  predicted_closing_rate(const double delta, const double rate, const double acceleration,
                         const double h)
  {
    if (delta >= 0)
      return std::max(rate, 0.0);
    // The parabola's largest value on [0, h]: at h, or at its vertex when
    // the gap turns back to opening inside the step.
    const double vertex  = (acceleration < 0 && rate > 0) ? -rate / acceleration : h;
    const double t       = std::min(vertex, h);
    if (delta + rate * t + 0.5 * acceleration * t * t <= 0)
      return 0;
    // the rate at the first crossing: v^2 = rate^2 - 2 acceleration delta
    return std::sqrt(std::max(rate * rate - 2 * acceleration * delta, 0.0));
  }

  bool
  NewmarkIntegrator::contact_needs_shorter_step(const Level &L) const
  {
    const unsigned int n = parameters.newton.steps_per_contact;
    for (const unsigned int h : records.gap_elements())
      {
        const double duration =
          episode_duration(records, *elements, L.uniaxial, h, a, L.dt,
                           parameters.newton.contact_onset_from_acceleration);
        if (duration > 0 && n * L.dt > duration)
          return true;
      }
    return false;
  }

  void
  NewmarkIntegrator::advance_from(const unsigned int cuts, const double t0,
                                  const LoadFunction &load)
  {
    Level &L = level(cuts);
    if (cuts < base_level) // Steps per shortest period: split without trying
      {
        ++stats.accuracy_refinements;
        advance_from(cuts + 1, t0, load);
        advance_from(cuts + 1, t0 + 0.5 * L.dt, load);
        return;
      }
    const unsigned int last_level = base_level + parameters.newton.max_step_cuts;
    if (parameters.newton.steps_per_contact > 0 && cuts < last_level &&
        (distribution ? distribution->any(contact_needs_shorter_step(L)) :
                        contact_needs_shorter_step(L)))
      {
        ++stats.contact_refinements;
        advance_from(cuts + 1, t0, load);
        advance_from(cuts + 1, t0 + 0.5 * L.dt, load);
        return;
      }
    const double t1 = (cuts == 0) ? (step_count + 1) * parameters.time_step : t0 + L.dt;
    Vector &p = L.load_end; // no allocation per step
    load(t1, p);
    for (unsigned int h = 0; h < n_elements; ++h)
      on_element(*elements, L.uniaxial, h, [t1](auto &e) { e.set_trial_time(t1); });
    bool converged = try_step(L, p);
    if (!converged && active_method() != NonlinearSolver::newton)
      {
        // the cheaper iteration failed: full Newton on the same step before
        // it is cut, and a fresh K_0 afterwards
        for (unsigned int h = 0; h < n_elements; ++h)
          (*elements)[h].revert();
        ++stats.full_newton_retries;
        full_newton_now = true;
        converged       = try_step(L, p);
        full_newton_now = false;
        L.frozen_set    = false;
      }
    bool       event     = false;
    if (converged && cuts < base_level + parameters.newton.event_refinement)
      for (const unsigned int h : event_elements)
        event = event || on_element(*elements, L.uniaxial, h, [](const auto &e) {
                  return e.phase() != e.committed_phase();
                });
    if (converged && cuts < base_level + parameters.newton.event_refinement && distribution)
      event = distribution->any(event);
    if (converged && !event)
      {
        accept(L, p);
        current_time = t1;
        if (cuts > 0 && substep_callback)
          substep_callback();
        return;
      }
    for (unsigned int h = 0; h < n_elements; ++h)
      (*elements)[h].revert();
    if (event)
      {
        ++stats.event_refinements;
        advance_from(cuts + 1, t0, load);
        advance_from(cuts + 1, t0 + 0.5 * L.dt, load);
        return;
      }
    if (cuts >= last_level)
      {
        // the exact times: a cut step's dt = Time step / 2^cuts and its
        // start are not round numbers, and 6 digits could print "0"
        throw NumericalError("the step from t = " + number_text(t0) + " s to " +
                             number_text(t1) + " s failed even at dt = " + number_text(L.dt) +
                             " s (" + std::to_string(cuts - base_level) +
                             " step cuts, Maximum step cuts = " +
                             std::to_string(parameters.newton.max_step_cuts) + "): " +
                             (failure.empty() ? "no cause recorded" : failure));
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
    balance.strain  = strain_energy(&element_energies);
    if (elements)
      balance.constant_load = records.held_load_work();
    if (held_load.size() > 0)
      {
        // p_g is constant: its trapezoidal work is p_g . (u - u_0) exactly
        const double nodal = held_load.dot(u - start_displacement);
        balance.input      = input_with_held - nodal;
        balance.constant_load += nodal;
      }
    if (!distribution)
      {
        if (elements)
          set_element_dissipation(balance, *elements, records.work(), records.supplied_work(),
                                  element_energies, {});
        update_balance_error(balance, energy_scale, max_balance_error);
        return;
      }
    if (elements)
      set_element_dissipation(balance, *elements, records.work(), records.supplied_work(),
                              element_energies, counted_here);
    sum_balance_over_ranks();
    update_balance_error(total_balance, energy_scale, max_balance_error);
  }

  void
  NewmarkIntegrator::sum_balance_over_ranks()
  {
    total_balance = balance;
    EnergyBalance &b = total_balance;
    std::array<double *, 12> terms{{&b.initial, &b.input, &b.belt, &b.constant_load,
                                    &b.kinetic, &b.damping, &b.strain, &b.hysteretic,
                                    &b.contact, &b.friction, &b.links, &b.foundation}};
    std::array<double, 12> values;
    for (unsigned int i = 0; i < terms.size(); ++i)
      values[i] = *terms[i];
    distribution->sum(values.data(), values.size());
    for (unsigned int i = 0; i < terms.size(); ++i)
      *terms[i] = values[i];
  }

  EnergyBalance
  NewmarkIntegrator::energy() const
  {
    return distribution ? total_balance : balance;
  }

  double
  NewmarkIntegrator::kinetic_energy() const
  {
    if (const FixedSizeStep *const fixed = levels[0]->fixed.get())
      return fixed->kinetic_energy(v);
    // no temporary per step
    return newmark_formulas::kinetic_energy(GeneralStorage{system, levels[0]->effective,
                                                           distribution},
                                            v, product);
  }

  const Vector &
  NewmarkIntegrator::stiffness_times_u() const
  {
    if (!stiffness_product_is_current)
      {
        if (const FixedSizeStep *const fixed = levels[0]->fixed.get())
          fixed->stiffness_product(u, stiffness_product);
        else
          stiffness_product.noalias() = system.stiffness * u;
        stiffness_product_is_current = true;
      }
    return stiffness_product;
  }

  double
  NewmarkIntegrator::strain_energy() const
  {
    return strain_energy(nullptr);
  }

  double
  NewmarkIntegrator::strain_energy(std::vector<double> *const noted) const
  {
    // this rank's part (the ranks' are summed with the other terms)
    const FixedSizeStep *const fixed = levels[0]->fixed.get();
    const Vector &stiffness_u = stiffness_times_u();
    double energy = 0.5 * (fixed ? fixed->dot(u, stiffness_u) : u.dot(stiffness_u));
    // the elements' trial state is the committed state at u
    // at a step, the elements listed at initialize()
    energy = add_element_energies(energy, elements, &levels[0]->uniaxial, n_elements,
                                  distribution, counted_here, noted);
    return held_load.size() > 0 ? energy - gravity_strain : energy;
  }

  double
  NewmarkIntegrator::strain_energy_at(const Vector &x) const
  {
    // summed in strain_energy()'s order, so that E_S(u_g) - E_S(u_g) is 0 exactly
    return add_element_energies(0.5 * x.dot(system.stiffness * x), elements, nullptr,
                                n_elements, distribution, counted_here);
  }
} // namespace poundfe
