// OpenSees's static and transient analyses of a script's domain
// (opensees_analysis.h gives the equations). Sources: OpenSees 3.8,
// SRC/analysis/integrator/Newmark.cpp (newStep: U kept, U' = (1 - gamma/beta)
// U'_n + dt (1 - gamma/(2 beta)) U''_n, U'' = -U'_n/(beta dt) + (1 - 1/(2
// beta)) U''_n; update: U += dU, U' += c2 dU, U'' += c3 dU), LoadControl.cpp
// (lambda += dlambda scaled by the iterations of the last step, clamped),
// HHT.cpp (newStep: Newmark's V, A, the elements at U_n with V_alpha and
// the loads at t + alpha dt; update: U_alpha = (1 - alpha) U_n + alpha U;
// commit: the elements at U_n+1, the time t + alpha dt + (1 - alpha) dt),
// NewtonLineSearch.cpp with InitialInterpolatedLineSearch.cpp,
// DisplacementControl.cpp (phat = the unbalance at lambda + 1 when the
// integrator first analyses; newStep: dUhat = K^-1 phat, dlambda = dU /
// dUhat_c; update: dU = dUbar + dlambda dUhat, dlambda = -dUbar_c / dUhat_c;
// the increment scaled by Jd over the last step's iterations, clamped),
// algorithm/equiSolnAlgo/NewtonRaphson.cpp, ModifiedNewton.cpp, Linear.cpp,
// convergenceTest/CTest*.cpp, DirectIntegrationAnalysis.cpp and
// StaticAnalysis.cpp (a failed step: the domain reverted, analyze < 0),
// TransformationConstraintHandler.cpp with RigidDiaphragm.cpp and
// RigidBeam.cpp (a rigid tie's constrained DOFs leave the equations:
// u_c = C u_r, the elements' forces and stiffness taken through C; nodal
// masses stay diagonal because the constrained nodes may carry none along
// their tied DOFs).
#include <poundfe/base/thread_limit.h>
#include <poundfe/assembly/band_lu_solver.h>
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/parallel_refusal.h>
#include <poundfe/opensees/opensees_analysis.h>
#include <poundfe/opensees/opensees_energy.h>


#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <limits>
#include <sstream>

namespace poundfe
{
  namespace opensees
  {
    namespace
    {
      constexpr int first_combination = Analysis::first_combination;

      /// The combination of a static analysis's components that poundfe
      /// refuses, named; empty if none. A line search, Krylov's acceleration
      /// or BFGS would move the state off DisplacementControl's or
      /// ArcLength's constraint. Under Lagrange OpenSees's multipliers enter
      /// ArcLength's arc and the test's norm (so an adaptive increment's
      /// iteration counts), which poundfe's exact elimination has not.
      std::string
      unsupported_combination(const AnalysisOptions &o)
      {
        using Algorithm = AnalysisOptions::Algorithm;
        if (o.transient || !(o.displacement_control || o.arc_length))
          return "";
        const std::string integrator =
          o.arc_length ? "ArcLength" : "DisplacementControl";
        const Algorithm a = o.algorithm;
        if (a == Algorithm::newton_line_search || a == Algorithm::krylov_newton ||
            a == Algorithm::bfgs)
          return std::string("algorithm ") +
                 (a == Algorithm::newton_line_search ? "NewtonLineSearch" :
                  a == Algorithm::krylov_newton      ? "KrylovNewton" :
                                                       "BFGS") +
                 " with integrator " + integrator;
        if (o.lagrange && o.arc_length)
          return "integrator ArcLength with constraints Lagrange (OpenSees's multipliers enter "
                 "the arc)";
        if (o.lagrange && o.d_u_min != o.d_u_max)
          return "integrator DisplacementControl with an adaptive increment (minIncr != maxIncr) "
                 "with constraints Lagrange (OpenSees's multipliers enter the iteration counts)";
        return "";
      }
    } // namespace

    /// The elements of a small model (a dense system) that are all
    /// UniaxialRows (zeroLength, truss) without Rayleigh damping, on
    /// equations without diaphragm combinations or imposed displacements:
    /// their trial states, forces and iteration matrices by typed loops
    /// over each element's laws and rows (UniaxialLinksOf, of the elements'
    /// number of DOFs), in place of the elements' virtual calls, local
    /// vectors and matrices of dynamic size. The same operations in the
    /// same order as ZeroLength's set_trial, force_into and
    /// tangent_and_damping_into (opensees_elements.cc) and as the
    /// analysis's assembly, so the same bits.
    class UniaxialLinks
    {
    public:
      virtual ~UniaxialLinks() = default;
      /// Null when some element does not qualify.
      static std::unique_ptr<UniaxialLinks> of(const std::vector<Element *> &elements);
      /// The laws' trial states at the elements' displacements u and
      /// velocities v (ZeroLength::set_trial); false, with why, when a law
      /// refuses.
      virtual bool set_trial(const Vector &u, const Vector &v, std::string &why) const = 0;
      /// r -= each element's force (ZeroLength::force_into).
      virtual void subtract_forces(Vector &r) const = 0;
      /// k += each element's c_k K_e + c_c C_e (ZeroLength's
      /// tangent_and_damping_into, the analysis's assembly).
      virtual void add_tangents(double c_k, double c_c, Matrix &k) const = 0;
    };

    namespace
    {
      /// UniaxialLinks of n_dofs DOFs each (2 ndf). Each loop repeats the
      /// operations of ZeroLength's (opensees_elements.cc) in their order, so
      /// that a model gives the same bits on either path: edit both.
      template <unsigned int n_dofs>
      class UniaxialLinksOf : public UniaxialLinks
      {
      public:
        void
        add(Element &element, UniaxialRows &rows)
        {
          Link link{&element, &rows, {}};
          std::copy(element.equations.begin(), element.equations.end(), link.equations.begin());
          links.push_back(link);
        }

        bool
        set_trial(const Vector &u, const Vector &v, std::string &why) const override
        {
          // ZeroLength::set_trial's sums, in its order
          for (const Link &link : links)
            {
              UniaxialRows &z = *link.rows;
              const auto    n = z.laws.size();
              std::array<double, n_dofs> local_u, local_v;
              for (unsigned int j = 0; j < n_dofs; ++j)
                {
                  const int eq = link.equations[j];
                  local_u[j]   = eq >= 0 ? u[eq] : 0.0;
                  local_v[j]   = eq >= 0 ? v[eq] : 0.0;
                }
              z.rate.resize(n);
              z.strain.resize(n);
              for (unsigned int m = 0; m < n; ++m)
                {
                  double e = 0, e_dot = 0;
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    {
                      e_dot += z.t(m, j) * local_v[j];
                      e += z.t(m, j) * local_u[j];
                    }
                  z.rate[m]   = e_dot * z.strain_scale;
                  z.strain[m] = e * z.strain_scale;
                }
              for (unsigned int m = 0; m < n; ++m)
                if (!z.laws[m]->set_trial(z.strain[m], z.rate[m]))
                  {
                    z.why = z.laws[m]->failure();
                    why   = "element " + std::to_string(link.element->tag) + ": " +
                          (z.why.empty() ? "its forces are not finite" : z.why);
                    return false;
                  }
            }
          return true;
        }

        void
        subtract_forces(Vector &r) const override
        {
          // ZeroLength::force_into's sums, in its order
          for (const Link &link : links)
            {
              const UniaxialRows        &z = *link.rows;
              std::array<double, n_dofs> f{};
              for (unsigned int m = 0; m < z.laws.size(); ++m)
                {
                  const double stress = z.laws[m]->force();
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    f[j] += z.t(m, j) * stress;
                }
              for (unsigned int j = 0; j < n_dofs; ++j)
                if (link.equations[j] >= 0)
                  r[link.equations[j]] += -(f[j] * z.force_scale);
            }
        }

