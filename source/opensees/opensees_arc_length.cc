// OpenSees's ArcLength integrator for static analyses past a limit point
// (OpenSees 3.8, SRC/analysis/integrator/ArcLength.cpp; Crisfield's
// spherical arc length, M. A. Crisfield, "A fast incremental/iterative
// solution procedure that handles snap-through", Computers & Structures 13,
// 1981). With the reference load phat (the unbalance at lambda + 1, as
// DisplacementControl's) and s, alpha the script's:
//   newStep: dUhat = K^-1 phat, dlambda = sign sqrt(s^2 / (dUhat.dUhat +
//     alpha^2)) with the sign of the last step's Delta lambda (+ at first),
//     dU = dlambda dUhat, Delta U = dU, Delta lambda = dlambda;
//   update(dUbar): dUhat = K^-1 phat with the iteration's tangent, dlambda
//     the root of a dlambda^2 + b dlambda + c = 0 that keeps
//     |Delta U + dU|^2 + alpha^2 (Delta lambda + dlambda)^2 = s^2,
//       a = alpha^2 + dUhat.dUhat,
//       b = 2 (alpha^2 Delta lambda + dUhat.dUbar + Delta U.dUhat),
//       c = 2 Delta U.dUbar + dUbar.dUbar,
//     the one with Delta U.Delta U + dUbar.Delta U + dlambda1 dUhat.Delta U
//     > 0 (dlambda1 the larger root), else the other; dU = dUbar + dlambda
//     dUhat, which the test sees. Imaginary roots fail the step.
#include <poundfe/opensees/opensees_analysis.h>

#include <cmath>

namespace poundfe
{
  namespace opensees
  {
    bool
    Analysis::arc_length_step(std::string &why)
    {
      if (fresh_integrator)
        {
          reference_load();
          if (phat.isZero(0))
            throw ScriptError("ArcLength: zero reference load");
          arc_lambda_step  = 0;
          fresh_integrator = false;
        }
      const double sign = arc_lambda_step < 0 ? -1 : 1;
      Vector       dx_hat(n_equations);
      if (!reference_displacement(dx_hat, why))
        return false;
      const double d_lambda =
        sign * std::sqrt(opts.arc_s * opts.arc_s /
                         (dx_hat.squaredNorm() + opts.arc_alpha * opts.arc_alpha));
      arc_lambda_step = d_lambda;
      arc_u_step      = d_lambda * dx_hat;
      return predict_and_iterate(d_lambda, arc_u_step, why);
    }

    bool
    Analysis::correct_arc_length(Vector &dx, std::string &why)
    {
      Vector dx_hat(n_equations);
      solve(phat, dx_hat);
      const double alpha2 = opts.arc_alpha * opts.arc_alpha;
      const double a      = alpha2 + dx_hat.squaredNorm();
      const double b =
        2 * (alpha2 * arc_lambda_step + dx_hat.dot(dx) + arc_u_step.dot(dx_hat));
      const double c   = 2 * arc_u_step.dot(dx) + dx.squaredNorm();
      const double b4ac = b * b - 4 * a * c;
      if (b4ac < 0)
        {
          why = "ArcLength: imaginary roots due to multiple instability directions - initial "
                "load increment was too large";
          return false;
        }
      if (a == 0)
        {
          why = "ArcLength: zero denominator (alpha 0 and zero reference load)";
          return false;
        }
      const double root     = std::sqrt(b4ac);
      const double lambda_1 = (-b + root) / (2 * a);
      const double lambda_2 = (-b - root) / (2 * a);
      const double theta_1  = arc_u_step.squaredNorm() + dx.dot(arc_u_step) +
                             lambda_1 * dx_hat.dot(arc_u_step);
      const double d_lambda = theta_1 > 0 ? lambda_1 : lambda_2;
      dx += d_lambda * dx_hat;
      arc_u_step += dx;
      arc_lambda_step += d_lambda;
      trial_time += d_lambda;
      return true;
    }
  } // namespace opensees
} // namespace poundfe
