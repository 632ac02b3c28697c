// Bidirectional Bouc-Wen hysteresis (Park, Wen & Ang 1986): the equations,
// their integration and the consistent tangent are stated in
// include/poundfe/laws/bidirectional_bouc_wen.h (doc/theory.md §2).
#include <poundfe/base/lean_assert.h>
#include <poundfe/laws/bidirectional_bouc_wen.h>

#include <Eigen/LU>

#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace
  {
    double
    sign_of(const double x)
    {
      return (x > 0) - (x < 0);
    }

    /// |z|^(n-2), with the usual n = 2 exactly 1.
    double
    interaction_factor(const Eigen::Vector2d &z, const double n)
    {
      return n == 2 ? 1.0 : std::pow(z.norm(), n - 2);
    }
  } // namespace

  BidirectionalBoucWen::BidirectionalBoucWen(const BoucWenParameters &axis_1,
                                             const BoucWenParameters &axis_2)
    : axes{{axis_1, axis_2}}
  {
    Assert(axis_1.alpha == axis_2.alpha && axis_1.A == axis_2.A &&
             axis_1.beta == axis_2.beta && axis_1.gamma == axis_2.gamma &&
             axis_1.n == axis_2.n && axis_1.theta == axis_2.theta,
           dealii::ExcMessage("the two axes share alpha, A, beta, gamma, n and theta"));
    Assert(axis_1.n >= 2, dealii::ExcMessage("the bidirectional law needs n >= 2"));
    Assert(axis_1.delta_A == 0 && axis_1.delta_nu == 0 && axis_1.delta_eta == 0,
           dealii::ExcMessage("the bidirectional law has no degradation"));
    reset();
  }

  Eigen::Matrix2d
  BidirectionalBoucWen::rate_matrix(const Eigen::Vector2d &z, const Eigen::Vector2d &s) const
  {
    const BoucWenParameters &p = shared();
    const double            f = interaction_factor(z, p.n);
    Eigen::Matrix2d         g = p.A * Eigen::Matrix2d::Identity();
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        g(i, j) -= f * z[i] * (p.beta * s[j] * std::abs(z[j]) + p.gamma * z[j]);
    return g;
  }

  Eigen::Matrix2d
  BidirectionalBoucWen::rate_jacobian(const Eigen::Vector2d &z, const Eigen::Vector2d &s,
                                      const Eigen::Vector2d &dc) const
  {
    const BoucWenParameters &p = shared();
    const double            f = interaction_factor(z, p.n);
    double                  w = 0;
    Eigen::Vector2d         dw;
    for (unsigned int k = 0; k < 2; ++k)
      {
        w += dc[k] * (p.beta * s[k] * std::abs(z[k]) + p.gamma * z[k]);
        dw[k] = dc[k] * (p.beta * s[k] * sign_of(z[k]) + p.gamma);
      }
    Eigen::Matrix2d dq = f * Eigen::Matrix2d::Identity();
    const double    r  = z.norm();
    if (p.n != 2 && r > 0)
      dq += (p.n - 2) * std::pow(r, p.n - 4) * z * z.transpose();
    return -(w * dq + f * z * dw.transpose());
  }

  Eigen::Vector2d
  BidirectionalBoucWen::force_of(const Eigen::Vector2d &deformation,
                                 const Eigen::Vector2d &z) const
  {
    const double    alpha = shared().alpha;
    Eigen::Vector2d f;
    for (unsigned int j = 0; j < 2; ++j)
      f[j] = alpha * axes[j].stiffness * deformation[j] +
             (1 - alpha) * axes[j].stiffness * axes[j].yield_deformation * z[j];
    return f;
  }

  Eigen::Matrix2d
  BidirectionalBoucWen::tangent_of(const Eigen::Matrix2d &dz_dc) const
  {
    const double    alpha = shared().alpha;
    Eigen::Matrix2d k;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        k(i, j) = (i == j ? alpha * axes[i].stiffness : 0.0) +
                  (1 - alpha) * axes[i].stiffness * axes[i].yield_deformation * dz_dc(i, j) /
                    axes[j].yield_deformation;
    return k;
  }

  namespace
  {
    /// z + step, the step halved until the residual's largest entry
    /// decreases (taken at the 30th try regardless); R: the residual there.
    template <typename Residual>
    void
    take_backtracked_step(const Residual &residual, Eigen::Vector2d step, Eigen::Vector2d &z,
                          Eigen::Vector2d &R)
    {
      for (unsigned int half = 0; half < 30; ++half)
        {
          const Eigen::Vector2d R_try = residual(z + step);
          if (R_try.lpNorm<Eigen::Infinity>() < R.lpNorm<Eigen::Infinity>() || half == 29)
            {
              z += step;
              R = R_try;
              return;
            }
          step *= 0.5;
        }
    }

    /// Why the local Newton iteration for z failed, with its increment, start
    /// and last residual.
    std::string
    newton_failure(const unsigned int max_iterations, const Eigen::Vector2d &du,
                   const Eigen::Vector2d &z0, const Eigen::Vector2d &R)
    {
      std::ostringstream message;
      message << "bidirectional Bouc-Wen: the local Newton iteration for z did not converge in "
              << max_iterations << " iterations (increment " << du[0] << ", " << du[1]
              << "; z0 = " << z0[0] << ", " << z0[1]
              << "; |residual| = " << R.lpNorm<Eigen::Infinity>() << ")";
      return message.str();
    }
  } // namespace

  bool
  BidirectionalBoucWen::set_trial(const Eigen::Vector2d &deformation)
  {
    const BoucWenParameters &p  = shared();
    const double             th = p.theta;
    const Eigen::Vector2d    du = deformation - committed.deformation;
    Eigen::Vector2d          dc, s;
    for (unsigned int j = 0; j < 2; ++j)
      {
        dc[j] = du[j] / axes[j].yield_deformation;
        s[j]  = du[j] != 0 ? sign_of(du[j]) : committed.direction[j];
      }
    const Eigen::Vector2d z0 = committed.z;
    const Eigen::Vector2d h0 = rate_matrix(z0, s) * dc;
    auto residual = [&](const Eigen::Vector2d &z1) {
      return Eigen::Vector2d(z1 - z0 - (1 - th) * h0 - th * rate_matrix(z1, s) * dc);
    };

    Eigen::Vector2d z = z0;
    Eigen::Vector2d R = residual(z);
    // At least one Newton step whenever the deformation changed (as the
    // uniaxial law, for the same reason: the force must follow the tangent).
    bool converged = du.isZero(0);
    for (unsigned int it = 0; it < p.max_iterations && !converged; ++it)
      {
        const Eigen::Matrix2d J =
          Eigen::Matrix2d::Identity() - th * rate_jacobian(z, s, dc);
        if (!(std::abs(J.determinant()) > 0))
          break;
        take_backtracked_step(residual, -J.inverse() * R, z, R);
        converged = R.lpNorm<Eigen::Infinity>() <= p.tolerance;
      }
    if (!converged || !z.allFinite())
      {
        failure_message = newton_failure(p.max_iterations, du, z0, R);
        return false;
      }

    const Eigen::Matrix2d J = Eigen::Matrix2d::Identity() - th * rate_jacobian(z, s, dc);
    const Eigen::Matrix2d dz_dc =
      J.inverse() * ((1 - th) * rate_matrix(z0, s) + th * rate_matrix(z, s));
    trial.deformation = deformation;
    trial.z           = z;
    for (unsigned int j = 0; j < 2; ++j)
      trial.direction[j] = du[j] != 0 ? s[j] : committed.direction[j];
    trial_force   = force_of(deformation, z);
    trial_tangent = tangent_of(dz_dc);
    return true;
  }

  double
  BidirectionalBoucWen::stored_energy() const
  {
    const double alpha  = shared().alpha;
    double       energy = 0;
    for (unsigned int j = 0; j < 2; ++j)
      {
        const double k = axes[j].stiffness, uy = axes[j].yield_deformation;
        energy += 0.5 * alpha * k * trial.deformation[j] * trial.deformation[j] +
                  0.5 * (1 - alpha) * k * uy * uy * trial.z[j] * trial.z[j];
      }
    return energy;
  }

  void
  BidirectionalBoucWen::commit()
  {
    committed = trial;
  }

  void
  BidirectionalBoucWen::revert()
  {
    trial         = committed;
    trial_force   = force_of(trial.deformation, trial.z);
    trial_tangent = tangent_of(rate_matrix(trial.z, trial.direction));
  }

  void
  BidirectionalBoucWen::reset()
  {
    committed = State();
    revert();
  }
} // namespace poundfe
