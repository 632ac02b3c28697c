// Bifurcation diagrams of a harmonically forced model (doc/theory.md §8.4).
//   Poincaré section: x_k = x(k T), T = 2 pi / omega the forcing period,
//     sampled exactly: the time step is dt' = T / round(T / dt) (dt the
//     input's), so the steps land on every k T.
//   Period n: the smallest n <= 16 with |x_{k+n} - x_k| <= eps R for every
//     sampled k, R the range of the response over the sampled periods and
//     eps the Period tolerance (1e-6); none: non-periodic (period 0).
//   Continuation: each value starts from the previous value's final state
//     (a branch is followed through a multistable range) instead of rest.
//   Largest Lyapunov exponent (Benettin et al. 1980, Meccanica 15:9-20;
//     Wolf et al. 1985, Physica D 16:285): a second trajectory starts at a
//     distance d0 from the first; every period its distance d_k is measured
//     and it is put back at d0 along the separation;
//     lambda = sum_k ln(d_k / d0) / (K T) over the K sampled periods.
//     Distance: |(du, dv / omega)| over all equations; d0 = delta |(u, v /
//     omega)| of the first trajectory at the renormalisation (delta 1e-8).
//     Both trajectories are integrated through impacts and yielding (no
//     variational equations, whose transition conditions at each
//     discontinuity Müller 1995, Chaos Solitons Fractals 5:1671, derives).
#ifndef poundfe_dynamics_bifurcation_h
#define poundfe_dynamics_bifurcation_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/base/sweep_parameters.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  struct Analysis;
  struct NodalForceParameters;
  struct TimeHistoryParameters;

  struct BifurcationParameters
  {
    SweepParameters sweep{"Bifurcation"}; // Parameter, Values
    std::string     response = "1 1 0 ux"; // building floor node dof
    std::string     quantity = "displacement"; // Response quantity: displacement | velocity
    double          forcing_period    = 0; // s; 0: 2 pi / omega of the first harmonic force
    unsigned int    transient_periods = 200;
    unsigned int    sampled_periods   = 64;
    double          period_tolerance  = 1e-6;
    bool            continuation      = false; // start from the previous value's final state
    bool            lyapunov_exponent = true;
    double          perturbation      = 1e-8; // delta: d0 relative to the state

    /// Declare the section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    void check(const InputFile &input) const;
  };

  /// The smallest n in 1..max_period with |x[k + n] - x[k]| <= tolerance
  /// for every k; 0 when none (or fewer than 2 n samples).
  unsigned int poincare_period(const std::vector<double> &samples, double tolerance,
                               unsigned int max_period = 16);

  /// The diagram at one value of the swept parameter.
  struct BifurcationPoint
  {
    double              value          = 0;
    double              forcing_period = 0; // s
    double              time_step      = 0; // s, T / steps per period
    std::vector<double> samples;            // the Poincaré samples x(k T)
    double              response_range = 0; // over the sampled periods
    unsigned int        period         = 0; // 0: non-periodic
    double              lyapunov_exponent = 0; // 1/s (0 when not computed)
    bool                completed      = true;
    double              wall_time      = 0; // s (set by the caller that prepared the model)
  };

  /// T: the Forcing period, or 2 pi / omega of the first harmonic nodal
  /// force. Throws InputError when there is neither.
  double forcing_period(const BifurcationParameters &b, const NodalForceParameters &nodal_forces,
                        const InputFile &input);

  /// A state to start from: the previous value's final one (Continuation).
  struct BifurcationState
  {
    Vector u, v;
  };

  /// One point of the diagram at `value`: the model run once with the
  /// Poincaré sampler (and the second trajectory), the forcing period
  /// `period` being `steps_per_period` steps of the parameters' time step
  /// (so steps land on every k T), from `state` when it is given and not
  /// empty, else from rest; `state` becomes the final state (empty after a
  /// failure). Throws InputError (e.g. a bad Response).
  BifurcationPoint bifurcation_point(const Analysis &analysis,
                                     const TimeHistoryParameters &parameters,
                                     const BifurcationParameters &b, double value, double period,
                                     unsigned long steps_per_period,
                                     BifurcationState *state = nullptr);
} // namespace poundfe

#endif
