// Steel01: bilinear steel with kinematic and optional isotropic hardening.
//   Elastic modulus E0, hardening modulus Esh = b E0, eps_y = fy / E0.
//   Trial stress from the committed (eps_n, sigma_n), trial eps:
//     sigma = max( Esh eps - (1 - b) fy s_n,  min( Esh eps + (1 - b) fy s_p,
//                                                  sigma_n + E0 (eps - eps_n) ) )
//   i.e. the elastic predictor clipped by the two hardening asymptotes
//   (kinematic hardening: the elastic range stays 2 fy (1 - b) wide, moved
//   along the line Esh eps). Tangent E0 on the elastic predictor, Esh on an
//   asymptote.
//   Isotropic hardening (Filippou et al. 1983) moves the asymptotes out:
//   at a reversal from loading to unloading,
//     s_n = 1 + a1 ((eps_max - eps_min) / (2 a2 eps_y))^0.8,
//   from unloading to loading s_p = 1 + a3 (... / (2 a4 eps_y))^0.8, with
//   eps_max, eps_min the largest and smallest strains at reversals; the
//   shift acts from the next step on, as in OpenSees.
// Sources: OpenSees Steel01 (F. Filippou), whose behaviour this reproduces,
// stress, tangent and history alike; F.C. Filippou, E.P. Popov & V.V. Bertero
// (1983), Effects of bond deterioration on hysteretic behavior of reinforced
// concrete joints, EERC 83/19. Theory: doc/theory.md §12.1.
#include <poundfe/laws/steel01.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace poundfe
{
  Steel01::Steel01(const Steel01Parameters &parameters)
    : p(parameters)
  {
    require_positive("Steel01", "fy", p.fy);
    require_positive("Steel01", "E0", p.E0);
    require_in("Steel01", "b", p.b, 0, 1);
    require_non_negative("Steel01", "a1", p.a1);
    require_positive("Steel01", "a2", p.a2);
    require_non_negative("Steel01", "a3", p.a3);
    require_positive("Steel01", "a4", p.a4);
    reset();
  }

  Steel01State
  Steel01::virgin() const
  {
    Steel01State s;
    s.tangent = p.E0;
    return s;
  }

  Steel01State
  Steel01::respond(const Steel01State &from, const double strain) const
  {
    // OpenSees's dead band: a change of at most DBL_EPSILON keeps the
    // committed state, tangent included (Steel01::setTrialStrain).
    const double d_strain = strain - from.strain;
    if (std::abs(d_strain) <= DBL_EPSILON)
      return from;
    Steel01State to = from;
    to.strain       = strain;

    const double hardening = p.b * p.E0;
    const double range     = p.fy * (1 - p.b);
    const double elastic   = from.stress + p.E0 * d_strain;
    to.stress = std::max(hardening * strain - range * from.shift_n,
                         std::min(hardening * strain + range * from.shift_p, elastic));
    to.tangent = (to.stress == elastic) ? p.E0 : hardening;

    // A reversal updates the reversal strains and the isotropic shifts
    // (used from the next step on).
    const double eps_y = p.fy / p.E0;
    if (to.loading == 0)
      to.loading = d_strain > 0 ? 1 : -1;
    if (to.loading == 1 && d_strain < 0)
      {
        to.loading    = -1;
        to.max_strain = std::max(to.max_strain, from.strain);
        to.shift_n = 1 + p.a1 * std::pow((to.max_strain - to.min_strain) / (2 * p.a2 * eps_y), 0.8);
      }
    else if (to.loading == -1 && d_strain > 0)
      {
        to.loading    = 1;
        to.min_strain = std::min(to.min_strain, from.strain);
        to.shift_p = 1 + p.a3 * std::pow((to.max_strain - to.min_strain) / (2 * p.a4 * eps_y), 0.8);
      }
    return to;
  }

  namespace materials
  {
    MaterialType
    steel01()
    {
      return {"Steel01",
              "bilinear steel, kinematic and isotropic hardening (OpenSees Steel01)",
              {{"fy", NAN, "yield stress"},
               {"E0", NAN, "initial elastic modulus"},
               {"b", NAN, "hardening ratio Esh/E0"},
               {"a1", 0, "isotropic hardening in compression"},
               {"a2", 1, "its plastic-excursion scale"},
               {"a3", 0, "isotropic hardening in tension"},
               {"a4", 1, "its plastic-excursion scale"}},
              [](const std::map<std::string, double> &v) -> std::unique_ptr<UniaxialLaw> {
                return std::make_unique<Steel01>(Steel01Parameters{
                  v.at("fy"), v.at("E0"), v.at("b"), v.at("a1"), v.at("a2"), v.at("a3"),
                  v.at("a4")});
              }};
    }
  } // namespace materials
} // namespace poundfe
