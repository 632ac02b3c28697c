// Steel02: Giuffré–Menegotto–Pinto steel with isotropic hardening.
//   Between reversals the stress follows the curve from the last reversal
//   point (eps_r, sig_r) towards the point (eps_0, sig_0) where the elastic
//   line from the reversal (slope E0) meets the hardening asymptote (slope
//   b E0):
//     eps* = (eps - eps_r) / (eps_0 - eps_r),
//     sig* = b eps* + (1 - b) eps* / (1 + |eps*|^R)^(1/R),
//     sig  = sig_r + sig* (sig_0 - sig_r),
//     dsig/deps = [b + (1 - b) / (1 + |eps*|^R)^(1 + 1/R)] (sig_0 - sig_r) / (eps_0 - eps_r),
//   with R = R0 (1 - cR1 xi / (cR2 + xi)), xi = |eps_pl - eps_0| / eps_y the
//   plastic excursion since the previous reversal from the other side
//   (Menegotto & Pinto 1973).
//   At a reversal the asymptote moves out by the isotropic shift of
//   Filippou et al. (1983): on unloading the compression asymptote passes
//   through -fy s with s = 1 + a1 ((eps_max - eps_min) / (2 a2 eps_y))^0.8,
//   on reloading the tension asymptote through fy s with a3, a4.
//   First loading starts at the origin towards (±eps_y, ±fy) with R = R0.
// Sources: OpenSees Steel02 (F. Filippou), whose behaviour this reproduces
// without its initial-stress option (under `poundfe opensees` its dead band
// too: a virgin state given a strain change below 10 DBL_EPSILON stays
// virgin, Steel02::setTrialStrain); M. Menegotto & P.E. Pinto (1973), IABSE
// Symposium, Lisbon; F.C. Filippou, E.P. Popov & V.V. Bertero (1983), EERC
// 83/19. Theory: doc/theory.md §12.2.
#include <poundfe/laws/steel02.h>

#include <cfloat>
#include <cmath>

namespace poundfe
{
  Steel02::Steel02(const Steel02Parameters &parameters, const bool opensees_dead_band)
    : p(parameters)
    , eps_y(p.fy / p.E0)
    , hardening(p.b * p.E0)
    , opensees_dead_band(opensees_dead_band)
  {
    require_positive("Steel02", "fy", p.fy);
    require_positive("Steel02", "E0", p.E0);
    require_in("Steel02", "b", p.b, 0, 1);
    require_positive("Steel02", "R0", p.R0);
    require_in("Steel02", "cR1", p.cR1, 0, 1);
    require_positive("Steel02", "cR2", p.cR2);
    require_non_negative("Steel02", "a1", p.a1);
    require_positive("Steel02", "a2", p.a2);
    require_non_negative("Steel02", "a3", p.a3);
    require_positive("Steel02", "a4", p.a4);
    reset();
  }

  Steel02State
  Steel02::virgin() const
  {
    Steel02State s;
    s.tangent = p.E0;
    s.eps_max = p.fy / p.E0;
    s.eps_min = -s.eps_max;
    return s;
  }

  void
  Steel02::set_branch(Steel02State &s) const
  {
    const double xi = std::abs((s.eps_pl - s.eps_0) / eps_y);
    s.R             = p.R0 * (1 - p.cR1 * xi / (p.cR2 + xi));
    s.inverse_R     = 1 / s.R;
    s.secant        = (s.sig_0 - s.sig_r) / (s.eps_0 - s.eps_r);
  }

  Steel02State
  Steel02::respond(const Steel02State &from, const double strain) const
  {
    return trial_state(from, trial, strain);
  }

