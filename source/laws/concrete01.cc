// Concrete01: Kent–Scott–Park concrete without tension, with linear
// unloading and reloading of degraded stiffness (compression negative).
//   Envelope (Kent & Park 1971, Scott, Park & Priestley 1982, as OpenSees):
//     eps >= epsc0:          sigma = fpc (2 eta - eta^2), eta = eps / epsc0,
//                            E = Ec0 (1 - eta), Ec0 = 2 fpc / epsc0;
//     epscu < eps < epsc0:   sigma = fpc + (fpc - fpcu) / (epsc0 - epscu) (eps - epsc0);
//     eps <= epscu:          sigma = fpcu, E = 0.
//   Unloading from the largest compression eps_min reached (Karsan & Jirsa
//   1969): the plastic strain eps_p = epsc0 (0.145 eta^2 + 0.13 eta) for
//   eta = eps_min / epsc0 < 2, epsc0 (0.707 (eta - 2) + 0.834) beyond
//   (eta from min(|eps_min|, |epscu|)). The unloading line joins
//   (eps_min, sigma_env(eps_min)) to (eps_p, 0), except that its slope is
//   at most Ec0: when the line to eps_p would be steeper, it is the line of
//   slope Ec0 and its end strain eps_min - sigma_env / Ec0.
//   Unloading and reloading follow that line between eps_min and its end
//   strain; beyond the end strain (towards tension) the stress is 0; past
//   eps_min the envelope again; positive strains carry no stress.
// Sources: OpenSees Concrete01 (F. Filippou, M. Scott), whose behaviour this
// reproduces, stress, tangent and history alike (under `poundfe opensees`
// its dead band too: a strain within DBL_EPSILON of the committed one keeps
// the committed state, Concrete01::setTrialStrain); D.C. Kent & R. Park (1971),
// J. Struct. Div. ASCE 97(7) 1969; B.D. Scott, R. Park & M.J.N. Priestley
// (1982), ACI J. 79(2) 13; I.D. Karsan & J.O. Jirsa (1969), J. Struct. Div.
// ASCE 95(12) 2543. Theory: doc/theory.md §12.3.
#include <poundfe/laws/concrete01.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace poundfe
{
  KentScottParkEnvelope::KentScottParkEnvelope(const char *material,
                                               const Concrete01Parameters &q)
    : fpc(-std::abs(q.fpc))
    , epsc0(-std::abs(q.epsc0))
    , fpcu(-std::abs(q.fpcu))
    , epscu(-std::abs(q.epscu))
  {
    require_positive(material, "fpc", std::abs(q.fpc));
    require_positive(material, "epsc0", std::abs(q.epsc0));
    if (!(std::isfinite(q.fpcu) && std::abs(q.fpcu) <= std::abs(q.fpc)))
      refuse_parameter(material, "fpcu",
                       "the crushing strength must not exceed fpc in magnitude");
    if (!(std::isfinite(q.epscu) && std::abs(q.epscu) > std::abs(q.epsc0)))
      refuse_parameter(material, "epscu",
                       "the crushing strain must exceed epsc0 in magnitude");
  }

  StressPoint
  KentScottParkEnvelope::at(const double strain) const
  {
    if (strain > epsc0)
      {
        const double eta = strain / epsc0;
        return {fpc * (2 * eta - eta * eta), initial_modulus() * (1 - eta)};
      }
    if (strain > epscu)
      {
        const double slope = (fpc - fpcu) / (epsc0 - epscu);
        return {fpc + slope * (strain - epsc0), slope};
      }
    return {fpcu, 0};
  }

  Concrete01::Concrete01(const Concrete01Parameters &parameters, const bool opensees_dead_band)
    : envelope("Concrete01", parameters)
    , opensees_dead_band(opensees_dead_band)
  {
    reset();
  }

  Concrete01State
  Concrete01::virgin() const
  {
    Concrete01State s;
    s.tangent = s.unload_slope = envelope.initial_modulus();
    return s;
  }

  double
  Concrete01::stored_energy() const
  {
    // a crushed fibre of zero residual strength unloads along a flat line
    return trial.stress == 0 ? 0.0 : 0.5 * trial.stress * trial.stress / trial.unload_slope;
  }

  Concrete01State
  Concrete01::on_envelope(const double strain) const
  {
    Concrete01State   s;
    const StressPoint e = envelope.at(strain);
    s.strain = s.min_strain = strain;
    s.stress                = e.stress;
    s.tangent               = e.tangent;

    const double eta = std::max(strain, envelope.epscu) / envelope.epsc0;
    const double ratio = eta < 2 ? 0.145 * eta * eta + 0.13 * eta : 0.707 * (eta - 2) + 0.834;
    const double Ec0      = envelope.initial_modulus();
    const double to_end   = strain - ratio * envelope.epsc0; // eps_min - eps_p, < 0
    const double to_elastic = e.stress / Ec0;                // the same at slope Ec0
    if (to_end > -std::numeric_limits<double>::epsilon())
      {
        s.end_strain   = ratio * envelope.epsc0;
        s.unload_slope = Ec0;
      }
    else if (to_end <= to_elastic)
      {
        s.end_strain   = strain - to_end;
        s.unload_slope = e.stress / to_end;
      }
    else
      {
        s.end_strain   = strain - to_elastic;
        s.unload_slope = Ec0;
      }
    return s;
  }

  Concrete01State
  Concrete01::respond(const Concrete01State &from, const double strain) const
  {
    if (strain == from.strain || in_dead_band(from, strain))
      return from;
    Concrete01State s = from;
    s.strain          = strain;
    if (strain > 0)
      {
        s.stress = s.tangent = 0;
        return s;
      }
    // the unloading line through the committed point
    const double line = from.stress + from.unload_slope * (strain - from.strain);
    if (strain <= from.strain)
      {
        if (strain <= from.min_strain)
          s = on_envelope(strain);
        else if (strain <= from.end_strain)
          {
            s.stress  = from.unload_slope * (strain - from.end_strain);
            s.tangent = from.unload_slope;
          }
        else
          s.stress = s.tangent = 0;
        if (line > s.stress)
          {
            s.stress  = line;
            s.tangent = from.unload_slope;
          }
      }
    else if (line <= 0)
      {
        s.stress  = line;
        s.tangent = from.unload_slope;
      }
    else
      s.stress = s.tangent = 0;
    return s;
  }

  bool
  Concrete01::in_dead_band(const Concrete01State &from, const double strain) const
  {
    return opensees_dead_band && std::abs(strain - from.strain) < DBL_EPSILON;
  }

  namespace materials
  {
    namespace
    {
      std::unique_ptr<UniaxialLaw>
      make_concrete01(const std::map<std::string, double> &v, const bool opensees_dead_band)
      {
        return std::make_unique<Concrete01>(
          Concrete01Parameters{v.at("fpc"), v.at("epsc0"), v.at("fpcu"), v.at("epscu")},
          opensees_dead_band);
      }
    } // namespace

    MaterialType
    concrete01()
    {
      return {"Concrete01",
              "Kent-Scott-Park concrete, no tension, Karsan-Jirsa unloading (OpenSees Concrete01)",
              {{"fpc", NAN, "compressive strength (negative)"},
               {"epsc0", NAN, "strain at fpc (negative)"},
               {"fpcu", NAN, "crushing strength (negative)"},
               {"epscu", NAN, "strain at fpcu (negative)"}},
              [](const std::map<std::string, double> &v) { return make_concrete01(v, false); }};
    }

    std::unique_ptr<UniaxialLaw>
    concrete01_with_dead_band(const std::map<std::string, double> &values)
    {
      return make_concrete01(values, true);
    }
  } // namespace materials
} // namespace poundfe
