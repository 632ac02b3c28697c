// Marginal distributions of the basic random variables of a reliability
// problem, and their map to a standard normal variable.
//
//   normal N(mu, sigma):             F = Phi((x - mu)/sigma)
//   lognormal (lambda, zeta):        F = Phi((ln x - lambda)/zeta),
//     from mean m and COV d:         zeta^2 = ln(1 + d^2), lambda = ln m - zeta^2/2
//   uniform [a, b]:                  F = (x - a)/(b - a); mean (a+b)/2, sd (b-a)/sqrt(12)
//   truncated normal (mu, sigma) on [a, b] (the parent's mu, sigma):
//                                    F = (Phi(z) - Phi(za))/(Phi(zb) - Phi(za)), z = (x-mu)/sigma
//   Gumbel (largest values; location u, scale s):
//                                    F = exp(-exp(-(x - u)/s)),
//                                    mean u + gamma_E s, sd pi s/sqrt(6)
//   Weibull (smallest values; shape k, scale l):
//                                    F = 1 - exp(-(x/l)^k), mean l Gamma(1 + 1/k),
//                                    sd^2 = l^2 (Gamma(1 + 2/k) - Gamma(1 + 1/k)^2);
//                                    from mean and COV: k solves
//                                    COV^2 = Gamma(1+2/k)/Gamma(1+1/k)^2 - 1 (monotone in k).
//   Standard normal image (Rosenblatt for one variable): u = Phi^{-1}(F(x)),
//   x = F^{-1}(Phi(u)); for u > 0 the complements are used, so the upper
//   tail keeps its precision.
// Sources: Melchers & Beck, Structural Reliability Analysis and Prediction,
// 3rd ed. (Wiley 2018), Appendix A; Ditlevsen & Madsen, Structural
// Reliability Methods (Wiley 1996), ch. 7; Der Kiureghian, "First- and
// second-order reliability methods", ch. 14 of the Engineering Design
// Reliability Handbook (CRC 2005), Table 14.1.
#ifndef poundfe_reliability_distribution_h
#define poundfe_reliability_distribution_h

#include <poundfe/base/standard_normal.h>

#include <string>
#include <vector>

namespace poundfe
{
  enum class DistributionType
  {
    normal,
    lognormal,
    uniform,
    truncated_normal,
    gumbel,
    weibull
  };

  /// The names in parameter files and summary.json ("normal", "lognormal",
  /// "uniform", "truncated normal", "Gumbel", "Weibull").
  const std::string &distribution_name(DistributionType type);
  /// The type called `name`; throws std::invalid_argument naming the choices.
  DistributionType distribution_type(const std::string &name);

  class Distribution
  {
  public:
    /// From the native parameters of the type: normal (mu, sigma); lognormal
    /// (lambda, zeta); uniform (a, b); truncated normal (mu, sigma, a, b);
    /// Gumbel (location, scale); Weibull (shape, scale). Throws
    /// std::invalid_argument saying which parameter is impossible.
    static Distribution from_native(DistributionType type, const std::vector<double> &p);
    /// From the mean and the standard deviation (all but the truncated
    /// normal, whose mean and sd are not its parameters). Throws
    /// std::invalid_argument (sd <= 0, lognormal or Weibull mean <= 0, ...).
    static Distribution from_moments(DistributionType type, double mean, double sd);

    DistributionType type() const { return kind; }
    /// The native parameters (as from_native takes them).
    const std::vector<double> &parameters() const { return native; }
    double mean() const;
    double standard_deviation() const;

    double pdf(double x) const;
    double cdf(double x) const;
    /// 1 - F(x), without the cancellation of 1 - cdf(x) in the upper tail.
    double complementary_cdf(double x) const;
    /// x with F(x) = p, p in (0, 1).
    double quantile(double p) const;

    /// u = Phi^{-1}(F(x)) (+-37.5 where F(x) rounds to 0 or 1).
    double to_standard_normal(double x) const;
    /// x = F^{-1}(Phi(u)).
    double from_standard_normal(double u) const;

  private:
    Distribution(DistributionType type, std::vector<double> native);
    /// Upper-tail quantile: x with 1 - F(x) = q.
    double complementary_quantile(double q) const;

    DistributionType    kind;
    std::vector<double> native;
  };

  /// The inverse of Phi, u clipped to +-u_limit at p = 0 and 1 (phi and Phi
  /// themselves: base/standard_normal.h).
  double standard_normal_quantile(double p);
} // namespace poundfe

#endif
