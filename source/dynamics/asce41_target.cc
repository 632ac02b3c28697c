// The coefficient method of ASCE/SEI 41-17 §7.4.3.3 and its bilinear
// idealisation §7.4.3.2.4 (dynamics/asce41_target.h, which states the
// equations). Delta_d is the fixed point of Delta_d = min(delta_t(Delta_d),
// Delta at the largest base shear), to 1e-10 of the latter: plain iteration
// first (20 steps), then, where it cycles (jagged curves), a root of the
// mismatch g = min(delta_t, peak) - Delta_d, bracketed on 64 samples from the
// peak down and bisected (the root nearest the peak). `converged` is false
// only where every bracket closes on a jump of g (no fixed point found);
// `iterations` counts the evaluations of delta_t. A curve straight to
// Delta_d (V_y = V_d, no yield) is elastic response: C1 = C2 = 1 (7.4.3.3.2).
#include <poundfe/dynamics/asce41_target.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace poundfe
{
  namespace
  {
    /// The curve's force at displacement x (d ascending, d_0 <= x <= d.back()).
    double
    asce41_force_at(const std::vector<double> &d, const std::vector<double> &V, const double x)
    {
      for (unsigned int i = 1; i < d.size(); ++i)
        if (x <= d[i] && d[i] > d[i - 1])
          return V[i - 1] + (V[i] - V[i - 1]) * (x - d[i - 1]) / (d[i] - d[i - 1]);
      return V.back();
    }

    /// The area under the curve from 0 to x, trapezoidal.
    double
    asce41_area_to(const std::vector<double> &d, const std::vector<double> &V, const double x)
    {
      double area = 0;
      for (unsigned int i = 1; i < d.size() && d[i - 1] < x; ++i)
        {
          const double end = std::min(d[i], x);
          area += 0.5 * (V[i - 1] + asce41_force_at(d, V, end)) * (end - d[i - 1]);
        }
      return area;
    }

    /// Where the curve first reaches the force f (interpolated); the last
    /// displacement when it never does.
    double
    displacement_at_force(const std::vector<double> &d, const std::vector<double> &V,
                          const double f)
    {
      for (unsigned int i = 1; i < d.size(); ++i)
        if (V[i] >= f)
          return V[i] > V[i - 1] ? d[i - 1] + (d[i] - d[i - 1]) * (f - V[i - 1]) / (V[i] - V[i - 1]) :
                                   d[i];
      return d.back();
    }

    /// Whether the curve is straight from the origin to `end` (each point
    /// before it within 1e-6 of V(end) of the chord: round-off and the
    /// solver's tolerance, not a bend).
    bool
    straight_to(const std::vector<double> &d, const std::vector<double> &V, const double end)
    {
      const double end_force = asce41_force_at(d, V, end);
      for (unsigned int i = 1; i < d.size() && d[i] < end; ++i)
        if (std::abs(V[i] - end_force * d[i] / end) > 1e-6 * std::abs(end_force))
          return false;
      return true;
    }

    /// K_e, T_e, S_a, mu_strength, C1, C2 and delta_t of the idealisation in t.
    void
    evaluate_target(Asce41Target &t, const bool straight, const Asce41Building &building,
                    const std::function<double(double)> &spectrum)
    {
      const Asce41Bilinear &b = t.bilinear;
      t.effective_period      = building.initial_period *
                           std::sqrt(t.initial_stiffness / b.effective_stiffness);
      t.spectral_acceleration = spectrum(t.effective_period);
      t.mass_factor           = t.effective_period > 1.0 ? 1.0 : building.mass_factor;
      t.strength_ratio        = t.spectral_acceleration * building.mass * t.mass_factor / b.yield_force;
      // straight to Delta_d (V_y = V_d): elastic response, no strength
      // ratio above 1, whatever C_m W / M_1 makes of S_a M C_m / V_d
      // (7.4.3.3.2); a curve that stiffens is not elastic for this
      const Asce41Coefficients c =
        straight ? Asce41Coefficients() :
                    asce41_coefficients(t.strength_ratio, t.effective_period, building.site_class);
      t.c0     = building.c0;
      t.c1     = c.c1;
      t.c2     = c.c2;
      t.target = t.c0 * t.c1 * t.c2 * t.spectral_acceleration *
                 std::pow(t.effective_period / (2 * M_PI), 2);
    }

    /// alpha_2 from (Delta_d, V_d) to where the curve falls to 0.6 V_y (or
    /// its last point), and mu_max (7-32), where the curve falls.
    void
    check_strength_degradation(Asce41Target &t, const std::vector<double> &d,
                               const std::vector<double> &V)
    {
      const Asce41Bilinear &b     = t.bilinear;
      const double          floor = 0.6 * b.yield_force;
      double                d2 = d.back(), V2 = V.back();
      for (unsigned int i = 1; i < d.size(); ++i)
        if (d[i] > b.end_displacement && V[i] <= floor)
          {
            const bool   from_end = d[i - 1] < b.end_displacement; // the segment holds Delta_d
            const double d0       = from_end ? b.end_displacement : d[i - 1];
            const double V0       = from_end ? b.end_force : V[i - 1];
            d2 = V0 > floor ? d0 + (d[i] - d0) * (V0 - floor) / (V0 - V[i]) : d[i];
            V2 = V0 > floor ? floor : V[i];
            break;
          }
      if (!(d2 > b.end_displacement && V2 < b.end_force))
        return; // no fall past (Delta_d, V_d)
      t.degrading_slope_ratio =
        (V2 - b.end_force) / (d2 - b.end_displacement) / b.effective_stiffness;
      const double h = 1 + 0.15 * std::log(t.effective_period);
      t.max_strength_ratio = b.end_displacement / b.yield_displacement +
                             std::pow(std::abs(t.degrading_slope_ratio), -h) / 4;
      t.exceeds_strength_limit = t.strength_ratio > t.max_strength_ratio;
    }
    /// The first root of `f` (negative at 0, linear between `breaks`,
    /// ascending) by bisection within its piece, to 1e-15 of `scale`; where
    /// f never turns positive, the break where it comes closest.
    double
    first_crossing(const std::function<double(double)> &f, const std::vector<double> &breaks,
                   const double scale)
    {
      double low = 0, closest = breaks.front(), best = -std::numeric_limits<double>::infinity();
      for (const double x : breaks)
        {
          const double value = f(x);
          if (value > 0)
            {
              double high = x;
              while (high - low > 1e-15 * scale)
                (f(0.5 * (low + high)) > 0 ? high : low) = 0.5 * (low + high);
              return 0.5 * (low + high);
            }
          low = x;
          if (value >= best)
            {
              best    = value;
              closest = x;
            }
        }
      return closest;
    }

    /// Bisects g on [low, high] (g(low) > 0 > g(high)) until |g| <=
    /// `tolerance` (true) or the bracket closes on a jump of g (false, the
    /// bracket left around it).
    bool
    bisect_bracket(const std::function<double(double)> &g, double &low, double &high,
                   const double tolerance)
    {
      while (high - low > 4 * std::numeric_limits<double>::epsilon() * high)
        {
          const double middle = 0.5 * (low + high);
          const double value  = g(middle);
          if (std::abs(value) <= tolerance)
            return true;
          (value > 0 ? low : high) = middle;
        }
      return false;
    }

    /// A root of the fixed-point mismatch g(Delta_d) = min(delta_t, peak) -
    /// Delta_d (`g` also leaves the target evaluated at its argument), g
    /// negative at the peak: 64 samples from the peak down to 1e-12 of it,
    /// each step from g <= 0 above to g > 0 below bisected in turn, the
    /// first root found (the one nearest the peak) kept. False where every
    /// such step closes on a jump of g instead (no fixed point found), the
    /// target then evaluated at the highest jump.
    bool
    search_fixed_point(const std::function<double(double)> &g, const double peak,
                       const double tolerance)
    {
      const unsigned int n_samples = 64;
      double             above = peak, jump = 0;
      for (unsigned int k = n_samples; k-- > 0;)
        {
          const double x     = k > 0 ? peak * k / n_samples : 1e-12 * peak;
          const double value = g(x);
          if (std::abs(value) <= tolerance)
            return true;
          if (value <= 0)
            above = x;
          else if (above > x)
            {
              double low = x;
              if (bisect_bracket(g, low, above, tolerance))
                return true;
              jump  = jump > 0 ? jump : above;
              above = 0; // the next bracket starts at the next g <= 0
            }
        }
      g(jump > 0 ? jump : 1e-12 * peak);
      return false;
    }
  } // namespace

  const NameTable<SiteClass> &
  site_class_names()
  {
    static const NameTable<SiteClass> table({{SiteClass::A, "A"},
                                             {SiteClass::B, "B"},
                                             {SiteClass::C, "C"},
                                             {SiteClass::D, "D"},
                                             {SiteClass::E, "E"},
                                             {SiteClass::F, "F"}});
    return table;
  }

  double
  asce41_site_factor(const SiteClass site_class)
  {
    switch (site_class)
      {
        case SiteClass::A:
        case SiteClass::B:
          return 130;
        case SiteClass::C:
          return 90;
        default:
          return 60;
      }
  }

  Asce41Bilinear
  asce41_bilinear(const std::vector<double> &d, const std::vector<double> &V,
                  const double end_displacement)
  {
    AssertThrow(d.size() == V.size() && d.size() >= 2,
                dealii::ExcMessage("a capacity curve needs two points or more"));
    Assert(end_displacement > 0 && end_displacement <= d.back() * (1 + 1e-12),
           dealii::ExcMessage("the idealisation ends within the curve"));
    Asce41Bilinear b;
    b.end_displacement = end_displacement;
    b.end_force        = asce41_force_at(d, V, end_displacement);
    const double area  = asce41_area_to(d, V, end_displacement);
    const double chord = 0.5 * b.end_force * end_displacement; // the area of a straight curve
    if (area <= chord * (1 + 1e-9))
      {
        b.elastic             = true;
        b.yield_force         = b.end_force;
        b.yield_displacement  = end_displacement;
        b.effective_stiffness = b.end_force / end_displacement;
        return b;
      }
    const auto yield_displacement = [&](const double Vy) {
      return displacement_at_force(d, V, 0.6 * Vy) / 0.6;
    };
    // twice the idealisation's area less twice the curve's: negative at
    // V_y = 0 (the curve bends down), piecewise linear in V_y between the
    // forces where 0.6 V_y reaches a new height of the curve, rising while
    // the curve at 0.6 V_y is stiffer than the secant to (Delta_d, V_d),
    // falling after; the root is its first crossing of zero
    const auto balance = [&](const double Vy) {
      return Vy * end_displacement + b.end_force * (end_displacement - yield_displacement(Vy)) -
             2 * area;
    };
    const double peak = *std::max_element(V.begin(), V.end());
    std::vector<double> breaks; // of the pieces, ascending
    double              reached = 0;
    for (const double f : V)
      if (f > reached && f / 0.6 < peak)
        breaks.push_back((reached = f) / 0.6);
    breaks.push_back(peak); // V_y may not pass the largest base shear
    b.yield_force = first_crossing(balance, breaks, peak);
    b.yield_displacement  = yield_displacement(b.yield_force);
    b.effective_stiffness = b.yield_force / b.yield_displacement;
    if (end_displacement > b.yield_displacement)
      b.post_yield_ratio = (b.end_force - b.yield_force) /
                           (end_displacement - b.yield_displacement) / b.effective_stiffness;
    return b;
  }

  Asce41Coefficients
  asce41_coefficients(const double strength_ratio, const double effective_period,
                      const SiteClass site_class)
  {
    const double       excess = std::max(strength_ratio, 1.0) - 1; // elastic: none
    Asce41Coefficients c;
    if (effective_period <= 1.0)
      c.c1 = 1 + excess / (asce41_site_factor(site_class) *
                           std::pow(std::max(effective_period, 0.2), 2));
    if (effective_period <= 0.7)
      c.c2 = 1 + std::pow(excess / effective_period, 2) / 800;
    return c;
  }

  Asce41Target
  asce41_target(const std::vector<double> &d, const std::vector<double> &V,
                const Asce41Building &building, const std::function<double(double)> &spectrum)
  {
    AssertThrow(d.size() == V.size() && d.size() >= 2,
                dealii::ExcMessage("a capacity curve needs two points or more"));
    Asce41Target t;
    for (unsigned int i = 1; i < d.size() && t.initial_stiffness == 0; ++i)
      if (d[i] > 0)
        t.initial_stiffness = V[i] / d[i];
    // where the largest base shear is reached: on a plateau (within 1e-6
    // of it) its end, which round-off would otherwise pick anywhere
    const double peak              = *std::max_element(V.begin(), V.end());
    double       peak_displacement = 0;
    for (unsigned int i = 0; i < d.size(); ++i)
      if (V[i] >= (1 - 1e-6) * peak)
        peak_displacement = d[i];
    const auto mismatch = [&](const double end) {
      ++t.iterations;
      t.bilinear = asce41_bilinear(d, V, end);
      evaluate_target(t, straight_to(d, V, end), building, spectrum);
      return std::min(t.target, peak_displacement) - end;
    };
    const double tolerance = 1e-10 * peak_displacement;
    // plain iteration settles within a few steps on a smooth curve ...
    double end = peak_displacement;
    for (unsigned int i = 0; i < 20 && !t.converged; ++i)
      {
        const double g = mismatch(end);
        t.converged    = std::abs(g) <= tolerance;
        end += t.converged ? 0 : g;
      }
    // ... but can cycle on a jagged one: bracket and bisect g instead
    if (!t.converged)
      t.converged = search_fixed_point(mismatch, peak_displacement, tolerance);
    t.beyond_curve = t.target > d.back();
    check_strength_degradation(t, d, V);
    return t;
  }
} // namespace poundfe
