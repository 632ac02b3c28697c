// The laws of links between buildings; equations and sources in
// include/poundfe/laws/link_laws.h and doc/theory.md §1.14.
#include <poundfe/base/numbers.h>
#include <poundfe/laws/link_laws.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace poundfe
{
  std::string
  link_kind_name(const LinkKind kind)
  {
    switch (kind)
      {
        case LinkKind::viscous:
          return "viscous";
        case LinkKind::kelvin_voigt:
          return "kelvin-voigt";
        case LinkKind::maxwell:
          return "maxwell";
        case LinkKind::elastic_plastic:
          return "elastic-plastic";
      }
    throw std::logic_error("link_kind_name: unknown kind");
  }

  DamperResponse
  damper_response(const LinkLawParameters &p, const double v)
  {
    if (p.exponent == 1)
      return {p.damping * v, p.damping};
    const double s2 = v * v + p.regularization_velocity * p.regularization_velocity;
    const double power = std::pow(s2, 0.5 * (p.exponent - 1)); // (v^2 + eps^2)^((a-1)/2)
    return {p.damping * v * power,
            p.damping * power * (p.exponent * v * v + s2 - v * v) / s2};
  }

  namespace
  {
    /// Viscous damper and Kelvin-Voigt link: F = k d + F_damper(v); history-free.
    class ParallelLink final : public UniaxialLaw
    {
    public:
      explicit ParallelLink(const LinkLawParameters &p)
        : p(p)
      {
        reset();
      }
      bool set_trial(const double d, const double v) override
      {
        deformation         = d;
        const DamperResponse r = damper_response(p, v);
        trial_force         = p.stiffness * d + r.force;
        trial_damping       = r.damping_tangent;
        return std::isfinite(trial_force) && std::isfinite(trial_damping);
      }
      double force() const override { return trial_force; }
      double tangent() const override { return p.stiffness; }
      double damping_tangent() const override { return trial_damping; }
      double stored_energy() const override { return 0.5 * p.stiffness * deformation * deformation; }
      double initial_stiffness() const override { return p.stiffness; }
      void   commit() override { committed = {{deformation, trial_force, trial_damping}}; }
      void   revert() override
      {
        deformation   = committed[0];
        trial_force   = committed[1];
        trial_damping = committed[2];
      }
      void reset() override
      {
        committed = {{0, 0, damper_response(p, 0).damping_tangent}};
        revert();
      }
      std::string failure() const override
      {
        return "the " + link_kind_name(p.kind) + " link's force is not finite at a deformation of " +
               number_text(deformation) + " m";
      }

    private:
      LinkLawParameters     p;
      double                deformation = 0, trial_force = 0, trial_damping = 0;
      std::array<double, 3> committed{{0, 0, 0}};
    };

    /// Maxwell link: spring k in series with a linear dashpot c; the
    /// dashpot stroke z is the internal variable (trapezoidal rule).
    class MaxwellLink final : public UniaxialLaw
    {
    public:
      explicit MaxwellLink(const LinkLawParameters &p)
        : p(p)
      {
        reset();
      }
      void set_trial_time(const double time) override { trial.time = time; }
      bool set_trial(const double d, const double /*rate*/) override
      {
        const double a = p.stiffness * (trial.time - committed.time) / (2 * p.damping);
        trial.deformation = d;
        trial.force  = (p.stiffness * (d - committed.stroke) - a * committed.force) / (1 + a);
        trial.stroke = d - trial.force / p.stiffness;
        trial_tangent = p.stiffness / (1 + a);
        return std::isfinite(trial.force);
      }
      double force() const override { return trial.force; }
      double tangent() const override { return trial_tangent; }
      double stored_energy() const override
      {
        return 0.5 * trial.force * trial.force / p.stiffness;
      }
      /// The dashpot's stroke z.
      double history_variable() const override { return trial.stroke; }
      double initial_stiffness() const override { return p.stiffness; }
      void   commit() override { committed = trial; }
      void   revert() override
      {
        const double time = trial.time;
        trial             = committed;
        trial.time        = time; // the step about to be retried keeps its end
      }
      void reset() override
      {
        committed     = State();
        trial         = committed;
        trial_tangent = p.stiffness;
      }
      std::string failure() const override
      {
        return "the Maxwell link's force is not finite at a deformation of " +
               number_text(trial.deformation) + " m";
      }

    private:
      struct State
      {
        double time = 0, deformation = 0, stroke = 0, force = 0;
      };
      LinkLawParameters p;
      State             committed, trial;
      double            trial_tangent = 0;
    };

    /// Elastic-plastic link: bilinear, kinematic hardening H = r k/(1 - r)
    /// (so the post-yield stiffness is k H/(k + H) = r k), return mapping.
    class ElasticPlasticLink final : public UniaxialLaw
    {
    public:
      explicit ElasticPlasticLink(const LinkLawParameters &p)
        : p(p)
        , hardening_modulus(p.stiffness * p.hardening / (1 - p.hardening))
      {
        reset();
      }
      bool set_trial(const double d, const double /*rate*/) override
      {
        trial             = committed;
        trial.deformation = d;
        trial.force       = p.stiffness * (d - committed.plastic);
        trial_tangent     = p.stiffness;
        const double xi   = trial.force - committed.back_force;
        const double f    = std::abs(xi) - p.yield_force;
        if (f > 0)
          {
            const double gamma = f / (p.stiffness + hardening_modulus);
            const double sign  = xi > 0 ? 1.0 : -1.0;
            trial.plastic += gamma * sign;
            trial.back_force += hardening_modulus * gamma * sign;
            trial.force -= p.stiffness * gamma * sign;
            trial_tangent = p.stiffness * hardening_modulus / (p.stiffness + hardening_modulus);
          }
        return std::isfinite(trial.force);
      }
      double force() const override { return trial.force; }
      double tangent() const override { return trial_tangent; }
      /// Elastic energy F^2/(2k) and the hardening's q^2/(2H).
      double stored_energy() const override
      {
        const double hardening_energy =
          hardening_modulus > 0 ? 0.5 * trial.back_force * trial.back_force / hardening_modulus :
                                  0.0;
        return 0.5 * trial.force * trial.force / p.stiffness + hardening_energy;
      }
      double history_variable() const override { return trial.plastic; }
      double yield_deformation() const override { return p.yield_force / p.stiffness; }
      double initial_stiffness() const override { return p.stiffness; }
      void   commit() override { committed = trial; }
      void   revert() override { trial = committed; }
      void   reset() override
      {
        committed     = State();
        trial         = committed;
        trial_tangent = p.stiffness;
      }
      std::string failure() const override
      {
        return "the elastic-plastic link's force is not finite at a deformation of " +
               number_text(trial.deformation) + " m";
      }

    private:
      struct State
      {
        double deformation = 0, plastic = 0, back_force = 0, force = 0;
      };
      LinkLawParameters p;
      double            hardening_modulus;
      State             committed, trial;
      double            trial_tangent = 0;
    };
  } // namespace

  std::unique_ptr<UniaxialLaw>
  make_link_law(const LinkLawParameters &parameters)
  {
    switch (parameters.kind)
      {
        case LinkKind::viscous:
        case LinkKind::kelvin_voigt:
          return std::make_unique<ParallelLink>(parameters);
        case LinkKind::maxwell:
          return std::make_unique<MaxwellLink>(parameters);
        case LinkKind::elastic_plastic:
          return std::make_unique<ElasticPlasticLink>(parameters);
      }
    throw std::logic_error("make_link_law: unknown kind");
  }
} // namespace poundfe