        void
        add_tangents(const double c_k, const double c_c, Matrix &k) const override
        {
          // ZeroLength::weighted's sums, in its order
          for (const Link &link : links)
            {
              const UniaxialRows                  &z = *link.rows;
              std::array<double, n_dofs * n_dofs> kt{}, ct{};
              for (unsigned int m = 0; m < z.laws.size(); ++m)
                {
                  const double d = z.laws[m]->tangent();
                  const double e = c_c != 0 ? z.laws[m]->damping_tangent() : 0.0;
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    if (z.t(m, i) != 0)
                      for (unsigned int j = 0; j < n_dofs; ++j)
                        {
                          kt[i * n_dofs + j] += z.t(m, i) * d * z.t(m, j);
                          if (c_c != 0)
                            ct[i * n_dofs + j] += z.t(m, i) * e * z.t(m, j);
                        }
                }
              const double scale = z.force_scale * z.strain_scale;
              for (unsigned int i = 0; i < n_dofs; ++i)
                for (unsigned int j = 0; j < n_dofs; ++j)
                  {
                    const int ei = link.equations[i], ej = link.equations[j];
                    if (ei < 0 || ej < 0)
                      continue;
                    double value = kt[i * n_dofs + j] * scale * c_k;
                    if (c_c != 0)
                      value += c_c * (ct[i * n_dofs + j] * scale);
                    k(ei, ej) += value;
                  }
            }
        }

      private:
        struct Link
        {
          Element                      *element;
          UniaxialRows                 *rows;
          std::array<int, n_dofs>       equations;
        };
        std::vector<Link> links;
      };

      template <unsigned int n_dofs>
      std::unique_ptr<UniaxialLinks>
      links_of(const std::vector<Element *> &elements)
      {
        auto links = std::make_unique<UniaxialLinksOf<n_dofs>>();
        for (Element *element : elements)
          {
            UniaxialRows *rows = element->uniaxial_rows();
            const auto   &eq   = element->equations;
            if (!rows || element->rayleigh_damped() || eq.size() != n_dofs ||
                rows->t.cols() != n_dofs ||
                std::any_of(eq.begin(), eq.end(), [](const int e) { return e < -1; }))
              return nullptr;
            links->add(*element, *rows);
          }
        return links;
      }
    } // namespace

    std::unique_ptr<UniaxialLinks>
    UniaxialLinks::of(const std::vector<Element *> &elements)
    {
      switch (elements.empty() ? 0 : elements.front()->equations.size())
        {
          case 2: // ndf 1, 2, 3, 6
            return links_of<2>(elements);
          case 4:
            return links_of<4>(elements);
          case 6:
            return links_of<6>(elements);
          case 12:
            return links_of<12>(elements);
          default:
            return nullptr;
        }
    }

    Analysis::Analysis(Domain &domain, AnalysisOptions options)
      : domain(domain)
      , opts(std::move(options))
    {}

    Analysis::~Analysis() = default;

    void
    Analysis::configure(const AnalysisOptions &options)
    {
      if (options.d_lambda != opts.d_lambda)
        lambda_step = 0; // a new LoadControl integrator
      if (options.integrator_serial != opts.integrator_serial)
        fresh_integrator = true;
      if (options.penalty != opts.penalty) // the equations differ
        numbered = false;
      if (options.banded_system != opts.banded_system) // another solver
        {
          solver.reset();
          analysed = false;
        }
      opts = options;
    }

    void
    Analysis::number()
    {
      const bool eliminating = !opts.penalty; // Penalty keeps every DOF an equation
      DofMap     retained_by;
      for (const EqualDof &e : domain.equal_dofs)
        for (const unsigned int k : e.dofs)
          if (eliminating)
            retained_by[{e.constrained, k}] = {e.retained, k};
      std::set<std::pair<int, unsigned int>> in_tie; // numbered by number_ties
      for (const RigidTie &d : domain.rigid_ties)
        for (const int c : d.constrained)
          for (const unsigned int k : d.tied_dofs(domain.ndf))
            if (eliminating)
              in_tie.insert({c, k});
      imposed_dofs.clear();
      for (const auto &[dof, value] : domain.imposed_displacements(domain.time))
        if (eliminating)
          imposed_dofs.push_back(dof);
      n_equations = 0;
      for (auto &[tag, node] : domain.nodes)
        {
          node.equation.assign(node.fixed.size(), -1);
          for (unsigned int k = 0; k < node.fixed.size(); ++k)
            if ((!node.fixed[k] || !eliminating) && retained_by.count({tag, k}) == 0 &&
                in_tie.count({tag, k}) == 0 &&
                std::find(imposed_dofs.begin(), imposed_dofs.end(), std::make_pair(tag, k)) ==
                  imposed_dofs.end())
              node.equation[k] = n_equations++;
        }
      // an imposed DOF leaves the equations (Transformation's SP constraint)
      for (unsigned int j = 0; j < imposed_dofs.size(); ++j)
        domain.node(imposed_dofs[j].first).equation[imposed_dofs[j].second] = -2 - int(j);
      imposed_u.setZero(imposed_dofs.size());
      penalty_rows.clear();
      combinations.clear();
      if (eliminating)
        number_ties(retained_by);
      else
        number_penalty();
      number_inertia();
      number_coupled_masses();
      number_mass_damping();
      beam_loads_taken = false;
      for (auto &[tag, element] : domain.elements)
        {
          beam_loads_taken = beam_loads_taken || element->takes_beam_loads();
          element->equations.clear();
          for (const int n : element->node_tags)
            for (const int eq : domain.node(n).equation)
              element->equations.push_back(eq);
        }
      domain.changed = false;
      numbered       = true;
      modal_numbered = false;
      analysed       = false;
    }

    void
    Analysis::number_inertia()
    {
      mass_of_equation.setZero(n_equations);
      inertia_terms.clear();
      for (const auto &[tag, node] : domain.nodes)
        for (unsigned int k = 0; k < node.fixed.size(); ++k)
          if (node.equation[k] >= 0)
            {
              const double m = node.mass[k] + node.element_mass[k];
              mass_of_equation[node.equation[k]] += m;
              inertia_terms.push_back({node.equation[k], k, m});
            }
      second_ground_terms.clear();
      for (const Domain::LumpedMass &m : domain.lumped_masses)
        if (m.ground_load_twice)
          {
            const Node &node = domain.node(m.node);
            for (unsigned int k = 0; k < std::min(domain.ndm, domain.ndf); ++k)
              if (node.equation[k] >= 0)
                second_ground_terms.push_back({node.equation[k], k, m.mass});
          }
    }

    /// The masses' damping by equation when regions give alpha_M by element
    /// and node, or an element's mass is not Rayleigh-damped.
    void
    Analysis::number_mass_damping()
    {
      uniform_mass_damping = domain.uniform_mass_damping();
      if (uniform_mass_damping)
        return;
      mass_damping_of_equation.setZero(n_equations);
      for (const auto &[tag, c] : domain.mass_damping())
        {
          const Node &node = domain.node(tag);
          for (unsigned int k = 0; k < c.size(); ++k)
            if (node.equation[k] >= 0)
              mass_damping_of_equation[node.equation[k]] += c[k];
        }
    }

