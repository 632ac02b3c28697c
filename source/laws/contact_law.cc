#include <poundfe/base/numbers.h>
#include <poundfe/laws/contact_law.h>

#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <tuple>

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
    trial.closure     = closure;
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

  std::string
  ContactLaw::failure() const
  {
    const std::string state = "closure " + number_text(trial.closure) + " m (initial gap " +
                              number_text(p.initial_gap) + " m), closing rate " +
                              number_text(trial.rate) + " m/s";
    if (!std::isfinite(trial.closure) || !std::isfinite(trial.rate))
      return "the " + p.law + " contact's deformation is not finite: " + state;
    const Response r = respond(trial.penetration, trial.rate, trial.approach_velocity);
    return "the " + p.law + " contact force is not finite (" + number_text(r.force) +
           " N) at " + state + ", penetration " + number_text(trial.penetration) +
           " m: the stiffness " + number_text(p.stiffness) + " or the motion is out of range";
  }

  double
  ContactLaw::stored_energy() const
  {
    return trial.penetration > 0 ? elastic_energy(trial.penetration) : 0.0;
  }

  namespace
  {
    double
    impact_duration(const ContactLawParameters &p, const bool linear, const double v0)
    {
      const double m = p.effective_mass;
      if (linear)
        return M_PI * std::sqrt(m / p.stiffness);
      return v0 > 0 ? 2.9432 * std::pow(1.25 * m * v0 * v0 / p.stiffness, 0.4) / v0 : 0.0;
    }
  } // namespace

  double
  elastic_impact_duration(const ContactLawParameters &p, const double v0)
  {
    return impact_duration(p, contact_law_type(p.law).linear_impact_duration, v0);
  }

  double
  ContactLaw::contact_duration(const double closing_rate) const
  {
    if (linear_impact < 0) // looked up once: the registry search compares names
      linear_impact = contact_law_type(p.law).linear_impact_duration;
    return impact_duration(p, linear_impact > 0,
                           was_active() ? committed.approach_velocity : closing_rate);
  }

  double
  simulate_restitution(const ContactLawParameters &parameters, const double v0)
  {
    ContactLawParameters q = parameters;
    q.initial_gap          = 0;
    auto         law       = make_contact_law(q);
    const double m         = q.effective_mass;
    // The elastic impact, resolved by 20000 steps.
    const double h = elastic_impact_duration(q, v0) / 20000;
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

  namespace
  {
    /// The bisection of calibrate_damping.
    double
    bisect_damping(ContactLawParameters parameters, const double e, const double v0)
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
  } // namespace

  double
  calibrate_damping(const ContactLawParameters parameters, const double e, const double v0)
  {
    // A function of the law, k, m_e, e and v0 alone that costs tens of
    // fine impacts (~0.1 s): remembered for the process, so that a loop of
    // runs (Python, a sweep) preparing the same contact law calibrates it
    // once. The same arguments give the same bits either way.
    if (!std::isfinite(parameters.stiffness + parameters.effective_mass + e + v0))
      return bisect_damping(parameters, e, v0);
    using Key = std::tuple<std::string, double, double, double, double>;
    static std::mutex           mutex;
    static std::map<Key, double> known;
    const Key key{parameters.law, parameters.stiffness, parameters.effective_mass, e, v0};
    {
      const std::lock_guard<std::mutex> lock(mutex);
      if (const auto found = known.find(key); found != known.end())
        return found->second;
    }
    const double damping = bisect_damping(parameters, e, v0);
    const std::lock_guard<std::mutex> lock(mutex);
    known.emplace(key, damping);
    return damping;
  }
} // namespace poundfe
