// A reliability problem in the standard form of Der Kiureghian (2005) and
// Melchers & Beck (2018, ch. 4): random variables X with a Nataf joint
// distribution (nataf.h), limit-state functions g_k(x) with failure
// g_k <= 0, and the way they combine:
//   series system:   failure when any g_k <= 0, i.e. min_k g_k <= 0;
//   parallel system: failure when all g_k <= 0, i.e. max_k g_k <= 0.
// The methods work in the standard normal space u, G_k(u) = g_k(T(u)), and
// count every evaluation of a g_k.
#ifndef poundfe_reliability_reliability_problem_h
#define poundfe_reliability_reliability_problem_h

#include <poundfe/reliability/nataf.h>

#include <functional>
#include <string>
#include <vector>

namespace poundfe
{
  enum class SystemType
  {
    series,
    parallel
  };

  /// g(x) on the physical values of the random variables.
  using LimitStateFunction = std::function<double(const std::vector<double> &)>;

  struct ReliabilityProblem
  {
    NatafTransformation             transformation;
    std::vector<LimitStateFunction> limit_states;
    SystemType                      system = SystemType::series;
  };

  /// G_k(u) = g_k(T(u)) with a count of the evaluations (one object per
  /// method run; not shared between threads).
  class StandardSpaceLimitStates
  {
  public:
    explicit StandardSpaceLimitStates(const ReliabilityProblem &problem)
      : problem(problem)
    {}

    unsigned int n_variables() const { return problem.transformation.n_variables(); }
    unsigned int n_limit_states() const { return problem.limit_states.size(); }
    SystemType   system() const { return problem.system; }
    const NatafTransformation &transformation() const { return problem.transformation; }

    /// G_k(u).
    double operator()(unsigned int k, const std::vector<double> &u) const;
    /// min_k G_k (series) or max_k G_k (parallel): the system fails when <= 0.
    double system_value(const std::vector<double> &u) const;
    /// dG_k/du by finite differences: central (2n evaluations) or forward
    /// (n, reusing `value` = G_k(u)) with the absolute step h (u is in
    /// standard deviations, so one step fits every variable).
    void gradient(unsigned int k, const std::vector<double> &u, double value, double h,
                  bool central, std::vector<double> &gradient) const;

    unsigned long n_evaluations() const { return evaluations; }

  private:
    const ReliabilityProblem   &problem;
    mutable std::vector<double> x;
    mutable unsigned long       evaluations = 0;
  };

  double dot(const std::vector<double> &a, const std::vector<double> &b);
  double norm(const std::vector<double> &a);
} // namespace poundfe

#endif
