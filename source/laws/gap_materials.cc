// OpenSees's gap materials of pounding scripts and its elastic material, as
// OpenSees 3.8 defines them (SRC/material/uniaxial/), so that a script's
// zero-length gaps give OpenSees's numbers.
//
// Elastic (ElasticMaterial): sigma = E eps + eta eps_dot for eps >= 0 and
//   Eneg eps + eta eps_dot below; tangent E or Eneg, damping tangent eta.
//
// ElasticPPGap (EPPGapMaterial, for Fy >= 0; Fy < 0 mirrors it): with the
//   committed elastic range [e_min, e_max] (virgin: [gap, Fy/E + gap]),
//     eps > e_max:  sigma = Fy + eta E (eps - gap - Fy/E), tangent eta E
//     eps < e_min:  sigma = 0, tangent 0
//     otherwise:    sigma = E (eps - e_min), tangent E.
//   Committing eps > e_max moves the range to [eps - sigma/E, eps]; without
//   `damage`, committing gap < eps < e_min moves it back to
//   [eps, (eps - eta gap)/(1 - eta) + Fy/E]. OpenSees updates the range in
//   commitState; here the trial state carries the range its commit would
//   leave, the same committed history. The virgin state has the stress and
//   tangent at strain 0 and the range [gap, Fy/E + gap] even when strain 0
//   lies outside it (Fy and gap of opposite signs), as OpenSees's constructor.
//
// ImpactMaterial (Muthukumar and DesRoches 2006, Earthquake Engng Struct.
//   Dyn. 35: 811-828; OpenSees ImpactMaterial): gap < 0, Delta_y < 0; with
//   d eps = eps - eps_committed, for eps < gap:
//     loading (d eps < 0):   sigma = max-compression of sigma_c + K1 d eps
//                            and the K2 line K1 Delta_y + K2 (eps - gap - Delta_y)
//     unloading (d eps > 0): sigma = sigma_c + K1 d eps, at most K2 (eps - gap)
//   and sigma = 0 for eps >= gap. With d eps = 0 the committed stress and
//   tangent stay (OpenSees keeps its last trial values, the same after a
//   commit or a revert).
#include <poundfe/laws/gap_materials.h>

#include <cmath>

namespace poundfe
{
  ElasticUniaxial::ElasticUniaxial(const double E, const double eta, const double Eneg)
    : E(E)
    , eta(eta)
    , Eneg(Eneg)
  {}

  bool
  ElasticUniaxial::set_trial(const double strain, const double rate)
  {
    trial_strain = strain;
    trial_rate   = rate;
    return std::isfinite(strain) && std::isfinite(rate);
  }

  double
  ElasticUniaxial::force() const
  {
    return tangent() * trial_strain + eta * trial_rate;
  }

  double
  ElasticUniaxial::stored_energy() const
  {
    return 0.5 * tangent() * trial_strain * trial_strain;
  }

  ElasticPPGap::ElasticPPGap(const double E, const double Fy, const double gap, const double eta,
                             const bool damage)
    : E(E)
    , Fy(Fy)
    , gap(gap)
    , eta(eta)
    , damage(damage)
  {
    require_positive("ElasticPPGap", "E", E);
    require_in("ElasticPPGap", "eta", eta, 0, 1);
    if (!std::isfinite(Fy) || Fy == 0)
      refuse_parameter("ElasticPPGap", "Fy", "must be a finite number other than 0");
    if (!std::isfinite(gap))
      refuse_parameter("ElasticPPGap", "gap", "must be a finite number");
    reset();
  }

  GapMaterialState
  ElasticPPGap::virgin() const
  {
    // OpenSees's constructor takes the stress and tangent at strain 0 but
    // commits no range: with Fy and gap of opposite signs strain 0 is past
    // the yield strain, and the virgin range must stay [gap, Fy/E + gap].
    GapMaterialState s;
    s.min_elastic               = gap;
    s.max_elastic               = Fy / E + gap;
    const GapMaterialState at_0 = respond(s, 0.0);
    s.stress                    = at_0.stress;
    s.tangent                   = at_0.tangent;
    return s;
  }