    namespace
    {
      /// Marks every rigid tie's constrained DOFs with the equation
      /// `waiting`, refusing a DOF fixed or constrained already and one with
      /// mass (the tie's own command named: the error surfaces at analyze).
      void
      hold_tied_dofs(Domain &domain, const int waiting)
      {
        for (const RigidTie &tie : domain.rigid_ties)
          for (const int c : tie.constrained)
            for (const unsigned int k : tie.tied_dofs(domain.ndf))
              {
                Node &node = domain.node(c);
                if (node.fixed[k] || node.equation[k] != -1)
                  throw ScriptError(tie.name() + ": node " + std::to_string(c) + " DOF " +
                                    std::to_string(k + 1) + " is fixed or constrained already");
                if (node.mass[k] + node.element_mass[k] != 0)
                  throw ScriptError(tie.name() + ": node " + std::to_string(c) +
                                    " has mass along DOF " + std::to_string(k + 1) +
                                    ": poundfe takes a " +
                                    (tie.beam ? "rigid link's" : "diaphragm's") +
                                    " mass at its retained node");
                node.equation[k] = waiting;
              }
      }
    } // namespace

    /// The equalDOFs and rigid ties (OpenSees's RigidDiaphragm and
    /// RigidBeam) as the Transformation handler imposes them, numbered in
    /// dependency order: a constrained DOF is numbered once its retained
    /// DOFs are, an equalDOF's taking its retained DOF's equation (or
    /// combination), a tie's the combination of its retained node's DOFs (a
    /// combination substituted, a fixed DOF contributing 0). A chain through
    /// a tie so gives OpenSees's Lagrange handler's displacements. The
    /// constrained DOFs must carry no mass (their inertia would need the
    /// transformed, non-diagonal mass matrix).
    void
    Analysis::number_ties(const DofMap &retained_by)
    {
      constexpr int waiting  = first_combination + 1; // not numbered yet
      const auto    equation = [this](const std::pair<int, unsigned int> &dof) -> int & {
        return domain.node(dof.first).equation[dof.second];
      };
      for (const auto &[dof, retained] : retained_by)
        equation(dof) = waiting;
      hold_tied_dofs(domain, waiting);
      const auto retained_numbered = [&](const RigidTie &tie) {
        const std::vector<unsigned int> dofs = tie.tied_dofs(domain.ndf);
        return std::none_of(dofs.begin(), dofs.end(), [&](const unsigned int k) {
          return equation({tie.retained, k}) == waiting;
        });
      };
      std::vector<bool> tie_numbered(domain.rigid_ties.size(), false);
      for (bool progress = true; progress;)
        {
          progress = false;
          for (const auto &[dof, retained] : retained_by)
            if (equation(dof) == waiting && equation(retained) != waiting)
              equation(dof) = equation(retained), progress = true;
          for (unsigned int t = 0; t < tie_numbered.size(); ++t)
            if (!tie_numbered[t] && retained_numbered(domain.rigid_ties[t]))
              {
                number_tie(domain.rigid_ties[t]);
                tie_numbered[t] = progress = true;
              }
        }
      for (unsigned int t = 0; t < tie_numbered.size(); ++t)
        if (!tie_numbered[t])
          throw ScriptError(domain.rigid_ties[t].name() + ": the retained node " +
                            std::to_string(domain.rigid_ties[t].retained) +
                            " is constrained in a loop of constraints");
      for (const auto &[dof, retained] : retained_by)
        {
          const std::string where = "equalDOF " + std::to_string(retained.first) + " " +
                                    std::to_string(dof.first) + ": node " +
                                    std::to_string(dof.first) + " DOF " +
                                    std::to_string(dof.second + 1);
          const Node &node = domain.node(dof.first);
          if (equation(dof) == waiting)
            throw ScriptError(where + " is constrained in a loop of constraints");
          if (equation(dof) <= first_combination &&
              node.mass[dof.second] + node.element_mass[dof.second] != 0)
            throw ScriptError(where + " has mass and follows a rigid tie's constrained node: "
                                      "poundfe takes a tie's mass at its retained node");
        }
    }

    /// One tie's combinations u_c = C_cr u_r, its retained DOFs numbered.
    void
    Analysis::number_tie(const RigidTie &tie)
    {
      const Node &retained = domain.node(tie.retained);
      for (const unsigned int k : tie.tied_dofs(domain.ndf))
        if (retained.equation[k] < -1 && retained.equation[k] > first_combination)
          throw ScriptError(tie.name() + ": the retained node " + std::to_string(tie.retained) +
                            " is imposed along DOF " + std::to_string(k + 1) + " (an sp)");
      for (const int c : tie.constrained)
        for (const unsigned int k : tie.tied_dofs(domain.ndf))
          {
            std::map<int, double> row;
            for (const auto &[dof, factor] : domain.tie_row(tie, c, k))
              {
                const int eq = retained.equation[dof];
                if (eq >= 0)
                  row[eq] += factor;
                else if (eq <= first_combination)
                  for (const auto &[e, f] : combinations[first_combination - eq])
                    row[e] += factor * f;
              }
            domain.node(c).equation[k] = first_combination - int(combinations.size());
            combinations.emplace_back(row.begin(), row.end());
          }
    }

    void
    Analysis::gather()
    {
      U.setZero(n_equations);
      V.setZero(n_equations);
      A.setZero(n_equations);
      for (const auto &[tag, node] : domain.nodes)
        for (unsigned int k = 0; k < node.equation.size(); ++k)
          if (node.equation[k] >= 0)
            {
              U[node.equation[k]] = node.disp[k];
              V[node.equation[k]] = node.vel[k];
              A[node.equation[k]] = node.accel[k];
            }
      trial_time = domain.time;
      at_alpha   = false;
    }

    void
    Analysis::scatter()
    {
      for (auto &[tag, node] : domain.nodes)
        for (unsigned int k = 0; k < node.equation.size(); ++k)
          {
            const int eq = node.equation[k];
            if (eq <= first_combination)
              {
                node.disp[k] = node.vel[k] = node.accel[k] = 0.0;
                for (const auto &[e, c] : combinations[first_combination - eq])
                  {
                    node.disp[k] += c * U[e];
                    node.vel[k] += c * V[e];
                    node.accel[k] += c * A[e];
                  }
                continue;
              }
            node.disp[k]  = eq >= 0 ? U[eq] : eq <= -2 ? imposed_u[-2 - eq] : 0.0;
            node.vel[k]   = eq < 0 ? 0.0 : V[eq];
            node.accel[k] = eq < 0 ? 0.0 : A[eq];
          }
    }

    std::vector<std::pair<int, double>>
    Analysis::terms(const int eq) const
    {
      if (eq <= first_combination)
        return combinations[first_combination - eq];
      return {{eq, 1.0}};
    }

    void
    Analysis::add_to(Vector &r, const int eq, const double value) const
    {
      if (eq >= 0)
        r[eq] += value;
      else if (eq <= first_combination)
        for (const auto &[e, c] : combinations[first_combination - eq])
          r[e] += c * value;
    }

    namespace
    {
      using Combinations = std::vector<std::vector<std::pair<int, double>>>;

      /// The element's local values of a vector by equation (into `local`,
      /// its storage kept): 0 where fixed, `imposed` where an sp command
      /// imposes the DOF (-2 - j: its j-th), a diaphragm's combination of
      /// equations where it constrains the DOF; `imposed` null: 0 there too.
      void
      element_values(const Element &element, const Vector &x, const Vector *imposed,
                     const Combinations &combinations, Vector &local)
      {
        local.resize(element.equations.size());
        for (unsigned int i = 0; i < local.size(); ++i)
          {
            const int eq = element.equations[i];
            local[i]     = eq >= 0 ? x[eq] :
                           imposed && eq > first_combination && eq <= -2 ? (*imposed)[-2 - eq] :
                                                                           0.0;
            if (eq <= first_combination)
              for (const auto &[e, c] : combinations[first_combination - eq])
                local[i] += c * x[e];
          }
      }