  Steel02State
  Steel02::trial_state(const Steel02State &from, const Steel02State & /*last*/,
                       const double strain) const
  {
    const double d_strain = strain - from.strain;
    Steel02State s        = from;
    s.strain              = strain;
    if (from.direction == 0 && stays_virgin(d_strain))
      return s;
    if (s.direction == 0) // first loading: towards (±eps_y, ±fy)
      {
        const double sign = d_strain > 0 ? 1 : -1;
        s.direction       = d_strain > 0 ? 1 : 2;
        s.eps_0 = s.eps_pl = sign * eps_y;
        s.sig_0            = sign * p.fy;
        set_branch(s);
      }
    else if ((s.direction == 2 && d_strain > 0) || (s.direction == 1 && d_strain < 0))
      {
        // a reversal at the committed point; the new asymptote, shifted out
        // isotropically, meets the elastic line from it at (eps_0, sig_0)
        const bool   reloading = d_strain > 0;
        const double sign      = reloading ? 1 : -1;
        s.eps_r                = from.strain;
        s.sig_r                = from.stress;
        if (reloading)
          s.eps_min = std::min(s.eps_min, from.strain);
        else
          s.eps_max = std::max(s.eps_max, from.strain);
        const double a     = reloading ? p.a3 : p.a1;
        const double scale = reloading ? p.a4 : p.a2;
        const double shift = 1 + a * std::pow((s.eps_max - s.eps_min) / (2 * scale * eps_y), 0.8);
        s.eps_0 = (sign * p.fy * shift - hardening * sign * eps_y * shift - s.sig_r +
                   p.E0 * s.eps_r) /
                  (p.E0 - hardening);
        s.sig_0     = sign * p.fy * shift + hardening * (s.eps_0 - sign * eps_y * shift);
        s.eps_pl    = reloading ? s.eps_max : s.eps_min;
        s.direction = reloading ? 1 : 2;
        set_branch(s);
      }

    const double ratio = (strain - s.eps_r) / (s.eps_0 - s.eps_r);
    const double g     = 1 + std::pow(std::abs(ratio), s.R);
    const double g_R   = std::pow(g, s.inverse_R);
    s.stress  = s.sig_r + (p.b * ratio + (1 - p.b) * ratio / g_R) * (s.sig_0 - s.sig_r);
    s.tangent = (p.b + (1 - p.b) / (g * g_R)) * s.secant;
    return s;
  }

  bool
  Steel02::stays_virgin(const double d_strain) const
  {
    return d_strain == 0 || (opensees_dead_band && std::abs(d_strain) < 10 * DBL_EPSILON);
  }

  namespace materials
  {
    namespace
    {
      std::unique_ptr<UniaxialLaw>
      make_steel02(const std::map<std::string, double> &v, const bool opensees_dead_band)
      {
        return std::make_unique<Steel02>(
          Steel02Parameters{v.at("fy"), v.at("E0"), v.at("b"), v.at("R0"), v.at("cR1"),
                            v.at("cR2"), v.at("a1"), v.at("a2"), v.at("a3"), v.at("a4")},
          opensees_dead_band);
      }
    } // namespace

    MaterialType
    steel02()
    {
      return {"Steel02",
              "Giuffré-Menegotto-Pinto steel with isotropic hardening (OpenSees Steel02)",
              {{"fy", NAN, "yield stress"},
               {"E0", NAN, "initial elastic modulus"},
               {"b", NAN, "hardening ratio Esh/E0"},
               {"R0", 20, "curvature of the first transition"},
               {"cR1", 0.925, "reduction of R with the plastic excursion"},
               {"cR2", 0.15, "its scale"},
               {"a1", 0, "isotropic hardening in compression"},
               {"a2", 1, "its plastic-excursion scale"},
               {"a3", 0, "isotropic hardening in tension"},
               {"a4", 1, "its plastic-excursion scale"}},
              [](const std::map<std::string, double> &v) { return make_steel02(v, false); }};
    }

    std::unique_ptr<UniaxialLaw>
    steel02_with_dead_band(const std::map<std::string, double> &values)
    {
      return make_steel02(values, true);
    }
  } // namespace materials
} // namespace poundfe
