#include <poundfe/laws/contact_law.h>
#include <poundfe/laws/hertz.h>
#include <poundfe/laws/hertz_damp.h>
#include <poundfe/laws/jankowski.h>
#include <poundfe/laws/kelvin_voigt.h>
#include <poundfe/laws/linear_contact.h>
#include <poundfe/laws/modified_kelvin_voigt.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace poundfe
{
  ContactLaw::ContactLaw(const ContactLawParameters &parameters)
    : p(parameters)
  {
    reset();
  }

  void
  ContactLaw::reset()
  {
    committed             = State();
    committed.penetration = -p.initial_gap;
    trial                 = committed;
  }

  bool
  ContactLaw::set_trial(const double closure, const double rate)
  {
    trial             = State();
    trial.penetration = closure - p.initial_gap;
    trial.rate        = rate;
    if (!(trial.penetration > 0))
      return std::isfinite(closure) && std::isfinite(rate);
    // The approach velocity of this contact: kept while it lasts; at onset
    // the committed (pre-contact) rate, so it does not depend on the trial.
    double v0 = was_active() ? committed.approach_velocity :
                               (committed.rate > 0 ? committed.rate : rate);
    v0                      = std::max(std::abs(v0), 1e-12);
    trial.approach_velocity = v0;
    const Response r        = respond(trial.penetration, rate, v0);
    if (r.force > 0)
      {
        trial.force     = r.force;
        trial.stiffness = r.stiffness;
        trial.damping   = r.damping;
      }
    return std::isfinite(r.force);
  }

  double
  ContactLaw::stored_energy() const
  {
    return trial.penetration > 0 ? elastic_energy(trial.penetration) : 0.0;
  }

  std::vector<std::string>
  contact_law_names()
  {
    return {"linear", "kelvin-voigt", "modified-kelvin-voigt", "hertz", "hertz-damp", "jankowski"};
  }

  bool
  contact_law_is_damped(const std::string &law)
  {
    return law != "linear" && law != "hertz";
  }

  std::unique_ptr<ContactLaw>
  make_contact_law(const ContactLawParameters &parameters)
  {
    const std::string &law = parameters.law;
    if (law == "linear")
      return std::make_unique<LinearContact>(parameters);
    if (law == "kelvin-voigt")
      return std::make_unique<KelvinVoigt>(parameters);
    if (law == "modified-kelvin-voigt")
      return std::make_unique<ModifiedKelvinVoigt>(parameters);
    if (law == "hertz")
      return std::make_unique<Hertz>(parameters);
    if (law == "hertz-damp")
      return std::make_unique<HertzDamp>(parameters);
    if (law == "jankowski")
      return std::make_unique<Jankowski>(parameters);
    throw std::invalid_argument("unknown contact law '" + law + "'");
  }

  double
  damping_from_restitution_formula(const std::string &law, const double e,
                                   const std::string &variant)
  {
    if (law == "kelvin-voigt")
      return -std::log(e) / std::sqrt(M_PI * M_PI + std::log(e) * std::log(e));
    if (law == "modified-kelvin-voigt")
      return (1 - e * e) / (e * (e * (M_PI - 2) + 2));
    if (law == "hertz-damp")
      return variant == "ye-li-zhu" ? 8 * (1 - e) / (5 * e) : 3 * (1 - e * e) / 4;
    if (law == "jankowski")
      return 9 * std::sqrt(5.0) * (1 - e * e) / (2 * e * (e * (9 * M_PI - 16) + 16));
    return 0;
  }

  double
  simulate_restitution(const ContactLawParameters &parameters, const double v0)
  {
    ContactLawParameters q = parameters;
    q.initial_gap          = 0;
    auto         law       = make_contact_law(q);
    const double m         = q.effective_mass;
    // Duration scale of the elastic impact (linear: pi sqrt(m/k); Hertz:
    // 2.94 delta_max / v0), resolved by 20000 steps.
    const bool   linear = q.law == "linear" || q.law == "kelvin-voigt" ||
                        q.law == "modified-kelvin-voigt";
    const double duration =
      linear ? M_PI * std::sqrt(m / q.stiffness) :
               2.9432 * std::pow(1.25 * m * v0 * v0 / q.stiffness, 0.4) / v0;
    const double h = duration / 20000;
    // approach from just outside the wall: delta = 0, rate v0
    law->set_trial(0, v0);
    law->commit();
    double x = 0, v = v0;
    auto   acceleration = [&](const double xs, const double vs) {
      law->set_trial(xs, vs);
      return -law->force() / m;
    };
    for (unsigned long i = 0; i < 200000; ++i)
      {
        const double k1x = v, k1v = acceleration(x, v);
        const double k2x = v + 0.5 * h * k1v, k2v = acceleration(x + 0.5 * h * k1x, k2x);
        const double k3x = v + 0.5 * h * k2v, k3v = acceleration(x + 0.5 * h * k2x, k3x);
        const double k4x = v + h * k3v, k4v = acceleration(x + h * k3x, k4x);
        const double x_new = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        const double v_new = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        law->set_trial(x_new, v_new);
        law->commit();
        // separated: back at the wall, or moving away with no force left
        if (i > 0 && v_new < 0 && (x_new <= 0 || law->force() <= 0))
          return -v_new / v0;
        x = x_new;
        v = v_new;
      }
    return std::numeric_limits<double>::quiet_NaN();
  }

  double
  calibrate_damping(ContactLawParameters parameters, const double e, const double v0)
  {
    auto restitution = [&](const double damping) {
      parameters.damping = damping;
      return simulate_restitution(parameters, v0);
    };
    double low = 0, high = 0.5;
    while (restitution(high) > e && high < 1e6)
      {
        low = high;
        high *= 2;
      }
    for (unsigned int it = 0; it < 200 && high - low > 1e-12 * high; ++it)
      {
        const double middle = 0.5 * (low + high);
        const double value  = restitution(middle);
        (value > e ? low : high) = middle;
        if (std::abs(value - e) < 1e-8)
          return middle;
      }
    return 0.5 * (low + high);
  }
} // namespace poundfe