      /// The element's damping matrix C_e (see opensees_analysis.h) into c,
      /// `work` the storage of its tangents.
      void
      element_damping(const Element &element, const RayleighFactors &r, Matrix &c, Matrix &work)
      {
        if (!element.rayleigh_damped())
          {
            element.material_damping_into(c);
            return;
          }
        c.setZero(element.n_dofs(), element.n_dofs());
        if (r.beta_k != 0)
          {
            element.tangent_into(work);
            c += r.beta_k * work;
          }
        if (r.beta_k_init != 0)
          {
            element.initial_tangent_into(work);
            c += r.beta_k_init * work;
          }
        if (r.beta_k_committed != 0)
          c += r.beta_k_committed * element.committed_tangent;
      }
    } // namespace

    void
    Analysis::list_elements(const bool renumbered)
    {
      nodal_loads_given = std::any_of(domain.patterns.begin(), domain.patterns.end(),
                                      [](const auto &p) { return !p.second.loads.empty(); });
      if (!renumbered && element_list.size() == domain.elements.size())
        {
          auto listed = element_list.begin();
          for (const auto &[tag, element] : domain.elements)
            (listed++)->rayleigh = &domain.rayleigh_of(tag);
          return;
        }
      element_list.clear();
      std::vector<Element *> elements;
      for (auto &[tag, element] : domain.elements)
        {
          const std::vector<int> &eq = element->equations;
          element_list.push_back(
            {element.get(), &domain.rayleigh_of(tag),
             std::any_of(eq.begin(), eq.end(), [](const int e) { return e <= first_combination; })});
          elements.push_back(element.get());
        }
      links = dense() && imposed_dofs.empty() ? UniaxialLinks::of(elements) : nullptr;
      // a member's microseconds pay for a thread, a spring's nanoseconds do not
      constexpr long costly_elements = 8;
      elements_on_threads =
        thread_limit() > 1 &&
        std::count_if(elements.begin(), elements.end(),
                      [](const Element *e) { return e->costly_trial(); }) >= costly_elements;
    }

    bool
    Analysis::set_trial(std::string &why)
    {
      const Vector &u = at_alpha ? U_alpha : U, &v = at_alpha ? V_alpha : V;
      if (!imposed_dofs.empty() && opts.transformation) // static only: they do not move
        {
          const auto imposed = domain.imposed_displacements(trial_time);
          for (unsigned int j = 0; j < imposed_dofs.size(); ++j)
            imposed_u[j] = imposed.at(imposed_dofs[j]);
        }
      if (links)
        return links->set_trial(u, v, why);
      element_state.resize(element_list.size());
      // each element writes only its own state, so threads keep the bits;
      // a refusal fails the step, which reverts every element
      const auto evaluate = [&](const unsigned int e) {
        Element &element         = *element_list[e].element;
        auto &[local_u, local_v] = element_state[e];
        element_values(element, u, &imposed_u, combinations, local_u);
        element_values(element, v, nullptr, combinations, local_v);
        return element.set_trial(local_u, local_v);
      };
      const unsigned int refused =
        first_refusal(element_list.size(), evaluate, elements_on_threads);
      if (refused == element_list.size())
        return true;
      // an element without a law to blame refuses non-finite forces
      const Element    &element = *element_list[refused].element;
      const std::string reason  = element.failure();
      why = "element " + std::to_string(element.tag) + ": " +
            (reason.empty() ? "its forces are not finite" : reason);
      return false;
    }

    const Vector &
    Analysis::residual()
    {
      Vector &r = unbalance;
      r.setZero(n_equations);
      const Vector &v = at_alpha ? V_alpha : V; // HHT: the damping at t + alpha dt
      if (beam_loads_taken)
        domain.apply_element_loads(trial_time); // their resisting forces take them
      for (const auto &[tag, load] :
           nodal_loads_given ? domain.nodal_loads(trial_time) : no_nodal_loads)
        {
          const Node &node = domain.node(tag);
          for (unsigned int k = 0; k < load.size(); ++k)
            add_to(r, node.equation[k], load[k]);
        }
      if (links)
        links->subtract_forces(r);
      else
        subtract_element_forces(r, v);
      add_penalty_forces(r);
      if (!opts.transient)
        return r;
      const double alpha_m = uniform_mass_damping ? domain.rayleigh.alpha_m : 0.0;
      if (!ground_known || ground_time != trial_time)
        {
          domain.ground_acceleration(trial_time, ground);
          ground_time  = trial_time;
          ground_known = true;
        }
      for (const InertiaTerm &t : inertia_terms) // the nodes' order, as OpenSees sums
        r[t.equation] -=
          t.mass * (A[t.equation] + ground[t.dof] + alpha_m * v[t.equation]);
      for (const InertiaTerm &t : second_ground_terms)
        r[t.equation] -= t.mass * ground[t.dof];
      if (!coupled_masses.empty())
        subtract_coupled_inertia(r, v);
      if (!uniform_mass_damping)
        r -= mass_damping_of_equation.cwiseProduct(v);
      if (modal_damping_active()) // HHT: OpenSees's getVel is the velocity at t + dt
        r -= modal_mass_shapes *
             modal_coefficients.cwiseProduct(modal_mass_shapes.transpose() * (opts.hht ? V : v));
      return r;
    }

    void
    Analysis::subtract_element_forces(Vector &r, const Vector &v)
    {
      for (const ListedElement &listed : element_list)
        {
          const Element &element = *listed.element;
          Vector        &f       = element_force;
          element.force_into(f);
          if (opts.transient && element.rayleigh_damped()) // materials' own damping is in f
            {
              element_damping(element, *listed.rayleigh, element_damping_matrix,
                              element_work_matrix);
              element_values(element, v, nullptr, combinations, element_velocity);
              f.noalias() += element_damping_matrix * element_velocity;
            }
          const std::vector<int> &eq = element.equations;
          for (unsigned int i = 0; i < f.size(); ++i)
            if (listed.combined)
              add_to(r, eq[i], -f[i]);
            else if (eq[i] >= 0)
              r[eq[i]] += -f[i];
        }
    }

    void
    Analysis::add_element_tangents(const double c_k, const double c_c)
    {
      const bool as_dense = dense();
      const auto add      = [&](const int i, const int j, const double value) {
        if (as_dense)
          dense_tangent(i, j) += value;
        else
          tangent_entries.emplace_back(i, j, value);
      };
      if (links) // dense, the elements' equations without combinations
        return links->add_tangents(c_k, c_c, dense_tangent);
      for (const ListedElement &listed : element_list)
        {
          const Element &element = *listed.element;
          Matrix        &k       = element_matrix;
          if (!element.rayleigh_damped()) // c_k K_e + c_c C_e in one pass
            element.tangent_and_damping_into(c_k, c_c, k, element_damping_matrix);
          else
            {
              element.tangent_into(k);
              k *= c_k;
              if (c_c != 0)
                {
                  element_damping(element, *listed.rayleigh, element_damping_matrix,
                                  element_work_matrix);
                  k += c_c * element_damping_matrix;
                }
            }
          const auto &eq = element.equations;
          if (as_dense && !listed.combined) // the entries where they go, in the same order
            {
              for (unsigned int i = 0; i < eq.size(); ++i)
                for (unsigned int j = 0; j < eq.size(); ++j)
                  if (eq[i] >= 0 && eq[j] >= 0)
                    dense_tangent(eq[i], eq[j]) += k(i, j);
              continue;
            }
          for (unsigned int i = 0; i < eq.size(); ++i)
            for (unsigned int j = 0; j < eq.size(); ++j)
              if (eq[i] >= 0 && eq[j] >= 0)
                add(eq[i], eq[j], k(i, j));
              else if ((eq[i] >= 0 || eq[i] <= first_combination) &&
                       (eq[j] >= 0 || eq[j] <= first_combination))
                for (const auto &[ei, ci] : terms(eq[i]))
                  for (const auto &[ej, cj] : terms(eq[j]))
                    add(ei, ej, ci * cj * k(i, j));
        }
    }

