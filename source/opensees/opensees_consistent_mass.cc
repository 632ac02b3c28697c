// The consistent masses of a script's elements (-cMass 1; OpenSees's
// Truss/CorotTruss::getMass with cMass: rho L/6 [2 1; 1 2] on each
// translation): a matrix M_e on the element's DOFs beside the nodes'
// diagonal M, as OpenSees's TransientIntegrator assembles getMass:
//   residual  -M_e (a + alpha_M v + r a_g),   tangent  (c_m + c_c alpha_M) M_e,
// r a_g the ground acceleration along each row's DOF (the element's
// addInertiaLoadToUnbalance, -M R a_g), alpha_M the element's Rayleigh
// factor when it is Rayleigh-damped (Element::getDamp's alpha_M M).
#include <poundfe/opensees/opensees_analysis.h>

#include <algorithm>

namespace poundfe
{
  namespace opensees
  {
    void
    Analysis::number_coupled_masses()
    {
      coupled_masses.clear();
      for (const Domain::ConsistentMass &m : domain.consistent_masses)
        {
          CoupledMass c;
          c.matrix = &m.matrix;
          for (const int tag : m.nodes)
            {
              for (const Diaphragm &d : domain.diaphragms)
                if (std::find(d.constrained.begin(), d.constrained.end(), tag) !=
                    d.constrained.end())
                  throw ScriptError("element " + std::to_string(m.element) +
                                    ": a consistent mass (-cMass) on node " +
                                    std::to_string(tag) + ", which a rigidDiaphragm constrains");
              const Node &node = domain.node(tag);
              for (unsigned int k = 0; k < node.equation.size(); ++k)
                {
                  c.equations.push_back(std::max(node.equation[k], -1));
                  c.dofs.push_back(k);
                }
            }
          const auto element = domain.elements.find(m.element);
          if (element != domain.elements.end() && element->second->rayleigh_damped())
            c.alpha_m = domain.rayleigh_of(m.element).alpha_m;
          coupled_masses.push_back(std::move(c));
        }
    }

    void
    Analysis::subtract_coupled_inertia(Vector &r, const Vector &v)
    {
      for (const CoupledMass &c : coupled_masses)
        {
          Vector &x = coupled_work;
          x.resize(c.equations.size());
          for (unsigned int i = 0; i < x.size(); ++i)
            {
              const int eq = c.equations[i];
              x[i] = (eq >= 0 ? A[eq] + c.alpha_m * v[eq] : 0.0) + ground[c.dofs[i]];
            }
          const Vector f = *c.matrix * x;
          for (unsigned int i = 0; i < x.size(); ++i)
            if (c.equations[i] >= 0)
              r[c.equations[i]] -= f[i];
        }
    }

    void
    Analysis::add_coupled_masses(const double c_m, const double c_c)
    {
      for (const CoupledMass &c : coupled_masses)
        {
          const double factor = c_m + c_c * c.alpha_m;
          if (factor == 0)
            continue;
          const auto &eq = c.equations;
          for (unsigned int i = 0; i < eq.size(); ++i)
            for (unsigned int j = 0; j < eq.size(); ++j)
              if (eq[i] >= 0 && eq[j] >= 0 && (*c.matrix)(i, j) != 0)
                {
                  if (dense())
                    dense_tangent(eq[i], eq[j]) += factor * (*c.matrix)(i, j);
                  else
                    tangent_entries.emplace_back(eq[i], eq[j], factor * (*c.matrix)(i, j));
                }
        }
    }

    Vector
    Analysis::mass_times(const Vector &x) const
    {
      Vector y = mass_of_equation.cwiseProduct(x);
      for (const CoupledMass &c : coupled_masses)
        {
          const auto &eq = c.equations;
          for (unsigned int i = 0; i < eq.size(); ++i)
            for (unsigned int j = 0; j < eq.size(); ++j)
              if (eq[i] >= 0 && eq[j] >= 0)
                y[eq[i]] += (*c.matrix)(i, j) * x[eq[j]];
        }
      return y;
    }
  } // namespace opensees
} // namespace poundfe
