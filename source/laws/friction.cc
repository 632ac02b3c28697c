#include <poundfe/base/numbers.h>
#include <poundfe/laws/friction.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    double
    sign(const double x)
    {
      return (x > 0) - (x < 0);
    }
  } // namespace

  NormalForce::Value
  NormalForce::operator()(const double x, const double v) const
  {
    Value value;
    const double speed = std::abs(v);
    value.n  = constant + per_displacement * std::abs(x) +
              (per_velocity + per_velocity_cubed * speed * speed) * speed;
    value.dx = per_displacement * sign(x);
    value.dv = per_velocity * sign(v) + 3 * per_velocity_cubed * v * speed;
    // H = 0: the SD spring lies in the belt's plane and presses nothing (the
    // limit of K H (1 - L/r) as H -> 0 at every x, including x = 0, where L/r
    // alone would be infinite and the product NaN)
    if (sd_reaction && sd_height != 0)
      {
        const double r = std::hypot(x, sd_height);
        value.n -= sd_stiffness * sd_height * (1 - sd_length / r);
        value.dx -= sd_stiffness * sd_height * sd_length * x / (r * r * r);
      }
    if (value.n <= 0) // the mass lifts off: no contact, no friction
      return Value();
    return value;
  }

  Friction::Friction(const FrictionLawParameters &parameters)
    : p(parameters)
  {
    reset();
  }

  double
  Friction::coefficient(const double slip_velocity, double &derivative) const
  {
    derivative = 0;
    if (p.stribeck_velocity <= 0)
      return p.kinetic_coefficient;
    const double decay = std::exp(-std::abs(slip_velocity) / p.stribeck_velocity);
    derivative         = -(p.static_coefficient - p.kinetic_coefficient) * decay /
                 p.stribeck_velocity * sign(slip_velocity);
    return p.kinetic_coefficient + (p.static_coefficient - p.kinetic_coefficient) * decay;
  }

  bool
  Friction::set_trial(const double deformation, const double rate)
  {
    const double             slip_velocity = rate - p.belt_velocity;
    const NormalForce::Value n             = p.normal(deformation, rate);
    trial_deformation                      = deformation;
    trial_rate                             = rate;
    trial_normal                           = n.n;
    if (p.model == FrictionModel::regularized)
      regularized(slip_velocity, n);
    else
      elastic_plastic(deformation - p.belt_velocity * trial_time, slip_velocity, n);
    return std::isfinite(trial.force) && std::isfinite(trial.tangent);
  }

  std::string
  Friction::failure() const
  {
    return "the friction force is not finite (force " + number_text(trial.force) +
           " N, tangent " + number_text(trial.tangent) + " N/m) at a displacement of " +
           number_text(trial_deformation) + " m, velocity " + number_text(trial_rate) +
           " m/s, normal force " + number_text(trial_normal) + " N";
  }

  void
  Friction::elastic_plastic(const double relative, const double slip_velocity,
                            const NormalForce::Value &n)
  {
    double       mu_derivative = 0;
    const double mu            = coefficient(slip_velocity, mu_derivative);
    // from stick the slider breaks away at the static limit
    const double limit   = (committed.slipping ? mu : p.static_coefficient) * n.n;
    const double spring  = p.stick_stiffness * (relative - committed.slip);
    const double elastic = spring + p.stick_damping * slip_velocity;
    trial.slip           = committed.slip;
    if (std::abs(elastic) <= limit)
      {
        trial.force           = elastic;
        trial.spring_force    = spring;
        trial.tangent         = p.stick_stiffness;
        trial.damping_tangent = p.stick_damping;
        trial.slipping        = false;
        return;
      }
    const double s        = sign(elastic);
    trial.force           = s * mu * n.n;
    trial.tangent         = s * mu * n.dx;
    trial.damping_tangent = s * (mu_derivative * n.n + mu * n.dv);
    trial.slip            = relative - trial.force / p.stick_stiffness;
    trial.spring_force    = trial.force;
    trial.slipping        = true;
  }

  void
  Friction::regularized(const double slip_velocity, const NormalForce::Value &n)
  {
    double       mu_derivative = 0;
    const double mu            = coefficient(slip_velocity, mu_derivative);
    const double eps           = p.regularization_velocity;
    const double t             = std::tanh(slip_velocity / eps);
    trial.force                = mu * n.n * t;
    trial.tangent              = mu * n.dx * t;
    trial.damping_tangent = (mu_derivative * n.n + mu * n.dv) * t + mu * n.n * (1 - t * t) / eps;
    trial.slip            = 0;
    trial.slipping        = std::abs(slip_velocity) > eps;
  }

  double
  Friction::stored_energy() const
  {
    if (p.model == FrictionModel::regularized)
      return 0;
    return 0.5 * trial.spring_force * trial.spring_force / p.stick_stiffness;
  }

  double
  Friction::supplied_work_increment() const
  {
    return -0.5 * (committed.force + trial.force) * p.belt_velocity *
           (trial_time - committed_time);
  }

  void
  Friction::commit()
  {
    committed      = trial;
    committed_time = trial_time;
  }

  void
  Friction::revert()
  {
    trial      = committed;
    trial_time = committed_time;
  }

  void
  Friction::reset()
  {
    committed      = State();
    committed_time = 0;
    revert();
  }
} // namespace poundfe