    void
    Analysis::assemble_tangent(const double c_k, const double c_c, const double c_m)
    {
      const double diagonal = c_m + (uniform_mass_damping ? c_c * domain.rayleigh.alpha_m : 0.0);
      // a mass or factor near the largest double overflows m / dt^2: the
      // solution would be 0 where it is not
      const char *not_finite = "the effective matrix is not finite (a mass, damping factor or "
                               "stiffness too large)";
      if (dense())
        {
          dense_tangent.setZero(n_equations, n_equations);
          add_element_tangents(c_k, c_c);
          add_penalty_tangent();
          dense_tangent.diagonal() += diagonal * mass_of_equation;
          add_coupled_masses(c_m, c_c);
          if (!uniform_mass_damping)
            dense_tangent.diagonal() += c_c * mass_damping_of_equation;
          if (modal_damping_in_tangent(c_c))
            dense_tangent += c_c * modal_mass_shapes * modal_coefficients.asDiagonal() *
                             modal_mass_shapes.transpose();
          if (!dense_tangent.allFinite())
            throw NumericalError(not_finite);
          const char *singular = "LU: the effective matrix is singular";
          if (small())
            {
              if (!small_factors.factorize(dense_tangent, n_equations))
                throw NumericalError(singular);
              ++counts.factorizations;
              return;
            }
          dense_factors.compute(dense_tangent);
          if ((dense_factors.matrixLU().diagonal().array() == 0).any())
            throw NumericalError(singular);
          ++counts.factorizations;
          return;
        }
      tangent_entries.clear();
      add_element_tangents(c_k, c_c);
      add_penalty_tangent();
      for (unsigned int i = 0; i < n_equations; ++i) // the diagonal always in the pattern
        tangent_entries.emplace_back(i, i,
                                     diagonal * mass_of_equation[i] +
                                       (uniform_mass_damping ? 0.0 :
                                                               c_c * mass_damping_of_equation[i]));
      add_coupled_masses(c_m, c_c);
      if (modal_damping_in_tangent(c_c))
        {
          const Matrix C = modal_mass_shapes * modal_coefficients.asDiagonal() *
                           modal_mass_shapes.transpose();
          for (unsigned int j = 0; j < n_equations; ++j)
            for (unsigned int i = 0; i < n_equations; ++i)
              if (C(i, j) != 0)
                tangent_entries.emplace_back(i, j, c_c * C(i, j));
        }
      tangent_matrix.resize(n_equations, n_equations);
      tangent_matrix.setFromTriplets(tangent_entries.begin(), tangent_entries.end());
      if (!Eigen::Map<const Vector>(tangent_matrix.valuePtr(), tangent_matrix.nonZeros()).allFinite())
        throw NumericalError(not_finite);
      if (!solver)
        solver = opts.banded_system ? create_band_lu_solver("give system UmfPack")
                                     : create_umfpack_solver();
      if (!analysed)
        solver->analyze(tangent_matrix);
      analysed = true;
      solver->factorize(tangent_matrix);
      ++counts.factorizations;
    }

    void
    Analysis::solve(const Vector &b, Vector &x)
    {
      if (!dense())
        {
          solver->solve(b, x);
          return;
        }
      x.resize(b.size());
      if (small())
        small_factors.solve(b, x);
      else
        x = dense_factors.solve(b);
    }

    double
    Analysis::test_norm(const Vector &dx, const Vector &r) const
    {
      switch (opts.test.kind)
        {
          case ConvergenceTest::Kind::norm_disp_incr:
          case ConvergenceTest::Kind::relative_norm_disp_incr: // judge divides
            return dx.norm();
          case ConvergenceTest::Kind::norm_unbalance:
            return r.norm();
          case ConvergenceTest::Kind::energy_incr:
            return 0.5 * std::abs(dx.dot(r));
        }
      return 0;
    }

    bool
    Analysis::fresh_test_met(const Vector &dx, const Vector &r) const
    {
      double norm = test_norm(dx, r);
      // a relative test started afresh takes this norm as its first: the
      // ratio is 1 (0 when dx is 0), as CTestRelativeNormDispIncr's copy
      if (opts.test.kind == ConvergenceTest::Kind::relative_norm_disp_incr && norm != 0)
        norm = 1;
      return norm <= opts.test.tolerance;
    }

    void
    Analysis::print_iteration(const unsigned int iteration, const double norm) const
    {
      using Kind = ConvergenceTest::Kind;
      const Kind         kind = opts.test.kind;
      std::ostringstream text;
      text << "CTest"
           << (kind == Kind::norm_disp_incr          ? "NormDispIncr" :
               kind == Kind::relative_norm_disp_incr ? "RelativeNormDispIncr" :
               kind == Kind::norm_unbalance          ? "NormUnbalance" :
                                                       "EnergyIncr")
           << "::test() - iteration: " << iteration << " current "
           << (kind == Kind::energy_incr ? "EnergyIncr" : "Norm") << ": " << norm
           << " (max: " << opts.test.tolerance << ")";
      if (print)
        print(text.str());
    }

    bool
    Analysis::apply_increment(const Vector &dx, std::string &why)
    {
      U += dx;
      V += c_c * dx;
      A += c_m * dx;
      update_alpha_point();
      return set_trial(why);
    }

    void
    Analysis::update_alpha_point()
    {
      if (!at_alpha)
        return;
      const double a = opts.alpha;
      U_alpha        = (1 - a) * U_n + a * U;
      V_alpha        = (1 - a) * V_n + a * V;
    }

    bool
    Analysis::line_search(const double s0, Vector &dx, Vector &r, std::string &why)
    {
      const AnalysisOptions::LineSearch &p = opts.line_search;
      double       s     = -dx.dot(r);
      const double r0    = s0 != 0 ? std::abs(s / s0) : 0;
      if (r0 <= p.tolerance)
        return true; // the residual fell enough
      const Vector d   = dx;
      double       eta = 1, eta_prev = 1, ratio = r0;
      const auto   say = [&](const std::string &text) {
        if (p.print && print) // OpenSees prints with -pFlag 0
          print("InitialInterpolated Line Search - " + text);
      };
      std::ostringstream text;
      text << "initial           eta : " << eta << " , Ratio |s/s0| = " << r0;
      say(text.str());
      for (unsigned int count = 0; ratio > p.tolerance && count < p.max_iterations;)
        {
          ++count;
          eta *= s0 / (s0 - s);
          eta = std::min(eta, p.max_eta);
          if (ratio > r0)
            eta = 1.0;
          eta = std::max(eta, p.min_eta);
          if (eta == eta_prev)
            break;
          if (!apply_increment(d * (eta - eta_prev), why))
            return false;
          r     = residual();
          s     = d.dot(r); // OpenSees's sign from here on
          ratio = std::abs(s / s0);
          text.str("");
          text << "iteration: " << count << " , eta(j) : " << eta << " , Ratio |sj/s0| = " << ratio;
          say(text.str());
          eta_prev = eta;
        }
      if (eta != 0)
        dx = d * eta;
      return true;
    }

    namespace
    {
      /// OpenSees's KrylovAccelerator: the subspace of one tangent's
      /// iterations (v: the accelerated increments, av: the differences of
      /// the solutions, the last one the latest solution itself).
      class KrylovAccelerator
      {
      public:
        KrylovAccelerator(const unsigned int max_dimension, const unsigned int n_equations)
          : max_dimension(std::min(max_dimension, n_equations))
        {}

