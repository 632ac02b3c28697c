#include <poundfe/base/numbers.h>
#include <poundfe/laws/bouc_wen.h>
#include <poundfe/laws/bouc_wen_bounds.h>

#include <cmath>
#include <sstream>
#include <utility>

namespace poundfe
{
  BoucWen::BoucWen(const BoucWenParameters &parameters)
    : p(parameters)
  {
    reset();
  }

  // inline: set_trial calls it at every residual of its local iteration
  inline BoucWen::Rate
  BoucWen::rate_of(const double z, const double epsilon, const double direction) const
  {
    const double a     = std::abs(z);
    const double sz    = (z > 0) - (z < 0);
    // |z|^(n-1); the usual n = 2 and n = 1 without pow (pow(a, 1) = a and
    // pow(a, 0) = 1 exactly, so the results are the same to the bit)
    const double a_n1  = (a == 0)    ? 0.0 :
                         (p.n == 2) ? a :
                         (p.n == 1) ? 1.0 :
                                      std::pow(a, p.n - 1);
    const double a_n   = a_n1 * a;
    const double psi   = p.beta * direction * sz + p.gamma;
    Rate         r;
    // Without degradation (delta_A = delta_nu = delta_eta = 0) and at a
    // finite eps, A = A0, nu = 1 and eta = 1 exactly: the same bits without
    // the terms of eps and the divisions by 1, whatever eps is.
    if (p.delta_A == 0 && p.delta_nu == 0 && p.delta_eta == 0 && std::isfinite(epsilon))
      {
        const double phi = p.A - a_n * psi;
        r.g              = phi;
        r.g_z            = -p.n * a_n1 * sz * psi;
        r.g_epsilon      = (-p.delta_A - p.delta_nu * a_n * psi) - phi * p.delta_eta;
        return r;
      }
    const double A     = p.A - p.delta_A * epsilon;
    const double nu    = 1 + p.delta_nu * epsilon;
    const double eta   = 1 + p.delta_eta * epsilon;
    const double phi   = A - nu * a_n * psi;
    r.g         = phi / eta;
    r.g_z       = -nu * p.n * a_n1 * sz * psi / eta;
    r.g_epsilon = (-p.delta_A - p.delta_nu * a_n * psi) / eta - phi * p.delta_eta / (eta * eta);
    return r;
  }

  double
  BoucWen::force_of(const double deformation, const double z) const
  {
    return p.alpha * p.stiffness * deformation + (1 - p.alpha) * p.stiffness * p.yield_deformation * z;
  }

  bool
  BoucWen::set_trial(const double deformation, const double /*rate*/)
  {
    const double uy = p.yield_deformation, k = p.stiffness, th = p.theta;
    const double du = deformation - committed.deformation;
    const double c  = du / uy;
    const double s  = du > 0 ? 1.0 : (du < 0 ? -1.0 : committed.direction);
    const double z0 = committed.z, e0 = committed.epsilon;
    // Without degradation the rate does not depend on eps (rate_of): the
    // first residual's rate at (z0, eps1) is the one at (z0, eps0).
    const bool   plain = p.delta_A == 0 && p.delta_nu == 0 && p.delta_eta == 0;
    const Rate   r0    = rate_of(z0, e0, s);
    const double g0    = r0.g;

    // Residual of the discrete map and its derivative in z1.
    auto residual = [&](const double z1, Rate &r1, double &e1) {
      e1 = e0 + 0.5 * c * (z0 + z1);
      r1 = rate_of(z1, e1, s);
      return z1 - z0 - c * ((1 - th) * g0 + th * r1.g);
    };

    double z = z0, e1 = e0;
    Rate   r1{};
    double R = 0;
    if (plain && std::isfinite(e0 + 0.5 * c * (z0 + z0)))
      {
        e1 = e0 + 0.5 * c * (z0 + z0);
        r1 = r0;
        R  = z0 - z0 - c * ((1 - th) * g0 + th * r1.g);
      }
    else
      R = residual(z, r1, e1);
    // At least one Newton step whenever the deformation changed: z1 = z0
    // would already pass the tolerance for an increment below about
    // tolerance * u_y, and the force would then ignore (1 - alpha) k du
    // although the tangent below includes it. The global Newton iteration
    // (theory §3.3) then converges only linearly, or not at all on the
    // massless hinge rotations of an undamped frame (theory §2.4).
    bool converged = du == 0;
    for (unsigned int it = 0; it < p.max_iterations && !converged; ++it)
      {
        const double dR = 1 - c * th * (r1.g_z + 0.5 * c * r1.g_epsilon);
        if (!(std::abs(dR) > 0))
          break;
        double step = -R / dR;
        // Backtrack until the residual decreases (the map is monotone in z1
        // for beta >= gamma, so this only matters for exotic parameters).
        for (unsigned int half = 0; half < 30; ++half)
          {
            Rate         r_try;
            double       e_try;
            const double R_try = residual(z + step, r_try, e_try);
            if (std::abs(R_try) < std::abs(R) || half == 29)
              {
                z  = z + step;
                R  = R_try;
                r1 = r_try;
                e1 = e_try;
                break;
              }
            step *= 0.5;
          }
        converged = std::abs(R) <= p.tolerance;
      }
    if (!converged || !std::isfinite(z))
      {
        std::ostringstream message;
        message << "Bouc-Wen: the local Newton iteration for z did not converge in "
                << p.max_iterations << " iterations (increment " << du << ", z0 = " << z0
                << ", |residual| = " << std::abs(R) << ")";
        failure_message = message.str();
        return false;
      }

    const double dR   = 1 - c * th * (r1.g_z + 0.5 * c * r1.g_epsilon);
    const double dR_c = -((1 - th) * g0 + th * r1.g) - c * th * r1.g_epsilon * 0.5 * (z0 + z);
    const double dz_du = -dR_c / dR / uy;

    trial.deformation = deformation;
    trial.z           = z;
    trial.epsilon     = e1;
    trial.direction   = (du != 0) ? s : committed.direction;
    trial_force       = force_of(deformation, z);
    trial_tangent     = p.alpha * k + (1 - p.alpha) * k * uy * dz_du;
    return true;
  }

