// The equal-energy bilinear idealisation and the N2 target displacement
// (dynamics/capacity_curve.h; EN 1998-1:2004 Annex B).
#include <poundfe/dynamics/capacity_curve.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  BilinearCurve
  ec8_bilinear(const std::vector<double> &d, const std::vector<double> &F)
  {
    AssertThrow(d.size() == F.size() && d.size() >= 2,
                dealii::ExcMessage("a capacity curve needs two points or more"));
    BilinearCurve curve;
    curve.ultimate_displacement = d.back();
    curve.yield_force           = *std::max_element(F.begin(), F.end());
    for (unsigned int i = 1; i < d.size(); ++i)
      curve.energy += 0.5 * (F[i] + F[i - 1]) * (d[i] - d[i - 1]);
    curve.yield_displacement =
      curve.yield_force > 0 ?
        2 * (curve.ultimate_displacement - curve.energy / curve.yield_force) :
        0.0;
    return curve;
  }

  N2Target
  ec8_n2_target(const BilinearCurve &sdof, const double equivalent_mass, const double gamma,
                const std::function<double(double)> &spectrum, const double tc)
  {
    constexpr double two_pi = 2 * M_PI;
    N2Target         t;
    t.period = two_pi * std::sqrt(equivalent_mass * sdof.yield_displacement / sdof.yield_force);
    t.spectral_acceleration = spectrum(t.period);
    t.elastic_displacement  = t.spectral_acceleration * std::pow(t.period / two_pi, 2);
    t.target_sdof           = t.elastic_displacement;
    if (t.period < tc && sdof.yield_force / equivalent_mass < t.spectral_acceleration)
      {
        t.reduction   = t.spectral_acceleration * equivalent_mass / sdof.yield_force;
        t.target_sdof = std::max(t.elastic_displacement,
                                 t.elastic_displacement / t.reduction *
                                   (1 + (t.reduction - 1) * tc / t.period));
      }
    t.target = gamma * t.target_sdof;
    return t;
  }
} // namespace poundfe