        /// The accelerated increment of the solution r (accelerate()).
        Vector
        accelerate(const Vector &r)
        {
          const std::size_t k = v.size();
          Vector            x = r;
          av.push_back(r);
          if (k > 0)
            {
              av[k - 1] -= r; // r_{k-1} - r_k
              Matrix a(r.size(), k);
              for (std::size_t j = 0; j < k; ++j)
                a.col(j) = av[j];
              const Vector c = a.householderQr().solve(r); // LAPACK's dgels: QR
              for (std::size_t j = 0; j < k; ++j)
                {
                  x += c[j] * v[j];
                  x -= c[j] * av[j];
                }
            }
          v.push_back(x);
          return x;
        }

        /// After an iteration that did not converge: true when the
        /// subspace is past maxDim and emptied (then a new tangent).
        bool
        restart()
        {
          if (v.size() <= max_dimension)
            return false;
          v.clear();
          av.clear();
          return true;
        }

      private:
        const unsigned int  max_dimension;
        std::vector<Vector> v, av;
      };
    } // namespace

    int
    Analysis::judge(const unsigned int iteration, const unsigned int max_iterations,
                    const Vector &dx, const Vector &r, std::string &why, const bool script_test)
    {
      double    norm = test_norm(dx, r);
      const int flag = opts.test.print_flag;
      if (script_test) // CTest::start zeroes the norms, test() counts on but when met
        {
          if (iteration == 1 || test_norms.size() != max_iterations)
            test_norms.assign(max_iterations, 0.0);
          if (iteration <= max_iterations)
            test_norms[iteration - 1] = norm;
          test_iterations = iteration + 1;
        }
      if (opts.test.kind == ConvergenceTest::Kind::relative_norm_disp_incr)
        {
          double &first = first_norms[script_test ? 0 : 1];
          if (iteration == 1)
            first = norm;
          if (first != 0)
            norm /= first;
        }
      if (flag == 1 || (flag == 2 && norm <= opts.test.tolerance))
        print_iteration(iteration, norm);
      if (norm <= opts.test.tolerance || ((flag == 5 || flag == 6) && iteration >= max_iterations))
        {
          test_iterations -= script_test ? 1 : 0;
          return iteration; // met, or OpenSees's "failed to converge but going on"
        }
      if (iteration < max_iterations)
        return 0;
      std::ostringstream text;
      text << "failed to converge after " << iteration << " iterations, current norm " << norm
           << " (max: " << opts.test.tolerance << ")";
      why = text.str();
      return -1;
    }

    namespace
    {
      /// BFGS::BFGSUpdate's history on one tangent: the increments s_i, the
      /// solutions z_i = K^-1 dr_i of the residual changes dr_i = R_i-1 -
      /// R_i, and s_i . dr_i, z_i . dr_i. OpenSees stops each sum at the
      /// first s_i . dr_i below 1e-16 (a signed test, kept as it is).
      class BfgsHistory
      {
      public:
        explicit BfgsHistory(const Vector &s_1)
          : s{s_1}
        {}

        /// z_n from K^-1 dr_n (z) corrected by the earlier pairs, then the
        /// quasi-Newton increment du from K^-1 R_n (du) and R_n (b).
        void
        update(Vector z, const Vector &dr, Vector &du, const Vector &b)
        {
          correct(z, dr, z_i.size());
          z_i.push_back(z);
          s_dot_r.push_back(s.back().dot(dr));
          r_dot_z.push_back(z.dot(dr));
          correct(du, b, z_i.size());
        }

        /// The increment the state moved by: s_n+1.
        void
        add(const Vector &du)
        {
          s.push_back(du);
        }

      private:
        /// x += sum_i [(1 + r.z_i / s.r_i) (s_i . b) s_i - (z_i . b) s_i -
        /// (s_i . b) z_i] / s.r_i over the first n pairs.
        void
        correct(Vector &x, const Vector &b, const std::size_t n) const
        {
          for (std::size_t i = 0; i < n; ++i)
            {
              if (s_dot_r[i] < 1e-16)
                break;
              const double sb = s[i].dot(b), zb = z_i[i].dot(b);
              x += (1 + r_dot_z[i] / s_dot_r[i]) / s_dot_r[i] * sb * s[i];
              x -= zb / s_dot_r[i] * s[i];
              x -= sb / s_dot_r[i] * z_i[i];
            }
        }

        std::vector<Vector> s, z_i;
        std::vector<double> s_dot_r, r_dot_z;
      };
    } // namespace

    int
    Analysis::iterate_bfgs(std::string &why)
    {
      Vector x(n_equations), du(n_equations);
      for (unsigned int tangent = 1;; ++tangent)
        {
          assemble_tangent(k_k, k_c, c_m);
          Vector r = residual();
          solve(r, x); // the Newton increment s_1
          ++last_iterations;
          ++counts.iterations;
          if (!apply_increment(x, why))
            return -1;
          BfgsHistory history(x);
          Vector      resid_old = -r;
          r                     = residual();
          for (unsigned int n = 1;; ++n)
            {
              const Vector dr = -r - resid_old; // OpenSees's residNew - residOld
              solve(r, du);
              solve(dr, x); // K^-1 dr: the system's last solution, which the test sees
              history.update(x, dr, du, r);
              resid_old = -r;
              ++last_iterations;
              ++counts.iterations;
              if (!apply_increment(du, why))
                return -1;
              history.add(du);
              r = residual();
              std::string local_why; // the inner test only ends the sequence
              if (judge(n, opts.bfgs_count, x, r, local_why, false) != 0 ||
                  n >= opts.bfgs_count)
                break;
            }
          const int verdict = judge(tangent, opts.test.max_iterations, x, r, why);
          if (verdict != 0)
            return verdict;
        }
    }

    int
    Analysis::iterate(std::string &why)
    {
      using Algorithm = AnalysisOptions::Algorithm;
      const bool searching = opts.algorithm == Algorithm::newton_line_search;
      const bool krylov    = opts.algorithm == Algorithm::krylov_newton;
      if (opts.algorithm == Algorithm::bfgs)
        return iterate_bfgs(why);
      const bool every_iteration = opts.algorithm == Algorithm::newton || searching;
      Vector    &r               = iteration_residual; // their storage kept
      Vector    &dx              = iteration_increment;
      Vector     accelerated; // KrylovNewton's increment
      r                          = residual();
      if (!every_iteration) // Linear, ModifiedNewton, KrylovNewton: one tangent per step
        assemble_tangent(k_k, k_c, c_m);
      KrylovAccelerator accelerator(opts.krylov_dimension, n_equations);
      for (unsigned int iteration = 1;; ++iteration)
        {
          if (every_iteration)
            assemble_tangent(k_k, k_c, c_m);
          solve(r, dx);
          if (opts.displacement_control && !opts.transient && !correct_displacement(dx, why))
            return -1;
          if (opts.arc_length && !opts.transient && !correct_arc_length(dx, why))
            return -1;
          const double s0 = -dx.dot(r);
          ++last_iterations;
          ++counts.iterations;
          // the state moves by the accelerated increment; the test sees dx
          if (!apply_increment(krylov ? accelerated = accelerator.accelerate(dx) : dx, why))
            return -1;
          if (opts.algorithm == Algorithm::linear)
            return 1;
          r = residual();
          // NewtonLineSearch searches unless the test is already met
          if (searching && !fresh_test_met(dx, r) && !line_search(s0, dx, r, why))
            return -1;
          const int verdict = judge(iteration, opts.test.max_iterations, dx, r, why);
          if (verdict != 0)
            return verdict;
          if (krylov && accelerator.restart())
            assemble_tangent(k_k, k_c, c_m);
        }
    }

