// The displacement-based and force-based beam-columns: their common state
// handling and the two state determinations (equations in the header).
// The force-based element's last resort (basic_state): when even the
// smallest piece of the subdivision fails, the rest of the increment is
// applied again the same way with the sections' deformations corrected by
// their initial flexibility, e_i += f_s0,i (b_i q - s_i), in up to 200
// iterations (OpenSees's ForceBeamColumn second strategy, which it tries
// before subdividing; here after, so that every path the tangent's Newton
// iteration converges on keeps its numbers): a fixed, stiffest flexibility
// contracts where the tangent's Newton cycles, at a fibre law's kink, as
// Concrete01 without tension about zero strain, a beam cracking and
// closing at once near zero deformation.
#include <poundfe/base/lean_assert.h>
#include <poundfe/elements/beam_column.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace poundfe
{
  namespace
  {
    /// Why section i refused its trial deformation: its own reason, or (a
    /// section that gives none, such as an elastic one) that the deformation
    /// or its resultants are not finite.
    std::string
    section_failure(const unsigned int i, const SectionLaw &section)
    {
      const std::string why = section.failure();
      return "section " + std::to_string(i) + ": " +
             (why.empty() ? "its deformation or resultants are not finite" : why);
    }
  } // namespace

  std::vector<std::unique_ptr<SectionLaw>>
  sections_along(const BeamIntegration &integration, const SectionLaw &section)
  {
    std::vector<std::unique_ptr<SectionLaw>> sections;
    for (unsigned int i = 0; i < integration.size(); ++i)
      sections.push_back(section.clone());
    return sections;
  }

  std::vector<std::unique_ptr<SectionLaw>>
  hinge_sections(const SectionLaw &end_i, const SectionLaw &interior, const SectionLaw &end_j)
  {
    std::vector<std::unique_ptr<SectionLaw>> sections;
    for (const SectionLaw *s : {&end_i, &end_i, &interior, &interior, &end_j, &end_j})
      sections.push_back(s->clone());
    return sections;
  }

  // ---------------------------------------------------------- element loads

  template <int dim>
  UniformLoadForces<dim>
  uniform_load_forces(const double L, const MemberLoad<dim> &w)
  {
    UniformLoadForces<dim> f;
    const double           axial = w[0] * L, vy = 0.5 * w[1] * L, mz = vy * L / 6;
    f.q0.setZero();
    f.q0[0] = -0.5 * axial;
    f.q0[1] = -mz;
    f.q0[2] = mz;
    f.p0[0] = -axial;
    f.p0[1] = f.p0[2] = -vy;
    if constexpr (dim == 3)
      {
        const double vz = 0.5 * w[2] * L, my = vz * L / 6;
        f.q0[3] = my;
        f.q0[4] = -my;
        f.p0[3] = f.p0[4] = -vz;
      }
    return f;
  }

  template <int dim>
  typename CrdTransformation<dim>::GlobalVector
  basic_reactions(const CrdTransformation<dim> &transformation,
                  const Eigen::Matrix<double, 2 * dim - 1, 1> &p0)
  {
    using Translation = Eigen::Matrix<double, dim, 1>;
    constexpr int j   = dim == 2 ? 3 : 6; // end J's first DOF
    Translation   at_i = Translation::Zero(), at_j = Translation::Zero();
    at_i[0] = p0[0];
    at_i[1] = p0[1];
    at_j[1] = p0[2];
    if constexpr (dim == 3)
      {
        at_i[2] = p0[3];
        at_j[2] = p0[4];
      }
    typename CrdTransformation<dim>::GlobalVector p =
      CrdTransformation<dim>::GlobalVector::Zero();
    const auto &axes              = transformation.local_axes(); // rows: local axes
    p.template segment<dim>(0)    = axes.transpose() * at_i;
    p.template segment<dim>(j)    = axes.transpose() * at_j;
    return transformation.offset_matrix().transpose() * p;
  }

  template <int dim>
  typename CrdTransformation<dim>::GlobalVector
  fixed_end_forces(const CrdTransformation<dim> &transformation, const MemberLoad<dim> &w)
  {
    CrdTransformation<dim> at_rest = transformation;
    at_rest.update(CrdTransformation<dim>::GlobalVector::Zero());
    const UniformLoadForces<dim> f = uniform_load_forces<dim>(at_rest.initial_length(), w);
    return at_rest.global_force(f.q0) + basic_reactions(at_rest, f.p0);
  }

  // ---------------------------------------------------------------- common

  template <int dim>
  BeamColumn<dim>::BeamColumn(const CrdTransformation<dim> &transformation,
                              BeamIntegration integration,
                              std::vector<std::unique_ptr<SectionLaw>> sections_)
    : transf(transformation)
    , rule(std::move(integration))
    , sections(std::move(sections_))
  {
    AssertDimension(sections.size(), rule.size());
    for ([[maybe_unused]] const auto &s : sections)
      AssertDimension(s->n_resultants(), static_cast<unsigned int>(n_resultants));
    trial.force.setZero();
    trial.stiffness.setZero();
    trial.basic_force.setZero();
    trial.basic_stiffness.setZero();
    committed = trial;
    trial_u = committed_u = GlobalVector::Zero();
    virgin_stiffness.setZero();
    load_reactions.setZero();
  }

  template <int dim>
  void
  BeamColumn<dim>::set_uniform_load(const MemberLoad<dim> &w)
  {
    Assert(transf.kind() != Transformation::corotational,
           dealii::ExcMessage("a uniform load on a corotational member"));
    load           = w;
    has_load       = !w.isZero(0);
    load_forces    = uniform_load_forces<dim>(length(), w);
    load_reactions = basic_reactions(transf, load_forces.p0);
  }

  template <int dim>
  typename BeamColumn<dim>::ResultantVector
  BeamColumn<dim>::particular_forces(const unsigned int i) const
  {
    const double    xi = rule.points[i], L = length();
    ResultantVector s  = ResultantVector::Zero();
    s[0]               = load[0] * L * (1 - xi);
    s[1]               = 0.5 * load[1] * L * L * xi * (xi - 1);
    if constexpr (dim == 3)
      s[2] = 0.5 * load[2] * L * L * xi * (1 - xi);
    return s;
  }

  template <int dim>
  bool
  BeamColumn<dim>::set_trial(const GlobalVector &u)
  {
    // measured from the nodes' displacements when the member was made
    trial_u = u - transf.displacements_when_made();
    transf.update(trial_u);
    why.clear();
    if (!basic_state(transf.basic_deformation(), trial.basic_force, trial.basic_stiffness))
      return false;
    if (has_load && !sections_carry_load())
      trial.basic_force += load_factor * load_forces.q0;
    trial.force = transf.global_force(trial.basic_force);
    if (has_load)
      trial.force += load_factor * load_reactions;
    trial.stiffness = transf.global_tangent(trial.basic_force, trial.basic_stiffness);
    return trial.force.allFinite() && trial.stiffness.allFinite();
  }

  template <int dim>
  void
  BeamColumn<dim>::commit()
  {
    for (const auto &s : sections)
      s->commit();
    commit_basic();
    transf.commit();
    committed   = trial;
    committed_u = trial_u;
  }

  template <int dim>
  void
  BeamColumn<dim>::revert()
  {
    for (const auto &s : sections)
      s->revert();
    revert_basic();
    trial   = committed;
    trial_u = committed_u;
    transf.revert();
    transf.update(trial_u);
    why.clear();
  }

  template <int dim>
  void
  BeamColumn<dim>::reset()
  {
    load_factor = 0;
    for (const auto &s : sections)
      s->reset();
    reset_basic();
    trial_u = committed_u = GlobalVector::Zero();
    transf.reset();
    transf.update(trial_u);
    // the virgin state: q = 0 and the initial tangent, from one evaluation
    // at v = 0 that the sections and the basic state forget
    basic_state(transf.basic_deformation(), trial.basic_force, trial.basic_stiffness);
    for (const auto &s : sections)
      s->revert();
    forget_reset_evaluation();
    trial.force      = transf.global_force(trial.basic_force);
    trial.stiffness  = transf.global_tangent(trial.basic_force, trial.basic_stiffness);
    virgin_stiffness = trial.stiffness;
    committed        = trial;
    why.clear();
  }

  template <int dim>
  double
  BeamColumn<dim>::stored_energy() const
  {
    double energy = 0;
    for (unsigned int i = 0; i < rule.size(); ++i)
      {
        const ResultantVector s  = sections[i]->resultant();
        const ResultantMatrix k0 = sections[i]->initial_tangent();
        energy += 0.5 * rule.weights[i] * length() * s.dot(k0.inverse() * s);
      }
    return energy;
  }

  template <int dim>
  double
  BeamColumn<dim>::held_load_work() const
  {
    if (!has_load || load_factor == 0)
      return 0;
    double work = -load_reactions.dot(trial_u);
    if (!sections_carry_load())
      work -= load_forces.q0.dot(transf.basic_deformation());
    else
      for (unsigned int i = 0; i < rule.size(); ++i)
        {
          const ResultantVector e = sections[i]->deformation();
          work += rule.weights[i] * length() * particular_forces(i).dot(e);
        }
    return load_factor * work;
  }

  // ---------------------------------------------------- displacement-based

  template <int dim>
  DispBeamColumn<dim>::DispBeamColumn(const CrdTransformation<dim> &transformation,
                                      const SectionLaw &section, const unsigned int n_points)
    : DispBeamColumn(transformation, legendre_integration(n_points),
                     sections_along(legendre_integration(n_points), section))
  {}

  template <int dim>
  DispBeamColumn<dim>::DispBeamColumn(const CrdTransformation<dim> &transformation,
                                      BeamIntegration integration,
                                      std::vector<std::unique_ptr<SectionLaw>> sections)
    : BeamColumn<dim>(transformation, std::move(integration), std::move(sections))
  {
    this->reset();
  }

  template <int dim>
  typename DispBeamColumn<dim>::Interpolation
  DispBeamColumn<dim>::deformation_interpolation(const double xi, const double L)
  {
    Interpolation a = Interpolation::Zero();
    a(0, 0)         = 1 / L;
    a(1, 1)         = (6 * xi - 4) / L;
    a(1, 2)         = (6 * xi - 2) / L;
    if constexpr (dim == 3)
      {
        a(2, 3) = (6 * xi - 4) / L;
        a(2, 4) = (6 * xi - 2) / L;
        a(3, 5) = 1 / L;
      }
    return a;
  }

  template <int dim>
  bool
  DispBeamColumn<dim>::basic_state(const BasicVector &v, BasicVector &q, BasicMatrix &k)
  {
    using Base = BeamColumn<dim>;
    q.setZero();
    k.setZero();
    const double L = this->length();
    for (unsigned int i = 0; i < this->rule.size(); ++i)
      {
        const Interpolation a = deformation_interpolation(this->rule.points[i], L);
        SectionLaw         &s = *this->sections[i];
        if (!s.set_trial(SectionVector(a * v)))
          {
            this->why = section_failure(i, s);
            return false;
          }
        const double wl = this->rule.weights[i] * L;
        q += wl * a.transpose() * typename Base::ResultantVector(s.resultant());
        k += wl * a.transpose() * typename Base::ResultantMatrix(s.tangent()) * a;
      }
    return true;
  }

  // ----------------------------------------------------------- force-based

  template <int dim>
  ForceBeamColumn<dim>::ForceBeamColumn(const CrdTransformation<dim> &transformation,
                                        const SectionLaw &section, const unsigned int n_points)
    : ForceBeamColumn(transformation, lobatto_integration(n_points),
                      sections_along(lobatto_integration(n_points), section))
  {}

  template <int dim>
  ForceBeamColumn<dim>::ForceBeamColumn(const CrdTransformation<dim> &transformation,
                                        BeamIntegration integration,
                                        std::vector<std::unique_ptr<SectionLaw>> sections)
    : BeamColumn<dim>(transformation, std::move(integration), std::move(sections))
  {
    const unsigned int n = this->rule.size();
    for (IterationState *state : {&current, &committed, &start})
      {
        state->e.resize(n);
        state->s.resize(n);
        state->fs.resize(n);
      }
    for (unsigned int i = 0; i < n; ++i)
      initial_section_stiffness.push_back(this->sections[i]->initial_tangent());
    this->reset();
  }

  template <int dim>
  typename ForceBeamColumn<dim>::Interpolation
  ForceBeamColumn<dim>::force_interpolation(const double xi)
  {
    Interpolation b = Interpolation::Zero();
    b(0, 0)         = 1;
    b(1, 1)         = xi - 1;
    b(1, 2)         = xi;
    if constexpr (dim == 3)
      {
        b(2, 3) = xi - 1;
        b(2, 4) = xi;
        b(3, 5) = 1;
      }
    return b;
  }

  template <int dim>
  typename ForceBeamColumn<dim>::ResultantMatrix
  ForceBeamColumn<dim>::flexibility(const unsigned int i) const
  {
    ResultantMatrix k = this->sections[i]->tangent();
    for (int r = 0; r < k.rows(); ++r)
      {
        const double floor = 1e-8 * std::abs(initial_section_stiffness[i](r, r));
        if (std::abs(k(r, r)) < floor)
          k(r, r) = floor;
      }
    return k.inverse();
  }

  template <int dim>
  void
  ForceBeamColumn<dim>::reset_basic()
  {
    // the virgin state: e = s = 0, f_s = k_s0^-1, F^-1 the elastic k_b
    BasicMatrix  f = BasicMatrix::Zero();
    const double L = this->length();
    for (unsigned int i = 0; i < this->rule.size(); ++i)
      {
        current.e[i].setZero();
        current.s[i].setZero();
        current.fs[i]          = initial_section_stiffness[i].inverse();
        const Interpolation b  = force_interpolation(this->rule.points[i]);
        f += this->rule.weights[i] * L * b.transpose() * current.fs[i] * b;
      }
    current.v.setZero();
    current.q.setZero();
    current.factor = 0;
    current.kv     = f.inverse();
    committed   = current;
    initialised = false;
  }

  template <int dim>
  void
  ForceBeamColumn<dim>::use_opensees_iteration(const OpenSeesIteration &controls)
  {
    opensees          = true;
    opensees_controls = controls;
  }

  template <int dim>
  int
  ForceBeamColumn<dim>::opensees_pass(const unsigned int pass, const BasicVector &vin,
                                      const BasicVector &dv)
  {
    const double       L = this->length();
    const unsigned int n_iterations =
      pass == 1 ? 10 * opensees_controls.max_iterations : opensees_controls.max_iterations;
    start = current;
    start.q += start.kv * dv;
    for (unsigned int j = 0; j < n_iterations; ++j)
      {
        ++iterations;
        BasicMatrix f = BasicMatrix::Zero();
        BasicVector achieved = BasicVector::Zero();
        for (unsigned int i = 0; i < this->rule.size(); ++i)
          {
            const Interpolation   b  = force_interpolation(this->rule.points[i]);
            // s = b q + s_p at the load's current factor: OpenSees applies
            // the whole load in every piece (computeSectionForces)
            const ResultantVector ss = section_forces(i, start.q, this->load_factor);
            const bool initial = pass == 1 || (pass == 2 && j == 0);
            if (initialised)
              start.e[i] += (initial ? ResultantMatrix(initial_section_stiffness[i].inverse()) :
                                       start.fs[i]) *
                            (ss - start.s[i]);
            SectionLaw &section = *this->sections[i];
            if (!section.set_trial(SectionVector(start.e[i])))
              {
                this->why = section_failure(i, section);
                return -1;
              }
            start.s[i]      = section.resultant();
            start.fs[i]     = flexibility(i);
            const double wl = this->rule.weights[i] * L;
            f += wl * b.transpose() * start.fs[i] * b;
            achieved += wl * b.transpose() * (start.e[i] + start.fs[i] * (ss - start.s[i]));
          }
        start.kv             = f.inverse();
        const BasicVector r  = vin + dv - achieved;
        const BasicVector dq = start.kv * r;
        start.q += dq;
        if (!start.q.allFinite())
          return 0;
        if (std::abs(r.dot(dq)) < opensees_controls.tolerance)
          return 1;
      }
    return 0;
  }

  template <int dim>
  bool
  ForceBeamColumn<dim>::opensees_state(const BasicVector &v)
  {
    iterations = pieces = 0;
    // current.v: the last trial's v, skipped or not, so that dv is the
    // increment since the last update (OpenSees: getBasicIncrDeltaDisp, and
    // vin = v - dv), not since the last one the element took
    BasicVector to_do = v - current.v;
    // a loaded member iterates at every update (OpenSees: numEleLoads > 0)
    if (initialised && to_do.norm() <= std::numeric_limits<double>::epsilon() && !this->has_load)
      {
        current.v = v;
        return true;
      }
    BasicVector  dv           = to_do;
    unsigned int subdivisions = 1;
    while (subdivisions <= opensees_controls.max_subdivisions)
      {
        int result = 0;
        for (unsigned int pass = 0; pass < 3 && result == 0; ++pass)
          result = opensees_pass(pass, current.v, dv);
        if (result < 0)
          return false;
        if (result == 0)
          {
            dv /= opensees_controls.subdivide_factor;
            ++subdivisions;
            continue;
          }
        ++pieces;
        to_do -= dv;
        start.v = current.v + dv;
        current = start;
        if (to_do.norm() <= std::numeric_limits<double>::epsilon())
          {
            current.v   = v; // OpenSees's vin ends within DBL_EPSILON of v
            initialised = true;
            return true;
          }
        dv           = to_do;
        subdivisions = 1;
      }
    return false;
  }

  template <int dim>
  bool
  ForceBeamColumn<dim>::basic_state(const BasicVector &v, BasicVector &q, BasicMatrix &k)
  {
    if (opensees)
      {
        const bool ok = opensees_state(v);
        q             = current.q;
        k             = current.kv;
        if (!ok && this->why.empty())
          this->why = "force-based element: no compatible state after " +
                      std::to_string(iterations) + " iterations (OpenSees's iteration)";
        return ok;
      }
    constexpr unsigned int max_levels = 4, max_pieces = 100;
    iterations = pieces = 0;
    // the load factor's change goes in the same pieces as v's (an unloaded
    // member stays at factor 0: its pieces are v's alone)
    const double lambda         = this->has_load ? this->load_factor : 0.0;
    BasicVector  remaining      = v - current.v;
    BasicVector  piece          = remaining;
    double       load_remaining = lambda - current.factor, load_piece = load_remaining;
    unsigned int level          = 0;
    // the sections' initial flexibility, once the tangent's has failed at
    // every level (OpenSees's second strategy; see iterate)
    bool initial = false;
    while ((remaining.squaredNorm() > 0 && current.v != v) || current.factor != lambda)
      {
        start = current;
        // the last piece ends at v and lambda exactly
        const BasicVector target        = v - (remaining - piece);
        const double      target_factor = lambda - (load_remaining - load_piece);
        if (iterate(target, target_factor, initial))
          {
            current.v      = target;
            current.factor = target_factor;
            remaining -= piece;
            piece = remaining;
            load_remaining -= load_piece;
            load_piece = load_remaining;
            level      = 0;
            if (++pieces > max_pieces)
              break;
            continue;
          }
        current = start;
        if (++level > max_levels)
          {
            if (initial)
              break;
            initial    = true;
            level      = 0;
            piece      = remaining;
            load_piece = load_remaining;
            continue;
          }
        piece /= 10;
        load_piece /= 10;
      }
    q = current.q;
    k = current.kv;
    if (current.v == v && current.factor == lambda)
      return true;
    // the sections back at the last compatible state (a commit must not
    // see the failed iteration's)
    for (unsigned int i = 0; i < this->rule.size(); ++i)
      this->sections[i]->set_trial(SectionVector(current.e[i]));
    if (this->why.empty())
      this->why = "force-based element: no compatible state after " +
                  std::to_string(iterations) + " iterations in " + std::to_string(pieces + 1) +
                  " pieces (basic deformation increment norm " +
                  std::to_string(remaining.norm()) + ")";
    return false;
  }

  template <int dim>
  typename ForceBeamColumn<dim>::ResultantVector
  ForceBeamColumn<dim>::section_forces(const unsigned int i, const BasicVector &q,
                                       const double factor) const
  {
    const ResultantVector s = force_interpolation(this->rule.points[i]) * q;
    return this->has_load ? ResultantVector(s + factor * this->particular_forces(i)) : s;
  }

  template <int dim>
  double
  ForceBeamColumn<dim>::load_energy(const double factor) const
  {
    if (!this->has_load || factor == 0)
      return 0;
    double energy = 0;
    for (unsigned int i = 0; i < this->rule.size(); ++i)
      {
        const ResultantVector sp = factor * this->particular_forces(i);
        energy += this->rule.weights[i] * this->length() * std::abs(sp.dot(current.fs[i] * sp));
      }
    return energy;
  }

  template <int dim>
  bool
  ForceBeamColumn<dim>::iterate(const BasicVector &target, const double target_factor,
                                const bool initial)
  {
    const unsigned int     max_iterations = initial ? 200 : 20;
    const double           L              = this->length();
    const BasicVector      dv             = target - current.v;
    // The energy scale of the tolerance: the target's and the increment's
    // energies, and the sections' own work, sum_i w_i L |e_i . s_i|. The last
    // is what round-off in the compatibility sum L sum_i w_i b_i^T e_i is
    // relative to: a member back near v = 0 after cracking or yielding keeps
    // residual e_i and s_i, and without it a tiny increment from there asks
    // for a residual far below the round-off of those terms.
    double scale = std::abs(target.dot(current.kv * target)) + std::abs(dv.dot(current.kv * dv));
    for (unsigned int i = 0; i < this->rule.size(); ++i)
      scale += this->rule.weights[i] * L * std::abs(current.e[i].dot(current.s[i]));
    // and the element load's: a fixed-fixed member under it alone has v = 0
    scale += load_energy(target_factor);
    // An absolute floor, for a member near v = 0 with nothing behind it
    // (the scale above then ~ |v|^2, a tolerance that the residual's
    // round-off at a fibre law's kink, as Concrete01's at zero strain, never
    // meets): the work of a residual axial strain at round-off of a
    // yield-level strain, DBL_EPSILON * 2e-3 (reinforcing steel's yield,
    // concrete's strain at peak), over the member, sum_i w_i L EA_i eps^2.
    // It is ~1e-31 of the member's yield work, below 1e-20 of any loaded
    // member's scale, so converged paths keep their numbers.
    constexpr double noise_strain = 2e-3 * std::numeric_limits<double>::epsilon();
    double           noise_work   = 0;
    for (unsigned int i = 0; i < this->rule.size(); ++i)
      noise_work += this->rule.weights[i] * L * std::abs(initial_section_stiffness[i](0, 0)) *
                    noise_strain * noise_strain;
    current.q += current.kv * dv;
    double       previous = std::numeric_limits<double>::infinity();
    for (unsigned int j = 0; j < max_iterations; ++j)
      {
        ++iterations;
        BasicMatrix f        = BasicMatrix::Zero();
        BasicVector achieved = BasicVector::Zero();
        for (unsigned int i = 0; i < this->rule.size(); ++i)
          {
            const Interpolation   b  = force_interpolation(this->rule.points[i]);
            const ResultantVector ss = section_forces(i, current.q, target_factor);
            current.e[i] += (initial ? ResultantMatrix(initial_section_stiffness[i].inverse()) :
                                       current.fs[i]) *
                            (ss - current.s[i]);
            SectionLaw &section = *this->sections[i];
            if (!section.set_trial(SectionVector(current.e[i])))
              {
                this->why = section_failure(i, section);
                return false;
              }
            current.s[i]    = section.resultant();
            current.fs[i]   = flexibility(i);
            const double wl = this->rule.weights[i] * L;
            f += wl * b.transpose() * current.fs[i] * b;
            achieved += wl * b.transpose() * (current.e[i] + current.fs[i] * (ss - current.s[i]));
          }
        current.kv             = f.inverse();
        const BasicVector r    = target - achieved;
        const BasicVector dq   = current.kv * r;
        const double      work = std::abs(r.dot(dq));
        current.q += dq;
        if (!current.q.allFinite() || !current.kv.allFinite())
          return false;
        // converged, or stalled at round-off well below OpenSees's tolerance
        if (work <= std::max(1e-20 * scale, noise_work) ||
            (work <= 1e-12 * scale && work > 0.25 * previous))
          return true;
        previous = work;
      }
    return false;
  }

  template UniformLoadForces<2> uniform_load_forces<2>(double, const MemberLoad<2> &);
  template UniformLoadForces<3> uniform_load_forces<3>(double, const MemberLoad<3> &);
  template CrdTransformation<2>::GlobalVector
  basic_reactions<2>(const CrdTransformation<2> &, const Eigen::Matrix<double, 3, 1> &);
  template CrdTransformation<3>::GlobalVector
  basic_reactions<3>(const CrdTransformation<3> &, const Eigen::Matrix<double, 5, 1> &);
  template CrdTransformation<2>::GlobalVector fixed_end_forces<2>(const CrdTransformation<2> &,
                                                                  const MemberLoad<2> &);
  template CrdTransformation<3>::GlobalVector fixed_end_forces<3>(const CrdTransformation<3> &,
                                                                  const MemberLoad<3> &);
  template class BeamColumn<2>;
  template class BeamColumn<3>;
  template class DispBeamColumn<2>;
  template class DispBeamColumn<3>;
  template class ForceBeamColumn<2>;
  template class ForceBeamColumn<3>;
} // namespace poundfe