  double
  BoucWen::stored_energy() const
  {
    const double k = p.stiffness, uy = p.yield_deformation;
    return 0.5 * p.alpha * k * trial.deformation * trial.deformation +
           0.5 * (1 - p.alpha) * k * uy * uy * trial.z * trial.z;
  }

  void
  BoucWen::commit()
  {
    committed = trial;
  }

  void
  BoucWen::revert()
  {
    trial         = committed;
    trial_force   = force_of(trial.deformation, trial.z);
    trial_tangent = p.stiffness * (p.alpha + (1 - p.alpha) * rate_of(trial.z, trial.epsilon,
                                                                      trial.direction).g);
  }

  void
  BoucWen::reset()
  {
    committed = State();
    revert();
  }

  namespace
  {
    /// "must lie in [lower, upper], got value" when value is outside it.
    std::string
    outside_bouc_wen_range(const double value, const double lower, const double upper)
    {
      if (value >= lower && value <= upper)
        return "";
      return "must lie in [" + number_text(lower) + ", " + number_text(upper) + "], got " +
             number_text(value);
    }
  } // namespace

  BoucWenShapeProblem
  bouc_wen_shape_problem(const BoucWenParameters &h)
  {
    if (const std::string p = outside_bouc_wen_range(h.alpha, 0, 1); !p.empty())
      return {"alpha", p};
    if (const std::string p = outside_bouc_wen_range(h.A, 0.01, 100); !p.empty())
      return {"A", p + " (the hysteretic part's initial stiffness is A (1 - alpha) k; A = 1 "
                       "makes the stiffness entry the initial stiffness)"};
    if (const std::string p = outside_bouc_wen_range(h.n, 1, 100); !p.empty())
      return {"n", p + " (at n = 100 the yield transition is already the bilinear law's)"};
    for (const auto &[entry, value] : {std::pair{"beta", h.beta}, std::pair{"gamma", h.gamma}})
      if (!(std::abs(value) <= 100))
        return {entry, "must be at most 100 in size, got " + number_text(value) +
                         " (beta + gamma = A, at most 100, in the normalised law)"};
    if (!(h.beta + h.gamma > 0))
      return {"beta", "beta + gamma must be positive (|z| stays bounded)"};
    if (!(h.beta >= std::abs(h.gamma)) && !(h.gamma >= std::abs(h.beta)))
      return {"gamma", "needs beta >= |gamma| or gamma >= |beta|"};
    const double z_u = std::pow(h.A / (h.beta + h.gamma), 1 / h.n);
    if (!(z_u >= 0.01 && z_u <= 100))
      return {"beta", "(A / (beta + gamma))^(1/n) = " + number_text(z_u) +
                        ", the hysteretic strength over (1 - alpha) k u_y: must lie in "
                        "[0.01, 100], near the yield force the stiffness and yield entries give"};
    return {};
  }
} // namespace poundfe