    bool
    Analysis::step(const double dt, std::string &why)
    {
      if (opts.transient)
        {
          const double g = opts.gamma, b = opts.beta, a = opts.alpha;
          c_c            = g / (b * dt);
          c_m            = 1 / (b * dt * dt);
          k_k            = a;
          k_c            = a * c_c;
          step_dt        = dt;
          const Vector &v = step_velocity; // V_n, its storage kept
          step_velocity   = V;
          V               = (1 - g / b) * v + dt * (1 - 0.5 * g / b) * A;
          A              = (1 - 0.5 / b) * A - 1 / (b * dt) * v;
          trial_time     = domain.time + a * dt;
          if (a != 1) // HHT: the elements at U_n (exactly), the velocity V_alpha
            {
              at_alpha = true;
              U_n = U_alpha = U;
              V_n           = v;
              V_alpha       = (1 - a) * V_n + a * V;
            }
        }
      else if (opts.displacement_control)
        return displacement_step(why);
      else if (opts.arc_length)
        return arc_length_step(why);
      else
        {
          lambda_step *= opts.lambda_iterations / last_iterations;
          lambda_step = std::min(std::max(lambda_step, opts.lambda_min), opts.lambda_max);
          trial_time  = domain.time + lambda_step;
          c_c = c_m = k_c = 0;
          k_k               = 1;
        }
      last_iterations = 0;
      if (!set_trial(why) || iterate(why) < 0)
        return false;
      if (!at_alpha)
        return true;
      // HHT's commit: the elements at U_n+1, the time t + alpha dt + (1 - alpha) dt
      at_alpha = false;
      trial_time += (1 - opts.alpha) * step_dt;
      return set_trial(why);
    }

    void
    Analysis::reference_load()
    {
      std::string why;
      set_trial(why); // the committed state
      const double time = trial_time;
      trial_time        = domain.time + 1;
      phat              = residual();
      trial_time        = time;
    }

    bool
    Analysis::displacement_step(std::string &why)
    {
      if (fresh_integrator)
        {
          const Node &node = domain.node(opts.control_node);
          if (opts.control_dof >= node.equation.size() || node.equation[opts.control_dof] < 0)
            throw ScriptError("DisplacementControl: node " + std::to_string(node.tag) + " DOF " +
                              std::to_string(opts.control_dof + 1) +
                              " is fixed or constrained");
          control_equation = node.equation[opts.control_dof];
          d_u_step         = opts.d_u;
          last_iterations  = opts.d_u_iterations;
          reference_load();
          fresh_integrator = false;
        }
      d_u_step *= opts.d_u_iterations / last_iterations;
      d_u_step = std::min(std::max(d_u_step, opts.d_u_min), opts.d_u_max);
      Vector dx_hat(n_equations);
      if (!reference_displacement(dx_hat, why))
        return false;
      if (dx_hat[control_equation] == 0)
        {
          why = "DisplacementControl: zero reference displacement at the control DOF";
          return false;
        }
      const double d_lambda = d_u_step / dx_hat[control_equation];
      return predict_and_iterate(d_lambda, d_lambda * dx_hat, why);
    }

    bool
    Analysis::reference_displacement(Vector &dx_hat, std::string &why)
    {
      c_c = c_m = k_c = 0;
      k_k             = 1;
      if (!set_trial(why))
        return false;
      assemble_tangent(1, 0, 0);
      solve(phat, dx_hat);
      return true;
    }

    bool
    Analysis::predict_and_iterate(const double d_lambda, const Vector &dx, std::string &why)
    {
      trial_time = domain.time + d_lambda;
      U += dx;
      last_iterations = 0;
      if (!set_trial(why))
        return false;
      return iterate(why) >= 0;
    }

    bool
    Analysis::correct_displacement(Vector &dx, std::string &why)
    {
      Vector dx_hat(n_equations);
      solve(phat, dx_hat);
      if (dx_hat[control_equation] == 0)
        {
          why = "DisplacementControl: zero reference displacement at the control DOF";
          return false;
        }
      const double d_lambda = -dx[control_equation] / dx_hat[control_equation];
      dx += d_lambda * dx_hat;
      trial_time += d_lambda;
      return true;
    }

    void
    Analysis::commit()
    {
      const bool committed_stiffness = domain.committed_stiffness_damping();
      for (const ListedElement &listed : element_list)
        {
          listed.element->commit();
          if (committed_stiffness)
            listed.element->committed_tangent = listed.element->tangent();
        }
      if (events)
        events->commit();
      domain.time = trial_time;
      scatter();
      ++counts.steps;
    }

    void
    Analysis::begin_analysis(const std::function<void(const std::string &)> &warn)
    {
      const std::string refused = unsupported_combination(opts);
      if (!refused.empty())
        throw ScriptError(refused + " is not supported");
      const bool renumber = domain.changed || !numbered;
      if (renumber)
        number();
      list_elements(renumber);
      const bool penalty_imposed = std::any_of(penalty_rows.begin(), penalty_rows.end(),
                                               [](const PenaltyRow &p) { return p.is_imposed; });
      if (opts.transient && (!imposed_dofs.empty() || penalty_imposed))
        throw ScriptError("sp in a transient analysis is not supported");
      if (!opts.transformation && !imposed_dofs.empty())
        warn("PlainHandler::handle() - non-homogeneous sp constraint: homogeneous constraint "
             "assumed (constraints Transformation imposes its value)");
      print        = warn;
      ground_known = false; // the patterns may have changed since the last analyze
      if (lambda_step == 0)
        {
          lambda_step     = opts.d_lambda;
          last_iterations = opts.lambda_iterations;
        }
    }

    bool
    Analysis::advance(const double dt, std::string &why, bool *event)
    {
      gather();
      bool converged = false;
      try
        {
          converged = step(dt, why);
        }
      catch (const NumericalError &e)
        {
          why = e.what();
        }
      // poundfe::locateEvents: a contact that starts or ends in the step
      const bool located = converged && event && events->changed();
      if (!converged || located)
        {
          revert_to_last_commit();
          if (located)
            *event = true;
          else
            ++counts.failed_steps;
          return false;
        }
      commit();
      return true;
    }

    bool
    Analysis::advance_in_halves(const double dt, const unsigned int depth,
                                const std::function<void()> &after_step, std::string &why)
    {
      // ops_Dt is each sub-step's, as for a cut step; the second half ends
      // at the step's end exactly
      const double script_dt = domain.time_step;
      const double end       = domain.time + dt;
      const bool   locate    = depth < event_levels;
      bool         done      = true;
      for (unsigned int half = 0; half < 2 && done; ++half)
        {
          const double h   = half == 0 ? 0.5 * dt : end - domain.time;
          domain.time_step = h;
          bool event       = false;
          if (advance(h, why, locate ? &event : nullptr))
            after_step();
          else // an event or a failure: halved again, or at dt/2^R cut
            done = locate ? advance_in_halves(h, depth + 1, after_step, why) :
                            cut_step(h, after_step, why);
        }
      domain.time_step = script_dt;
      return done;
    }

    void
    Analysis::revert_to_last_commit()
    {
      // OpenSees's Domain::revertToLastCommit: every element reverts, the
      // loads go back to the committed time, then update(): every element's
      // state at the committed displacements. A force-based member iterates
      // there once more with its sections held (its revert leaves initialFlag
      // 0), so the next step starts from its q corrected to compatibility.
      for (auto &[tag, element] : domain.elements)
        element->revert();
      const double failed_time = trial_time; // for the caller's message
      gather();
      if (beam_loads_taken)
        domain.apply_element_loads(trial_time);
      std::string ignored; // OpenSees goes on when this update fails
      set_trial(ignored);
      trial_time = failed_time;
    }

