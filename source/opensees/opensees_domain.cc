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
              if (time < 0 || values.empty())
                return 0;
              const double    position = time / dt;
              const long long i        = static_cast<long long>(std::floor(position));
              if (i + 1 >= static_cast<long long>(values.size()))
                return 0;
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
    Domain::reactions() const
    {
      // The applied loads include each node's own ground-motion load
      // -m a_g (Node::addInertiaLoadToUnbalance), in fixed DOFs too:
      // Node::resetReactionForce subtracts it, so it enters as +m a_g.
      std::map<int, std::vector<double>> r;
      const auto                         loads = nodal_loads(time);
      const std::vector<double>          a_g   = ground_acceleration(time);
      for (const auto &[tag, n] : nodes)
        {
          std::vector<double> &v = r[tag];
          v.assign(n.disp.size(), 0.0);
          const auto p = loads.find(tag);
          for (unsigned int k = 0; k < v.size(); ++k)
            v[k] = (p == loads.end() ? 0.0 : -p->second[k]) +
                   n.mass[k] * (a_g[k] + alpha_m_of(tag) * n.vel[k]);
        }
      for (const auto &[tag, element] : elements)
        {
          const Vector f = element->force();
          unsigned int i = 0;
          for (const int node_tag : element->node_tags)
            for (double &value : r[node_tag])
              value += f[i++];
        }
      for (const LumpedMass &m : lumped_masses)
        if (m.load_in_reaction)
          for (unsigned int k = 0; k < std::min(ndm, ndf); ++k)
            r[m.node][k] += m.mass * a_g[k];
      for (const ConsistentMass &m : consistent_masses)
        if (m.load_in_reaction)
          {
            Vector g(m.matrix.rows());
            for (Eigen::Index i = 0; i < g.size(); ++i)
              g[i] = a_g[i % ndf];
            const Vector load = m.matrix * g;
            for (Eigen::Index i = 0; i < g.size(); ++i)
              r[m.nodes[i / ndf]][i % ndf] += load[i];
          }
      return r;
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
