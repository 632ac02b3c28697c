// Hysteretic: trilinear envelopes with pinching, damage and degraded
// unloading stiffness, as OpenSees's Hysteretic material.
//   Envelope in each direction: (0,0)-(e1,s1)-(e2,s2)-(e3,s3), then the
//   last segment continued if it rises, else s3 held. Given two points
//   only (by name, without s3, e3), the second becomes the third and the
//   middle one lies halfway, as OpenSees's two-point form.
//   Unloading modulus E_u k with E_u the largest envelope slope of that
//   direction and k = (mu)^-beta, mu = eps_max / e1 (1 when mu < 1).
//   On unloading to zero stress the strain of zero stress is remembered;
//   reloading then heads for the largest excursion of the other side,
//   eps_max (1 + d), grown by damage
//     d = damage1 (mu - 1) + damage2 E / E_A
//   (E the dissipated energy less the elastic part recovered, E_A the area
//   of the two envelopes to e3), through the pinching point
//     eps_ch = eps_rel + pinchX (eps_max - (1 - pinchY) s(eps_max) / (E_u k) - eps_rel),
//     sigma_ch = pinchY s(eps_max):
//   the stress is the smaller (in the loading direction) of the unloading
//   line from the committed point and the broken line eps_rel -> pinching
//   point -> (eps_max, s(eps_max)).
//   A negative increment is the positive one of the mirrored state.
//   Tangents of zero-stress branches are 1e-9 of a modulus, as in OpenSees.
//   Under `poundfe opensees`, OpenSees 3.8's dead band (in_dead_band): a
//   strain change below DBL_EPSILON from the committed strain keeps the
//   committed history with the last trial's stress and tangent (the tangent
//   also across a revert, as OpenSees's revertToLastCommit leaves it).
// Sources: OpenSees HystereticMaterial (M. Scott, F. Filippou), whose
// behaviour this reproduces, stress, tangent and history alike; its rules go
// back to Y.J. Park, A.M. Reinhorn & S.K. Kunnath (1987), IDARC, NCEER-87-0008.
// Theory: doc/theory.md §12.6.
#include <poundfe/laws/hysteretic.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace poundfe
{
  namespace
  {
    constexpr double hysteretic_infinite_strain = 1e16; // OpenSees's POS_INF_STRAIN

    double slope1(const HystereticEnvelope &e) { return e.s1 / e.e1; }
    double slope2(const HystereticEnvelope &e) { return (e.s2 - e.s1) / (e.e2 - e.e1); }
    double slope3(const HystereticEnvelope &e) { return (e.s3 - e.s2) / (e.e3 - e.e2); }

    double
    hysteretic_envelope_stress(const HystereticEnvelope &e, const double x)
    {
      if (x <= 0)
        return 0;
      if (x <= e.e1)
        return slope1(e) * x;
      if (x <= e.e2)
        return e.s1 + slope2(e) * (x - e.e1);
      if (x <= e.e3 || slope3(e) > 0)
        return e.s2 + slope3(e) * (x - e.e2);
      return e.s3;
    }

    double
    hysteretic_envelope_tangent(const HystereticEnvelope &e, const double x)
    {
      if (x < 0)
        return slope1(e) * 1e-9;
      if (x <= e.e1)
        return slope1(e);
      if (x <= e.e2)
        return slope2(e);
      if (x <= e.e3 || slope3(e) > 0)
        return slope3(e);
      return slope1(e) * 1e-9;
    }

    /// Where a descending envelope beyond x reaches zero stress; infinite
    /// when it does not.
    double
    hysteretic_envelope_limit(const HystereticEnvelope &e, const double x)
    {
      double limit = hysteretic_infinite_strain;
      if (x <= e.e1)
        return limit;
      if (x <= e.e2 && slope2(e) < 0)
        limit = e.e1 - e.s1 / slope2(e);
      if (x > e.e2 && slope3(e) < 0)
        limit = e.e2 - e.s2 / slope3(e);
      if (limit == hysteretic_infinite_strain || hysteretic_envelope_stress(e, limit) > 0)
        return hysteretic_infinite_strain;
      return limit;
    }

    HystereticEnvelope
    hysteretic_flipped(const HystereticEnvelope &e)
    {
      return {-e.s1, -e.e1, -e.s2, -e.e2, -e.s3, -e.e3};
    }

    HystereticState
    hysteretic_mirror(HystereticState s)
    {
      s.strain  = -s.strain;
      s.stress  = -s.stress;
      s.max_strain = -s.max_strain;
      s.min_strain = -s.min_strain;
      std::swap(s.max_strain, s.min_strain);
      s.zero_p = -s.zero_p;
      s.zero_n = -s.zero_n;
      std::swap(s.zero_p, s.zero_n);
      s.loading = s.loading == 0 ? 0 : 3 - s.loading;
      return s;
    }

    double
    hysteretic_area(const HystereticEnvelope &e)
    {
      return 0.5 * (e.e1 * e.s1 + (e.e2 - e.e1) * (e.s2 + e.s1) + (e.e3 - e.e2) * (e.s3 + e.s2));
    }

    double
    hysteretic_unloading_modulus(const HystereticEnvelope &e)
    {
      return std::max({slope1(e), slope2(e), slope3(e)});
    }

    void
    check_hysteretic_envelope(const HystereticEnvelope &e, const char *sign)
    {
      const std::string s(sign);
      require_positive("Hysteretic", ("s1" + s).c_str(), std::abs(e.s1));
      require_positive("Hysteretic", ("e1" + s).c_str(), e.e1);
      if (!(e.e2 > e.e1))
        refuse_parameter("Hysteretic", ("e2" + s).c_str(), "must exceed e1" + s + " in magnitude");
      if (!(e.e3 > e.e2))
        refuse_parameter("Hysteretic", ("e3" + s).c_str(), "must exceed e2" + s + " in magnitude");
      if (!(e.s1 > 0))
        refuse_parameter("Hysteretic", ("s1" + s).c_str(),
                         "must have the sign of its direction (s1p > 0, s1n < 0)");
      if (!std::isfinite(e.s2 + e.s3))
        refuse_parameter("Hysteretic", ("s2" + s).c_str(), "must be a finite number");
    }
  } // namespace

  Hysteretic::Hysteretic(const HystereticParameters &parameters, const bool opensees_dead_band)
    : p(parameters)
    , opensees_dead_band(opensees_dead_band)
  {
    const HystereticEnvelope negative = hysteretic_flipped(p.negative);
    check_hysteretic_envelope(p.positive, "p");
    check_hysteretic_envelope(negative, "n");
    for (const auto &[name, value] : {std::pair{"pinchX", p.pinchX}, std::pair{"pinchY", p.pinchY}})
      if (!(value >= 0 && value <= 1))
        refuse_parameter("Hysteretic", name, "must lie in [0, 1]");
    require_non_negative("Hysteretic", "damage1", p.damage1);
    require_non_negative("Hysteretic", "damage2", p.damage2);
    require_non_negative("Hysteretic", "beta", p.beta);
    const double Eup = hysteretic_unloading_modulus(p.positive);
    const double Eun = hysteretic_unloading_modulus(negative);
    forward          = {p.positive, negative, Eup, Eun};
    mirrored         = {negative, p.positive, Eun, Eup};
    energy_A         = hysteretic_area(p.positive) + hysteretic_area(negative);
    reset();
  }

  HystereticState
  Hysteretic::virgin() const
  {
    HystereticState s;
    s.tangent        = initial_stiffness();
    opensees_tangent = s.tangent; // revertToStart sets Ttangent = E1p
    return s;
  }

  HystereticState
  Hysteretic::respond(const HystereticState &from, const double strain) const
  {
    const double    d_strain = strain - from.strain;
    HystereticState s;
    if (in_dead_band(from, strain, s))
      return s;
    if ((from.loading == 0 && strain == 0) || d_strain == 0)
      return from;
    s                = respond_outside_band(from, strain);
    opensees_tangent = s.tangent;
    return s;
  }

  HystereticState
  Hysteretic::respond_outside_band(const HystereticState &from, const double strain) const
  {
    const double    d_strain = strain - from.strain;
    HystereticState s;
    if (strain >= from.max_strain) // on the positive envelope
      {
        s            = from;
        s.max_strain = strain;
        s.stress     = hysteretic_envelope_stress(p.positive, strain);
        s.tangent    = hysteretic_envelope_tangent(p.positive, strain);
        s.loading    = 1;
      }
    else if (strain <= from.min_strain) // on the negative envelope
      {
        s            = from;
        s.min_strain = strain;
        s.stress     = -hysteretic_envelope_stress(forward.behind, -strain);
        s.tangent    = hysteretic_envelope_tangent(forward.behind, -strain);
        s.loading    = 2;
      }
    else if (d_strain > 0)
      s = positive_increment(from, strain, forward);
    else
      s = hysteretic_mirror(positive_increment(hysteretic_mirror(from), -strain, mirrored));
    s.strain = strain;
    s.energy = from.energy + 0.5 * (from.stress + s.stress) * d_strain;
    return s;
  }

  bool
  Hysteretic::in_dead_band(const HystereticState &from, const double strain,
                           HystereticState &s) const
  {
    if (!opensees_dead_band)
      return false;
    // this->trial is OpenSees's T* (set_trial replaces it only when respond
    // returns; after a commit or a revert it is the committed state), except
    // for the tangent: OpenSees's revertToLastCommit leaves Ttangent as the
    // last trial made it, and so does its band (opensees_tangent)
    if (trial.loading == 0 && strain == 0)
      {
        s         = trial;
        s.tangent = opensees_tangent;
        return true;
      }
    if (!(std::abs(strain - from.strain) < DBL_EPSILON))
      return false;
    s         = from;
    s.strain  = strain;
    s.stress  = trial.stress;
    s.tangent = opensees_tangent;
    s.loading = trial.loading;
    return true;
  }

  HystereticState
  Hysteretic::positive_increment(const HystereticState &from, const double strain,
                                 const Sides &sides) const
  {
    const HystereticEnvelope &ahead = sides.ahead, &behind = sides.behind;
    // unloading stiffness factors from each side's largest excursion
    const double k_behind = std::max(1.0, std::pow(-from.min_strain / behind.e1, p.beta));
    const double k_ahead  = std::max(1.0, std::pow(from.max_strain / ahead.e1, p.beta));
    const double E_behind = sides.E_behind / k_behind, E_ahead = sides.E_ahead / k_ahead;
    const double d_strain = strain - from.strain;

    HystereticState s = from;
    if (from.loading == 2 && from.stress <= 0) // a reversal: zero stress and damage
      {
        s.zero_n            = from.strain - from.stress / E_behind;
        const double energy = from.energy - 0.5 * from.stress / E_behind * from.stress;
        double       damage = 0;
        if (-from.min_strain > behind.e1)
          damage = p.damage2 * energy / energy_A +
                   p.damage1 * (-from.min_strain - behind.e1) / behind.e1;
        s.max_strain = from.max_strain * (1 + damage);
      }
    s.loading    = 1;
    s.max_strain = std::max(std::min(s.max_strain, hysteretic_infinite_strain), ahead.e1);

    const double max_stress = hysteretic_envelope_stress(ahead, s.max_strain);
    const double released =
      std::max(-hysteretic_envelope_limit(behind, -from.min_strain), s.zero_n);
    const double target  = s.max_strain - (1 - p.pinchY) * max_stress / E_ahead;
    const double pinched = released + (target - released) * p.pinchX;
    if (strain < s.zero_n) // still unloading the other side
      {
        s.stress  = from.stress + E_behind * d_strain;
        s.tangent = E_behind;
        if (s.stress >= 0)
          {
            s.stress  = 0;
            s.tangent = sides.E_behind * 1e-9;
          }
        return s;
      }
    if (strain < pinched && strain <= released) // slack: no stress yet
      {
        s.stress  = 0;
        s.tangent = sides.E_ahead * 1e-9;
        return s;
      }
    if (strain < pinched) // towards the pinching point
      {
        s.tangent = max_stress * p.pinchY / (pinched - released);
        s.stress  = (strain - released) * s.tangent;
      }
    else // from the pinching point to the largest excursion
      {
        s.tangent = (1 - p.pinchY) * max_stress / (s.max_strain - pinched);
        s.stress  = p.pinchY * max_stress + (strain - pinched) * s.tangent;
      }
    // but never above the unloading line from the committed point
    const double unloading = from.stress + E_ahead * d_strain;
    if (unloading < s.stress)
      {
        s.stress  = unloading;
        s.tangent = E_ahead;
      }
    return s;
  }

  HystereticEnvelope
  hysteretic_envelope(const std::map<std::string, double> &values, const std::string &side)
  {
    const auto at = [&](const char *name) {
      const auto it = values.find(name + side);
      return it == values.end() ? 0.0 : it->second;
    };
    const double s1 = at("s1"), e1 = at("e1"), s2 = at("s2"), e2 = at("e2");
    const double s3 = at("s3"), e3 = at("e3");
    if (s3 == 0 && e3 == 0) // two points: OpenSees puts the middle one halfway
      return HystereticEnvelope{s1, e1, 0.5 * (s1 + s2), 0.5 * (e1 + e2), s2, e2};
    return HystereticEnvelope{s1, e1, s2, e2, s3, e3};
  }

  namespace materials
  {
    namespace
    {
      std::unique_ptr<UniaxialLaw>
      make_hysteretic(const std::map<std::string, double> &v, const bool opensees_dead_band)
      {
        HystereticParameters q;
        q.positive = hysteretic_envelope(v, "p");
        q.negative = hysteretic_envelope(v, "n");
        q.pinchX   = v.at("pinchX");
        q.pinchY   = v.at("pinchY");
        q.damage1  = v.at("damage1");
        q.damage2  = v.at("damage2");
        q.beta     = v.at("beta");
        return std::make_unique<Hysteretic>(q, opensees_dead_band);
      }
    } // namespace

    MaterialType
    hysteretic()
    {
      std::vector<MaterialParameter> parameters;
      for (const char *side : {"p", "n"})
        for (const char *point : {"1", "2", "3"})
          for (const char *what : {"s", "e"})
            parameters.push_back({std::string(what) + point + side, *point == '3' ? 0.0 : NAN,
                                  std::string(*what == 's' ? "stress" : "strain") + " of point " +
                                    point + " of the " + (*side == 'p' ? "positive" : "negative") +
                                    " envelope" + (*point == '3' ? " (none: bilinear)" : "")});
      parameters.push_back({"pinchX", 1, "pinching in strain"});
      parameters.push_back({"pinchY", 1, "pinching in stress"});
      parameters.push_back({"damage1", 0, "damage from ductility"});
      parameters.push_back({"damage2", 0, "damage from energy"});
      parameters.push_back({"beta", 0, "unloading stiffness exponent"});
      return {"Hysteretic",
              "trilinear envelopes with pinching and damage (OpenSees Hysteretic)",
              parameters,
              [](const std::map<std::string, double> &v) { return make_hysteretic(v, false); }};
    }

    std::unique_ptr<UniaxialLaw>
    hysteretic_with_dead_band(const std::map<std::string, double> &values)
    {
      return make_hysteretic(values, true);
    }
  } // namespace materials
} // namespace poundfe
