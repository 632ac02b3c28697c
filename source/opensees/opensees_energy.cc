// The energy balance and impact log of an OpenSees script's transient
// analyses (opensees_energy.h gives the equations). The forces are those
// the analysis balances (opensees_analysis.cc): the nodes' lumped masses
// with the elements' (Node::element_mass, Domain::LumpedMass's second
// ground load of a 2D elasticBeamColumn), the consistent masses, alpha_M M
// by Domain::mass_damping, the stiffness-proportional damping of the
// Rayleigh-damped elements and OpenSees 3.8's modal damping C = W diag(c)
// W^T, W's columns M phi_i, c_i = 2 zeta_i omega_i
// (IncrementalIntegrator::addModalDampingForce).
#include <poundfe/base/lean_assert.h>
#include <poundfe/laws/combined_materials.h>
#include <poundfe/opensees/opensees_energy.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace poundfe
{
  namespace opensees
  {
    Vector
    EnergyBalance::gathered(const Domain &d, const std::vector<double> Node::*response) const
    {
      Vector       x(n_dofs);
      unsigned int i = 0;
      for (const auto &[tag, node] : d.nodes)
        for (const double value : node.*response)
          x[i++] = value;
      return x;
    }

    Vector
    EnergyBalance::mass_times(const Domain &d, const Vector &x) const
    {
      Vector y = mass.cwiseProduct(x);
      for (const Domain::ConsistentMass &m : d.consistent_masses)
        {
          std::vector<unsigned int> rows;
          for (const int tag : m.nodes)
            for (unsigned int k = 0; k < d.ndf; ++k)
              rows.push_back(offset.at(tag) + k);
          for (unsigned int i = 0; i < rows.size(); ++i)
            for (unsigned int j = 0; j < rows.size(); ++j)
              y[rows[i]] += m.matrix(i, j) * x[rows[j]];
        }
      return y;
    }

    EnergyBalance::State
    EnergyBalance::state(const Domain &d, const State *previous) const
    {
      State s;
      s.time = d.time;
      s.u    = gathered(d, &Node::disp);
      s.v    = gathered(d, &Node::vel);
      // the ground-motion load -M r a_g (r: each node's DOFs along a_g's)
      const std::vector<double> a_g = d.ground_acceleration(d.time);
      Vector                    r(n_dofs);
      for (const auto &[tag, node] : d.nodes)
        for (unsigned int k = 0; k < node.disp.size(); ++k)
          r[offset.at(tag) + k] = k < a_g.size() ? a_g[k] : 0.0;
      s.p = -ground_mass.cwiseProduct(r);
      if (!d.consistent_masses.empty())
        s.p -= mass_times(d, r) - mass.cwiseProduct(r);
      if (nodal_loads)
        for (const auto &[tag, load] : d.nodal_loads(d.time))
          for (unsigned int k = 0; k < load.size(); ++k)
            s.p[offset.at(tag) + k] += load[k];
      s.u_e.reserve(d.elements.size());
      s.f_e.reserve(d.elements.size());
      for (const auto &[tag, element] : d.elements)
        {
          s.u_e.push_back(d.element_values(*element, &Node::disp));
          s.f_e.push_back(element->force());
        }
      add_damping_forces(d, previous, s);
      return s;
    }

    void
    EnergyBalance::add_damping_forces(const Domain &d, const State *previous, State &s) const
    {
      s.c = mass_damping.cwiseProduct(s.v);
      for (std::size_t i = 0; i < modal_w.size(); ++i)
        s.c += modal_c[i] * modal_w[i].dot(s.v) * modal_w[i];
      const bool same_elements = previous && previous->k_c.size() == d.elements.size();
      s.k_c.resize(d.elements.size());
      unsigned int e = 0;
      for (const auto &[tag, element] : d.elements)
        {
          const unsigned int this_element = e++;
          if (!element->rayleigh_damped())
            continue;
          Vector       c_e     = d.rayleigh_damping_forces(*element);
          const double beta_kc = d.rayleigh_of(tag).beta_k_committed;
          if (beta_kc != 0)
            {
              // the step's equilibrium took the tangent committed before
              // it (Analysis::commit renews committed_tangent after it)
              s.k_c[this_element] = element->committed_tangent;
              const Matrix &used  = same_elements ? previous->k_c[this_element] : Matrix();
              if (used.rows() == c_e.size() && used.rows() == element->committed_tangent.rows())
                c_e += beta_kc * ((used - element->committed_tangent) *
                                  d.element_values(*element, &Node::vel));
            }
          unsigned int i = 0;
          for (const int node_tag : element->node_tags)
            for (unsigned int k = 0; k < d.node(node_tag).disp.size(); ++k)
              s.c[offset.at(node_tag) + k] += c_e[i++];
        }
    }

    double
    EnergyBalance::kinetic(const Domain &d, const Vector &v) const
    {
      return 0.5 * v.dot(mass_times(d, v));
    }

    void
    EnergyBalance::begin(const Domain &d, const std::vector<int> &contact)
    {
      contact_elements = contact;
      offset.clear();
      n_dofs = 0;
      for (const auto &[tag, node] : d.nodes)
        {
          offset[tag] = n_dofs;
          n_dofs += node.disp.size();
        }
      mass.setZero(n_dofs);
      mass_damping.setZero(n_dofs);
      for (const auto &[tag, node] : d.nodes)
        for (unsigned int k = 0; k < node.disp.size(); ++k)
          mass[offset[tag] + k] =
            node.mass[k] + (k < node.element_mass.size() ? node.element_mass[k] : 0.0);
      ground_mass = mass;
      for (const Domain::LumpedMass &m : d.lumped_masses)
        if (m.ground_load_twice)
          for (unsigned int k = 0; k < std::min(d.ndm, d.ndf); ++k)
            ground_mass[offset[m.node] + k] += m.mass;
      // alpha_M of the nodes' own masses (the elements' are in their
      // Domain::rayleigh_damping_forces)
      for (const auto &[tag, node] : d.nodes)
        for (unsigned int k = 0; k < node.mass.size(); ++k)
          mass_damping[offset[tag] + k] = d.alpha_m_of(tag) * node.mass[k];
      // OpenSees 3.8's modal damping: c_i = 2 zeta_i omega_i, W_i = M phi_i
      modal_c.clear();
      modal_w.clear();
      for (std::size_t i = 0; i < d.modal_damping.size() && i < d.modes.shapes.size(); ++i)
        {
          Vector phi = Vector::Zero(n_dofs);
          for (const auto &[tag, shape] : d.modes.shapes[i])
            if (d.nodes.count(tag))
              for (unsigned int k = 0; k < shape.size(); ++k)
                phi[offset[tag] + k] = shape[k];
          modal_w.push_back(mass_times(d, phi));
          modal_c.push_back(2 * d.modal_damping[i] * std::sqrt(std::abs(d.modes.eigenvalues[i])));
        }
      resume(d);
    }

    void
    EnergyBalance::resume(const Domain &d)
    {
      nodal_loads = std::any_of(d.patterns.begin(), d.patterns.end(), [](const auto &p) {
        return !p.second.uniform_excitation && !p.second.loads.empty();
      });
      // the rule goes on from the last step when the domain is still at it:
      // its forces are those of that step's equilibrium (the damping's too,
      // should the script have changed it since)
      if (has_last && last.time == d.time && last.u.size() == n_dofs &&
          last.f_e.size() == d.elements.size() && last.u == gathered(d, &Node::disp) &&
          last.v == gathered(d, &Node::vel))
        return;
      last        = state(d, nullptr);
      kinetic_now = kinetic(d, last.v);
      if (!started)
        kinetic_0 = kinetic_now;
      started  = true;
      has_last = true;
    }

    void
    EnergyBalance::step(const Domain &d)
    {
      Assert(started, dealii::ExcMessage("begin() comes before the steps"));
      State now = state(d, &last);
      if (now.f_e.size() != last.f_e.size())
        {
          last = std::move(now); // the domain changed: the rule starts again
          return;
        }
      const Vector du = now.u - last.u;
      input += 0.5 * (last.p + now.p).dot(du);
      damping += 0.5 * (last.c + now.c).dot(du);
      unsigned int e = 0;
      for (const auto &[tag, element] : d.elements)
        {
          const double work = 0.5 * (last.f_e[e] + now.f_e[e]).dot(now.u_e[e] - last.u_e[e]);
          const bool   gap  = std::find(contact_elements.begin(), contact_elements.end(), tag) !=
                           contact_elements.end();
          (gap ? contact : elements) += work;
          ++e;
        }
      kinetic_now = kinetic(d, now.v);
      last        = std::move(now);
    }

    EnergyTerms
    EnergyBalance::terms() const
    {
      EnergyTerms t;
      t.input    = input;
      t.kinetic  = kinetic_now - kinetic_0;
      t.elements = elements;
      t.damping  = damping;
      t.contact  = contact;
      t.residual = t.input - t.kinetic - t.elements - t.damping - t.contact;
      const double largest =
        std::max({std::abs(t.input), std::abs(t.kinetic), std::abs(t.elements),
                  std::abs(t.damping), std::abs(t.contact)});
      t.relative_residual = largest > 0 ? std::abs(t.residual) / largest : 0.0;
      return t;
    }

    namespace
    {
      /// The law `path` leads to from `law`, its deformation into `strain`
      /// (a Series's component's own) and whether a MinMax on the way has
      /// failed (its force is then 0 whatever its component's).
      const UniaxialLaw *
      gap_law(const UniaxialLaw *law, const std::vector<unsigned int> &path, double &strain,
              bool &failed)
      {
        for (const unsigned int i : path)
          if (const auto *minmax = dynamic_cast<const MinMaxUniaxial *>(law))
            {
              failed = failed || minmax->force() != minmax->component().force();
              law    = &minmax->component();
            }
          else if (const auto *parallel = dynamic_cast<const ParallelUniaxial *>(law))
            law = &parallel->part(i);
          else if (const auto *series = dynamic_cast<const SeriesUniaxial *>(law))
            {
              strain = series->part_strain(i);
              law    = &series->part(i);
            }
          else
            Assert(false, dealii::ExcMessage("a gap path leads through MinMax, Parallel or Series"));
        return law;
      }
    } // namespace

    ImpactLog::GapState
    gap_state(const Domain &d, const GapRow &g)
    {
      ImpactLog::GapState s;
      const auto          e    = d.elements.find(g.element);
      UniaxialRows       *rows = e == d.elements.end() ? nullptr : link_rows(*e->second);
      if (!rows || g.row >= rows->laws.size() || g.row >= rows->strain.size())
        return s;
      const UniaxialLaw &row_law = *rows->laws[g.row];
      double             strain  = rows->strain[g.row];
      bool               failed  = false;
      const UniaxialLaw *gap     = gap_law(&row_law, g.path, strain, failed);
      s.penetration              = g.direction * (strain - g.gap);
      s.rate                     = g.direction * rows->rate[g.row];
      // the force is the law's, whatever its sign convention
      s.force = failed || gap->force() == 0 ? 0.0 : std::abs(row_law.force());
      return s;
    }

    void
    ContactEvents::watch(const Domain &d, const std::vector<GapRow> &rows)
    {
      domain   = &d;
      gap_rows = rows;
      committed_contact.resize(rows.size());
      for (std::size_t h = 0; h < rows.size(); ++h)
        committed_contact[h] = in_contact(h);
    }

    bool
    ContactEvents::in_contact(const std::size_t h) const
    {
      return gap_state(*domain, gap_rows[h]).force != 0;
    }

    bool
    ContactEvents::changed() const
    {
      for (std::size_t h = 0; h < gap_rows.size(); ++h)
        if (in_contact(h) != static_cast<bool>(committed_contact[h]))
          return true;
      return false;
    }

    void
    ContactEvents::commit()
    {
      for (std::size_t h = 0; h < gap_rows.size(); ++h)
        committed_contact[h] = in_contact(h);
    }

    std::vector<ImpactLog::GapState>
    ScriptImpacts::states(const Domain &d) const
    {
      std::vector<ImpactLog::GapState> s(gap_rows.size());
      for (std::size_t h = 0; h < gap_rows.size(); ++h)
        s[h] = gap_state(d, gap_rows[h]);
      return s;
    }

    void
    ScriptImpacts::begin(const Domain &d, const std::vector<GapRow> &rows)
    {
      const bool same = rows.size() == gap_rows.size() &&
                        std::equal(rows.begin(), rows.end(), gap_rows.begin(),
                                   [](const GapRow &a, const GapRow &b) {
                                     return a.element == b.element && a.row == b.row;
                                   });
      if (!same)
        {
          gap_rows = rows;
          log.reset(rows.size());
        }
      resume(d);
    }

    void
    ScriptImpacts::resume(const Domain &d)
    {
      last      = states(d);
      last_time = d.time;
    }

    void
    ScriptImpacts::step(const Domain &d)
    {
      const auto now = states(d);
      for (std::size_t h = 0; h < gap_rows.size(); ++h)
        log.record(h, last_time, d.time, last[h], now[h]);
      last      = now;
      last_time = d.time;
    }

    std::string
    ScriptImpacts::csv() const
    {
      std::ostringstream out;
      out << std::setprecision(17);
      out << "element,start_time,end_time,peak_force,impulse,max_penetration,"
             "max_penetration_time\n";
      for (const Impact &i : log.impacts())
        out << gap_rows[i.element].element << ',' << i.start_time << ',' << i.end_time << ','
            << i.peak_force << ',' << i.impulse << ',' << i.max_penetration << ','
            << i.max_penetration_time << '\n';
      return out.str();
    }
  } // namespace opensees
} // namespace poundfe