  GapMaterialState
  ElasticPPGap::respond(const GapMaterialState &from, const double strain) const
  {
    GapMaterialState s = from;
    s.strain           = strain;
    const double sign  = Fy >= 0 ? 1 : -1; // Fy < 0: the mirror image
    if (sign * strain > sign * from.max_elastic)
      {
        s.stress  = Fy + (strain - gap - Fy / E) * eta * E;
        s.tangent = eta * E;
      }
    else if (sign * strain < sign * from.min_elastic)
      s.stress = s.tangent = 0;
    else
      {
        s.stress  = E * (strain - from.min_elastic);
        s.tangent = E;
      }
    // the elastic range that committing this state leaves
    if (sign * strain > sign * from.max_elastic)
      {
        s.max_elastic = strain;
        s.min_elastic = strain - s.stress / E;
      }
    else if (sign * strain < sign * from.min_elastic && sign * strain > sign * gap && !damage)
      {
        s.max_elastic = (strain - eta * gap) / (1 - eta) + Fy / E;
        s.min_elastic = strain;
      }
    return s;
  }

  ImpactMaterial::ImpactMaterial(const double K1, const double K2, const double Delta_y,
                                 const double gap)
    : K1(K1)
    , K2(K2)
    , Delta_y(-std::abs(Delta_y)) // OpenSees makes both negative
    , gap(-std::abs(gap))
  {
    require_positive("ImpactMaterial", "K1", K1);
    require_non_negative("ImpactMaterial", "K2", K2);
    require_positive("ImpactMaterial", "Delta_y", std::abs(Delta_y));
    if (!std::isfinite(gap))
      refuse_parameter("ImpactMaterial", "gap", "must be a finite number");
    reset();
  }

  GapMaterialState
  ImpactMaterial::virgin() const
  {
    GapMaterialState s;
    s.tangent = K1;
    return s;
  }

  GapMaterialState
  ImpactMaterial::respond(const GapMaterialState &from, const double strain) const
  {
    GapMaterialState s = from;
    s.strain           = strain;
    const double step  = strain - from.strain;
    if (strain >= gap)
      s.stress = s.tangent = 0;
    else if (step < 0)
      {
        s.stress          = from.stress + K1 * step;
        s.tangent         = K1;
        const double line = K1 * Delta_y + K2 * (strain - gap - Delta_y);
        if (s.stress < line)
          {
            s.stress  = line;
            s.tangent = K2;
          }
      }
    else if (step > 0)
      {
        s.stress          = from.stress + K1 * step;
        s.tangent         = K1;
        const double line = K2 * (strain - gap);
        if (s.stress > line)
          {
            s.stress  = line;
            s.tangent = K2;
          }
      }
    return s;
  }

  namespace materials
  {
    MaterialType
    elastic()
    {
      return {"Elastic",
              "linear elastic with a dashpot (OpenSees Elastic)",
              {{"E", NAN, "elastic modulus in tension"},
               {"eta", 0, "damping tangent"},
               {"Eneg", INFINITY, "elastic modulus in compression (default: E)"}},
              [](const std::map<std::string, double> &v) -> std::unique_ptr<UniaxialLaw> {
                const double E = v.at("E"), Eneg = v.at("Eneg");
                return std::make_unique<ElasticUniaxial>(E, v.at("eta"), std::isinf(Eneg) ? E : Eneg);
              }};
    }

    MaterialType
    elastic_pp_gap()
    {
      return {"ElasticPPGap",
              "elastic-perfectly-plastic gap (OpenSees ElasticPPGap)",
              {{"E", NAN, "elastic modulus"},
               {"Fy", NAN, "yield force (its sign is the gap's side)"},
               {"gap", NAN, "initial gap"},
               {"eta", 0, "hardening ratio"},
               {"damage", 0, "1: the plastic deformation widens the gap"}},
              [](const std::map<std::string, double> &v) -> std::unique_ptr<UniaxialLaw> {
                return std::make_unique<ElasticPPGap>(v.at("E"), v.at("Fy"), v.at("gap"),
                                                      v.at("eta"), v.at("damage") != 0);
              }};
    }

    MaterialType
    impact_material()
    {
      return {"ImpactMaterial",
              "bilinear compression-only contact (OpenSees ImpactMaterial)",
              {{"K1", NAN, "initial stiffness"},
               {"K2", NAN, "secondary stiffness"},
               {"Delta_y", NAN, "yield deformation (negative)"},
               {"gap", NAN, "initial gap (negative)"}},
              [](const std::map<std::string, double> &v) -> std::unique_ptr<UniaxialLaw> {
                return std::make_unique<ImpactMaterial>(v.at("K1"), v.at("K2"), v.at("Delta_y"),
                                                        v.at("gap"));
              }};
    }
  } // namespace materials
} // namespace poundfe
