// Concrete02: Kent–Scott–Park compression (Concrete01's envelope, shared)
// with Yassin's unloading rule and linear tension softening (compression
// negative).
//   Compression beyond the largest compression eps_min: the envelope.
//   Between: the point R = (eps_R, Ec0 eps_R) with
//     eps_R = (fpcu - lambda Ec0 epscu) / (Ec0 (1 - lambda))
//   (where the line of slope lambda Ec0 through (epscu, fpcu) meets the
//   initial elastic line) sets the reloading slope
//     Er = (sigma_m - Ec0 eps_R) / (eps_min - eps_R), sigma_m = sigma_env(eps_min),
//   and the zero-stress strain eps_t = eps_min - sigma_m / Er. For eps <= eps_t
//   the stress is the elastic predictor sigma_n + Ec0 (eps - eps_n) kept
//   between the reloading line sigma_m + Er (eps - eps_min) (tangent Er) and
//   the unloading curve Er (eps - eps_t) / 2 (tangent Er / 2).
//   Tension (eps > eps_t): the envelope shifted by eps_t,
//     Ec0 e for e = eps - eps_t <= ft / Ec0, ft - Ets (e - ft / Ec0) down to 0,
//   and below the largest shifted tensile strain e_max reached, the secant
//   line to that envelope point, sigma = sigma_env,t(e_max) / e_max e.
// Sources: OpenSees Concrete02 (F. Filippou), whose behaviour this
// reproduces, stress and history alike (its tangent 1e-10 on the flat
// branches is 0 here, the derivative of the stress; under `poundfe opensees`
// its dead band too: a strain within DBL_EPSILON of the committed one keeps
// the committed history with the last trial's stress and tangent,
// Concrete02::setTrialStrain); A.H.M. Yassin (1994),
// Nonlinear analysis of prestressed concrete structures under monotonic and
// cyclic loads, PhD thesis, UC Berkeley; D.C. Kent & R. Park (1971). Theory:
// doc/theory.md §12.4.
#include <poundfe/laws/concrete02.h>

#include <cfloat>
#include <cmath>

namespace poundfe
{
  Concrete02::Concrete02(const Concrete02Parameters &parameters, const bool opensees_dead_band)
    : envelope("Concrete02", parameters.compression)
    , lambda(parameters.lambda)
    , ft(parameters.ft)
    , Ets(parameters.Ets)
    , Ec0(envelope.initial_modulus())
    , eps_R((envelope.fpcu - lambda * Ec0 * envelope.epscu) / (Ec0 * (1 - lambda)))
    , crack_strain(ft / Ec0)
    , tension_end(ft * (1 / Ets + 1 / Ec0))
    , opensees_dead_band(opensees_dead_band)
  {
    require_in("Concrete02", "lambda", lambda, 0, 1);
    require_non_negative("Concrete02", "ft", ft);
    require_positive("Concrete02", "Ets", Ets);
    reset();
  }

  Concrete02State
  Concrete02::virgin() const
  {
    Concrete02State s;
    s.tangent = Ec0;
    s.min_stress = envelope.at(0).stress;
    // never compressed: the initial line (the limit of the formula of
    // set_min_strain, which is 0/0 when eps_R = 0)
    s.reload_slope = Ec0;
    s.zero_strain  = 0;
    return s;
  }

  void
  Concrete02::set_min_strain(Concrete02State &s, const double strain,
                             const StressPoint &on_envelope) const
  {
    s.min_strain   = strain;
    s.min_stress   = on_envelope.stress;
    s.reload_slope = strain == 0 ? Ec0 : (s.min_stress - Ec0 * eps_R) / (strain - eps_R);
    s.zero_strain  = strain == 0 ? 0.0 : strain - s.min_stress / s.reload_slope;
  }

  StressPoint
  Concrete02::tension_envelope(const double strain) const
  {
    if (strain <= crack_strain)
      return {Ec0 * strain, Ec0};
    if (strain <= tension_end)
      return {ft - Ets * (strain - crack_strain), -Ets};
    return {0, 0};
  }

