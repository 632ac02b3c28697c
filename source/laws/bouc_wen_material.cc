// OpenSees's BoucWenMaterial (Haukaas and Der Kiureghian; OpenSees 3.8,
// SRC/material/uniaxial/BoucWenMaterial.cpp), so that a script's BoucWen
// gives OpenSees's numbers. Bouc-Wen with Baber-Noori degradation, z in
// units of the strain:
//   sigma = alpha ko eps + (1 - alpha) ko z,
//   z1 = z0 + Phi(z1) / eta * d eps    (backward Euler over the step),
//   Phi = A - |z1|^n (gamma + beta sgn(d eps z1)) nu,
//   A = Ao - deltaA e, nu = 1 + deltaNu e, eta = 1 + deltaEta e,
//   e = e0 + (1 - alpha) ko d eps z1   (the hysteretic energy).
// z1 is found by Newton's iteration from z = 0.01 (not from z0) until two
// iterates differ by at most `tolerance` or after maxNumIter iterations (then
// OpenSees warns and goes on with the last iterate; so does this material);
// sgn(x) is 1 for x > 0 and -1 otherwise. The tangent is OpenSees's
// derivative of that discrete map (alpha ko + (1 - alpha) ko where z1 = 0).
// poundfe's own Bouc-Wen (laws/bouc_wen.h) integrates the same ODE by the
// trapezoidal rule with z dimensionless: a different discrete law.
#include <poundfe/base/exceptions.h>
#include <poundfe/laws/material_registry.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    struct BoucWenMaterialState
    {
      double strain = 0, stress = 0, tangent = 0, z = 0, energy = 0;
    };

    struct BoucWenMaterialParameters
    {
      double alpha, ko, n, gamma, beta, Ao, deltaA, deltaNu, deltaEta, tolerance;
      int    max_iterations;
    };

    double
    bouc_wen_signum(const double x)
    {
      return x > 0 ? 1.0 : -1.0;
    }

    class OpenSeesBoucWen : public UniaxialMaterial<BoucWenMaterialState>
    {
    public:
      explicit OpenSeesBoucWen(const BoucWenMaterialParameters &parameters)
        : p(parameters)
      {
        require_positive("BoucWen", "ko", p.ko);
        require_positive("BoucWen", "n", p.n);
        require_positive("BoucWen", "tolerance", p.tolerance);
        if (p.max_iterations < 1)
          refuse_parameter("BoucWen", "maxNumIter", "must be at least 1");
        reset();
      }
      double initial_stiffness() const override
      {
        return p.alpha * p.ko + (1 - p.alpha) * p.ko * p.Ao;
      }
      double history_variable() const override { return trial.z; }

    private:
      BoucWenMaterialState
      virgin() const override
      {
        BoucWenMaterialState s;
        s.tangent = initial_stiffness();
        return s;
      }

      /// Newton's step for z and, at the new z, the stress and the tangent,
      /// in OpenSees's order of operations.
      BoucWenMaterialState
      respond(const BoucWenMaterialState &from, const double strain) const override
      {
        const double d = strain - from.strain, k = (1 - p.alpha) * p.ko;
        BoucWenMaterialState s = from;
        s.strain               = strain;
        double z = 0.01, z_old = 0.01, z_new = 1.0;
        for (int count = 0; std::abs(z_old - z_new) > p.tolerance && count < p.max_iterations;
             ++count)
          {
            const double e = from.energy + k * d * z, A = p.Ao - p.deltaA * e;
            const double nu = 1 + p.deltaNu * e, eta = 1 + p.deltaEta * e;
            const double psi = p.gamma + p.beta * bouc_wen_signum(d * z);
            const double phi = A - std::pow(std::abs(z), p.n) * psi * nu;
            const double f   = z - from.z - phi / eta * d;
            const double de = k * d, dA = -p.deltaA * de, dnu = p.deltaNu * de;
            const double deta = p.deltaEta * de;
            const double pow1 = z == 0 ? 0.0 : std::pow(std::abs(z), p.n - 1);
            const double pow2 = z == 0 ? 0.0 : std::pow(std::abs(z), p.n);
            const double dphi = dA - p.n * pow1 * bouc_wen_signum(z) * psi * nu - pow2 * psi * dnu;
            const double df   = 1.0 - (dphi * eta - phi * deta) / std::pow(eta, 2.0) * d;
            z_new             = z - f / df;
            z_old             = z;
            z                 = z_new;
          }
        s.z      = z;
        s.stress = p.alpha * p.ko * strain + k * z;
        s.energy = from.energy + k * d * z;
        s.tangent = tangent_at(s, d);
        return s;
      }

      double
      tangent_at(const BoucWenMaterialState &s, const double d) const
      {
        if (s.z == 0)
          return p.alpha * p.ko + (1 - p.alpha) * p.ko;
        const double k = (1 - p.alpha) * p.ko, e = s.energy, z = s.z;
        const double A = p.Ao - p.deltaA * e, nu = 1 + p.deltaNu * e, eta = 1 + p.deltaEta * e;
        const double psi = p.gamma + p.beta * bouc_wen_signum(d * z);
        const double phi = A - std::pow(std::abs(z), p.n) * psi * nu;
        const double b1 = k * z, b2 = k * d, b3 = d / eta;
        const double b4 = -b3 * p.deltaA * b1 - b3 * std::pow(std::abs(z), p.n) * psi * p.deltaNu * b1 -
                          phi / (eta * eta) * d * p.deltaEta * b1 + phi / eta;
        const double b5 = 1.0 + b3 * p.deltaA * b2 +
                          b3 * p.n * std::pow(std::abs(z), p.n - 1) * bouc_wen_signum(z) * psi * nu +
                          b3 * std::pow(std::abs(z), p.n) * psi * p.deltaNu * b2 +
                          phi / (eta * eta) * d * p.deltaEta * b2;
        return p.alpha * p.ko + k * b4 / b5;
      }

      const BoucWenMaterialParameters p;
    };
  } // namespace

  namespace materials
  {
    MaterialType
    bouc_wen_material()
    {
      return {"BoucWen",
              "Bouc-Wen with Baber-Noori degradation, backward Euler (OpenSees BoucWen)",
              {{"alpha", NAN, "ratio of the post-yield to the initial stiffness"},
               {"ko", NAN, "initial stiffness"},
               {"n", NAN, "sharpness of the yield"},
               {"gamma", NAN, "shape (units of 1/strain^n)"},
               {"beta", NAN, "shape (units of 1/strain^n)"},
               {"Ao", NAN, "amplitude A at zero energy"},
               {"deltaA", NAN, "degradation of A per unit energy"},
               {"deltaNu", NAN, "degradation of nu per unit energy"},
               {"deltaEta", NAN, "degradation of eta per unit energy"},
               {"tolerance", 1e-8, "of z's Newton iteration"},
               {"maxNumIter", 20, "of z's Newton iteration"}},
              [](const std::map<std::string, double> &v) -> std::unique_ptr<UniaxialLaw> {
                return std::make_unique<OpenSeesBoucWen>(BoucWenMaterialParameters{
                  v.at("alpha"), v.at("ko"), v.at("n"), v.at("gamma"), v.at("beta"), v.at("Ao"),
                  v.at("deltaA"), v.at("deltaNu"), v.at("deltaEta"), v.at("tolerance"),
                  static_cast<int>(v.at("maxNumIter"))});
              }};
    }
  } // namespace materials
} // namespace poundfe
