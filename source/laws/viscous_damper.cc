// OpenSees 3.8's ViscousDamper: equations, integration and source in
// laws/viscous_damper.h. The arithmetic is OpenSees's, in its order, so
// that a script's forces agree to round-off.
#include <poundfe/laws/material_registry.h>
#include <poundfe/laws/viscous_damper.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    struct DamperState
    {
      double strain = 0, stress = 0, rate = 0;
      /// Where the force last turned positive / negative (LGap > 0).
      double positive_gap_start = 0, negative_gap_start = 0;
    };

    /// One trial sub-step's force and its error estimate.
    struct SubStep
    {
      double force = 0, error = 0, relative_error = 0;
    };

    class ViscousDamper : public UniaxialLaw
    {
    public:
      ViscousDamper(const std::map<std::string, double> &v, const double &time_step)
        : K(v.at("K"))
        , C(v.at("C"))
        , alpha(v.at("Alpha"))
        , gap(v.at("LGap"))
        , method(v.at("NM"))
        , rel_tol(v.at("RelTol"))
        , abs_tol(v.at("AbsTol"))
        , smallest_fraction(std::pow(0.5, v.at("MaxHalf")))
        , time_step(time_step)
      {
        require_positive("ViscousDamper", "K", K);
        require_positive("ViscousDamper", "C", C);
        require_positive("ViscousDamper", "Alpha", alpha);
        require_non_negative("ViscousDamper", "LGap", gap);
        if (method != 1 && method != 2 && method != 3)
          refuse_parameter("ViscousDamper", "NM", "must be 1, 2 or 3");
        // A tolerance no sub-step can meet halves every sub-step down to
        // 0.5^MaxHalf of the step: 2^MaxHalf evaluations a trial. Both
        // bounds keep that finite and short (2^20 at most).
        if (!(std::isfinite(rel_tol) && rel_tol >= 1e-15))
          refuse_parameter("ViscousDamper", "RelTol", "must be a number of at least 1e-15");
        if (!(std::isfinite(abs_tol) && abs_tol >= 0))
          refuse_parameter("ViscousDamper", "AbsTol", "must be a number >= 0");
        const double max_half = v.at("MaxHalf");
        if (!(max_half >= 0 && max_half <= 20 && max_half == std::floor(max_half)))
          refuse_parameter("ViscousDamper", "MaxHalf", "must be an integer from 0 to 20");
      }

      bool set_trial(double strain, double rate) override;
      std::string
      failure() const override
      {
        return "ViscousDamper: strain " + std::to_string(trial.strain) + ", rate " +
               std::to_string(trial.rate) + ", force not finite";
      }
      double force() const override { return trial.stress; }
      double tangent() const override { return 0; }
      double stored_energy() const override { return 0.5 * trial.stress * trial.stress / K; }
      double initial_stiffness() const override { return 0; }
      void   commit() override { committed = trial; }
      void   revert() override { trial = committed; }
      void   reset() override { committed = trial = DamperState{}; }

    private:
      /// dF/dt at rate v and force F.
      double
      f(const double v, const double F) const
      {
        return (v - (F < 0 ? -1.0 : 1.0) * std::pow(std::abs(F) / C, 1.0 / alpha)) * K;
      }
      SubStep dormand_prince(double v0, double v1, double y0, double h) const;
      SubStep adams_bashforth_moulton(double v0, double v1, double y0, double h) const;
      SubStep rosenbrock(double v0, double v1, double y0, double h) const;
      double  integrate(double rate) const;
      double  with_gap(double force, double strain);

      const double  K, C, alpha, gap, method, rel_tol, abs_tol, smallest_fraction;
      const double &time_step;
      DamperState   committed, trial;
    };

    bool
    ViscousDamper::set_trial(const double strain, const double rate)
    {
      trial              = committed;
      const double force = integrate(rate);
      trial.stress       = with_gap(force, strain);
      trial.rate         = rate == 0 ? 0.0 : rate;
      trial.strain       = strain;
      return std::isfinite(trial.stress);
    }

    /// The force at the end of the step: sub-steps of s dt, s halved until
    /// one is accepted (OpenSees's loop; a rate of exactly 0, a static
    /// step, keeps the committed rate over the step).
    double
    ViscousDamper::integrate(const double rate) const
    {
      const double v_end = rate == 0 ? 0.0 : rate;
      const double acc   = rate == 0 ? 0.0 : (v_end - committed.rate) / time_step;
      double       s = 1, done = 0, v0 = committed.rate, y0 = committed.stress;
      while (done != 1.0)
        {
          const double h  = s * time_step;
          const double v1 = v0 + acc * h;
          const SubStep step = method == 1 ? dormand_prince(v0, v1, y0, h) :
                               method == 2 ? adams_bashforth_moulton(v0, v1, y0, h) :
                                             rosenbrock(v0, v1, y0, h);
          if (step.relative_error <= rel_tol || s == smallest_fraction ||
              std::abs(step.error) <= abs_tol)
            {
              v0 = v1;
              y0 = step.force;
              done += s;
            }
          else
            s = s > smallest_fraction ? 0.5 * s : smallest_fraction;
          if (!std::isfinite(step.force) && s == smallest_fraction)
            return step.force; // no sub-step can help: the trial fails
        }
      return y0;
    }

    /// LGap: no force while the strain is within the gap of where the force
    /// changed sign (OpenSees's approximate gap start, linear in the force).
    double
    ViscousDamper::with_gap(double force, const double strain)
    {
      if (!(gap > 0))
        return force;
      const double d_strain = strain - committed.strain, last = committed.stress;
      DamperState &t        = trial;
      if (force > 0 && last < 0)
        {
          t.positive_gap_start =
            committed.strain + d_strain * std::abs(force) / std::abs(force - last);
          t.negative_gap_start = 0;
          if (std::abs(strain - t.positive_gap_start) < gap)
            force = 0;
        }
      if (force < 0 && last > 0)
        {
          t.negative_gap_start =
            committed.strain + d_strain * std::abs(force) / std::abs(force - last);
          t.positive_gap_start = 0;
          if (std::abs(strain - t.negative_gap_start) < gap)
            force = 0;
        }
      if (std::abs(t.positive_gap_start) > 0 && last == 0 && strain > t.positive_gap_start &&
          strain - t.positive_gap_start < gap)
        force = 0;
      if (std::abs(t.negative_gap_start) > 0 && last == 0 && strain < t.negative_gap_start &&
          strain - t.negative_gap_start > -gap)
        force = 0;
      return force;
    }

    SubStep
    ViscousDamper::dormand_prince(const double v0, const double v1, const double y0,
                                  const double h) const
    {
      const double dv = v1 - v0;
      const double k1 = f(v0, y0) * h;
      const double k2 = f(dv * (1. / 5.) + v0, y0 + (1. / 5.) * k1) * h;
      const double k3 = f(dv * (3. / 10.) + v0, y0 + (3. / 40.) * k1 + (9. / 40.) * k2) * h;
      const double k4 = f(dv * (4. / 5.) + v0,
                          y0 + (44. / 45.) * k1 + (-56. / 15.) * k2 + (32. / 9.) * k3) * h;
      const double k5 =
        f(dv * (8. / 9.) + v0, y0 + (19372.0 / 6561.0) * k1 + (-25360.0 / 2187.0) * k2 +
                                 (64448.0 / 6561.0) * k3 + (-212.0 / 729.0) * k4) * h;
      const double k6 =
        f(dv * (1.) + v0, y0 + (9017.0 / 3168.0) * k1 + (-355.0 / 33.0) * k2 +
                            (46732.0 / 5247.0) * k3 + (49.0 / 176.0) * k4 +
                            (-5103.0 / 18656.0) * k5) * h;
      SubStep s;
      s.force = y0 + (35. / 384.) * k1 + (500. / 1113.) * k3 + (125. / 192.) * k4 +
                (-2187. / 6784.) * k5 + (11. / 84.) * k6;
      const double k7 = f(dv * (1.) + v0, s.force) * h;
      s.error = (71. / 57600.) * k1 + (-71. / 16695.) * k3 + (71. / 1920.) * k4 +
                (-17253. / 339200.) * k5 + (22. / 525.) * k6 + (-1. / 40.) * k7;
      s.relative_error = std::abs(s.error / s.force);
      return s;
    }

    SubStep
    ViscousDamper::adams_bashforth_moulton(const double v0, const double v1, const double y0,
                                           double h) const
    {
      const double dv = v1 - v0;
      h               = h / 6.0;
      const double f0 = f(dv * (0. / 6.) + v0, y0);
      double       y1 = y0 + h * f0; // predictor, then corrector
      const double f1 = f(dv * (1. / 6.) + v0, y1);
      y1              = y0 + h * f1;
      double y2       = y1 + 0.5 * h * (3. * f1 - 1. * f0);
      const double f2 = f(dv * (2. / 6.) + v0, y2);
      y2              = y1 + 0.5 * h * (f2 + f1);
      double y3       = y2 + h / 12. * (23. * f2 - 16. * f1 + 5. * f0);
      const double f3 = f(dv * (3. / 6.) + v0, y3);
      y3              = y2 + h / 12. * (5. * f3 + 8. * f2 - 1. * f1);
      double y4       = y3 + h / 24. * (55. * f3 - 59. * f2 + 37. * f1 - 9. * f0);
      const double f4 = f(dv * (4. / 6.) + v0, y4);
      y4              = y3 + h / 24. * (9. * f4 + 19. * f3 - 5. * f2 + f1);
      double y5 =
        y4 + h / 720. * (1901. * f4 - 2774. * f3 + 2616. * f2 - 1274. * f1 + 251. * f0);
      const double f5 = f(dv * (5. / 6.) + v0, y5);
      y5 = y4 + h / 720. * (251. * f5 + 646. * f4 - 264. * f3 + 106. * f2 - 19. * f1);
      const double yp6 = y5 + h / 1440. *
                                (4277. * f5 - 7923. * f4 + 9982. * f3 - 7298. * f2 +
                                 2877. * f1 - 475. * f0);
      const double f6 = f(dv * (6. / 6.) + v0, yp6);
      SubStep s;
      s.force = y5 + (h / 1440.) *
                       (475. * f6 + 1427. * f5 - 798. * f4 + 482. * f3 - 173. * f2 + 27. * f1);
      s.error          = yp6 - s.force;
      s.relative_error = std::abs(s.error / s.force);
      return s;
    }

    SubStep
    ViscousDamper::rosenbrock(const double v0, const double v1, const double y0,
                              const double h) const
    {
      const double J = -K / (alpha * C), T = K;
      const double d = 1. / (2. + std::sqrt(2.)), e32 = 6. + std::sqrt(2.);
      const double W  = 1. - h * d * J;
      const double f0 = f(v0, y0);
      const double k1 = (f0 + h * d * T) / W;
      const double f1 = f((v1 - v0) * (0.5) + v0, y0 + (0.5) * k1 * h);
      const double k2 = (f1 - k1) / W + k1;
      SubStep      s;
      s.force         = y0 + h * k2;
      const double f2 = f(v1, s.force);
      const double k3 = 1. / W * (f2 - e32 * (k2 - f1) - 2. * (k1 - f0) + h * d * T);
      s.error         = h / 6. * (k1 - 2. * k2 + k3);
      s.relative_error = std::abs(s.error / (s.force + s.error));
      return s;
    }
  } // namespace

  std::unique_ptr<UniaxialLaw>
  make_viscous_damper(const std::map<std::string, double> &values, const double &time_step)
  {
    std::map<std::string, double> v = {{"LGap", 0.0},      {"NM", 1},
                                       {"RelTol", 1.0e-6}, {"AbsTol", 1.0e-10},
                                       {"MaxHalf", 15}};
    for (const auto &[name, value] : values)
      v[name] = value;
    for (const char *required : {"K", "C", "Alpha"})
      if (v.count(required) == 0)
        refuse_parameter("ViscousDamper", required, "is missing");
    return std::make_unique<ViscousDamper>(v, time_step);
  }
} // namespace poundfe
