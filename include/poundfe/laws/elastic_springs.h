// Nonlinear elastic springs between a mass and the ground (history-free
// uniaxial laws):
//   SD spring (Cao, Wiercigroch, Pavlovskaia, Grebogi & Thompson 2006): a mass
//   held by a pair of linear springs of stiffness K/2 and natural length L
//   pinned at height H above (and below) its line of motion; their horizontal
//   resultant is
//       F(x) = K x (1 - L / sqrt(x^2 + H^2)),
//       dF/dx = K (1 - L H^2 / (x^2 + H^2)^(3/2)),
//       U(x)  = K (x^2/2 - L sqrt(x^2 + H^2) + L H)    (U(0) = 0).
//   Smooth for H > 0 (bistable with wells at x = +-sqrt(L^2 - H^2) when
//   H < L); H = 0 is the discontinuous limit F = K (x - L sgn x).
//   Cubic (Duffing) spring: F = k1 x + k3 x^3, U = k1 x^2/2 + k3 x^4/4.
// The linear part (K, k1) is assembled into the linear K (reference
// stiffness); the element carries only the rest.
// Sources: Q. Cao, M. Wiercigroch, E.E. Pavlovskaia, C. Grebogi &
// J.M.T. Thompson, Phys. Rev. E 74 (2006) 046218 (the SD oscillator);
// I. Kovacic & M.J. Brennan (eds.), The Duffing Equation, Wiley 2011;
// doc/theory.md §8.2.
#ifndef poundfe_laws_elastic_springs_h
#define poundfe_laws_elastic_springs_h

#include <poundfe/laws/uniaxial_law.h>

#include <string>

namespace poundfe
{
  enum class SpringKind
  {
    sd,   // smooth-and-discontinuous
    cubic // Duffing
  };

  struct SpringLawParameters
  {
    SpringKind kind      = SpringKind::sd;
    double     stiffness = 1; // K (sd) or k1 (cubic), N/m: the linear part
    double     length    = 1; // L (sd), m
    double     height    = 1; // H (sd), m
    double     cubic     = 0; // k3 (cubic), N/m^3

    /// F(x) and dF/dx.
    double force(double x) const;
    double tangent(double x) const;
    /// U(x), with U(0) = 0.
    double energy(double x) const;
  };

  /// A history-free law F(d) of SpringLawParameters.
  class ElasticSpring final : public UniaxialLaw
  {
  public:
    explicit ElasticSpring(const SpringLawParameters &parameters);

    bool   set_trial(double deformation, double rate) override;
    double force() const override { return trial_force; }
    double tangent() const override { return trial_tangent; }
    double stored_energy() const override { return p.energy(trial_deformation); }
    double initial_stiffness() const override { return p.tangent(0); }
    /// The side of the force jump at 0 of a discontinuous SD spring (H = 0):
    /// crossing it is an event. Always false for smooth springs.
    bool is_active() const override { return discontinuous && trial_deformation > 0; }
    bool was_active() const override { return discontinuous && committed_deformation > 0; }

    void commit() override;
    void revert() override;
    void reset() override;
    std::string failure() const override;

  private:
    SpringLawParameters p;
    bool                discontinuous = false;
    double              trial_deformation = 0, trial_force = 0, trial_tangent = 0;
    double              committed_deformation = 0;
  };
} // namespace poundfe

#endif
