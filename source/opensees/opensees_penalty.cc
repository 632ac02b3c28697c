// OpenSees's Penalty constraint handler (OpenSees 3.8,
// SRC/analysis/handler/PenaltyConstraintHandler.cpp, fe_ele/penalty/
// PenaltySP_FE.cpp and PenaltyMP_FE.cpp): no DOF leaves the equations; each
// single-point constraint (fix, sp) is a spring of stiffness alphaSP to its
// value g(t), and each multi-point constraint u_c = C_cr u_r (equalDOF,
// rigidLink bar|beam, rigidDiaphragm) adds, with C = [-I C_cr] on (u_c, u_r),
//   K += alphaMP C^T C,   R -= alphaMP C^T C u,
// row by row (C^T C is the sum of its rows' outer products). The tangent is
// the penalty's own, unscaled by the integrator's K factor, as OpenSees's
// FE_Elements return it; the residual takes the displacements where the
// elements are evaluated (HHT: U_alpha, as OpenSees's nodes hold them). The
// constraint is met to the penalty's error, of order (element stiffness /
// alpha) of the constrained motion. Displacements are measured from zero:
// OpenSees measures them from those of the nodes when the constraint was
// made, which is zero unless it was made after an analysis.
#include <poundfe/opensees/opensees_analysis.h>

namespace poundfe
{
  namespace opensees
  {
    void
    Analysis::number_penalty()
    {
      combinations.clear();
      penalty_rows.clear();
      const auto equation = [&](const int tag, const unsigned int k) {
        return domain.node(tag).equation.at(k);
      };
      for (const auto &[tag, node] : domain.nodes)
        for (unsigned int k = 0; k < node.fixed.size(); ++k)
          if (node.fixed[k])
            penalty_rows.push_back({{{equation(tag, k), 1.0}}, opts.alpha_sp, {tag, k}, false});
      for (const auto &[dof, value] : domain.imposed_displacements(domain.time))
        penalty_rows.push_back(
          {{{equation(dof.first, dof.second), 1.0}}, opts.alpha_sp, dof, true});
      for (const EqualDof &e : domain.equal_dofs)
        for (const unsigned int k : e.dofs)
          penalty_rows.push_back(
            {{{equation(e.constrained, k), -1.0}, {equation(e.retained, k), 1.0}},
             opts.alpha_mp});
      for (const RigidTie &d : domain.rigid_ties)
        for (const int c : d.constrained)
          for (const unsigned int k : d.tied_dofs(domain.ndf))
            {
              std::vector<std::pair<int, double>> terms{{equation(c, k), -1.0}};
              for (const auto &[dof, factor] : domain.tie_row(d, c, k))
                terms.emplace_back(equation(d.retained, dof), factor);
              penalty_rows.push_back({terms, opts.alpha_mp});
            }
    }

    void
    Analysis::add_penalty_forces(Vector &r)
    {
      if (penalty_rows.empty())
        return;
      const Vector &u = at_alpha ? U_alpha : U;
      std::map<std::pair<int, unsigned int>, double> imposed;
      for (const PenaltyRow &row : penalty_rows)
        if (row.is_imposed)
          {
            imposed = domain.imposed_displacements(trial_time);
            break;
          }
      for (const PenaltyRow &row : penalty_rows)
        {
          double gap = row.is_imposed ? imposed.at(row.imposed) : 0.0;
          for (const auto &[eq, c] : row.terms)
            gap -= c * u[eq];
          for (const auto &[eq, c] : row.terms)
            r[eq] += row.alpha * c * gap;
        }
    }

    void
    Analysis::add_penalty_tangent()
    {
      for (const PenaltyRow &row : penalty_rows)
        for (const auto &[i, ci] : row.terms)
          for (const auto &[j, cj] : row.terms)
            if (dense())
              dense_tangent(i, j) += row.alpha * ci * cj;
            else
              tangent_entries.emplace_back(i, j, row.alpha * ci * cj);
    }
  } // namespace opensees
} // namespace poundfe
