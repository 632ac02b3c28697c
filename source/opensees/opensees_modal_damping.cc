// OpenSees 3.8's modal damping (analysis/integrator/IncrementalIntegrator.cpp:
// setupModal, addModalDampingForce, addModalDampingMatrix; the factors set
// by the modalDamping command of tcl/commands.cpp on the Domain): with the
// modes phi_i of the last `eigen`, M-normalised (phi_i^T M phi_i = 1), and
// omega_i = sqrt(lambda_i),
//   f_d = -sum_i 2 zeta_i omega_i (M phi_i) (M phi_i)^T v
// joins the unbalance of a transient step, and c_c times the same matrix
// its tangent (modalDamping; modalDampingQ leaves the tangent alone).
// Under HHT, v is the velocity at t + dt (HHT::getVel), not at t + alpha
// dt, and the matrix stays out of the tangent (HHT has no getCFactor: the
// base's 0 leaves addModalDampingMatrix empty).
// M phi_i is formed once per `eigen` (or modalDamping command, or new
// analysis): a mass changed afterwards leaves it as it was (OpenSees's
// setupModal runs only when the eigenvalues change).
// Modes with lambda_i <= 0 or zeta_i = 0 add nothing; modes past the
// factors, or factors past the modes, none either.
#include <poundfe/opensees/opensees_analysis.h>

#include <cmath>

namespace poundfe
{
  namespace opensees
  {
    void
    Analysis::keep_modes(const Matrix &shapes, const std::vector<double> &eigenvalues)
    {
      Domain::Modes modes;
      modes.eigenvalues = eigenvalues;
      for (unsigned int i = 0; i < eigenvalues.size(); ++i)
        {
          Vector phi = shapes.col(i);
          // the solver's phi^T K phi = 1: rescaled to phi^T M phi = 1
          const double mass = phi.dot(mass_times(phi));
          if (mass > 0)
            phi /= std::sqrt(mass);
          std::map<int, std::vector<double>> by_node;
          for (const auto &[tag, node] : domain.nodes)
            {
              std::vector<double> &values = by_node[tag];
              values.assign(node.equation.size(), 0.0);
              for (unsigned int k = 0; k < node.equation.size(); ++k)
                for (const auto &[e, c] : terms(node.equation[k]))
                  if (e >= 0)
                    values[k] += c * phi[e];
            }
          modes.shapes.push_back(std::move(by_node));
        }
      domain.modes = std::move(modes);
      ++domain.modal_stamp;
    }

    bool
    Analysis::modal_damping_in_tangent(const double c_c)
    {
      return c_c != 0 && !opts.hht && domain.modal_damping_in_tangent && modal_damping_active();
    }

    bool
    Analysis::modal_damping_active()
    {
      if (!opts.transient || domain.modal_damping.empty())
        return false;
      if (modal_numbered && modal_stamp_seen == domain.modal_stamp)
        return modal_coefficients.size() > 0;
      std::vector<int> equations;
      for (const auto &[tag, node] : domain.nodes)
        equations.insert(equations.end(), node.equation.begin(), node.equation.end());
      // a mass changed since `eigen` renumbers but keeps M phi, as OpenSees
      modal_numbered = true;
      if (modal_stamp_seen == domain.modal_stamp && equations == modal_equations &&
          modal_mass_shapes.rows() == n_equations)
        return modal_coefficients.size() > 0;
      modal_equations = std::move(equations);
      const std::size_t n_modes =
        std::min(domain.modal_damping.size(), domain.modes.eigenvalues.size());
      modal_mass_shapes.setZero(n_equations, n_modes);
      modal_coefficients.setZero(n_modes);
      for (unsigned int i = 0; i < n_modes; ++i)
        {
          const double lambda = domain.modes.eigenvalues[i], zeta = domain.modal_damping[i];
          if (!(lambda > 0) || zeta == 0)
            continue;
          modal_coefficients[i] = 2.0 * zeta * std::sqrt(lambda);
          for (const auto &[tag, values] : domain.modes.shapes[i])
            {
              const auto node = domain.nodes.find(tag);
              if (node == domain.nodes.end())
                continue;
              const std::vector<int> &equation = node->second.equation;
              for (unsigned int k = 0; k < std::min(values.size(), equation.size()); ++k)
                if (equation[k] >= 0)
                  modal_mass_shapes(equation[k], i) = values[k];
            }
          modal_mass_shapes.col(i) = mass_times(modal_mass_shapes.col(i));
        }
      if (modal_coefficients.isZero(0))
        modal_coefficients.resize(0);
      modal_numbered   = true;
      modal_stamp_seen = domain.modal_stamp;
      analysed         = false; // the tangent's pattern changes
      return modal_coefficients.size() > 0;
    }
  } // namespace opensees
} // namespace poundfe
