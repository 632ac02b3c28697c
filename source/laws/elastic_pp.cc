// ElasticPP: elastic-perfectly-plastic with an initial strain.
//   sigma_trial = E (eps - eps0 - eps_p);
//   elastic while -E epsyN' < sigma_trial < E epsyP (epsyN' = |epsyN|; a
//   given epsyN of -0 is no compressive strength, +0 not given, -epsyP):
//     sigma = sigma_trial, tangent E;
//   otherwise sigma = E epsyP or -E |epsyN|, tangent 0, and the plastic
//   strain eps_p grows by the excess (sigma_trial - sigma) / E.
//   As OpenSees, a trial exactly on the yield surface counts as plastic
//   (the elastic test is f <= -E DBL_EPSILON).
// Sources: OpenSees ElasticPPMaterial (F. Filippou, M. Scott), whose
// behaviour this reproduces (its plastic strain, updated in commitState,
// is part of the trial state here: the same committed history). Theory:
// doc/theory.md §12.5.
#include <poundfe/laws/elastic_pp.h>

#include <cmath>
#include <limits>

namespace poundfe
{
  ElasticPP::ElasticPP(const ElasticPPParameters &parameters)
    : p(parameters)
  {
    require_positive("ElasticPP", "E", p.E);
    require_positive("ElasticPP", "epsyP", p.epsyP);
    if (p.epsyN == 0 && !std::signbit(p.epsyN)) // not given: symmetric, as OpenSees
      p.epsyN = -p.epsyP;
    // -0: given as zero, no compressive strength (OpenSees's ElasticPP of a
    // given epsyN = 0)
    if (p.epsyN != 0)
      require_positive("ElasticPP", "epsyN", std::abs(p.epsyN));
    if (!std::isfinite(p.eps0))
      refuse_parameter("ElasticPP", "eps0", "must be a finite number");
    p.epsyN = -std::abs(p.epsyN);
    reset();
  }

  ElasticPPState
  ElasticPP::virgin() const
  {
    ElasticPPState s;
    s.tangent = p.E;
    return s;
  }

  ElasticPPState
  ElasticPP::respond(const ElasticPPState &from, const double strain) const
  {
    ElasticPPState s = from;
    s.strain         = strain;
    const double trial_stress = p.E * (strain - p.eps0 - from.plastic_strain);
    const double yield        = trial_stress >= 0 ? p.E * p.epsyP : -p.E * p.epsyN;
    const double excess       = std::abs(trial_stress) - yield;
    if (excess <= -p.E * std::numeric_limits<double>::epsilon())
      {
        s.stress  = trial_stress;
        s.tangent = p.E;
      }
    else
      {
        const double sign = trial_stress > 0 ? 1 : -1;
        s.stress          = sign * yield;
        s.tangent         = 0;
        s.plastic_strain += sign * excess / p.E;
      }
    return s;
  }

  namespace materials
  {
    MaterialType
    elastic_pp()
    {
      return {"ElasticPP",
              "elastic-perfectly-plastic (OpenSees ElasticPP)",
              {{"E", NAN, "elastic modulus"},
               {"epsyP", NAN, "yield strain in tension"},
               {"epsyN", 0, "yield strain in compression (0: -epsyP)"},
               {"eps0", 0, "initial strain"}},
              [](const std::map<std::string, double> &v) -> std::unique_ptr<UniaxialLaw> {
                return std::make_unique<ElasticPP>(
                  ElasticPPParameters{v.at("E"), v.at("epsyP"), v.at("epsyN"), v.at("eps0")});
              }};
    }
  } // namespace materials
} // namespace poundfe