    int
    Analysis::analyze(const unsigned int n_steps, const double dt,
                      const std::function<void()>                     &after_step,
                      const std::function<void(const std::string &)> &warn)
    {
      begin_analysis(warn);
      // poundfe::locateEvents: a step with an event is redone in halves; so
      // is a step that fails, which cannot tell whether a contact began in
      // it (a Hertz law's Newton fails on an impact's step more often than not)
      const bool locate = events && opts.transient; // events: event_levels > 0
      for (unsigned int i = 0; i < n_steps; ++i)
        {
          std::string why;
          bool        event = false;
          if (advance(dt, why, locate ? &event : nullptr))
            {
              after_step();
              continue;
            }
          // the sub-steps recorded as they converge
          if (!(locate ? advance_in_halves(dt, 1, after_step, why) :
                         cut_step(dt, after_step, why)))
            {
              std::ostringstream text;
              text << "analyze: the step to time " << trial_time << " failed (" << why
                   << "); the domain is back at time " << domain.time;
              warn(text.str());
              return -3;
            }
        }
      return 0;
    }

    bool
    Analysis::cut_step(const double dt, const std::function<void()> &after_step, std::string &why)
    {
      if (max_cuts == 0)
        return false;
      // OpenSees's ops_Dt is each sub-step's, as a script's own loop of
      // `analyze 1 h` would set it (a ViscousDamper integrates over it)
      const double script_dt = domain.time_step;
      const double end       = domain.time + dt;
      double       h         = dt;
      unsigned int cuts      = 0;
      bool         done      = false;
      while (!done)
        {
          if (++cuts > max_cuts)
            break;
          h *= 0.5;
          // the sub-steps of this size up to the step's end (the last one
          // lands on it); a failure halves them again from where it failed
          for (bool failed = false; !failed && !done;)
            {
              const bool   last = domain.time + 1.5 * h >= end;
              const double step = last ? end - domain.time : h;
              domain.time_step  = step;
              std::string sub_why;
              failed = !advance(step, sub_why);
              if (failed)
                why = sub_why;
              else
                {
                  after_step();
                  done = last;
                }
            }
        }
      domain.time_step = script_dt;
      if (done)
        why.clear();
      return done;
    }

    int
    Analysis::analyze_variable(const VariableSteps &v, const std::function<void()> &after_step,
                               const std::function<void(const std::string &)> &warn)
    {
      begin_analysis(warn);
      const double total = v.n_steps * v.dt;
      double       done = 0, dt = v.dt;
      while (done < total)
        {
          std::string why;
          if (advance(dt, why))
            {
              done += dt;
              after_step();
            }
          else if (dt <= v.dt_min)
            {
              std::ostringstream text;
              text << "analyze: the step of " << dt << " to time " << trial_time << " failed ("
                   << why << ") at dtMin; the domain is back at time " << domain.time;
              warn(text.str());
              return -3;
            }
          // determineDt: the test's iterations (Linear has no test: 1)
          const double iterations =
            opts.algorithm == AnalysisOptions::Algorithm::linear ? 1.0 : test_iterations;
          const double failed = why.empty() ? 0.0 : dt;
          dt = std::min(dt * v.jd / iterations, v.dt_max); // clipped first, as determineDt
          if (failed > 0 && !(dt < failed)) // OpenSees would try the same step for ever
            {
              std::ostringstream text;
              text << "analyze: the step of " << failed << " to time " << trial_time
                   << " failed (" << why << ") and Jd " << v.jd << " does not shorten it";
              warn(text.str());
              return -3;
            }
          if (dt < v.dt_min)
            dt = v.dt_min - std::numeric_limits<double>::epsilon();
        }
      return 0;
    }

    namespace
    {
      /// True when K equals its transpose up to round-off (1e-12 of its
      /// largest entry): a 3D Corotational member's tangent after it has
      /// moved is not (CorotCrdTransf3d), nor are some links'.
      bool
      is_symmetric(const Matrix &K)
      {
        const double largest = K.cwiseAbs().maxCoeff();
        return (K - K.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * largest;
      }

      /// K phi = lambda M phi for a symmetric K, solved as M phi = (1/lambda)
      /// K phi: M may be singular (massless rotations), K is positive
      /// definite for a stable structure. The positive lambda, smallest
      /// first, at most shapes.cols() of them.
      void
      symmetric_modes(const Matrix &K, const Matrix &M, Matrix &shapes,
                      std::vector<double> &lambda)
      {
        Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> solution(M, K);
        if (solution.info() != Eigen::Success)
          throw ScriptError("eigen: the stiffness matrix is not positive definite");
        const std::size_t n_modes = shapes.cols();
        for (int i = solution.eigenvalues().size() - 1; i >= 0 && lambda.size() < n_modes; --i)
          if (solution.eigenvalues()[i] > 0)
            {
              shapes.col(lambda.size()) = solution.eigenvectors().col(i);
              lambda.push_back(1 / solution.eigenvalues()[i]);
            }
      }

      /// K phi = lambda M phi for a nonsymmetric K, as OpenSees's
      /// FullGenEigenSolver (LAPACK dggev): the QZ pairs (alpha, beta),
      /// lambda = alpha / beta for a real alpha, -|alpha| / beta for a
      /// complex one (so left out, as negative), a
      /// vanishing beta (a massless DOF) infinite; the positive finite
      /// lambda, smallest first, with the real parts of their vectors.
      void
      general_modes(const Matrix &K, const Matrix &M, Matrix &shapes, std::vector<double> &lambda)
      {
        Eigen::GeneralizedEigenSolver<Matrix> solution(K, M);
        if (solution.info() != Eigen::Success)
          throw ScriptError("eigen: the generalized eigenproblem did not converge");
        const auto &alpha = solution.alphas();
        const auto &beta  = solution.betas();
        std::vector<std::pair<double, Eigen::Index>> order;
        for (Eigen::Index i = 0; i < beta.size(); ++i)
          {
            const double magnitude = std::abs(alpha[i]);
            if (!(magnitude * std::numeric_limits<double>::epsilon() < std::abs(beta[i])))
              continue;
            const double value =
              alpha[i].imag() == 0 ? alpha[i].real() / beta[i] : -magnitude / beta[i];
            if (value > 0)
              order.emplace_back(value, i);
          }
        std::sort(order.begin(), order.end());
        const Eigen::MatrixXcd vectors = solution.eigenvectors();
        for (const auto &[value, i] : order)
          if (lambda.size() < static_cast<std::size_t>(shapes.cols()))
            {
              shapes.col(lambda.size()) = vectors.col(i).real();
              lambda.push_back(value);
            }
      }
    } // namespace

    std::vector<double>
    Analysis::eigenvalues(const unsigned int n)
    {
      const std::string refused = unsupported_combination(opts);
      if (!refused.empty())
        throw ScriptError(refused + " is not supported");
      const bool renumber = domain.changed || !numbered;
      if (renumber)
        number();
      list_elements(renumber);
      gather();
      std::string why;
      if (!set_trial(why))
        throw ScriptError("eigen: " + why);
      assemble_tangent(1, 0, 0);
      const Matrix K = dense() ? dense_tangent : Matrix(tangent_matrix);
      Matrix M = mass_of_equation.asDiagonal();
      for (Eigen::Index j = 0; j < M.cols() && !coupled_masses.empty(); ++j)
        M.col(j) = mass_times(Matrix::Identity(n_equations, n_equations).col(j));
      std::vector<double> lambda;
      Matrix              shapes(n_equations, n);
      if (is_symmetric(K))
        symmetric_modes(K, M, shapes, lambda);
      else
        general_modes(K, M, shapes, lambda);
      if (lambda.size() < n)
        throw ScriptError("eigen: " + std::to_string(n) + " modes asked for, the model has " +
                          std::to_string(lambda.size()) + " with mass");
      keep_modes(shapes, lambda);
      return lambda;
    }
  } // namespace opensees
} // namespace poundfe