  Concrete02State
  Concrete02::respond(const Concrete02State &from, const double strain) const
  {
    return trial_state(from, trial, strain);
  }

  Concrete02State
  Concrete02::trial_state(const Concrete02State &from, const Concrete02State &last,
                          const double strain) const
  {
    if (opensees_dead_band && std::abs(strain - from.strain) < DBL_EPSILON)
      return in_dead_band(from, last, strain);
    if (strain == from.strain)
      return from;
    if (strain < from.min_strain)
      {
        Concrete02State   s = from;
        const StressPoint e = envelope.at(strain);
        s.strain            = strain;
        set_min_strain(s, strain, e);
        s.stress  = e.stress;
        s.tangent = e.tangent;
        return s;
      }
    return unload_or_reload(from, strain);
  }

  Concrete02State
  Concrete02::unload_or_reload(const Concrete02State &from, const double strain) const
  {
    Concrete02State s    = from;
    s.strain             = strain;
    const double sigma_m = from.min_stress, Er = from.reload_slope, eps_t = from.zero_strain;
    if (strain <= eps_t)
      {
        const double reloading = sigma_m + Er * (strain - from.min_strain);
        const double unloading = 0.5 * Er * (strain - eps_t);
        s.stress               = from.stress + Ec0 * (strain - from.strain);
        s.tangent              = Ec0;
        if (s.stress <= reloading)
          {
            s.stress  = reloading;
            s.tangent = Er;
          }
        if (s.stress >= unloading)
          {
            s.stress  = unloading;
            s.tangent = 0.5 * Er;
          }
      }
    else if (strain <= eps_t + from.tension_strain)
      {
        // the secant to the largest tensile point reached
        const StressPoint peak = tension_envelope(from.tension_strain);
        s.tangent = from.tension_strain != 0 ? peak.stress / from.tension_strain : Ec0;
        s.stress  = s.tangent * (strain - eps_t);
      }
    else
      {
        const StressPoint e = tension_envelope(strain - eps_t);
        s.stress            = e.stress;
        s.tangent           = e.tangent;
        s.tension_strain    = strain - eps_t;
      }
    return s;
  }

  Concrete02State
  Concrete02::in_dead_band(const Concrete02State &from, const Concrete02State &last,
                           const double strain) const
  {
    // OpenSees's setTrialStrain restores ecmin and dept, sets eps and returns,
    // leaving sig and e as its last trial set them: `last`, which set_trial
    // replaces only when respond returns (after a commit or a revert it is
    // the committed state, as OpenSees's sig and e are then)
    Concrete02State s = from;
    s.strain          = strain;
    s.stress          = last.stress;
    s.tangent         = last.tangent;
    return s;
  }

  namespace materials
  {
    namespace
    {
      std::unique_ptr<UniaxialLaw>
      make_concrete02(const std::map<std::string, double> &v, const bool opensees_dead_band)
      {
        Concrete02Parameters q;
        q.compression = {v.at("fpc"), v.at("epsc0"), v.at("fpcu"), v.at("epscu")};
        q.lambda      = v.at("lambda");
        q.ft          = v.at("ft");
        q.Ets         = v.at("Ets");
        return std::make_unique<Concrete02>(q, opensees_dead_band);
      }
    } // namespace

    MaterialType
    concrete02()
    {
      return {"Concrete02",
              "Kent-Scott-Park concrete with linear tension softening (OpenSees Concrete02)",
              {{"fpc", NAN, "compressive strength (negative)"},
               {"epsc0", NAN, "strain at fpc (negative)"},
               {"fpcu", NAN, "crushing strength (negative)"},
               {"epscu", NAN, "strain at fpcu (negative)"},
               {"lambda", 0.1, "unloading slope at epscu over the initial slope"},
               {"ft", NAN, "tensile strength"},
               {"Ets", NAN, "tension softening modulus"}},
              [](const std::map<std::string, double> &v) { return make_concrete02(v, false); }};
    }

    std::unique_ptr<UniaxialLaw>
    concrete02_with_dead_band(const std::map<std::string, double> &values)
    {
      return make_concrete02(values, true);
    }
  } // namespace materials
} // namespace poundfe
