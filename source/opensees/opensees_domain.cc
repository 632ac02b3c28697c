// The domain of an OpenSees script: its time series and load patterns as
// OpenSees 3.8 evaluates them (PathSeries::getFactor: linear interpolation
// of values spaced dt from time 0, zero before 0 and after the last value;
// LinearSeries: factor t; ConstantSeries: factor; TrigSeries: factor
// sin(2 pi (t - t_start)/T + phi) + zeroShift on [t_start, t_end]; LoadPattern::applyLoad:
// the series' factor times the pattern's -fact, frozen by loadConst), its
// nodal loads and ground accelerations, and OpenSees's nodal reactions.
#include <poundfe/laws/combined_materials.h>
#include <poundfe/laws/viscous_damper.h>
#include <poundfe/opensees/opensees_domain.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace opensees
  {
    double
    TimeSeries::path_time_factor(const double time) const
    {
      // PathTimeSeries::getFactor as it searches forward: the value at the
      // first time, else the interval (t_k, t_k+1] that holds the time
      // (at a repeated time the first of its values); 0 outside
      if (time == times.front())
        return factor * values.front();
      if (time < times.front() || time > times.back())
        return 0;
      const std::size_t k =
        std::lower_bound(times.begin(), times.end(), time) - times.begin() - 1;
      const double t1 = times[k], t2 = times[k + 1];
      return factor * (values[k] + (values[k + 1] - values[k]) * (time - t1) / (t2 - t1));
    }

    double
    TimeSeries::at(const double time) const
    {
      switch (kind)
        {
          case Kind::constant:
            return factor;
          case Kind::linear:
            return factor * time;
          case Kind::path:
            {
              if (!times.empty())
                return path_time_factor(time);
              if (time < start_time || values.empty())
                return 0;
              const double    position = (time - start_time) / dt;
              const long long i        = static_cast<long long>(std::floor(position));
              if (i + 1 >= static_cast<long long>(values.size()))
                return use_last ? factor * values.back() : 0.0;
              return factor * (values[i] + (values[i + 1] - values[i]) * (position - i));
            }
          case Kind::trig:
            {
              if (time < start || time > finish)
                return 0;
              const double two_pi = 4 * std::asin(1.0);
              const double phi    = shift - period / two_pi * std::asin(zero_shift / factor);
              return factor * std::sin(two_pi * (time - start) / period + phi) + zero_shift;
            }
        }
      return 0;
    }

    double
    Pattern::load_factor(const double time) const
    {
      if (constant)
        return constant_factor;
      return series->at(time) * factor;
    }

    const Node &
    Domain::node(const int tag) const
    {
      const auto it = nodes.find(tag);
      if (it == nodes.end())
        throw ScriptError("node " + std::to_string(tag) + " does not exist");
      return it->second;
    }

    Node &
    Domain::node(const int tag)
    {
      return const_cast<Node &>(static_cast<const Domain &>(*this).node(tag));
    }

    std::map<int, std::vector<double>>
    Domain::nodal_loads(const double at_time) const
    {
      std::map<int, std::vector<double>> loads;
      for (const auto &[tag, pattern] : patterns)
        {
          if (pattern.uniform_excitation || pattern.loads.empty())
            continue;
          const double lambda = pattern.load_factor(at_time);
          for (const NodalLoad &load : pattern.loads)
            {
              auto &p = loads[load.node];
              p.resize(ndf, 0.0);
              for (unsigned int k = 0; k < load.values.size(); ++k)
                p[k] += lambda * load.values[k];
            }
        }
      return loads;
    }

    void
    Domain::apply_element_loads(const double at_time)
    {
      for (auto &[tag, element] : elements)
        if (element->takes_beam_loads())
          element->zero_loads();
      for (const auto &[tag, pattern] : patterns)
        {
          if (pattern.uniform_excitation || pattern.beam_loads.empty())
            continue;
          const double lambda = pattern.load_factor(at_time);
          for (const BeamUniformLoad &load : pattern.beam_loads)
            elements.at(load.element)
              ->add_beam_uniform(load.wy * lambda, load.wx * lambda, load.wz * lambda);
        }
    }

    std::map<std::pair<int, unsigned int>, double>
    Domain::imposed_displacements(const double at_time) const
    {
      std::map<std::pair<int, unsigned int>, double> imposed;
      for (const auto &[tag, pattern] : patterns)
        for (const ImposedDisplacement &sp : pattern.imposed)
          imposed[{sp.node, sp.dof}] += sp.value * pattern.load_factor(at_time);
      return imposed;
    }

    std::vector<double>
    Domain::ground_acceleration(const double at_time) const
    {
      std::vector<double> a;
      ground_acceleration(at_time, a);
      return a;
    }

    void
    Domain::ground_acceleration(const double at_time, std::vector<double> &a) const
    {
      a.assign(ndf, 0.0);
      for (const auto &[tag, pattern] : patterns)
        if (pattern.uniform_excitation)
          a[pattern.direction] += pattern.load_factor(at_time);
    }

    const RayleighFactors &
    Domain::rayleigh_of(const int element) const
    {
      const auto it = element_rayleigh.find(element);
      return it == element_rayleigh.end() ? rayleigh : it->second;
    }

    double
    Domain::alpha_m_of(const int node) const
    {
      const auto it = node_alpha_m.find(node);
      return it == node_alpha_m.end() ? rayleigh.alpha_m : it->second;
    }

    bool
    Domain::committed_stiffness_damping() const
    {
      if (rayleigh.beta_k_committed != 0)
        return true;
      for (const auto &[tag, r] : element_rayleigh)
        if (r.beta_k_committed != 0)
          return true;
      return false;
    }

    bool
    Domain::uniform_mass_damping() const
    {
      if (!element_rayleigh.empty() || !node_alpha_m.empty())
        return false;
      if (rayleigh.alpha_m == 0)
        return true;
      for (const LumpedMass &m : lumped_masses)
        if (!elements.at(m.element)->rayleigh_damped())
          return false;
      return true;
    }

    std::map<int, std::vector<double>>
    Domain::mass_damping() const
    {
      std::map<int, std::vector<double>> c;
      for (const auto &[tag, n] : nodes)
        {
          std::vector<double> &row = c[tag];
          row.assign(n.mass.size(), 0.0);
          const double alpha = alpha_m_of(tag);
          for (unsigned int k = 0; k < row.size(); ++k)
            row[k] = alpha * n.mass[k];
        }
      for (const LumpedMass &m : lumped_masses)
        {
          const Element &element = *elements.at(m.element);
          const double   alpha   = element.rayleigh_damped() ? rayleigh_of(m.element).alpha_m : 0.0;
          std::vector<double> &row = c[m.node];
          for (unsigned int k = 0; k < std::min(ndm, ndf); ++k)
            row[k] += alpha * m.mass;
        }
      return c;
    }

    std::map<int, std::vector<double>>
    Domain::reactions(const ReactionFlag flag) const
    {
      // Node::resetReactionForce(flag): flag 0 subtracts the unbalanced
      // load and (its missing else) adds alpha_M M v; flag 1 subtracts the
      // unbalanced load with inertia (-M a - alpha_M M v); flag 2 alpha_M M
      // v alone. The unbalanced load holds each node's own ground-motion
      // load -m a_g (Node::addInertiaLoadToUnbalance), in fixed DOFs too.
      std::map<int, std::vector<double>> r;
      const auto                         loads = nodal_loads(time);
      const std::vector<double>          a_g   = ground_acceleration(time);
      const bool static_loads = flag != ReactionFlag::rayleigh;
      const bool inertia      = flag == ReactionFlag::dynamic;
      for (const auto &[tag, n] : nodes)
        {
          std::vector<double> &v = r[tag];
          v.assign(n.disp.size(), 0.0);
          const auto p = loads.find(tag);
          for (unsigned int k = 0; k < v.size(); ++k)
            v[k] = (static_loads ? (p == loads.end() ? 0.0 : -p->second[k]) + n.mass[k] * a_g[k] :
                                   0.0) +
                   n.mass[k] * ((inertia ? n.accel[k] : 0.0) + alpha_m_of(tag) * n.vel[k]);
        }
      // Element::addResistingForceToNodalReaction(flag)
      for (const auto &[tag, element] : elements)
        {
          const Vector f = flag == ReactionFlag::resisting ? force_with_ground_load(*element) :
                           inertia                         ? force_with_inertia(*element) :
                                                             rayleigh_damping_forces(*element);
          unsigned int i = 0;
          for (const int node_tag : element->node_tags)
            for (double &value : r[node_tag])
              value += f[i++];
        }
      return r;
    }

    Vector
    Domain::element_values(const Element &element,
                           const std::vector<double> Node::*response) const
    {
      Vector       values(element.n_dofs());
      unsigned int i = 0;
      for (const int tag : element.node_tags)
        for (const double value : node(tag).*response)
          values[i++] = value;
      return values;
    }

    namespace
    {
      /// Each lumped mass of the element, the offset of its node's first
      /// DOF in the element's DOFs, by f(mass, offset).
      template <typename F>
      void
      for_lumped_masses(const Domain &d, const Element &element, const F &f)
      {
        for (const Domain::LumpedMass &m : d.lumped_masses)
          if (m.element == element.tag)
            {
              unsigned int offset = 0;
              for (const int tag : element.node_tags)
                {
                  if (tag == m.node)
                    f(m, offset);
                  offset += d.node(tag).disp.size();
                }
            }
      }

      /// The element's consistent mass (-cMass) times x(m, i), x of the
      /// element's DOF i (its node's DOF i % ndf), added to f.
      template <typename X>
      void
      add_consistent_mass_times(const Domain &d, const Element &element, const X &x, Vector &f)
      {
        for (const Domain::ConsistentMass &m : d.consistent_masses)
          if (m.element == element.tag)
            {
              Vector values(m.matrix.rows());
              for (Eigen::Index i = 0; i < values.size(); ++i)
                values[i] = x(m, i);
              f += m.matrix * values;
            }
      }

      bool
      has_consistent_ground_load(const Domain &d, const Element &element)
      {
        for (const Domain::ConsistentMass &m : d.consistent_masses)
          if (m.element == element.tag && m.load_in_reaction)
            return true;
        return false;
      }
    } // namespace

    Vector
    Domain::rayleigh_damping_forces(const Element &element) const
    {
      const RayleighFactors &c = rayleigh_of(element.tag);
      const Vector           v = element_values(element, &Node::vel);
      Vector                 f = Vector::Zero(v.size());
      if (c.beta_k != 0)
        f += c.beta_k * (element.tangent() * v);
      if (c.beta_k_init != 0)
        f += c.beta_k_init * (element.initial_tangent() * v);
      if (c.beta_k_committed != 0 && element.committed_tangent.rows() == v.size())
        f += c.beta_k_committed * (element.committed_tangent * v);
      if (c.alpha_m != 0)
        {
          for_lumped_masses(*this, element, [&](const LumpedMass &m, const unsigned int offset) {
            for (unsigned int k = 0; k < std::min(ndm, ndf); ++k)
              f[offset + k] += c.alpha_m * m.mass * v[offset + k];
          });
          add_consistent_mass_times(*this, element, [&](const ConsistentMass &, Eigen::Index i) { return c.alpha_m * v[i]; }, f);
        }
      return f;
    }

    Vector
    Domain::force_with_ground_load(const Element &element) const
    {
      Vector                    f   = element.force();
      const std::vector<double> a_g = ground_acceleration(time);
      for_lumped_masses(*this, element, [&](const LumpedMass &m, const unsigned int offset) {
        if (m.load_in_reaction)
          for (unsigned int k = 0; k < std::min(ndm, ndf); ++k)
            f[offset + k] += m.mass * a_g[k];
      });
      if (has_consistent_ground_load(*this, element))
        add_consistent_mass_times(*this, element, [&](const ConsistentMass &, Eigen::Index i) { return a_g[i % ndf]; }, f);
      return f;
    }

    bool
    Domain::has_ground_load(const Element &element) const
    {
      for (const LumpedMass &m : lumped_masses)
        if (m.element == element.tag && m.load_in_reaction)
          return true;
      return has_consistent_ground_load(*this, element);
    }

    bool
    is_global_force(const std::vector<std::string> &words)
    {
      return words.size() == 1 && (words[0] == "force" || words[0] == "forces" ||
                                   words[0] == "globalForce" || words[0] == "globalForces");
    }

    std::vector<double>
    Domain::element_response(const Element &element, const std::vector<std::string> &words) const
    {
      if (!is_global_force(words) || !has_ground_load(element))
        return element.response(words);
      const Vector f = force_with_ground_load(element);
      return std::vector<double>(f.data(), f.data() + f.size());
    }

    Vector
    Domain::force_with_inertia(const Element &element) const
    {
      // every element's getResistingForceIncInertia subtracts its load
      // once; OpenSees 3.8's ElasticBeam2d once more (LumpedMass)
      Vector                    f   = element.force();
      const std::vector<double> a_g = ground_acceleration(time);
      const Vector              a   = element_values(element, &Node::accel);
      for_lumped_masses(*this, element, [&](const LumpedMass &m, const unsigned int offset) {
        const double loads = m.ground_load_twice ? 2.0 : 1.0;
        for (unsigned int k = 0; k < std::min(ndm, ndf); ++k)
          f[offset + k] += m.mass * (loads * a_g[k] + a[offset + k]);
      });
      // a consistent mass (-cMass) takes its ground load once, a 2D
      // elasticBeamColumn's twice
      add_consistent_mass_times(
        *this, element,
        [&](const ConsistentMass &m, Eigen::Index i) {
          return a[i] + (m.ground_load_twice ? 2.0 : 1.0) * a_g[i % ndf];
        },
        f);
      if (element.rayleigh_damped())
        f += rayleigh_damping_forces(element);
      return f;
    }

    void
    Domain::remove_element(const int tag)
    {
      if (elements.count(tag) == 0)
        return;
      for (const auto &[pattern_tag, pattern] : patterns)
        for (const BeamUniformLoad &load : pattern.beam_loads)
          if (load.element == tag)
            throw ScriptError("element " + std::to_string(tag) + " has an element load in pattern " +
                              std::to_string(pattern_tag) + " (remove the pattern first)");
      for (auto m = lumped_masses.begin(); m != lumped_masses.end();)
        if (m->element == tag)
          {
            std::vector<double> &mass = node(m->node).element_mass;
            for (unsigned int k = 0; k < std::min(ndm, ndf); ++k)
              mass[k] -= m->mass;
            m = lumped_masses.erase(m);
          }
        else
          ++m;
      consistent_masses.erase(std::remove_if(consistent_masses.begin(),
                                             consistent_masses.end(),
                                             [tag](const ConsistentMass &m) {
                                               return m.element == tag;
                                             }),
                              consistent_masses.end());
      element_rayleigh.erase(tag);
      elements.erase(tag);
      changed = true;
    }

    std::string
    RigidTie::name() const
    {
      return (beam ? "rigidLink beam" : "rigidDiaphragm") +
             (where.empty() ? std::string() : " (" + where + ")");
    }

    std::vector<unsigned int>
    RigidTie::tied_dofs(const unsigned int ndf) const
    {
      if (!beam)
        return {(perpendicular + 1) % 3, (perpendicular + 2) % 3, 3 + perpendicular};
      std::vector<unsigned int> dofs(ndf);
      for (unsigned int k = 0; k < ndf; ++k)
        dofs[k] = k;
      return dofs;
    }

    std::vector<std::pair<unsigned int, double>>
    RigidTie::row(const unsigned int              k,
                   const unsigned int              ndm,
                   const unsigned int              ndf,
                   const std::vector<double>      &d) const
    {
      std::vector<std::pair<unsigned int, double>> terms{{k, 1.0}};
      if (k >= ndm || ndf == ndm) // a rotation, or a model without rotations
        return terms;
      if (ndm == 2)
        terms.push_back({2, k == 0 ? -d[1] : d[0]});
      else // (theta x d)_k = eps_kjm theta_j d_m, +1 when (k, j, m) is cyclic
        for (unsigned int j = 0; j < 3; ++j)
          if (j != k && (beam || j == perpendicular))
            terms.push_back({3 + j, (j == (k + 1) % 3 ? 1.0 : -1.0) * d[3 - k - j]});
      return terms;
    }

    std::vector<std::pair<unsigned int, double>>
    Domain::tie_row(const RigidTie &tie, const int c, const unsigned int k) const
    {
      const std::vector<double> &xc = node(c).coordinates, &xr = node(tie.retained).coordinates;
      std::vector<double>        d(xc.size());
      for (unsigned int i = 0; i < d.size(); ++i)
        d[i] = xc[i] - xr[i];
      return tie.row(k, ndm, ndf, d);
    }

    void
    Domain::remove_ties_of(const int constrained)
    {
      const auto before = equal_dofs.size();
      equal_dofs.erase(std::remove_if(equal_dofs.begin(), equal_dofs.end(),
                                      [&](const EqualDof &e) { return e.constrained == constrained; }),
                       equal_dofs.end());
      bool removed = equal_dofs.size() != before;
      for (RigidTie &d : rigid_ties)
        {
          const auto n = d.constrained.size();
          d.constrained.erase(std::remove(d.constrained.begin(), d.constrained.end(), constrained),
                              d.constrained.end());
          removed = removed || d.constrained.size() != n;
        }
      rigid_ties.erase(std::remove_if(rigid_ties.begin(), rigid_ties.end(),
                                      [](const RigidTie &d) { return d.constrained.empty(); }),
                       rigid_ties.end());
      changed = changed || removed;
    }

    void
    Domain::remove_node(const int tag)
    {
      if (nodes.count(tag) == 0)
        return;
      const std::string name = "node " + std::to_string(tag);
      for (const auto &[element_tag, element] : elements)
        for (const int n : element->node_tags)
          if (n == tag)
            throw ScriptError(name + " is a node of element " + std::to_string(element_tag));
      for (const EqualDof &e : equal_dofs)
        if (e.retained == tag || e.constrained == tag)
          throw ScriptError(name + " is tied by an equalDOF");
      for (const RigidTie &d : rigid_ties)
        if (d.retained == tag || std::count(d.constrained.begin(), d.constrained.end(), tag) > 0)
          throw ScriptError(name + " is in a " + d.name());
      for (const auto &[pattern_tag, pattern] : patterns)
        {
          for (const NodalLoad &load : pattern.loads)
            if (load.node == tag)
              throw ScriptError(name + " has a load in pattern " + std::to_string(pattern_tag));
          for (const ImposedDisplacement &sp : pattern.imposed)
            if (sp.node == tag)
              throw ScriptError(name + " has an sp in pattern " + std::to_string(pattern_tag));
        }
      node_alpha_m.erase(tag);
      nodes.erase(tag);
      changed = true;
    }

    void
    Domain::revert_to_start()
    {
      for (auto &[tag, n] : nodes)
        for (std::vector<double> *response : {&n.disp, &n.vel, &n.accel})
          std::fill(response->begin(), response->end(), 0.0);
      for (auto &[tag, element] : elements)
        element->reset();
      time      = 0;
      time_step = 0;
      apply_element_loads(time); // applyLoad(0), then update():
      for (auto &[tag, element] : elements)
        {
          // the trial state at the nodes' displacements
          const Vector zero = Vector::Zero(element->n_dofs());
          element->set_trial(zero, zero);
        }
    }

    void
    Domain::clear()
    {
      *this = Domain();
    }

    std::unique_ptr<UniaxialLaw>
    make_domain_material(const Domain &domain, const int tag)
    {
      const auto combined = domain.combined_materials.find(tag);
      if (combined != domain.combined_materials.end())
        {
          const CombinedMaterial &c = combined->second;
          std::vector<std::unique_ptr<UniaxialLaw>> parts;
          for (const int component : c.components)
            parts.push_back(make_domain_material(domain, component));
          if (c.type == "MinMax")
            return std::make_unique<MinMaxUniaxial>(std::move(parts[0]), c.min_strain,
                                                    c.max_strain);
          if (c.type == "Series")
            return std::make_unique<SeriesUniaxial>(std::move(parts), c.max_iterations,
                                                    c.tolerance);
          return std::make_unique<ParallelUniaxial>(std::move(parts), c.factors);
        }
      const auto it = domain.materials.find(tag);
      if (it == domain.materials.end())
        throw ScriptError("uniaxialMaterial " + std::to_string(tag) + " does not exist");
      if (it->second.material == "ViscousDamper")
        return make_viscous_damper(it->second.values, domain.time_step);
      return make_material(it->second);
    }
  } // namespace opensees
} // namespace poundfe
