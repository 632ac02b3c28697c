// OpenSees's rate-dependent contact materials and its Viscous material, as
// OpenSees 3.8 defines them (SRC/material/uniaxial/), so that a script's
// zero-length gaps and dampers give OpenSees's numbers. A gap is closed
// while the strain eps is below the (negative) gap g; then the closure is
// delta = g - eps > 0 and its rate delta_dot = -eps_dot.
//
// Hertzdamp (P. J. Hughes, after Muthukumar and DesRoches 2006, Earthquake
//   Engng Struct. Dyn. 35: 811-828):
//     sigma = -(Kh + xi delta_dot) delta^n,  tangent -n (Kh + xi delta_dot) delta^(n-1),
//   xi = xiNorm Kh / delta_dot0, computed at each trial that closes the gap
//   from a committed open state with eps_dot < 0 and kept, outside the
//   committed state as in OpenSees, until a trial opens a committed closed gap.
// JankowskiImpact (Jankowski 2005, Earthquake Engng Struct. Dyn. 34: 595-611):
//   approach (eps_dot < 0): sigma = -(Kh delta^n + 2 xi sqrt(Kh delta^(n-1) mEff) delta_dot),
//     tangent -(n Kh delta^(n-1) + (n-1) xi sqrt(Kh delta^(n-3) mEff) delta_dot);
//   restitution: sigma = -Kh delta^n, tangent -n Kh delta^(n-1).
// ViscoelasticGap (Goldsmith 1960; OpenSees ViscoelasticGap):
//   sigma = -(K delta + C delta_dot), tangent K.
// Viscous (ViscousMaterial): sigma = C |eps_dot|^alpha sign(eps_dot), tangent 0,
//   damping tangent alpha C max(|eps_dot|, minVel)^(alpha-1).
// The tangents of Hertzdamp and JankowskiImpact are OpenSees 3.8's: the
// derivative with respect to the closure, so of the opposite sign to
// d sigma / d eps. The three gaps have no damping tangent and an initial
// tangent 0. Both as in OpenSees, so that a script's Newton iterations, and
// whether they converge, are OpenSees's too.
#include <poundfe/base/exceptions.h>
#include <poundfe/laws/material_registry.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    struct RateGapState
    {
      double strain = 0, rate = 0, stress = 0, tangent = 0;
    };

    /// The committed/trial frame the three gaps share: open (no force) at
    /// eps >= gap, closed() otherwise.
    class RateGapMaterial : public UniaxialLaw
    {
    public:
      explicit RateGapMaterial(const double gap)
        : gap(-std::abs(gap)) // OpenSees makes a positive gap negative
      {}

      bool
      set_trial(const double strain, const double rate) override
      {
        trial        = RateGapState{strain, rate, 0, 0};
        if (strain >= gap)
          opened();
        else
          closed(trial, committed.tangent == 0 && rate < 0);
        return std::isfinite(trial.stress) && std::isfinite(trial.tangent);
      }
      std::string
      failure() const override
      {
        return "contact material: strain " + std::to_string(trial.strain) + ", rate " +
               std::to_string(trial.rate) + ", stress not finite";
      }
      double force() const override { return trial.stress; }
      double tangent() const override { return trial.tangent; }
      double initial_stiffness() const override { return 0; }
      bool   is_active() const override { return trial.strain < gap; }
      bool   was_active() const override { return committed.strain < gap; }
      void   commit() override { committed = trial; }
      void   revert() override { trial = committed; }
      void
      reset() override
      {
        committed = trial = RateGapState{};
      }

    protected:
      /// The closure delta = gap - eps of the trial state.
      double closure() const { return gap - trial.strain; }
      virtual void opened() {}
      /// The trial stress and tangent of a closed gap; `new_impact`: the
      /// committed state carried no stiffness and the gap is closing.
      virtual void closed(RateGapState &s, bool new_impact) = 0;

      const double gap;
      RateGapState committed, trial;
    };

    class HertzdampMaterial : public RateGapMaterial
    {
    public:
      HertzdampMaterial(const double Kh, const double xi_norm, const double gap, const double n)
        : RateGapMaterial(gap)
        , Kh(Kh)
        , xi_norm(xi_norm)
        , n(n)
      {
        require_positive("Hertzdamp", "Kh", Kh);
        require_non_negative("Hertzdamp", "xiNorm", xi_norm);
        require_positive("Hertzdamp", "n", n);
      }
      double
      stored_energy() const override
      {
        return is_active() ? Kh * std::pow(closure(), n + 1) / (n + 1) : 0;
      }
      void
      reset() override
      {
        RateGapMaterial::reset();
        xi = 0;
      }

    private:
      void
      opened() override
      {
        if (committed.tangent != 0)
          xi = 0;
      }
      void
      closed(RateGapState &s, const bool new_impact) override
      {
        if (new_impact)
          xi = xi_norm * Kh / -s.rate;
        const double k = Kh - xi * s.rate, delta = closure();
        s.stress       = -k * std::pow(delta, n);
        s.tangent      = -n * k * std::pow(delta, n - 1); // OpenSees's sign
      }
      const double Kh, xi_norm, n;
      double       xi = 0; // OpenSees's impact damping coefficient, not reverted
    };

    class JankowskiImpactMaterial : public RateGapMaterial
    {
    public:
      JankowskiImpactMaterial(const double Kh, const double xi, const double m_eff,
                              const double gap, const double n)
        : RateGapMaterial(gap)
        , Kh(Kh)
        , xi(xi)
        , m_eff(m_eff)
        , n(n)
      {
        require_positive("JankowskiImpact", "Kh", Kh);
        require_non_negative("JankowskiImpact", "xi", xi);
        require_non_negative("JankowskiImpact", "mEff", m_eff);
        require_positive("JankowskiImpact", "n", n);
      }
      double
      stored_energy() const override
      {
        return is_active() ? Kh * std::pow(closure(), n + 1) / (n + 1) : 0;
      }

    private:
      void
      closed(RateGapState &s, bool) override
      {
        const double delta = closure();
        s.stress           = -Kh * std::pow(delta, n);
        s.tangent          = -n * Kh * std::pow(delta, n - 1); // OpenSees's sign
        if (s.rate < 0)
          {
            s.stress -= 2 * xi * std::sqrt(Kh * std::pow(delta, n - 1) * m_eff) * -s.rate;
            s.tangent -= (n - 1) * xi * std::sqrt(Kh * std::pow(delta, n - 3) * m_eff) * -s.rate;
          }
      }
      const double Kh, xi, m_eff, n;
    };

    class ViscoelasticGapMaterial : public RateGapMaterial
    {
    public:
      ViscoelasticGapMaterial(const double K, const double C, const double gap)
        : RateGapMaterial(gap)
        , K(K)
        , C(C)
      {
        require_positive("ViscoelasticGap", "K", K);
        require_non_negative("ViscoelasticGap", "C", C);
      }
      double
      stored_energy() const override
      {
        return is_active() ? 0.5 * K * closure() * closure() : 0;
      }

    private:
      void
      closed(RateGapState &s, bool) override
      {
        s.stress  = -(K * closure() - C * s.rate);
        s.tangent = K;
      }
      const double K, C;
    };

    class ViscousUniaxial : public UniaxialLaw
    {
    public:
      ViscousUniaxial(const double C, const double alpha, const double min_vel)
        : C(C)
        , alpha(alpha)
        , min_vel(min_vel == 0 ? 1e-21 : std::abs(min_vel)) // OpenSees's floor
      {
        if (!std::isfinite(C))
          refuse_parameter("Viscous", "C", "must be a finite number");
        require_non_negative("Viscous", "alpha", alpha);
      }
      bool
      set_trial(double, const double rate) override
      {
        trial_rate = rate;
        return std::isfinite(rate);
      }
      double
      force() const override
      {
        const double stress = C * std::pow(std::abs(trial_rate), alpha);
        return trial_rate < 0 ? -stress : stress;
      }
      double tangent() const override { return 0; }
      double
      damping_tangent() const override
      {
        return alpha * C * std::pow(std::max(std::abs(trial_rate), min_vel), alpha - 1);
      }
      double stored_energy() const override { return 0; }
      double initial_stiffness() const override { return 0; }
      void   commit() override {}
      void   revert() override {}
      void   reset() override { trial_rate = 0; }

    private:
      const double C, alpha, min_vel;
      double       trial_rate = 0;
    };
  } // namespace

  namespace materials
  {
    MaterialType
    hertzdamp()
    {
      return {"Hertzdamp",
              "Hertz contact with impact damping (OpenSees Hertzdamp)",
              {{"Kh", NAN, "Hertz stiffness"},
               {"xiNorm", NAN, "damping ratio normalised by the impact velocity"},
               {"gap", NAN, "initial gap (negative)"},
               {"n", 1.5, "exponent of the closure"}},
              [](const std::map<std::string, double> &v) -> std::unique_ptr<UniaxialLaw> {
                return std::make_unique<HertzdampMaterial>(v.at("Kh"), v.at("xiNorm"),
                                                           v.at("gap"), v.at("n"));
              }};
    }

    MaterialType
    jankowski_impact()
    {
      return {"JankowskiImpact",
              "nonlinear viscoelastic contact (OpenSees JankowskiImpact)",
              {{"Kh", NAN, "Hertz stiffness"},
               {"xi", NAN, "damping ratio"},
               {"mEff", NAN, "effective mass of the colliding bodies"},
               {"gap", NAN, "initial gap (negative)"},
               {"n", 1.5, "exponent of the closure"}},
              [](const std::map<std::string, double> &v) -> std::unique_ptr<UniaxialLaw> {
                return std::make_unique<JankowskiImpactMaterial>(
                  v.at("Kh"), v.at("xi"), v.at("mEff"), v.at("gap"), v.at("n"));
              }};
    }

    MaterialType
    viscoelastic_gap()
    {
      return {"ViscoelasticGap",
              "linear spring and dashpot past a gap (OpenSees ViscoelasticGap)",
              {{"K", NAN, "stiffness"},
               {"C", NAN, "damping coefficient"},
               {"gap", NAN, "initial gap (negative)"}},
              [](const std::map<std::string, double> &v) -> std::unique_ptr<UniaxialLaw> {
                return std::make_unique<ViscoelasticGapMaterial>(v.at("K"), v.at("C"),
                                                                 v.at("gap"));
              }};
    }

    MaterialType
    viscous()
    {
      return {"Viscous",
              "nonlinear dashpot C |v|^alpha (OpenSees Viscous)",
              {{"C", NAN, "damping coefficient"},
               {"alpha", NAN, "power of the velocity"},
               {"minVel", 1e-11, "smallest velocity of the damping tangent"}},
              [](const std::map<std::string, double> &v) -> std::unique_ptr<UniaxialLaw> {
                return std::make_unique<ViscousUniaxial>(v.at("C"), v.at("alpha"),
                                                         v.at("minVel"));
              }};
    }
  } // namespace materials
} // namespace poundfe
